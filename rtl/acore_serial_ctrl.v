// SPDX-License-Identifier: MIT
// acore_serial_ctrl: the serial core's sequencer. One state per operation kind, a bit/iteration
// counter cnt, a Horner power counter j and the curve bit; each state drives one datapath
// operation per clock (acore_serial_datapath.v) and the RAM read address the next clock needs
// (the RAM reads synchronously). Schedule of one sample (ACC, T1, T2 the datapath registers,
// Q the RAM word read the clock before; "x" = the curve nearest its zero crossing):
//
//   state  clocks         operation                                             RAM address issued
//   IDLE   1 (accept)     ACC = c1 - c3,  T1 = c2,  T2 = c4                      (host's)
//   PRE    1              T1 = T1 - T2                       (d24)               O13
//   OFF    1              T2 = ACC - O13 (curve 0) | T1 = T1 - O24 (curve 1)     R13 | R24
//   SC     REG_W          ACC = [ACC] + R[j] * shift(t, j - RS), j = REG_W-1..0  R13 | R24
//   RND    1              ACC = sat_S((ACC >>> SG) + rbit) -> also scratch s13/s24  O24 | S13
//          (OFF, SC, RND once per curve: curve 0 then curve 1)
//   RS0    1              ACC = |ACC| (|s24|),  T2 = ACC (s24)                    S13
//   RS1    1              |s24| -/+ s13 >= 0  -> use13, region                     S13
//   RS2    1              T2 = s13 if use13 (T2 = x)                               a_n(region, 0)
//   HI     1              ACC = a_n << ACC_G
//   HB     S_W            b = S_W-1: T1 = ACC, ACC = -x[b] * shift(ACC, b - S_F);  last: a_j
//                         b < S_W-1: ACC = ACC + x[b] * shift(T1, b - S_F)
//   HC     1              ACC = sat_ACC(ACC + (a_j << ACC_G))                      last: s_curve
//          (HB, HC DEGREE times, j = DEGREE-1..0)
//   HY     1              ACC = sat_S(s - ((ACC >>> RN) + rbit)), curve 0: -> y13   a_n(region, 1) | Y13
//          (HI..HY once per curve)
//   CR0    1              T1 = |ACC << G| (X0),  neg = y24 < 0                     Y13
//   CR1    1              ACC = +-(y13 << G)   (Y0)
//   CA     1 \ K times    T2 = ACC,  ACC = ACC -+ (T1 >>> i),  push d_i = (Y >= 0)
//   CB     1 / i = 0..K-1 T1 = T1 +- (T2 >>> i)
//   LOS    1              los = mag_lo - (T1 >>> G) - 1 >= 0
//   DOS    1              dos = mag_hi - (T1 >>> G) < 0                           atan_0
//   ZL     K              ACC = [half turn if neg | ACC] +- atan_i by d_i          atan_i+1
//   OUT    1              angle = (ACC >>> DROP) + rbit, flags, region -> output registers
//
// CYCLES (acore_serial_top.v) = 18 + 2 REG_W + 2 DEGREE (S_W + 1) + 3 K clocks from the accepting
// clock to out_valid_o, and between two accepts when out_ready_i stays high.
// Stalls (en_o = 0, nothing changes, the RAM output holds): OUT while the previous result is still
// held (out_valid_o && !out_ready_i), and a scratch write (RND, HY of curve 0) in a clock where the
// host writes the register file (the host owns the write port).
// The datapath arithmetic uses the one adder; the counters here are the sequencer's own.
`resetall
`default_nettype none

