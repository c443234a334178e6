// SPDX-License-Identifier: MIT
// acore_serial_datapath: the serial core's arithmetic: an accumulator ACC, two temporary registers
// T1 and T2, one shifter and one adder, all W bits wide, plus the sample's status bits. Every
// clock the controller (acore_serial_ctrl.v) picks one operation:
//
//   res = sat( A + ((shift(B) & {gate}) ^ {sub}) + cin )  -> ACC, T1, T2 and/or the scratch RAM
//
//   A      one of 0 (or half a turn), ACC, T1, the RAM word Q, pin c1, mag_lo, mag_hi
//   B      one of T1, T2, ACC, Q, pin c3, through the shifter: shift(B) = B * 2^k, k in [-MAXR, LS],
//          floor for right shifts (arithmetic), the bit shifted out last is the rounding bit rbit
//   gate   1, bit bit_idx of Q (the amplitude reciprocal, scaling) or of T2 (x, Horner)
//   sub    0/1 or a sign picked by the controller (of ACC, Q, T2, the CORDIC pre-rotation, the
//          CORDIC direction history); cin = sub, rbit, ~rbit or 0, so the one adder also rounds
//          (round_shr(v, s) = (v >>> s) + v[s-1]) and compares (a - b - 1 >= 0 <=> a > b)
//   sat    none, S_W or ACC_W bits (the contract's saturations; raises the sample's ovf)
//
// The shifter is the barrel (B << LS << 1) >>> sh_amt_i, so sh_amt_i = LS - k; its extra low bit
// is the rounding bit. W holds every exact intermediate of the contract (see acore_serial_top.v).
// T1 and T2 can also load ACC, Q or a pin directly (register moves beside the adder).
// en_i = 0 freezes every register (stall).
`resetall
`default_nettype none

