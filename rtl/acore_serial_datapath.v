// SPDX-License-Identifier: MIT
// acore_serial_datapath: the serial core's arithmetic: an accumulator ACC, two temporary registers
// T1 and T2, one shifter and one adder, all W bits wide, plus the sample's status bits. Each
// operation the controller (acore_serial_ctrl.v) issues takes two clocks, overlapped with the next
// operation's first:
//
//   stage 1 (operand):  A_q = one of 0 (or half a turn), T1, T2, Q, pin c1, mag_lo, mag_hi
//                       B_q = shift(one of T1, T2, ACC, Q, pin c3), gate_q = 1, 0, Q[bit] or T2[bit]
//                       sub_q, cin_q (add/subtract, carry-in); the sign of the B source; register
//                       moves T1 = c2 | ACC | Q, T2 = c4 | ACC (for values the next operation reads)
//   stage 2 (execute):  res = [ACC | A_q] + ((B_q & {gate_q}) ^ {sub_q}) + cin_q -> T1, T2, flags;
//                       saturated to S_W or ACC_W bits (raising the sample's ovf) -> ACC, scratch
//
//   shift(B) = B * 2^k, k in [-MAXR, LS], floor for right shifts (arithmetic): the barrel
//              (B << LS << 1) >>> sh_amt_i, so sh_amt_i = LS - k; its extra low bit is the last
//              bit shifted out, the rounding bit (round_shr(v, s) = (v >>> s) + v[s-1])
//   sub        0, 1, the sign of the B source or its complement, the sign of ACC or its complement,
//              the sign of the previous operation's B source; cin = sub, rbit, ~rbit or 0, so the
//              one adder also rounds and compares (a - b - 1 >= 0 <=> a > b)
//
// Stage 1 reads the registers before stage 2 of the previous operation writes them; the controller
// never issues an operation whose stage 1 needs the previous operation's result (it waits a clock).
// W holds every exact intermediate of the fixed-point contract (see acore_serial_top.v).
// en_i = 0 freezes every register (stall).
//
// MULT = 1 adds the hardware product (rtl/acore_hw_mul.v, the product register in stage 1's clock):
//
//   stage 1 (operand):  P_q = A * M, A = T1, T2 or ACC, M = R (Q, unsigned: the scaling) or x
//                       (T2's low S_W bits, signed: a Horner step), the exact product; A and M
//                       chosen by selects the controller registers a clock ahead (mul_a_i,
//                       mul_r_i), so the multiplier's inputs do not wait for the state decode
//   stage 2 (execute):  res = (P_q >>> PSH) + ((B_q & {gate_q}) ^ {sub_q}) + cin_q, the product in
//                       place of A, PSH = RS (scaling), S_F (Horner) or S_F - ACC_G (the first
//                       Horner step, whose multiplicand is the coefficient without its ACC_G)
//
// so a product with its floor once (fixed_point.hpp hw_mul) and the next coefficient added (B =
// Q << ACC_G) take one operation.
`resetall
`default_nettype none

