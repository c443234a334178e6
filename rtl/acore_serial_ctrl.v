// SPDX-License-Identifier: MIT
// acore_serial_ctrl: the serial core's sequencer. One state per operation kind, a bit/iteration
// counter cnt, a Horner power counter j and the curve bit. Each clock it issues one datapath
// operation (acore_serial_datapath.v): the stage-1 fields (operands, shift, add/subtract, carry-in,
// register moves, the RAM read address of the next operation's operand) directly, the stage-2
// fields (A source, saturation, destinations, flags) through a register, so they act a clock later.
//
// Schedule of one sample. ACC, T1, T2: the datapath registers; Q: the RAM word whose address the
// previous operation issued; "-" a bubble (the next operation's stage 1 needs this one's result).
//
//   state  ops           operation (stage 2 result)                          RAM address issued
//   IDLE   1 (accept)    ACC = c1 - c3;  T1 = c2, T2 = c4 (moves)             (the host's)
//   PRE    1             T1 = T1 - T2                     (d24)               O13
//   OFF13  1             T2 = ACC - O13                   (t13)               O24
//   OFF24  1             T1 = T1 - O24                    (t24)               R13
//   SC     REG_W         ACC = [0 | ACC] + R[j] shift(t, j - RS), j = REG_W-1..0   R13 | R24
//   SCB    1             -
//   RND    1             ACC = sat_S((ACC >>> SG) + rbit) -> scratch s13|s24       R24 (curve 0)
//          (SC, SCB, RND for t13 in T2, then for t24 in T1)
//   RNDB   1             -
//   RS0    1             ACC = |ACC| (|s24|);  T2 = ACC (move, s24)                  S13
//   RS1    1             |s24| -/+ s13 >= 0 -> use13, region                          S13
//   RS2    1             T2 = s13 if use13 (T2 = x)
//   RSB    1             -                                                          a_n(region, 0)
//   HB     S_W           b = S_W-1: ACC = -x[b] shift(M, b - S_F), T1 = M (move); then
//                        ACC = ACC + x[b] shift(T1, b - S_F), b = S_W-2..0          last: a_j
//                        (M = acc_{j+1}: a_n from Q, shifted ACC_G more, in the first step; ACC after)
//   HC     1             ACC = sat_ACC(ACC + (a_j << ACC_G))
//   HCB    1             - (before the next HB)
//   HCL    1             - (after the last HC)                                     s13 | s24
//   HY     1             ACC = sat_S(s - ((ACC >>> RN) + rbit)) -> curve 0: scratch y13
//                                                                         a_n(region, 1) | -
//          (HB..HC DEGREE times, then HY; once per curve)
//   HYB    1             -                                                          Y13
//   CR0    1             T1 = |ACC << G| (X0);  neg = y24 < 0                        Y13
//   CR1    1             ACC = +-(y13 << G)   (Y0)
//   CRB    1             - (CA reads the sign of Y0 in its stage 1)
//   CA     1 \           ACC = ACC -+ (T1 >>> i)           (Y)
//   CB     1  K times    T1 = T1 +- (ACC >>> i)            (X, with the old Y)        atan_i
//   CZ     1 /           T2 = [half turn if neg | T2] +- atan_i (Z, by the sign CB saw)
//   LOS    1             los = mag_lo - (T1 >>> G) - 1 >= 0
//   ZR     ZERO          T2 = (T2 >>> DROP) + rbit (the rounded angle; ZERO = 1 only)
//   DOS    1             dos = mag_hi - (T1 >>> G) < 0                              ZERO (ZERO = 1)
//   OUT    1             angle = (T2 >>> DROP) + rbit, region, flags -> output registers
//                        (ZERO = 1: angle = T2 - Q, the rounded angle minus the zero position)
//
// MULT = 1 (the datapath's hardware product P, acore_serial_datapath.v): the scaling and the
// Horner steps are one operation each, the rest as above:
//
//   SC     1             ACC = P(t, R) >>> RS                                   R24
//   SCB, RND as above (SC, SCB, RND for t13 in T2, then for t24 in T1)
//   RSB    1             -                                                      a_n(region, 0)
//   HL     1             T1 = a_n (move)                                        a_{n-1}
//   HM     1             ACC = sat_ACC((P(M, x) >>> S_F) + (a_j << ACC_G))
//                        (M = a_n in T1, shifted ACC_G more, in the first step; ACC after)
//   HMB    1             - (before the next HM)                                 a_{j-1}
//   HCL, HY as above     (HL, then HM, HMB DEGREE times with HCL for the last HMB, then HY;
//                        once per curve)
//
// OUT's stage 2 runs in the next IDLE clock, which can accept the next sample: one sample every
// CYCLES = 22 + ZERO + 2 REG_W + 2 DEGREE (S_W + 2) + 3 K clocks (MULT = 1: 26 + ZERO + 4 DEGREE
// + 3 K; acore_serial_cycles() in rtl/acore_derived.vh); the result appears
// LATENCY = CYCLES + 1 clocks after its accepting clock (acore_serial_top.v). The output takes the
// low ANGLE_W bits of T2 - Q, so the word's bits above ANGLE_W do not reach the angle.
// Stalls (en_o = 0: nothing changes, the RAM output holds): stage 2 of OUT while the previous
// result is still held (out_valid_o && !out_ready_i), and stage 2 of a scratch write (RND, HY of
// curve 0) in a clock where the host writes the register file (the host owns the write port).
// The datapath arithmetic uses the one adder; the counters here are the sequencer's own.
`resetall
`default_nettype none