module acore_serial_datapath #(
  parameter integer IN_W = 16,
  parameter integer REG_W = 18,
  // RAM word width (max(REG_W, S_W)).
  parameter integer MEM_W = 18,
  parameter integer S_W = 18,
  parameter integer ACC_W = 25,
  parameter integer Z_W = 20,
  parameter integer ANGLE_W = 16,
  parameter integer K = 16,
  parameter integer REGIONS = 4,
  // Datapath width, left shift range of the shifter, shift amount and bit index widths.
  parameter integer W = 29,
  parameter integer LS = 8,
  parameter integer SHA_W = 5,
  parameter integer BI_W = 5,
  // Derived, do not override.
  parameter integer RG_W = $clog2(REGIONS),
  parameter integer MAG_W = S_W + 2
) (
  input  wire               clk_i,
  // Advance: 0 holds every register.
  input  wire               en_i,
  // Channel codes (valid in the accepting clock only) and the status window.
  input  wire [IN_W-1:0]    c1_i,
  input  wire [IN_W-1:0]    c2_i,
  input  wire [IN_W-1:0]    c3_i,
  input  wire [IN_W-1:0]    c4_i,
  input  wire [MAG_W-1:0]   mag_lo_i,
  input  wire [MAG_W-1:0]   mag_hi_i,
  // RAM read data.
  input  wire [MEM_W-1:0]   q_i,
  // ---- operation (encodings: the localparams below, same as acore_serial_ctrl.v) ----
  input  wire [2:0]         a_sel_i,
  // With A_ZERO: add half a turn (2^(Z_W-1)) when the CORDIC pre-rotation negated the vector.
  input  wire               a_half_i,
  input  wire [2:0]         b_sel_i,
  // How Q is extended to W bits.
  input  wire [1:0]         q_ext_i,
  input  wire [SHA_W-1:0]   sh_amt_i,
  input  wire [1:0]         gate_sel_i,
  input  wire [BI_W-1:0]    bit_idx_i,
  input  wire [2:0]         sub_sel_i,
  input  wire [1:0]         cin_sel_i,
  input  wire [1:0]         sat_sel_i,
  // Destinations.
  input  wire               acc_we_i,
  input  wire               t1_we_i,
  input  wire [1:0]         t1_src_i,
  input  wire               t2_we_i,
  input  wire [1:0]         t2_src_i,
  // Status: clear ovf (new sample), latch the region compare, the pre-rotation sign, push/pop a
  // CORDIC direction, latch LOS / DOS, load the output registers.
  input  wire               ovf_clr_i,
  input  wire               region_we_i,
  input  wire               neg_we_i,
  input  wire               dir_push_i,
  input  wire               dir_pop_i,
  input  wire               los_we_i,
  input  wire               dos_we_i,
  input  wire               out_we_i,
  // Result for a scratch write.
  output wire [MEM_W-1:0]   wdata_o,
  // Region of the sample in flight, and "x is the sine curve" (|s13| <= |s24|).
  output wire [RG_W-1:0]    region_o,
  output wire               use13_o,
  // Output registers (valid-gating is the top's).
  output wire [ANGLE_W-1:0] angle_o,
  output wire [RG_W-1:0]    out_region_o,
  output wire               ovf_o,
  output wire               los_o,
  output wire               dos_o
);

  // Operation encodings (acore_serial_ctrl.v uses the same numbers).
  localparam [2:0] A_ZERO = 3'd0, A_ACC = 3'd1, A_T1 = 3'd2, A_Q = 3'd3, A_C1 = 3'd4, A_MLO = 3'd5,
                   A_MHI = 3'd6;
  localparam [2:0] B_T1 = 3'd0, B_T2 = 3'd1, B_ACC = 3'd2, B_Q = 3'd3, B_C3 = 3'd4;
  // Q as a signed coefficient word, an unsigned word, or a signed scratch word.
  localparam [1:0] Q_PS = 2'd0, Q_PU = 2'd1, Q_SC = 2'd2;
  localparam [1:0] G_ONE = 2'd0, G_RBIT = 2'd1, G_XBIT = 2'd2;
  localparam [2:0] S_ADD = 3'd0, S_SUB = 3'd1, S_ACCNEG = 3'd2, S_ACCPOS = 3'd3, S_QPOS = 3'd4,
                   S_NEG = 3'd5, S_T2NEG = 3'd6, S_DIRNEG = 3'd7;
  localparam [1:0] C_SUB = 2'd0, C_RND = 2'd1, C_NRND = 2'd2, C_ZERO = 2'd3;
  localparam [1:0] SAT_NONE = 2'd0, SAT_S = 2'd1, SAT_ACC = 2'd2;
  localparam [1:0] T1_RES = 2'd0, T1_ACC = 2'd1, T1_C2 = 2'd2;
  localparam [1:0] T2_RES = 2'd0, T2_ACC = 2'd1, T2_Q = 2'd2, T2_C4 = 2'd3;

  localparam integer BW = W + LS + 1;  // shifter width
  localparam integer NB = 1 << BI_W;   // bit-select vector width

  initial begin
    if (W < ACC_W + 1 || W < S_W + 2 || W < Z_W || W < REG_W + 1 || W < MAG_W + 1 || W < IN_W + 2)
      $error("acore_serial_datapath: W=%0d too narrow (instance %m)", W);
    if (NB < REG_W || NB < S_W) $error("acore_serial_datapath: BI_W=%0d too small (instance %m)", BI_W);
    if (MEM_W < REG_W || MEM_W < S_W) $error("acore_serial_datapath: MEM_W=%0d too small (instance %m)", MEM_W);
    if (K < 2) $error("acore_serial_datapath: K=%0d must be >= 2 (instance %m)", K);
  end

  reg [W-1:0] acc_q, t1_q, t2_q;
  reg         ovf_q, use13_q, neg_q, los_q, dos_q;
  reg [RG_W-1:0] region_q;
  reg [K-1:0] dir_q;  // CORDIC directions, d_0 first (it ends up in the top bit)

  // ---- operands ----
  wire [W-1:0] q_ps = {{(W-REG_W){q_i[REG_W-1]}}, q_i[REG_W-1:0]};
  wire [W-1:0] q_pu = {{(W-REG_W){1'b0}}, q_i[REG_W-1:0]};
  wire [W-1:0] q_sc = {{(W-MEM_W){q_i[MEM_W-1]}}, q_i};
  reg  [W-1:0] qx;
  always @(*) begin
    case (q_ext_i)
      Q_PS:    qx = q_ps;
      Q_PU:    qx = q_pu;
      Q_SC:    qx = q_sc;
      default: qx = q_sc;
    endcase
  end

  wire [W-1:0] half = {{(W-Z_W){1'b0}}, a_half_i & neg_q, {(Z_W-1){1'b0}}};
  reg  [W-1:0] a;
  always @(*) begin
    case (a_sel_i)
      A_ACC:   a = acc_q;
      A_T1:    a = t1_q;
      A_Q:     a = qx;
      A_C1:    a = {{(W-IN_W){c1_i[IN_W-1]}}, c1_i};
      A_MLO:   a = {{(W-MAG_W){1'b0}}, mag_lo_i};
      A_MHI:   a = {{(W-MAG_W){1'b0}}, mag_hi_i};
      A_ZERO:  a = half;
      default: a = half;
    endcase
  end

  reg [W-1:0] b;
  always @(*) begin
    case (b_sel_i)
      B_T2:    b = t2_q;
      B_ACC:   b = acc_q;
      B_Q:     b = qx;
      B_C3:    b = {{(W-IN_W){c3_i[IN_W-1]}}, c3_i};
      B_T1:    b = t1_q;
      default: b = t1_q;
    endcase
  end

  // ---- the shifter: (b << LS << 1) >>> sh_amt_i; the low bit is the last bit shifted out ----
  wire signed [BW-1:0] b_pre = {b, {(LS+1){1'b0}}};
  wire [BW-1:0] b_shd = b_pre >>> sh_amt_i;
  wire [W-1:0] b_sh = b_shd[W:1];
  wire rbit = b_shd[0];

  // ---- gate, conditional negation, carry-in ----
  wire [NB-1:0] q_bits = {{(NB-REG_W){1'b0}}, q_i[REG_W-1:0]};
  wire [NB-1:0] x_bits = {{(NB-S_W){1'b0}}, t2_q[S_W-1:0]};
  reg gate;
  always @(*) begin
    case (gate_sel_i)
      G_RBIT:  gate = q_bits[bit_idx_i];
      G_XBIT:  gate = x_bits[bit_idx_i];
      G_ONE:   gate = 1'b1;
      default: gate = 1'b1;
    endcase
  end
  reg sub;
  always @(*) begin
    case (sub_sel_i)
      S_SUB:    sub = 1'b1;
      S_ACCNEG: sub = acc_q[W-1];
      S_ACCPOS: sub = ~acc_q[W-1];
      S_QPOS:   sub = ~qx[W-1];
      S_NEG:    sub = neg_q;
      S_T2NEG:  sub = t2_q[W-1];
      S_DIRNEG: sub = ~dir_q[K-1];
      S_ADD:    sub = 1'b0;
      default:  sub = 1'b0;
    endcase
  end
  reg cin;
  always @(*) begin
    case (cin_sel_i)
      C_RND:   cin = rbit;
      C_NRND:  cin = ~rbit;
      C_ZERO:  cin = 1'b0;
      C_SUB:   cin = sub;
      default: cin = sub;
    endcase
  end
  wire [W-1:0] b_op = (b_sh & {W{gate}}) ^ {W{sub}};

  // ---- the adder: {a, 1} + {b_op, cin} carries cin into the real sum (a + b_op + cin) ----
  wire [W:0] sum = {a, 1'b1} + {b_op, cin};
  wire [W-1:0] res = sum[W:1];

  // ---- saturation to S_W or ACC_W bits ----
  wire neg_res = res[W-1];
  wire fits_s = (res[W-1:S_W-1] == {(W-S_W+1){1'b0}}) || (res[W-1:S_W-1] == {(W-S_W+1){1'b1}});
  wire fits_a = (res[W-1:ACC_W-1] == {(W-ACC_W+1){1'b0}}) || (res[W-1:ACC_W-1] == {(W-ACC_W+1){1'b1}});
  wire [W-1:0] clamp_s = {{(W-S_W+1){neg_res}}, {(S_W-1){~neg_res}}};
  wire [W-1:0] clamp_a = {{(W-ACC_W+1){neg_res}}, {(ACC_W-1){~neg_res}}};
  reg [W-1:0] r;
  reg ovf_hit;
  always @(*) begin
    case (sat_sel_i)
      SAT_S: begin
        r = fits_s ? res : clamp_s;
        ovf_hit = ~fits_s;
      end
      SAT_ACC: begin
        r = fits_a ? res : clamp_a;
        ovf_hit = ~fits_a;
      end
      SAT_NONE: begin
        r = res;
        ovf_hit = 1'b0;
      end
      default: begin
        r = res;
        ovf_hit = 1'b0;
      end
    endcase
  end
  assign wdata_o = r[MEM_W-1:0];

  // ---- write-back ----
  always @(posedge clk_i) begin
    if (en_i) begin
      if (acc_we_i) acc_q <= r;
      if (t1_we_i) begin
        case (t1_src_i)
          T1_ACC:  t1_q <= acc_q;
          T1_C2:   t1_q <= {{(W-IN_W){c2_i[IN_W-1]}}, c2_i};
          T1_RES:  t1_q <= r;
          default: t1_q <= r;
        endcase
      end
      if (t2_we_i) begin
        case (t2_src_i)
          T2_ACC:  t2_q <= acc_q;
          T2_Q:    t2_q <= qx;
          T2_C4:   t2_q <= {{(W-IN_W){c4_i[IN_W-1]}}, c4_i};
          T2_RES:  t2_q <= r;
          default: t2_q <= r;
        endcase
      end
      if (ovf_clr_i) ovf_q <= 1'b0;
      else if (ovf_hit) ovf_q <= 1'b1;
      if (neg_we_i) neg_q <= acc_q[W-1];
      if (dir_push_i) dir_q <= {dir_q[K-2:0], ~acc_q[W-1]};
      else if (dir_pop_i) dir_q <= {dir_q[K-2:0], 1'b0};
      if (los_we_i) los_q <= ~res[W-1];
      if (dos_we_i) dos_q <= res[W-1];
    end
  end

  // ---- domain selection (res = |s24| -/+ s13 = |s24| - |s13|, Q = s13, T2 = s24) ----
  wire use13 = ~res[W-1];
  wire s13_neg = qx[W-1];
  wire s24_neg = t2_q[W-1];
  wire [1:0] r4 = use13 ? {s24_neg, 1'b0} : {s13_neg, 1'b1};
  wire [RG_W-1:0] region_d;
  generate
    if (REGIONS == 8) begin : g_r8
      // Each region halved at the zero crossing of x.
      assign region_d = {r4, ~(use13 ? s13_neg : s24_neg)};
    end else begin : g_r4
      assign region_d = r4;
    end
  endgenerate
  always @(posedge clk_i) begin
    if (en_i && region_we_i) begin
      use13_q  <= use13;
      region_q <= region_d;
    end
  end
  assign region_o = region_q;
  assign use13_o = use13_q;

  // ---- output registers: angle = low ANGLE_W bits of the rounded Z ----
  reg [ANGLE_W-1:0] angle_q;
  reg [RG_W-1:0] out_region_q;
  reg out_ovf_q, out_los_q, out_dos_q;
  always @(posedge clk_i) begin
    if (en_i && out_we_i) begin
      angle_q      <= res[ANGLE_W-1:0];
      out_region_q <= region_q;
      out_ovf_q    <= ovf_q;
      out_los_q    <= los_q;
      out_dos_q    <= dos_q;
    end
  end
  assign angle_o = angle_q;
  assign out_region_o = out_region_q;
  assign ovf_o = out_ovf_q;
  assign los_o = out_los_q;
  assign dos_o = out_dos_q;

endmodule

`resetall