module acore_serial_datapath #(
  // Channel code width, register word width, RAM word width (max(REG_W, S_W)).
  parameter integer IN_W = 16,
  parameter integer REG_W = 18,
  parameter integer MEM_W = 18,
  // Curve width (S_W saturation) and Horner accumulator width (ACC_W saturation).
  parameter integer S_W = 18,
  parameter integer ACC_W = 25,
  // CORDIC angle accumulator width (half a turn = 2^(Z_W-1)) and output angle width.
  parameter integer Z_W = 20,
  parameter integer ANGLE_W = 16,
  // 4 or 8 regions.
  parameter integer REGIONS = 4,
  // Datapath width, left shift range of the shifter, shift amount and bit index widths.
  parameter integer W = 29,
  parameter integer LS = 8,
  parameter integer SHA_W = 5,
  parameter integer BI_W = 5,
  // 1: the hardware product (above); its multiplicand's width (the widest of the scaling's t, ACC
  // and a coefficient word) and the product's right shifts (scaling, Horner, first Horner step).
  parameter integer MULT = 0,
  parameter integer MA_W = 25,
  parameter integer PSH_SC = 9,
  parameter integer PSH_H = 16,
  parameter integer PSH_H0 = 12,
  // CORDIC guard bits (T1 holds X_K with G of them: the magnitude is T1 >>> G).
  parameter integer G = 3,
  // Derived, do not override.
  parameter integer RG_W = $clog2(REGIONS),
  parameter integer MAG_W = acore_mag_w(S_W)
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
  // ---- stage 1 of the current operation (encodings: the localparams below, as in the ctrl) ----
  input  wire [2:0]         a_sel_i,
  // With A_ZERO: half a turn (2^(Z_W-1)) instead when the CORDIC pre-rotation negated the vector.
  input  wire               a_half_i,
  input  wire [2:0]         b_sel_i,
  // How Q is extended to W bits.
  input  wire [1:0]         q_ext_i,
  input  wire [SHA_W-1:0]   sh_amt_i,
  input  wire [1:0]         gate_sel_i,
  input  wire [BI_W-1:0]    bit_idx_i,
  input  wire               t1_mv_i,
  input  wire [1:0]         t1_mv_src_i,
  input  wire               t2_mv_i,
  input  wire               t2_mv_src_i,
  input  wire [2:0]         sub_sel_i,
  input  wire [1:0]         cin_sel_i,
  // The product (MULT = 1; 0: none, else its shift, the encodings below).
  input  wire [1:0]         mul_sel_i,
  // Its operand sources, registered by the controller (MA_T1, MA_T2, MA_ACC; 1: R, 0: x).
  input  wire [1:0]         mul_a_i,
  input  wire               mul_r_i,
  // ---- stage 2 of the previous operation ----
  // A = ACC (else A_q).
  input  wire               a_acc_i,
  input  wire [1:0]         sat_sel_i,
  input  wire               acc_we_i,
  input  wire               t1_we_i,
  input  wire               t2_we_i,
  // T2 = res only when x is the sine curve (the region compare's use13).
  input  wire               t2_we_u13_i,
  // Status: clear ovf (new sample), latch the region compare, the pre-rotation sign, LOS / DOS,
  // load the output registers.
  input  wire               ovf_clr_i,
  input  wire               region_we_i,
  input  wire               neg_we_i,
  input  wire               los_we_i,
  input  wire               dos_we_i,
  input  wire               out_we_i,
  // Stage 2 result for a scratch write.
  output wire [MEM_W-1:0]   wdata_o,
  // Region of the sample in flight.
  output wire [RG_W-1:0]    region_o,
  // Output registers (valid-gating is the top's).
  output wire [ANGLE_W-1:0] angle_o,
  output wire [RG_W-1:0]    out_region_o,
  output wire               ovf_o,
  output wire               los_o,
  output wire               dos_o,
  // The magnitude X_K >>> G (the LOS/DOS operand), with the angle.
  output wire [MAG_W-1:0]   mag_o
);