module acore_serial_ctrl #(
  // Register word width (bits of the amplitude reciprocal R the scaling scans).
  parameter integer REG_W = 18,
  // Curve width and fraction bits (bits of x the Horner steps scan; their shifts).
  parameter integer S_W = 18,
  parameter integer S_F = 16,
  // Polynomial degree, regions (4 or 8), CORDIC iterations.
  parameter integer DEGREE = 3,
  parameter integer REGIONS = 4,
  parameter integer K = 16,
  // 1: the ZERO word (the map's last word) and the ZR operation.
  parameter integer ZERO = 0,
  // 1: the hardware product (the SC and HM operations above).
  parameter integer MULT = 0,
  // Words of the coefficient map (acore_words: 4 + 2 REGIONS (DEGREE + 1) + K, + 1 with ZERO).
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
  // The RAM writes the host's registered word this clock (it owns the RAM write port).
  input  wire              host_we_i,
  // From the datapath: region of the sample.
  input  wire [RG_W-1:0]   region_i,
  // Advance (0: stall).
  output wire              en_o,
  // ---- stage 1 (encodings as in acore_serial_datapath.v) ----
  output reg  [2:0]        a_sel_o,
  output reg               a_half_o,
  output reg  [2:0]        b_sel_o,
  output reg  [1:0]        q_ext_o,
  output reg  [SHA_W-1:0]  sh_amt_o,
  output reg  [1:0]        gate_sel_o,
  output wire [BI_W-1:0]   bit_idx_o,
  output reg               t1_mv_o,
  output reg  [1:0]        t1_mv_src_o,
  output reg               t2_mv_o,
  output reg               t2_mv_src_o,
  output reg  [2:0]        sub_sel_o,
  output reg  [1:0]        cin_sel_o,
  output reg  [1:0]        mul_sel_o,
  // The product's operand sources (MULT = 1), registered: decoded from the next state a clock
  // ahead, so the multiplier's inputs come through a 3:1 mux on a register's select instead of
  // the state decode and the A operand's mux (the ECP5's critical path): the multiplicand
  // (MA_T1, MA_T2, MA_ACC) and the multiplier (1: R from Q, the scaling; 0: x, a Horner step).
  output wire [1:0]        mul_a_o,
  output wire              mul_r_o,
  // ---- stage 2 (registered) ----
  output reg               a_acc_o,
  output reg  [1:0]        sat_sel_o,
  output reg               acc_we_o,
  output reg               t1_we_o,
  output reg               t2_we_o,
  output reg               t2_we_u13_o,
  output reg               ovf_clr_o,
  output reg               region_we_o,
  output reg               neg_we_o,
  output reg               los_we_o,
  output reg               dos_we_o,
  output reg               out_we_o,
  // RAM: the datapath owns the read port, the address for the next clock; a scratch write (stage 2).
  output wire              dp_read_o,
  output reg  [DA_W-1:0]   raddr_o,
  output reg               ram_we_o,
  output reg  [DA_W-1:0]   waddr_o
);

