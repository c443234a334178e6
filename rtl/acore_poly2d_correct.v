// SPDX-License-Identifier: MIT
// acore_poly2d_correct: stage 4 in CORRECTION = 1 (poly2d), 2-D polynomial correction of one curve
// (model/ip/stages/poly2d_correct.cpp, bit for bit): y = s - P_region(u, v), P of total degree DEGREE <= 3 in
//   u = x                                   (XCENTER = 0)  multiplier shift U_SH = S_F
//   u = x - (x >= 0 ? 3/8 : -3/8)           (XCENTER = 1)  U_SH = S_F - 1, i.e. read as 2 u
//   v = y_other - (y_other >= 0 ? 1 : -1)   V_SH = S_F - 2, i.e. read as 4 v
// where x is the region's linear curve and y_other the other one (s24 in regions 0 and 2 of four,
// s13 in 1 and 3). Both are exact (they move towards zero). Nested Horner on adder/shifter
// multipliers, every product's partial products floored on their own:
//   inner, side by side for i = 0..DEGREE-1:  Q_i = a_{i,d-i};  Q_i = sat(Q_i v + a_ij, ACC_W)
//   outer:  acc = a_{d,0};  acc = sat(acc u + Q_i, ACC_W), i = d-1..0
//   y = sat(s - round_shr(acc, ACC_F - S_F), S_W)
// (coefficients sign-extended and shifted left by ACC_G: ACC_F = COEF_F + ACC_G fraction bits).
//
// Schedule (one sample per clock, L = ML + 2 clocks per Horner step, ML = clog2(S_W)):
//   clock 0          u, v (one adder each), the leading coefficient of every Q_i
//   clocks 1..       inner chains: Q_i's step k at 1 + k L (ML clocks product, add, saturate)
//   clocks 3..       outer chain:  step m at 3 + (m-1) L; its add meets Q_{d-m}, which the inner
//                    chain of degree m delivers at 1 + m L = 3 + (m-1) L + ML: no extra delay
//   then round, subtract, saturate (one clock each). LATENCY = 6 + DEGREE L.
// The outer chain's latency equals the 1-D Horner's of the same degree; the inner chains run
// beside it, so poly2d costs area (DEGREE (DEGREE+3)/2 multipliers per curve), not latency.
//
// Coefficient words (register map 4 + T (2 r + c) + t, T = (DEGREE+1)(DEGREE+2)/2 terms): term
// t(i, j) = i (DEGREE+1) - i (i-1)/2 + j for u^i v^j, i.e. (0,0), (0,1), .., (0,d), (1,0), .., (d,0).
`resetall
`default_nettype none

module acore_poly2d_correct #(
  parameter integer REG_W = 18,
  // Curve width, signed, S_F fraction bits.
  parameter integer S_W = 18,
  parameter integer S_F = 16,
  // Total degree d of the polynomial, 1..3.
  parameter integer DEGREE = 3,
  // 4 or 8 regions.
  parameter integer REGIONS = 4,
  // 1 (8 regions only): the polynomial is in u = x -+ 3/8, centred in its half region.
  parameter integer XCENTER = 0,
  // Fraction bits of a coefficient (REG_W-bit signed word).
  parameter integer COEF_F = 15,
  // Guard fraction bits and integer bits (incl. sign) of the Horner accumulators.
  parameter integer ACC_G = 4,
  parameter integer ACC_I = 6,
  // Which curve this instance corrects (and whose words it reads): 0 = c13, 1 = c24.
  parameter integer CURVE = 0,
  // 0: products on adders and shifters; 1: on hardware multipliers (acore_hw_mul.v, DSP blocks).
  parameter integer MULT = 0,
  // Derived, do not override.
  parameter integer RG_W = $clog2(REGIONS)
) (
  input  wire                clk_i,
  input  wire                en_i,
  // Linear curve x, both scaled curves (this instance corrects s13 or s24, see CURVE), region.
  input  wire [S_W-1:0]      x_i,
  input  wire [S_W-1:0]      s13_i,
  input  wire [S_W-1:0]      s24_i,
  input  wire [RG_W-1:0]     region_i,
  // The polynomial words of the map (from word 4: [region][curve][term]), first in the low bits.
  input  wire [acore_poly_words(acore_terms_poly2d(DEGREE), REGIONS)*REG_W-1:0] coef_i,
  // Corrected curve and "some step saturated".
  output wire [S_W-1:0]      y_o,
  output wire                ovf_o
);