`include "acore_derived.vh"

  // Operation encodings (acore_serial_ctrl.v uses the same numbers).
  localparam [2:0] A_ZERO = 3'd0, A_T1 = 3'd1, A_T2 = 3'd2, A_Q = 3'd3, A_C1 = 3'd4, A_MLO = 3'd5,
                   A_MHI = 3'd6, A_ACC = 3'd7;
  localparam [2:0] B_T1 = 3'd0, B_T2 = 3'd1, B_ACC = 3'd2, B_Q = 3'd3, B_C3 = 3'd4;
  // Q as a signed coefficient word, an unsigned word, or a signed scratch word.
  localparam [1:0] Q_PS = 2'd0, Q_PU = 2'd1, Q_SC = 2'd2;
  localparam [1:0] G_ONE = 2'd0, G_ZERO = 2'd1, G_RBIT = 2'd2, G_XBIT = 2'd3;
  localparam [1:0] M1_C2 = 2'd0, M1_ACC = 2'd1, M1_Q = 2'd2;
  localparam       M2_C4 = 1'b0;  // else M2_ACC
  localparam [2:0] S_ADD = 3'd0, S_SUB = 3'd1, S_BNEG = 3'd2, S_BPOS = 3'd3, S_ACCNEG = 3'd4,
                   S_ACCPOS = 3'd5, S_PBNEG = 3'd6;
  localparam [1:0] C_SUB = 2'd0, C_RND = 2'd1, C_NRND = 2'd2, C_ZERO = 2'd3;
  localparam [1:0] SAT_S = 2'd1, SAT_ACC = 2'd2;  // 0: none
  localparam [1:0] P_NONE = 2'd0, P_SC = 2'd1, P_H = 2'd2, P_H0 = 2'd3;
  localparam [1:0] MA_T1 = 2'd0, MA_T2 = 2'd1, MA_ACC = 2'd2;

  localparam integer BW = W + LS + 1;  // shifter width
  localparam integer NB = 1 << BI_W;   // bit-select vector width

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(
    .OK(W >= ACC_W + 1 && W >= S_W + 2 && W >= Z_W && W >= REG_W + 1 && W >= MAG_W + 1 && W >= IN_W + 2),
    .VALUE(W),
    .MSG("illegal parameter: acore_serial_datapath: W too narrow for an intermediate"))
    W_must_hold_every_intermediate ();
  acore_check #(.OK(NB >= REG_W && NB >= S_W), .VALUE(BI_W),
    .MSG("illegal parameter: acore_serial_datapath: BI_W too small to index a REG_W or S_W-bit operand"))
    BI_W_must_index_every_bit ();
  acore_check #(.OK(MEM_W >= REG_W && MEM_W >= S_W), .VALUE(MEM_W),
    .MSG("illegal parameter: acore_serial_datapath: MEM_W must be >= REG_W and >= S_W"))
    MEM_W_must_hold_REG_W_and_S_W ();

  reg [W-1:0] acc_q, t1_q, t2_q;

  // ================= stage 1: operands =================
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

  reg neg_q;
  wire [W-1:0] half = {{(W-Z_W){1'b0}}, a_half_i & neg_q, {(Z_W-1){1'b0}}};
  reg  [W-1:0] a_d;
  always @(*) begin
    case (a_sel_i)
      A_T1:    a_d = t1_q;
      A_T2:    a_d = t2_q;
      A_Q:     a_d = qx;
      A_C1:    a_d = {{(W-IN_W){c1_i[IN_W-1]}}, c1_i};
      A_MLO:   a_d = {{(W-MAG_W){1'b0}}, mag_lo_i};
      A_MHI:   a_d = {{(W-MAG_W){1'b0}}, mag_hi_i};
      // ACC as an operand only for the product (MULT = 0: never issued).
      A_ACC:   a_d = (MULT != 0) ? acc_q : half;
      A_ZERO:  a_d = half;
      default: a_d = half;
    endcase
  end

  reg [W-1:0] b_src;
  always @(*) begin
    case (b_sel_i)
      B_T2:    b_src = t2_q;
      B_ACC:   b_src = acc_q;
      B_Q:     b_src = qx;
      B_C3:    b_src = {{(W-IN_W){c3_i[IN_W-1]}}, c3_i};
      B_T1:    b_src = t1_q;
      default: b_src = t1_q;
    endcase
  end

  // The shifter: (b << LS << 1) >>> sh_amt_i; the low bit is the last bit shifted out.
  wire signed [BW-1:0] b_pre = {b_src, {(LS+1){1'b0}}};
  wire [BW-1:0] b_shd = b_pre >>> sh_amt_i;

  wire [NB-1:0] q_bits = {{(NB-REG_W){1'b0}}, q_i[REG_W-1:0]};
  wire [NB-1:0] x_bits = {{(NB-S_W){1'b0}}, t2_q[S_W-1:0]};
  reg gate_d;
  always @(*) begin
    case (gate_sel_i)
      G_ZERO:  gate_d = 1'b0;
      G_RBIT:  gate_d = q_bits[bit_idx_i];
      G_XBIT:  gate_d = x_bits[bit_idx_i];
      G_ONE:   gate_d = 1'b1;
      default: gate_d = 1'b1;
    endcase
  end

  // Add or subtract, and the carry-in: from the signs stage 1 sees (the B source, ACC, or the B
  // source of the previous operation, which the CORDIC's Z update needs) and the rounding bit.
  wire rbit = b_shd[0];
  reg sub_d;
  always @(*) begin
    case (sub_sel_i)
      S_SUB:    sub_d = 1'b1;
      S_BNEG:   sub_d = b_src[W-1];
      S_BPOS:   sub_d = ~b_src[W-1];
      S_ACCNEG: sub_d = acc_q[W-1];
      S_ACCPOS: sub_d = ~acc_q[W-1];
      S_PBNEG:  sub_d = bsign_q;
      S_ADD:    sub_d = 1'b0;
      default:  sub_d = 1'b0;
    endcase
  end
  reg cin_d;
  always @(*) begin
    case (cin_sel_i)
      C_RND:   cin_d = rbit;
      C_NRND:  cin_d = ~rbit;
      C_ZERO:  cin_d = 1'b0;
      C_SUB:   cin_d = sub_d;
      default: cin_d = sub_d;
    endcase
  end

  reg [W-1:0] a_q, b_q;
  reg gate_q, sub_q, cin_q, bsign_q;
  always @(posedge clk_i) begin
    if (en_i) begin
      a_q     <= a_d;
      b_q     <= b_shd[W:1];
      gate_q  <= gate_d;
      sub_q   <= sub_d;
      cin_q   <= cin_d;
      bsign_q <= b_src[W-1];
    end
  end

  // The product (MULT = 1): registered in acore_hw_mul in stage 1's clock, shifted in stage 2 by
  // the operation's constant (every shifted product of the schedule fits W bits).
  wire [W-1:0] p_sh;
  wire mul_op;
  generate
    if (MULT != 0) begin : g_mul
      localparam integer MB_W = ((REG_W + 1) > S_W) ? (REG_W + 1) : S_W;
      localparam integer PR_W = MA_W + MB_W;
      wire [MB_W-1:0] m_r = {{(MB_W-REG_W){1'b0}}, q_i[REG_W-1:0]};
      wire [MB_W-1:0] m_x = {{(MB_W-S_W){t2_q[S_W-1]}}, t2_q[S_W-1:0]};
      // The multiplicand from the registers on the controller's registered select (not a_d).
      reg [MA_W-1:0] m_a;
      always @(*) begin
        case (mul_a_i)
          MA_T1:   m_a = t1_q[MA_W-1:0];
          MA_T2:   m_a = t2_q[MA_W-1:0];
          MA_ACC:  m_a = acc_q[MA_W-1:0];
          default: m_a = t1_q[MA_W-1:0];
        endcase
      end
      wire [PR_W-1:0] p;
      acore_hw_mul #(
        .A_W(MA_W), .B_W(MB_W), .B_SIGNED(1), .RSHIFT(0), .P_W(PR_W), .DEPTH(1)
      ) u_mul (
        .clk_i(clk_i), .en_i(en_i), .a_i(m_a),
        .b_i(mul_r_i ? m_r : m_x), .p_o(p));
      reg [1:0] mul_sel_q;
      always @(posedge clk_i) if (en_i) mul_sel_q <= mul_sel_i;
      wire signed [PR_W-1:0] p_s = p;
      // The first Horner step's shift is a left one when ACC_G > S_F (the product is then exact).
      localparam integer H0_R = (PSH_H0 > 0) ? PSH_H0 : 0;
      localparam integer H0_L = (PSH_H0 < 0) ? -PSH_H0 : 0;
      wire signed [PR_W-1:0] p_h0 = p_s <<< H0_L;
      reg signed [PR_W-1:0] p_shd;
      always @(*) begin
        case (mul_sel_q)
          P_SC:    p_shd = p_s >>> PSH_SC;
          P_H0:    p_shd = p_h0 >>> H0_R;
          P_H:     p_shd = p_s >>> PSH_H;
          default: p_shd = p_s >>> PSH_H;  // P_NONE: not used
        endcase
      end
      if (PR_W >= W) begin : g_cut
        assign p_sh = p_shd[W-1:0];
        if (PR_W > W) begin : g_unused
          // The sign bits above W (each shifted product of the schedule fits W bits).
          wire unused_hi = ^p_shd[PR_W-1:W];
        end
      end else begin : g_ext
        assign p_sh = {{(W-PR_W){p_shd[PR_W-1]}}, p_shd};
      end
      assign mul_op = (mul_sel_q != P_NONE);
    end else begin : g_nomul
      assign p_sh = {W{1'b0}};
      assign mul_op = 1'b0;
      wire unused_mul = ^{mul_sel_i, mul_a_i, mul_r_i};
    end
  endgenerate

  // ================= stage 2: add, saturate, write back =================
  wire [W-1:0] a_op = mul_op ? p_sh : (a_acc_i ? acc_q : a_q);
  wire [W-1:0] b_op = (b_q & {W{gate_q}}) ^ {W{sub_q}};

  // The adder: {a, 1} + {b, cin} carries cin into the real sum (a + b + cin).
  wire [W:0] sum = {a_op, 1'b1} + {b_op, cin_q};
  wire [W-1:0] res = sum[W:1];

  // Saturation to S_W or ACC_W bits (only results for ACC and the scratch words saturate): a
  // kept top bit that differs from the sign is an overflow; the clamp is +-max of the width.
  wire neg_res = res[W-1];
  wire ovf_s = |(res[W-2:S_W-1] ^ {(W-S_W){neg_res}});
  wire ovf_a = |(res[W-2:ACC_W-1] ^ {(W-ACC_W){neg_res}});
  wire sat_s = (sat_sel_i == SAT_S);
  wire sat_a = (sat_sel_i == SAT_ACC);
  wire ovf_hit = (sat_s & ovf_s) | (sat_a & ovf_a);
  wire [W-1:0] clamp = sat_s ? {{(W-S_W+1){neg_res}}, {(S_W-1){~neg_res}}}
                             : {{(W-ACC_W+1){neg_res}}, {(ACC_W-1){~neg_res}}};
  wire [W-1:0] r = ovf_hit ? clamp : res;
  assign wdata_o = r[MEM_W-1:0];

  // Domain selection (RS1: res = |s24| -/+ s13 = |s24| - |s13|, B source = s13, T2 = s24).
  reg use13_q;
  reg [RG_W-1:0] region_q;
  wire use13 = ~res[W-1];
  wire s13_neg = bsign_q;
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

  // ---- registers: stage 1 moves and stage 2 results (the controller never mixes them) ----
  reg ovf_q, los_q, dos_q;
  always @(posedge clk_i) begin
    if (en_i) begin
      if (acc_we_i) acc_q <= r;
      if (t1_mv_i) begin
        case (t1_mv_src_i)
          M1_ACC:  t1_q <= acc_q;
          M1_Q:    t1_q <= qx;
          M1_C2:   t1_q <= {{(W-IN_W){c2_i[IN_W-1]}}, c2_i};
          default: t1_q <= qx;
        endcase
      end else if (t1_we_i) begin
        t1_q <= res;
      end
      if (t2_mv_i) t2_q <= (t2_mv_src_i == M2_C4) ? {{(W-IN_W){c4_i[IN_W-1]}}, c4_i} : acc_q;
      else if (t2_we_i || (t2_we_u13_i && use13_q)) t2_q <= res;
      if (ovf_clr_i) ovf_q <= 1'b0;
      else if (ovf_hit) ovf_q <= 1'b1;
      if (region_we_i) begin
        use13_q  <= use13;
        region_q <= region_d;
      end
      if (neg_we_i) neg_q <= bsign_q;
      if (los_we_i) los_q <= ~res[W-1];
      if (dos_we_i) dos_q <= res[W-1];
    end
  end
  assign region_o = region_q;

  // ---- output registers: angle = low ANGLE_W bits of the rounded Z ----
  reg [ANGLE_W-1:0] angle_q;
  reg [RG_W-1:0] out_region_q;
  reg out_ovf_q, out_los_q, out_dos_q;
  // T1 still holds X_K at OUT (only T2 and the flags change after the last CB; the next sample's
  // move into T1 lands at this same edge). X_K >= 0 has XY_W = MAG_W + G bits: the slice is exact.
  reg [MAG_W-1:0] mag_q;
  always @(posedge clk_i) begin
    if (en_i && out_we_i) begin
      angle_q      <= res[ANGLE_W-1:0];
      mag_q        <= t1_q[G +: MAG_W];
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
  assign mag_o = mag_q;

endmodule

`resetall