`include "acore_derived.vh"

  function integer sc_max(input integer a, input integer b);
    sc_max = (a > b) ? a : b;
  endfunction

  // Operation encodings (acore_serial_datapath.v uses the same numbers).
  localparam [2:0] A_ZERO = 3'd0, A_T1 = 3'd1, A_T2 = 3'd2, A_Q = 3'd3, A_C1 = 3'd4, A_MLO = 3'd5,
                   A_MHI = 3'd6, A_ACC = 3'd7;
  localparam [2:0] B_T1 = 3'd0, B_T2 = 3'd1, B_ACC = 3'd2, B_Q = 3'd3, B_C3 = 3'd4;
  localparam [1:0] Q_PS = 2'd0, Q_PU = 2'd1, Q_SC = 2'd2;
  localparam [1:0] G_ONE = 2'd0, G_ZERO = 2'd1, G_RBIT = 2'd2, G_XBIT = 2'd3;
  localparam [1:0] M1_C2 = 2'd0, M1_ACC = 2'd1, M1_Q = 2'd2;
  localparam       M2_C4 = 1'b0, M2_ACC = 1'b1;
  localparam [2:0] S_ADD = 3'd0, S_SUB = 3'd1, S_BNEG = 3'd2, S_BPOS = 3'd3, S_ACCNEG = 3'd4,
                   S_ACCPOS = 3'd5, S_PBNEG = 3'd6;
  localparam [1:0] C_SUB = 2'd0, C_RND = 2'd1, C_NRND = 2'd2, C_ZERO = 2'd3;
  localparam [1:0] SAT_NONE = 2'd0, SAT_S = 2'd1, SAT_ACC = 2'd2;
  localparam [1:0] P_NONE = 2'd0, P_SC = 2'd1, P_H = 2'd2, P_H0 = 2'd3;
  localparam [1:0] MA_T1 = 2'd0, MA_T2 = 2'd1, MA_ACC = 2'd2;

  localparam [4:0] ST_IDLE = 5'd0, ST_PRE = 5'd1, ST_OFF13 = 5'd2, ST_OFF24 = 5'd3, ST_SC = 5'd4,
                   ST_SCB = 5'd5, ST_RND = 5'd6, ST_RNDB = 5'd7, ST_RS0 = 5'd8, ST_RS1 = 5'd9,
                   ST_RS2 = 5'd10, ST_RSB = 5'd11, ST_HB = 5'd12, ST_HC = 5'd13, ST_HCB = 5'd14,
                   ST_HCL = 5'd15, ST_HY = 5'd16, ST_HYB = 5'd17, ST_CR0 = 5'd18, ST_CR1 = 5'd19,
                   ST_CRB = 5'd20, ST_CA = 5'd21, ST_CB = 5'd22, ST_CZ = 5'd23, ST_LOS = 5'd24,
                   ST_DOS = 5'd25, ST_OUT = 5'd26, ST_ZR = 5'd27, ST_HL = 5'd28, ST_HM = 5'd29,
                   ST_HMB = 5'd30;

  // Counter widths: cnt runs over the REG_W bits of R, the S_W bits of x, the K iterations.
  localparam integer CNT_N = sc_max(sc_max(REG_W, S_W), K);
  localparam integer CNT_W = $clog2(CNT_N);
  localparam integer J_W = (DEGREE > 1) ? $clog2(DEGREE) : 1;
  localparam integer TERMS = acore_terms_poly(DEGREE);

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(BI_W <= CNT_W), .VALUE(BI_W),
    .MSG("illegal parameter: acore_serial_ctrl: BI_W must be <= the counter's width"))
    BI_W_must_fit_the_counter ();
  acore_check #(.OK(WORDS == acore_words(TERMS, REGIONS, K, 0, ZERO)), .VALUE(WORDS),
    .MSG("illegal parameter: acore_serial_ctrl: WORDS is derived (4 + 2 REGIONS (DEGREE+1) + K + ZERO word), do not override"))
    WORDS_is_derived ();
  acore_check #(.OK(DA_W == $clog2(WORDS + 3)), .VALUE(DA_W),
    .MSG("illegal parameter: acore_serial_ctrl: DA_W is derived (clog2(WORDS+3)), do not override"))
    DA_W_is_derived ();
  acore_check #(
    .OK(LS + RS >= REG_W - 1 && LS + S_F >= S_W - 1 + ACC_G && LS >= ACC_G && LS >= G),
    .VALUE(LS),
    .MSG("illegal parameter: acore_serial_ctrl: LS too small for the left shifts"))
    LS_must_cover_every_left_shift ();
  acore_check #(.OK(K >= 2), .VALUE(K),
    .MSG("illegal parameter: acore_serial_ctrl: K must be >= 2"))
    K_must_be_at_least_2 ();

  // Addresses (the register map, rtl/acore_derived.vh) and the scratch words after the map.
  localparam integer O13_I = acore_addr_offset(0), O24_I = acore_addr_offset(1);
  localparam integer R13_I = acore_addr_recip(0), R24_I = acore_addr_recip(1);
  localparam [DA_W-1:0] AD_O13 = O13_I[DA_W-1:0], AD_O24 = O24_I[DA_W-1:0];
  localparam [DA_W-1:0] AD_R13 = R13_I[DA_W-1:0], AD_R24 = R24_I[DA_W-1:0];
  localparam integer S13_I = WORDS, S24_I = WORDS + 1, Y13_I = WORDS + 2;
  localparam [DA_W-1:0] AD_S13 = S13_I[DA_W-1:0], AD_S24 = S24_I[DA_W-1:0], AD_Y13 = Y13_I[DA_W-1:0];
  localparam integer ATAN0_I = acore_addr_atan(TERMS, REGIONS, 0);
  localparam [DA_W-1:0] AD_ATAN0 = ATAN0_I[DA_W-1:0];
  localparam integer ZERO_I = acore_addr_zero(TERMS, REGIONS, K, 0);  // read with ZERO = 1 only
  localparam [DA_W-1:0] AD_ZERO = ZERO_I[DA_W-1:0];

  // Shift amounts (sh_amt = LS - k).
  localparam integer AM_ZERO_I = LS, AM_SC_I = LS + RS, AM_HB_I = LS + S_F, AM_HB0_I = LS + S_F - ACC_G;
  localparam integer AM_SG_I = LS + SG, AM_RN_I = LS + RN, AM_DROP_I = LS + DROP, AM_COEF_I = LS - ACC_G;
  localparam integer AM_GL_I = LS - G, AM_GR_I = LS + G;
  localparam [SHA_W-1:0] AM_ZERO = AM_ZERO_I[SHA_W-1:0], AM_SC = AM_SC_I[SHA_W-1:0];
  localparam [SHA_W-1:0] AM_HB = AM_HB_I[SHA_W-1:0], AM_HB0 = AM_HB0_I[SHA_W-1:0];
  localparam [SHA_W-1:0] AM_SG = AM_SG_I[SHA_W-1:0], AM_RN = AM_RN_I[SHA_W-1:0];
  localparam [SHA_W-1:0] AM_DROP = AM_DROP_I[SHA_W-1:0], AM_COEF = AM_COEF_I[SHA_W-1:0];
  localparam [SHA_W-1:0] AM_GL = AM_GL_I[SHA_W-1:0], AM_GR = AM_GR_I[SHA_W-1:0];

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

  wire [DA_W-1:0] j_ext = {{(DA_W-J_W){1'b0}}, j_q};
  // The address of the polynomial word of power j, region r, curve c: word 0 of {r, c} (the map's
  // addresses on a bus) plus j (the word of power j is j words further; J_N: the leading
  // coefficient's).
  localparam integer J_N_I = acore_addr_poly(TERMS, 0, 0, DEGREE) - acore_addr_poly(TERMS, 0, 0, 0);
  localparam [DA_W-1:0] J_N = J_N_I[DA_W-1:0];
  wire [2*REGIONS*DA_W-1:0] poly_base;
  genvar gb;
  generate
    for (gb = 0; gb < 2 * REGIONS; gb = gb + 1) begin : g_poly_base
      localparam integer BASE_I = acore_addr_poly(TERMS, gb >> 1, gb & 1, 0);
      assign poly_base[gb * DA_W +: DA_W] = BASE_I[DA_W-1:0];
    end
  endgenerate
  function automatic [DA_W-1:0] coef_addr(input [2*REGIONS*DA_W-1:0] bases, input [RG_W-1:0] r,
                                           input c, input [DA_W-1:0] j);
    integer k;
    begin
      coef_addr = {DA_W{1'b0}};
      for (k = 0; k < 2 * REGIONS; k = k + 1)
        if ({r, c} == k[RG_W:0]) coef_addr = bases[k * DA_W +: DA_W] + j;
    end
  endfunction
  // The counter as a shift amount and as an address offset (its values fit both: cnt <= LS + MAXR
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

  // Stage-2 fields of the operation issued now (registered below).
  reg       a_acc_d, acc_we_d, t1_we_d, t2_we_d, t2_we_u13_d, ovf_clr_d, region_we_d, neg_we_d;
  reg       los_we_d, dos_we_d, out_we_d, ram_we_d;
  reg [1:0] sat_sel_d;
  reg [DA_W-1:0] waddr_d;

  wire idle = (state_q == ST_IDLE);
  // Stage 2 of OUT cannot load the output registers while the previous result is held; a scratch
  // write cannot happen in a clock the host writes.
  wire out_block = out_we_o & out_valid_q & ~out_ready_i;
  wire wr_block = ram_we_o & host_we_i;
  wire en = ~(out_block | wr_block);
  // Nothing is taken while rst_i is high (in_ready_o low in reset, as in acore_top).
  wire accept = idle & en & in_valid_i & ~rst_i;
  assign en_o = en;
  assign in_ready_o = idle & en & ~rst_i;
  assign out_valid_o = out_valid_q;
  assign dp_read_o = ~idle;
  assign bit_idx_o = cnt_q[BI_W-1:0];

  wire cnt_zero = (cnt_q == {CNT_W{1'b0}});
  wire j_zero = (j_q == {J_W{1'b0}});
  wire step0 = (j_q == J_TOP);

  always @(*) begin
    // Defaults: a bubble (stage 1: A = 0, B = T1 unshifted; stage 2: nothing written).
    a_sel_o = A_ZERO;
    a_half_o = 1'b0;
    b_sel_o = B_T1;
    q_ext_o = Q_PS;
    sh_amt_o = AM_ZERO;
    gate_sel_o = G_ONE;
    t1_mv_o = 1'b0;
    t1_mv_src_o = M1_ACC;
    t2_mv_o = 1'b0;
    t2_mv_src_o = M2_ACC;
    raddr_o = AD_O13;
    a_acc_d = 1'b0;
    sub_sel_o = S_ADD;
    cin_sel_o = C_SUB;
    mul_sel_o = P_NONE;
    sat_sel_d = SAT_NONE;
    acc_we_d = 1'b0;
    t1_we_d = 1'b0;
    t2_we_d = 1'b0;
    t2_we_u13_d = 1'b0;
    ovf_clr_d = 1'b0;
    region_we_d = 1'b0;
    neg_we_d = 1'b0;
    los_we_d = 1'b0;
    dos_we_d = 1'b0;
    out_we_d = 1'b0;
    ram_we_d = 1'b0;
    waddr_d = curve_q ? AD_S24 : AD_S13;
    state_d = state_q;
    cnt_d = cnt_q;
    j_d = j_q;
    curve_d = curve_q;
    case (state_q)
      ST_IDLE: begin
        // d13 into ACC; c2, c4 moved into the temporaries.
        a_sel_o = A_C1;
        b_sel_o = B_C3;
        t1_mv_o = accept;
        t1_mv_src_o = M1_C2;
        t2_mv_o = accept;
        t2_mv_src_o = M2_C4;
        sub_sel_o = S_SUB;
        acc_we_d = accept;
        ovf_clr_d = accept;
        if (accept) begin
          state_d = ST_PRE;
          curve_d = 1'b0;
        end
      end
      ST_PRE: begin
        a_sel_o = A_T1;
        b_sel_o = B_T2;
        raddr_o = AD_O13;
        sub_sel_o = S_SUB;
        t1_we_d = 1'b1;
        state_d = ST_OFF13;
      end
      ST_OFF13: begin
        b_sel_o = B_Q;
        raddr_o = AD_O24;
        a_acc_d = 1'b1;
        sub_sel_o = S_SUB;
        t2_we_d = 1'b1;
        state_d = ST_OFF24;
      end
      ST_OFF24: begin
        a_sel_o = A_T1;
        b_sel_o = B_Q;
        raddr_o = AD_R13;
        sub_sel_o = S_SUB;
        t1_we_d = 1'b1;
        cnt_d = CNT_SC;
        state_d = ST_SC;
      end
      ST_SC: begin
        if (MULT != 0) begin
          // ACC = P(t, R) >>> RS (B gated to 0).
          a_sel_o = curve_q ? A_T1 : A_T2;
          mul_sel_o = P_SC;
          gate_sel_o = G_ZERO;
          raddr_o = AD_R24;
          acc_we_d = 1'b1;
          state_d = ST_SCB;
        end else begin
          // Bit j = cnt of R (from the top): ACC = [0 | ACC] + R[j] shift(t, j - RS).
          b_sel_o = curve_q ? B_T1 : B_T2;
          sh_amt_o = AM_SC - cnt_sh;
          gate_sel_o = G_RBIT;
          raddr_o = curve_q ? AD_R24 : AD_R13;
          a_acc_d = (cnt_q != CNT_SC);
          acc_we_d = 1'b1;
          cnt_d = cnt_q - CNT_ONE;
          if (cnt_zero) state_d = ST_SCB;
        end
      end
      ST_SCB: begin
        raddr_o = AD_R24;
        state_d = ST_RND;
      end
      ST_RND: begin
        b_sel_o = B_ACC;
        sh_amt_o = AM_SG;
        raddr_o = AD_R24;
        cin_sel_o = C_RND;
        sat_sel_d = SAT_S;
        acc_we_d = 1'b1;
        ram_we_d = 1'b1;
        curve_d = 1'b1;
        cnt_d = CNT_SC;
        state_d = curve_q ? ST_RNDB : ST_SC;
      end
      ST_RNDB: begin
        state_d = ST_RS0;
      end
      ST_RS0: begin
        b_sel_o = B_ACC;
        t2_mv_o = 1'b1;
        t2_mv_src_o = M2_ACC;
        raddr_o = AD_S13;
        sub_sel_o = S_BNEG;
        acc_we_d = 1'b1;
        state_d = ST_RS1;
      end
      ST_RS1: begin
        b_sel_o = B_Q;
        q_ext_o = Q_SC;
        raddr_o = AD_S13;
        a_acc_d = 1'b1;
        sub_sel_o = S_BPOS;
        region_we_d = 1'b1;
        state_d = ST_RS2;
      end
      ST_RS2: begin
        a_sel_o = A_Q;
        q_ext_o = Q_SC;
        gate_sel_o = G_ZERO;
        t2_we_u13_d = 1'b1;
        state_d = ST_RSB;
      end
      ST_RSB: begin
        raddr_o = coef_addr(poly_base, region_i, 1'b0, J_N);
        curve_d = 1'b0;
        cnt_d = CNT_HB;
        j_d = J_TOP;
        state_d = (MULT != 0) ? ST_HL : ST_HB;
      end
      ST_HB: begin
        // Bit b = cnt of x, from the sign bit (subtracted) down. The first bit moves the
        // multiplicand into T1: a_n from Q in the first step (its ACC_G alignment folded into the
        // shifts), acc_{j+1} from ACC after.
        if (cnt_q == CNT_HB) begin
          b_sel_o = step0 ? B_Q : B_ACC;
          t1_mv_o = 1'b1;
          t1_mv_src_o = step0 ? M1_Q : M1_ACC;
          sub_sel_o = S_SUB;
        end else begin
          b_sel_o = B_T1;
          a_acc_d = 1'b1;
        end
        sh_amt_o = (step0 ? AM_HB0 : AM_HB) - cnt_sh;
        gate_sel_o = G_XBIT;
        raddr_o = coef_addr(poly_base, region_i, curve_q, j_ext);
        acc_we_d = 1'b1;
        cnt_d = cnt_q - CNT_ONE;
        if (cnt_zero) state_d = ST_HC;
      end
      ST_HC: begin
        b_sel_o = B_Q;
        sh_amt_o = AM_COEF;
        raddr_o = curve_q ? AD_S24 : AD_S13;
        a_acc_d = 1'b1;
        sat_sel_d = SAT_ACC;
        acc_we_d = 1'b1;
        cnt_d = CNT_HB;
        j_d = j_q - 1'b1;
        state_d = j_zero ? ST_HCL : ST_HCB;
      end
      ST_HCB: begin
        state_d = ST_HB;
      end
      ST_HL: begin
        // The leading coefficient a_n (the previous operation issued its address) into T1.
        t1_mv_o = 1'b1;
        t1_mv_src_o = M1_Q;
        raddr_o = coef_addr(poly_base, region_i, curve_q, j_ext);
        state_d = ST_HM;
      end
      ST_HM: begin
        // ACC = sat_ACC((P(M, x) >>> S_F) + (a_j << ACC_G)): M = a_n in T1 (its ACC_G in the
        // product's shift) in the first step, ACC after; a_j from Q.
        a_sel_o = step0 ? A_T1 : A_ACC;
        mul_sel_o = step0 ? P_H0 : P_H;
        b_sel_o = B_Q;
        sh_amt_o = AM_COEF;
        raddr_o = curve_q ? AD_S24 : AD_S13;
        sat_sel_d = SAT_ACC;
        acc_we_d = 1'b1;
        j_d = j_q - 1'b1;
        state_d = j_zero ? ST_HCL : ST_HMB;
      end
      ST_HMB: begin
        raddr_o = coef_addr(poly_base, region_i, curve_q, j_ext);
        state_d = ST_HM;
      end
      ST_HCL: begin
        raddr_o = curve_q ? AD_S24 : AD_S13;
        state_d = ST_HY;
      end
      ST_HY: begin
        a_sel_o = A_Q;
        q_ext_o = Q_SC;
        b_sel_o = B_ACC;
        sh_amt_o = AM_RN;
        raddr_o = coef_addr(poly_base, region_i, 1'b1, J_N);
        sub_sel_o = S_SUB;
        cin_sel_o = C_NRND;
        sat_sel_d = SAT_S;
        acc_we_d = 1'b1;
        ram_we_d = ~curve_q;
        waddr_d = AD_Y13;
        curve_d = 1'b1;
        cnt_d = CNT_HB;
        j_d = J_TOP;
        state_d = curve_q ? ST_HYB : ((MULT != 0) ? ST_HL : ST_HB);
      end
      ST_HYB: begin
        raddr_o = AD_Y13;
        state_d = ST_CR0;
      end
      ST_CR0: begin
        b_sel_o = B_ACC;
        sh_amt_o = AM_GL;
        raddr_o = AD_Y13;
        sub_sel_o = S_BNEG;
        t1_we_d = 1'b1;
        neg_we_d = 1'b1;
        state_d = ST_CR1;
      end
      ST_CR1: begin
        b_sel_o = B_Q;
        q_ext_o = Q_SC;
        sh_amt_o = AM_GL;
        sub_sel_o = S_ACCNEG;  // y24 < 0 (ACC still holds y24)
        acc_we_d = 1'b1;
        cnt_d = {CNT_W{1'b0}};
        state_d = ST_CRB;
      end
      ST_CRB: begin
        state_d = ST_CA;
      end
      ST_CA: begin
        // Y in ACC: Y -= d (X >>> i), d = (Y >= 0).
        b_sel_o = B_T1;
        sh_amt_o = AM_ZERO + cnt_sh;
        a_acc_d = 1'b1;
        sub_sel_o = S_ACCPOS;
        acc_we_d = 1'b1;
        state_d = ST_CB;
      end
      ST_CB: begin
        // X in T1: X += d (Y >>> i) with the old Y (ACC before CA's stage 2 writes it).
        a_sel_o = A_T1;
        b_sel_o = B_ACC;
        sh_amt_o = AM_ZERO + cnt_sh;
        raddr_o = AD_ATAN0 + cnt_da;
        sub_sel_o = S_BNEG;
        t1_we_d = 1'b1;
        state_d = ST_CZ;
      end
      ST_CZ: begin
        // Z in T2: Z += d atan_i, from half a turn (or 0) at i = 0.
        a_sel_o = cnt_zero ? A_ZERO : A_T2;
        a_half_o = 1'b1;
        b_sel_o = B_Q;
        q_ext_o = Q_PU;
        sub_sel_o = S_PBNEG;  // Y_i < 0: the sign CB took of its B source
        t2_we_d = 1'b1;
        cnt_d = cnt_q + CNT_ONE;
        state_d = (cnt_q == CNT_K) ? ST_LOS : ST_CA;
      end
      ST_LOS: begin
        a_sel_o = A_MLO;
        b_sel_o = B_T1;
        sh_amt_o = AM_GR;
        sub_sel_o = S_SUB;
        cin_sel_o = C_ZERO;
        los_we_d = 1'b1;
        state_d = (ZERO != 0) ? ST_ZR : ST_DOS;
      end
      ST_ZR: begin
        // The angle rounded into T2, for OUT to subtract the zero position from.
        b_sel_o = B_T2;
        sh_amt_o = AM_DROP;
        cin_sel_o = C_RND;
        t2_we_d = 1'b1;
        state_d = ST_DOS;
      end
      ST_DOS: begin
        a_sel_o = A_MHI;
        b_sel_o = B_T1;
        sh_amt_o = AM_GR;
        sub_sel_o = S_SUB;
        dos_we_d = 1'b1;
        if (ZERO != 0) raddr_o = AD_ZERO;
        state_d = ST_OUT;
      end
      ST_OUT: begin
        if (ZERO != 0) begin
          // The rounded angle (ZR) minus the zero position (DOS issued its address).
          a_sel_o = A_T2;
          b_sel_o = B_Q;
          q_ext_o = Q_PU;
          sub_sel_o = S_SUB;
        end else begin
          b_sel_o = B_T2;
          sh_amt_o = AM_DROP;
          cin_sel_o = C_RND;
        end
        out_we_d = 1'b1;
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
      if (en && out_we_o) out_valid_q <= 1'b1;
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

  // The product's operands of the next operation (SC: t of the curve, R; HM: a_n in T1 in the
  // first step, ACC after, x), as the SC and HM cases issue them; only an SC or HM reads them.
  generate
    if (MULT != 0) begin : g_mul_src
      reg [1:0] mul_a_q;
      reg       mul_r_q;
      always @(posedge clk_i) begin
        if (en) begin
          if (state_d == ST_SC) mul_a_q <= curve_d ? MA_T1 : MA_T2;
          else mul_a_q <= (j_d == J_TOP) ? MA_T1 : MA_ACC;
          mul_r_q <= (state_d == ST_SC);
        end
      end
      assign mul_a_o = mul_a_q;
      assign mul_r_o = mul_r_q;
    end else begin : g_no_mul_src
      assign mul_a_o = MA_T1;
      assign mul_r_o = 1'b0;
    end
  endgenerate

  // Stage-2 register: the enables are control (reset to a bubble), the modes are not.
  always @(posedge clk_i) begin
    if (rst_i) begin
      acc_we_o <= 1'b0;
      t1_we_o <= 1'b0;
      t2_we_o <= 1'b0;
      t2_we_u13_o <= 1'b0;
      ovf_clr_o <= 1'b0;
      region_we_o <= 1'b0;
      neg_we_o <= 1'b0;
      los_we_o <= 1'b0;
      dos_we_o <= 1'b0;
      out_we_o <= 1'b0;
      ram_we_o <= 1'b0;
    end else if (en) begin
      acc_we_o <= acc_we_d;
      t1_we_o <= t1_we_d;
      t2_we_o <= t2_we_d;
      t2_we_u13_o <= t2_we_u13_d;
      ovf_clr_o <= ovf_clr_d;
      region_we_o <= region_we_d;
      neg_we_o <= neg_we_d;
      los_we_o <= los_we_d;
      dos_we_o <= dos_we_d;
      out_we_o <= out_we_d;
      ram_we_o <= ram_we_d;
    end
  end
  always @(posedge clk_i) begin
    if (en) begin
      a_acc_o <= a_acc_d;
      sat_sel_o <= sat_sel_d;
      waddr_o <= waddr_d;
    end
  end

endmodule

`resetall