`include "acore_derived.vh"

  // Derived, do not override.
  localparam integer TERMS = acore_terms_poly2d(DEGREE);
  localparam integer COEF_BUS_W = acore_poly_words(TERMS, REGIONS) * REG_W;
  localparam integer ACC_F = acore_acc_f(COEF_F, ACC_G);
  localparam integer ACC_W = acore_acc_w(COEF_F, ACC_G, ACC_I);
  localparam integer ML = acore_shift_add_mul_latency(S_W);
  localparam integer L = ML + 2;
  localparam integer LATENCY = acore_poly2d_latency(DEGREE, S_W);
  localparam integer U_SH = S_F - XCENTER;
  localparam integer V_SH = S_F - 2;
  // Products acc u and acc v: |acc| 2^(S_W - shift) plus floor slack, plus sign.
  localparam integer PU_W = ACC_W + S_W - U_SH + 1;
  localparam integer PV_W = ACC_W + S_W - V_SH + 1;
  localparam integer RN = ACC_F - S_F;      // rounding shift of the final accumulator
  localparam [S_W-1:0] ONE = {{(S_W-S_F-1){1'b0}}, 1'b1, {S_F{1'b0}}};
  // Term index of u^i v^j (see the header).
  function integer p2_term(input integer i, input integer j);
    p2_term = acore_term2d(DEGREE, i, j);
  endfunction
  // Bit offset on coef_i of term t, region r, this curve (the map's address, counted from the
  // first polynomial word).
  function integer coef_off(input integer r, input integer t);
    coef_off = (acore_addr_poly(TERMS, r, CURVE, t) - acore_addr_poly(TERMS, 0, 0, 0)) * REG_W;
  endfunction

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(DEGREE >= 1 && DEGREE <= 3), .VALUE(DEGREE),
    .MSG("illegal parameter: acore_poly2d_correct: DEGREE must be 1..3"))
    DEGREE_must_be_1_to_3 ();
  acore_check #(.OK(REGIONS == 4 || REGIONS == 8), .VALUE(REGIONS),
    .MSG("illegal parameter: acore_poly2d_correct: REGIONS must be 4 or 8"))
    REGIONS_must_be_4_or_8 ();
  acore_check #(.OK(XCENTER == 0 || (XCENTER == 1 && REGIONS == 8)), .VALUE(XCENTER),
    .MSG("illegal parameter: acore_poly2d_correct: XCENTER must be 0, or 1 with REGIONS=8"))
    XCENTER_must_be_0_or_1_with_8_regions ();
  acore_check #(.OK(S_F >= 3), .VALUE(S_F),
    .MSG("illegal parameter: acore_poly2d_correct: S_F must be >= 3"))
    S_F_must_be_at_least_3 ();
  acore_check #(.OK(S_W >= S_F + 2), .VALUE(S_W),
    .MSG("illegal parameter: acore_poly2d_correct: S_W must be >= S_F+2"))
    S_W_must_be_at_least_S_F_plus_2 ();
  acore_check #(.OK(ACC_F >= S_F), .VALUE(ACC_F),
    .MSG("illegal parameter: acore_poly2d_correct: COEF_F+ACC_G must be >= S_F"))
    COEF_F_plus_ACC_G_must_be_at_least_S_F ();
  acore_check #(.OK(ACC_I >= REG_W - COEF_F + 1), .VALUE(ACC_I),
    .MSG("illegal parameter: acore_poly2d_correct: ACC_I must be >= REG_W-COEF_F+1"))
    ACC_I_must_be_at_least_REG_W_minus_COEF_F_plus_1 ();
  acore_check #(.OK(CURVE == 0 || CURVE == 1), .VALUE(CURVE),
    .MSG("illegal parameter: acore_poly2d_correct: CURVE must be 0 or 1"))
    CURVE_must_be_0_or_1 ();

  // Coefficient of term t for region r of this curve, sign-extended and shifted to ACC_F bits.
  function automatic [ACC_W-1:0] coef_acc(input [COEF_BUS_W-1:0] bus, input [RG_W-1:0] r,
                                          input integer t);
    reg [REG_W-1:0] w;
    integer k;
    begin
      w = {REG_W{1'b0}};
      for (k = 0; k < REGIONS; k = k + 1)
        if (r == k[RG_W-1:0]) w = bus[coef_off(k, t) +: REG_W];
      coef_acc = {{(ACC_W-REG_W-ACC_G){w[REG_W-1]}}, w, {ACC_G{1'b0}}};
    end
  endfunction

  // ---- clock 0: arguments and leading coefficients ----
  // x is the sine curve in regions 0 and 2 of four (region bit RG_W-2), so y_other is s24 there.
  wire [S_W-1:0] y_other = region_i[RG_W-2] ? s13_i : s24_i;
  wire [S_W-1:0] s_own = (CURVE != 0) ? s24_i : s13_i;
  wire [S_W-1:0] v_next = y_other[S_W-1] ? y_other + ONE : y_other - ONE;
  wire [S_W-1:0] u_next;
  generate
    if (XCENTER != 0) begin : g_centre
      localparam [S_W-1:0] CENTRE = {{(S_W-S_F+1){1'b0}}, 2'b11, {(S_F-3){1'b0}}};  // 3/8
      assign u_next = x_i[S_W-1] ? x_i + CENTRE : x_i - CENTRE;
    end else begin : g_raw
      assign u_next = x_i;
    end
  endgenerate

  // Inner-chain nodes: node t(i, k) is Q_i after k Horner steps (k = 0: the leading coefficient,
  // k = DEGREE - i: Q_i itself), so the node index is the term index t(i, k).
  wire [ACC_W-1:0] node [0:TERMS-1];
  wire             nov  [0:TERMS-1];
  reg  [ACC_W-1:0] lead_q [0:DEGREE];
  reg  [S_W-1:0]   u0_q, v0_q, s0_q;
  reg  [RG_W-1:0]  r0_q;
  integer li;
  always @(posedge clk_i) begin
    if (en_i) begin
      for (li = 0; li <= DEGREE; li = li + 1) lead_q[li] <= coef_acc(coef_i, region_i, p2_term(li, DEGREE - li));
      u0_q <= u_next;
      v0_q <= v_next;
      s0_q <= s_own;
      r0_q <= region_i;
    end
  end

  genvar i, k, m;
  generate
    // Region at clock k L + ML, where the coefficient of inner step k is picked (a clock before its add).
    wire [RG_W-1:0] r_pick [0:DEGREE-1];
    // v at the start of inner step k.
    wire [S_W-1:0] v_at [0:DEGREE-1];
    assign v_at[0] = v0_q;
    for (k = 0; k < DEGREE; k = k + 1) begin : g_rline
      acore_delay #(.W(RG_W), .DEPTH(k * L + ML - 1)) u_dr (
        .clk_i(clk_i), .en_i(en_i), .d_i(r0_q), .q_o(r_pick[k]));
      if (k + 1 < DEGREE) begin : g_vnext
        acore_delay #(.W(S_W), .DEPTH(L)) u_dv (.clk_i(clk_i), .en_i(en_i), .d_i(v_at[k]), .q_o(v_at[k+1]));
      end
    end

    for (i = 0; i <= DEGREE; i = i + 1) begin : g_chain
      assign node[p2_term(i, 0)] = lead_q[i];
      assign nov[p2_term(i, 0)] = 1'b0;
      for (k = 0; k < DEGREE - i; k = k + 1) begin : g_step
        // Step k of Q_i: node(i, k) v + a_{i, d-i-1-k}.
        localparam integer NIN = p2_term(i, k);
        wire [PV_W-1:0] prod;
        acore_shift_add_mul #(
          .A_W(ACC_W), .B_W(S_W), .B_SIGNED(1), .RSHIFT(V_SH), .P_W(PV_W), .MULT(MULT)
        ) u_mul (
          .clk_i(clk_i), .en_i(en_i), .a_i(node[NIN]), .b_i(v_at[k]), .p_o(prod)
        );
        wire ov_e;
        acore_delay #(.W(1), .DEPTH(ML)) u_dov (.clk_i(clk_i), .en_i(en_i), .d_i(nov[NIN]), .q_o(ov_e));
        reg [ACC_W-1:0] a_q;
        reg [PV_W:0]    sum_q;
        reg [ACC_W-1:0] acc_q;
        reg             ov_s_q, ov_q;
        wire [PV_W:0] sum = {prod[PV_W-1], prod} + {{(PV_W+1-ACC_W){a_q[ACC_W-1]}}, a_q};
        wire [ACC_W-1:0] sum_sat;
        wire sum_ovf;
        acore_saturate #(.IN_W(PV_W + 1), .OUT_W(ACC_W)) u_sat (.d_i(sum_q), .q_o(sum_sat), .ovf_o(sum_ovf));
        always @(posedge clk_i) begin
          if (en_i) begin
            a_q    <= coef_acc(coef_i, r_pick[k], p2_term(i, DEGREE - i - 1 - k));
            sum_q  <= sum;
            ov_s_q <= ov_e;
            acc_q  <= sum_sat;
            ov_q   <= ov_s_q | sum_ovf;
          end
        end
        assign node[NIN + 1] = acc_q;
        assign nov[NIN + 1] = ov_q;
      end
    end
  endgenerate

  // ---- outer chain on u, from clock 3 ----
  wire [ACC_W-1:0] oacc [0:DEGREE];
  wire [S_W-1:0]   ou   [0:DEGREE];
  wire [S_W-1:0]   os   [0:DEGREE];
  wire             oov  [0:DEGREE];
  acore_delay #(.W(ACC_W + (S_W << 1)), .DEPTH(2)) u_d_outer (
    .clk_i(clk_i), .en_i(en_i), .d_i({lead_q[DEGREE], u0_q, s0_q}), .q_o({oacc[0], ou[0], os[0]}));
  assign oov[0] = 1'b0;

  generate
    for (m = 1; m <= DEGREE; m = m + 1) begin : g_outer
      // Q_{d-m}: the last node of inner chain d-m, due exactly when this step's product is.
      localparam integer NQ = p2_term(DEGREE - m, m);
      wire [PU_W-1:0] prod;
      acore_shift_add_mul #(
        .A_W(ACC_W), .B_W(S_W), .B_SIGNED(1), .RSHIFT(U_SH), .P_W(PU_W), .MULT(MULT)
      ) u_mul (
        .clk_i(clk_i), .en_i(en_i), .a_i(oacc[m-1]), .b_i(ou[m-1]), .p_o(prod)
      );
      wire ov_e;
      acore_delay #(.W(1), .DEPTH(ML)) u_dov (.clk_i(clk_i), .en_i(en_i), .d_i(oov[m-1]), .q_o(ov_e));
      acore_delay #(.W(S_W << 1), .DEPTH(L)) u_dus (
        .clk_i(clk_i), .en_i(en_i), .d_i({ou[m-1], os[m-1]}), .q_o({ou[m], os[m]}));
      reg [PU_W:0]    sum_q;
      reg [ACC_W-1:0] acc_q;
      reg             ov_s_q, ov_q;
      wire [PU_W:0] sum = {prod[PU_W-1], prod} + {{(PU_W+1-ACC_W){node[NQ][ACC_W-1]}}, node[NQ]};
      wire [ACC_W-1:0] sum_sat;
      wire sum_ovf;
      acore_saturate #(.IN_W(PU_W + 1), .OUT_W(ACC_W)) u_sat (.d_i(sum_q), .q_o(sum_sat), .ovf_o(sum_ovf));
      always @(posedge clk_i) begin
        if (en_i) begin
          sum_q  <= sum;
          ov_s_q <= ov_e | nov[NQ];
          acc_q  <= sum_sat;
          ov_q   <= ov_s_q | sum_ovf;
        end
      end
      assign oacc[m] = acc_q;
      assign oov[m] = ov_q;
    end
  endgenerate

  // y = saturate(s - round_shr(acc, RN), S_W): round, subtract, saturate, one clock each.
  acore_round_sub_sat #(.ACC_W(ACC_W), .RN(RN), .S_W(S_W)) u_out (
    .clk_i(clk_i), .en_i(en_i), .acc_i(oacc[DEGREE]), .s_i(os[DEGREE]), .ov_i(oov[DEGREE]), .y_o(y_o), .ovf_o(ovf_o));

endmodule

`resetall