module acore_serial_ctrl #(
  parameter integer REG_W = 18,
  parameter integer S_W = 18,
  parameter integer S_F = 16,
  parameter integer DEGREE = 3,
  parameter integer REGIONS = 4,
  parameter integer K = 16,
  // Words of the coefficient map: 4 + 2 REGIONS (DEGREE + 1) + K.
  parameter integer WORDS = 52,
  // Shift amounts: sh_amt = LS - k for a shift by k (k < 0: right), see acore_serial_datapath.v.
  parameter integer LS = 8,
  parameter integer SHA_W = 5,
  parameter integer BI_W = 5,
  // Right shifts of the scaling product (R_SHIFT - SCALE_G), of the scaled-curve rounding
  // (SCALE_G), of the correction rounding (ACC_F - S_F), of the angle rounding (Z_W - ANGLE_W);
  // left shift of a coefficient (ACC_G) and the CORDIC guard bits (G).
  parameter integer RS = 9,
  parameter integer SG = 4,
  parameter integer RN = 3,
  parameter integer DROP = 4,
  parameter integer ACC_G = 4,
  parameter integer G = 3,
  // Derived, do not override.
  parameter integer RG_W = $clog2(REGIONS),
  parameter integer DA_W = $clog2(WORDS + 3)
) (
  input  wire              clk_i,
  input  wire              rst_i,
  // Streaming handshake.
  input  wire              in_valid_i,
  output wire              in_ready_o,
  output wire              out_valid_o,
  input  wire              out_ready_i,
  // The host writes the register file this clock (it owns the RAM write port).
  input  wire              host_we_i,
  // From the datapath: region of the sample, x = sine curve.
  input  wire [RG_W-1:0]   region_i,
  input  wire              use13_i,
  // Advance (0: stall).
  output wire              en_o,
  // Datapath operation (encodings as in acore_serial_datapath.v).
  output reg  [2:0]        a_sel_o,
  output reg               a_half_o,
  output reg  [2:0]        b_sel_o,
  output reg  [1:0]        q_ext_o,
  output reg  [SHA_W-1:0]  sh_amt_o,
  output reg  [1:0]        gate_sel_o,
  output wire [BI_W-1:0]   bit_idx_o,
  output reg  [2:0]        sub_sel_o,
  output reg  [1:0]        cin_sel_o,
  output reg  [1:0]        sat_sel_o,
  output reg               acc_we_o,
  output reg               t1_we_o,
  output reg  [1:0]        t1_src_o,
  output reg               t2_we_o,
  output reg  [1:0]        t2_src_o,
  output reg               ovf_clr_o,
  output reg               region_we_o,
  output reg               neg_we_o,
  output reg               dir_push_o,
  output reg               dir_pop_o,
  output reg               los_we_o,
  output reg               dos_we_o,
  output reg               out_we_o,
  // RAM: the datapath owns the read port, the address for the next clock, a scratch write.
  output wire              dp_read_o,
  output reg  [DA_W-1:0]   raddr_o,
  output reg               ram_we_o,
  output reg  [DA_W-1:0]   waddr_o
);

  // Constant product by repeated addition (elaboration only; no multiplier in rtl/).
  function integer sc_cmul(input integer a, input integer b);
    integer n;
    begin
      sc_cmul = 0;
      for (n = 0; n < b; n = n + 1) sc_cmul = sc_cmul + a;
    end
  endfunction
  function integer sc_max(input integer a, input integer b);
    sc_max = (a > b) ? a : b;
  endfunction

  // Operation encodings (acore_serial_datapath.v uses the same numbers).
  localparam [2:0] A_ZERO = 3'd0, A_ACC = 3'd1, A_T1 = 3'd2, A_Q = 3'd3, A_C1 = 3'd4, A_MLO = 3'd5,
                   A_MHI = 3'd6;
  localparam [2:0] B_T1 = 3'd0, B_T2 = 3'd1, B_ACC = 3'd2, B_Q = 3'd3, B_C3 = 3'd4;
  localparam [1:0] Q_PS = 2'd0, Q_PU = 2'd1, Q_SC = 2'd2;
  localparam [1:0] G_ONE = 2'd0, G_RBIT = 2'd1, G_XBIT = 2'd2;
  localparam [2:0] S_ADD = 3'd0, S_SUB = 3'd1, S_ACCNEG = 3'd2, S_ACCPOS = 3'd3, S_QPOS = 3'd4,
                   S_NEG = 3'd5, S_T2NEG = 3'd6, S_DIRNEG = 3'd7;
  localparam [1:0] C_SUB = 2'd0, C_RND = 2'd1, C_NRND = 2'd2, C_ZERO = 2'd3;
  localparam [1:0] SAT_NONE = 2'd0, SAT_S = 2'd1, SAT_ACC = 2'd2;
  localparam [1:0] T1_RES = 2'd0, T1_ACC = 2'd1, T1_C2 = 2'd2;
  localparam [1:0] T2_RES = 2'd0, T2_ACC = 2'd1, T2_Q = 2'd2, T2_C4 = 2'd3;

  localparam [4:0] ST_IDLE = 5'd0, ST_PRE = 5'd1, ST_OFF = 5'd2, ST_SC = 5'd3, ST_RND = 5'd4,
                   ST_RS0 = 5'd5, ST_RS1 = 5'd6, ST_RS2 = 5'd7, ST_HI = 5'd8, ST_HB = 5'd9,
                   ST_HC = 5'd10, ST_HY = 5'd11, ST_CR0 = 5'd12, ST_CR1 = 5'd13, ST_CA = 5'd14,
                   ST_CB = 5'd15, ST_LOS = 5'd16, ST_DOS = 5'd17, ST_ZL = 5'd18, ST_OUT = 5'd19;

  // Counter widths: cnt runs over the REG_W bits of R, the S_W bits of x, the K iterations.
  localparam integer CNT_N = sc_max(sc_max(REG_W, S_W), K);
  localparam integer CNT_W = $clog2(CNT_N);
  localparam integer J_W = (DEGREE > 1) ? $clog2(DEGREE) : 1;
  localparam integer NCOEF = sc_cmul(REGIONS << 1, DEGREE + 1);

  initial begin
    if (BI_W > CNT_W) $error("acore_serial_ctrl: BI_W=%0d wider than the counter (instance %m)", BI_W);
    if (WORDS != 4 + NCOEF + K || DA_W != $clog2(WORDS + 3))
      $error("acore_serial_ctrl: WORDS/DA_W are derived (instance %m)");
    if (LS + RS < REG_W - 1 || LS + S_F < S_W - 1 || LS < ACC_G || LS < G)
      $error("acore_serial_ctrl: LS=%0d too small (instance %m)", LS);
  end

  // Addresses (register map of README / model/datapath_config.hpp) and the scratch words.
  localparam integer ATAN0_I = 4 + NCOEF;
  localparam [DA_W-1:0] AD_O13 = 0, AD_O24 = 1, AD_R13 = 2, AD_R24 = 3;
  localparam integer S13_I = WORDS, S24_I = WORDS + 1, Y13_I = WORDS + 2;
  localparam [DA_W-1:0] AD_S13 = S13_I[DA_W-1:0], AD_S24 = S24_I[DA_W-1:0], AD_Y13 = Y13_I[DA_W-1:0];
  localparam [DA_W-1:0] AD_ATAN0 = ATAN0_I[DA_W-1:0];

  // Shift amounts (sh_amt = LS - k).
  localparam integer AM_ZERO_I = LS, AM_SC_I = LS + RS, AM_HB_I = LS + S_F, AM_SG_I = LS + SG;
  localparam integer AM_RN_I = LS + RN, AM_DROP_I = LS + DROP, AM_COEF_I = LS - ACC_G;
  localparam integer AM_GL_I = LS - G, AM_GR_I = LS + G;
  localparam [SHA_W-1:0] AM_ZERO = AM_ZERO_I[SHA_W-1:0], AM_SC = AM_SC_I[SHA_W-1:0];
  localparam [SHA_W-1:0] AM_HB = AM_HB_I[SHA_W-1:0], AM_SG = AM_SG_I[SHA_W-1:0];
  localparam [SHA_W-1:0] AM_RN = AM_RN_I[SHA_W-1:0], AM_DROP = AM_DROP_I[SHA_W-1:0];
  localparam [SHA_W-1:0] AM_COEF = AM_COEF_I[SHA_W-1:0], AM_GL = AM_GL_I[SHA_W-1:0];
  localparam [SHA_W-1:0] AM_GR = AM_GR_I[SHA_W-1:0];

  localparam integer CNT_SC_I = REG_W - 1, CNT_HB_I = S_W - 1, CNT_K_I = K - 1;
  localparam [CNT_W-1:0] CNT_SC = CNT_SC_I[CNT_W-1:0], CNT_HB = CNT_HB_I[CNT_W-1:0];
  localparam [CNT_W-1:0] CNT_K = CNT_K_I[CNT_W-1:0], CNT_ONE = 1;
  localparam integer J_TOP_I = DEGREE - 1;
  localparam [J_W-1:0] J_TOP = J_TOP_I[J_W-1:0];

  reg [4:0]       state_q, state_d;
  reg [CNT_W-1:0] cnt_q, cnt_d;
  reg [J_W-1:0]   j_q, j_d;
  reg             curve_q, curve_d;
  reg             out_valid_q;

  // Address of the coefficient of x^j, region r, curve c: 4 + (DEGREE+1)(2r + c) + j, the base
  // from a table of constants (no multiplier), j added by the address counter logic.
  localparam integer STRIDE_I = DEGREE + 1, J_N_I = DEGREE;
  localparam [DA_W-1:0] STRIDE = STRIDE_I[DA_W-1:0], J_N = J_N_I[DA_W-1:0], AD_POLY0 = 4;
  function automatic [DA_W-1:0] coef_addr(input [RG_W-1:0] r, input c, input [DA_W-1:0] j);
    integer k;
    reg [DA_W-1:0] base;
    begin
      coef_addr = {DA_W{1'b0}};
      base = AD_POLY0;
      for (k = 0; k < (REGIONS << 1); k = k + 1) begin
        if ({r, c} == k[RG_W:0]) coef_addr = base + j;
        base = base + STRIDE;
      end
    end
  endfunction
  wire [DA_W-1:0] j_ext = {{(DA_W-J_W){1'b0}}, j_q};
  // The counter as a shift amount and as an address offset (its values fit both: cnt < LS + MAXR
  // where it shifts, cnt < K where it addresses).
  wire [SHA_W-1:0] cnt_sh;
  wire [DA_W-1:0] cnt_da;
  generate
    if (SHA_W > CNT_W) begin : g_sh_ext
      assign cnt_sh = {{(SHA_W-CNT_W){1'b0}}, cnt_q};
    end else begin : g_sh_cut
      assign cnt_sh = cnt_q[SHA_W-1:0];
    end
    if (DA_W > CNT_W) begin : g_da_ext
      assign cnt_da = {{(DA_W-CNT_W){1'b0}}, cnt_q};
    end else begin : g_da_cut
      assign cnt_da = cnt_q[DA_W-1:0];
    end
  endgenerate

  wire idle = (state_q == ST_IDLE);
  wire accept = idle & in_valid_i;
  wire out_block = (state_q == ST_OUT) & out_valid_q & ~out_ready_i;
  wire wr_block = ram_we_o & host_we_i;
  wire en = ~(out_block | wr_block);
  assign en_o = en;
  assign in_ready_o = idle;
  assign out_valid_o = out_valid_q;
  assign dp_read_o = ~idle;
  assign bit_idx_o = cnt_q[BI_W-1:0];

  wire cnt_zero = (cnt_q == {CNT_W{1'b0}});
  wire j_zero = (j_q == {J_W{1'b0}});

  always @(*) begin
    // Defaults: A = 0, B = T1 unshifted, add, no saturation, nothing written.
    a_sel_o = A_ZERO;
    a_half_o = 1'b0;
    b_sel_o = B_T1;
    q_ext_o = Q_PS;
    sh_amt_o = AM_ZERO;
    gate_sel_o = G_ONE;
    sub_sel_o = S_ADD;
    cin_sel_o = C_SUB;
    sat_sel_o = SAT_NONE;
    acc_we_o = 1'b0;
    t1_we_o = 1'b0;
    t1_src_o = T1_RES;
    t2_we_o = 1'b0;
    t2_src_o = T2_RES;
    ovf_clr_o = 1'b0;
    region_we_o = 1'b0;
    neg_we_o = 1'b0;
    dir_push_o = 1'b0;
    dir_pop_o = 1'b0;
    los_we_o = 1'b0;
    dos_we_o = 1'b0;
    out_we_o = 1'b0;
    raddr_o = AD_O13;
    ram_we_o = 1'b0;
    waddr_o = curve_q ? AD_S24 : AD_S13;
    state_d = state_q;
    cnt_d = cnt_q;
    j_d = j_q;
    curve_d = curve_q;
    case (state_q)
      ST_IDLE: begin
        // d13 into ACC; c2, c4 into the temporaries.
        a_sel_o = A_C1;
        b_sel_o = B_C3;
        sub_sel_o = S_SUB;
        acc_we_o = accept;
        t1_we_o = accept;
        t1_src_o = T1_C2;
        t2_we_o = accept;
        t2_src_o = T2_C4;
        ovf_clr_o = accept;
        if (accept) begin
          state_d = ST_PRE;
          curve_d = 1'b0;
        end
      end
      ST_PRE: begin
        a_sel_o = A_T1;
        b_sel_o = B_T2;
        sub_sel_o = S_SUB;
        t1_we_o = 1'b1;
        raddr_o = AD_O13;
        state_d = ST_OFF;
      end
      ST_OFF: begin
        // t = d - O: curve 0 from ACC into T2, curve 1 from T1 into T1.
        a_sel_o = curve_q ? A_T1 : A_ACC;
        b_sel_o = B_Q;
        sub_sel_o = S_SUB;
        t1_we_o = curve_q;
        t2_we_o = ~curve_q;
        raddr_o = curve_q ? AD_R24 : AD_R13;
        cnt_d = CNT_SC;
        state_d = ST_SC;
      end
      ST_SC: begin
        a_sel_o = (cnt_q == CNT_SC) ? A_ZERO : A_ACC;
        b_sel_o = curve_q ? B_T1 : B_T2;
        sh_amt_o = AM_SC - cnt_sh;
        gate_sel_o = G_RBIT;
        acc_we_o = 1'b1;
        raddr_o = curve_q ? AD_R24 : AD_R13;
        cnt_d = cnt_q - CNT_ONE;
        if (cnt_zero) state_d = ST_RND;
      end
      ST_RND: begin
        b_sel_o = B_ACC;
        sh_amt_o = AM_SG;
        cin_sel_o = C_RND;
        sat_sel_o = SAT_S;
        acc_we_o = 1'b1;
        ram_we_o = 1'b1;
        raddr_o = curve_q ? AD_S13 : AD_O24;
        curve_d = 1'b1;
        state_d = curve_q ? ST_RS0 : ST_OFF;
      end
      ST_RS0: begin
        b_sel_o = B_ACC;
        sub_sel_o = S_ACCNEG;
        acc_we_o = 1'b1;
        t2_we_o = 1'b1;
        t2_src_o = T2_ACC;
        raddr_o = AD_S13;
        state_d = ST_RS1;
      end
      ST_RS1: begin
        a_sel_o = A_ACC;
        b_sel_o = B_Q;
        q_ext_o = Q_SC;
        sub_sel_o = S_QPOS;
        region_we_o = 1'b1;
        raddr_o = AD_S13;
        state_d = ST_RS2;
      end
      ST_RS2: begin
        q_ext_o = Q_SC;
        t2_we_o = use13_i;
        t2_src_o = T2_Q;
        raddr_o = coef_addr(region_i, 1'b0, J_N);
        curve_d = 1'b0;
        state_d = ST_HI;
      end
      ST_HI: begin
        b_sel_o = B_Q;
        sh_amt_o = AM_COEF;
        acc_we_o = 1'b1;
        cnt_d = CNT_HB;
        j_d = J_TOP;
        state_d = ST_HB;
      end
      ST_HB: begin
        // Bit b = cnt of x, from the sign bit (subtracted) down; the first step also moves the
        // multiplicand acc_{j+1} into T1.
        if (cnt_q == CNT_HB) begin
          b_sel_o = B_ACC;
          sub_sel_o = S_SUB;
          t1_we_o = 1'b1;
          t1_src_o = T1_ACC;
        end else begin
          a_sel_o = A_ACC;
          b_sel_o = B_T1;
        end
        sh_amt_o = AM_HB - cnt_sh;
        gate_sel_o = G_XBIT;
        acc_we_o = 1'b1;
        raddr_o = coef_addr(region_i, curve_q, j_ext);
        cnt_d = cnt_q - CNT_ONE;
        if (cnt_zero) state_d = ST_HC;
      end
      ST_HC: begin
        a_sel_o = A_ACC;
        b_sel_o = B_Q;
        sh_amt_o = AM_COEF;
        sat_sel_o = SAT_ACC;
        acc_we_o = 1'b1;
        raddr_o = curve_q ? AD_S24 : AD_S13;
        cnt_d = CNT_HB;
        j_d = j_q - 1'b1;
        state_d = j_zero ? ST_HY : ST_HB;
      end
      ST_HY: begin
        a_sel_o = A_Q;
        q_ext_o = Q_SC;
        b_sel_o = B_ACC;
        sh_amt_o = AM_RN;
        sub_sel_o = S_SUB;
        cin_sel_o = C_NRND;
        sat_sel_o = SAT_S;
        acc_we_o = 1'b1;
        ram_we_o = ~curve_q;
        waddr_o = AD_Y13;
        raddr_o = curve_q ? AD_Y13 : coef_addr(region_i, 1'b1, J_N);
        curve_d = 1'b1;
        state_d = curve_q ? ST_CR0 : ST_HI;
      end
      ST_CR0: begin
        b_sel_o = B_ACC;
        sh_amt_o = AM_GL;
        sub_sel_o = S_ACCNEG;
        t1_we_o = 1'b1;
        neg_we_o = 1'b1;
        raddr_o = AD_Y13;
        state_d = ST_CR1;
      end
      ST_CR1: begin
        b_sel_o = B_Q;
        q_ext_o = Q_SC;
        sh_amt_o = AM_GL;
        sub_sel_o = S_NEG;
        acc_we_o = 1'b1;
        cnt_d = {CNT_W{1'b0}};
        state_d = ST_CA;
      end
      ST_CA: begin
        // Y in ACC: Y -= d (X >>> i), the old Y kept in T2, d_i = (Y >= 0) pushed.
        a_sel_o = A_ACC;
        b_sel_o = B_T1;
        sh_amt_o = AM_ZERO + cnt_sh;
        sub_sel_o = S_ACCPOS;
        acc_we_o = 1'b1;
        t2_we_o = 1'b1;
        t2_src_o = T2_ACC;
        dir_push_o = 1'b1;
        state_d = ST_CB;
      end
      ST_CB: begin
        // X in T1: X += d (Y >>> i) with the old Y.
        a_sel_o = A_T1;
        b_sel_o = B_T2;
        sh_amt_o = AM_ZERO + cnt_sh;
        sub_sel_o = S_T2NEG;
        t1_we_o = 1'b1;
        cnt_d = cnt_q + CNT_ONE;
        state_d = (cnt_q == CNT_K) ? ST_LOS : ST_CA;
      end
      ST_LOS: begin
        a_sel_o = A_MLO;
        b_sel_o = B_T1;
        sh_amt_o = AM_GR;
        sub_sel_o = S_SUB;
        cin_sel_o = C_ZERO;
        los_we_o = 1'b1;
        state_d = ST_DOS;
      end
      ST_DOS: begin
        a_sel_o = A_MHI;
        b_sel_o = B_T1;
        sh_amt_o = AM_GR;
        sub_sel_o = S_SUB;
        dos_we_o = 1'b1;
        raddr_o = AD_ATAN0;
        cnt_d = {CNT_W{1'b0}};
        state_d = ST_ZL;
      end
      ST_ZL: begin
        a_sel_o = cnt_zero ? A_ZERO : A_ACC;
        a_half_o = 1'b1;
        b_sel_o = B_Q;
        q_ext_o = Q_PU;
        sub_sel_o = S_DIRNEG;
        acc_we_o = 1'b1;
        dir_pop_o = 1'b1;
        raddr_o = AD_ATAN0 + cnt_da + 1'b1;
        cnt_d = cnt_q + CNT_ONE;
        if (cnt_q == CNT_K) state_d = ST_OUT;
      end
      ST_OUT: begin
        b_sel_o = B_ACC;
        sh_amt_o = AM_DROP;
        cin_sel_o = C_RND;
        out_we_o = 1'b1;
        state_d = ST_IDLE;
      end
      default: state_d = ST_IDLE;
    endcase
  end

  always @(posedge clk_i) begin
    if (rst_i) begin
      state_q <= ST_IDLE;
      out_valid_q <= 1'b0;
    end else begin
      if (en) state_q <= state_d;
      if (en && state_q == ST_OUT) out_valid_q <= 1'b1;
      else if (out_ready_i) out_valid_q <= 1'b0;
    end
  end
  always @(posedge clk_i) begin
    if (en) begin
      cnt_q <= cnt_d;
      j_q <= j_d;
      curve_q <= curve_d;
    end
  end

endmodule

`resetall
