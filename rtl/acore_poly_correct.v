// SPDX-License-Identifier: MIT
// acore_poly_correct: stage 4, polynomial correction of one curve (paper Eq. 6,
// model/ip/stages/poly_correct.cpp): y = s - P_region(x), Horner's scheme on the adder/shifter multiplier,
// unrolled into DEGREE pipelined steps so one sample enters per clock:
//   acc_n = a_n << ACC_G                                                ACC_F = COEF_F + ACC_G
//   acc_j = saturate(shift_add_mul(acc_{j+1}, u, S_W signed, U_SH) + (a_j << ACC_G), ACC_W)
//   y     = saturate(s - round_shr(acc_0, ACC_F - S_F), S_W)
// with u = x, U_SH = S_F (XCENTER = 0, the paper's), or u = x - (x >= 0 ? 3/8 : -3/8), U_SH = S_F - 1
// (XCENTER = 1, 8 regions: the polynomial in 2 (x -+ 3/8), centred in its half region, so that
// high-degree coefficients stay in range; exact, computed in clock 0 by one adder).
// The coefficients a_j of the sample's region are picked from the register file bus at the step
// that uses them (the region travels with the sample).
//
//   1 clock: a_n of the region; step m = 0..DEGREE-1 (j = DEGREE-1-m): ML clocks of adder tree,
//   1 clock add, 1 clock saturate; then round, subtract, saturate for y (one carry chain per clock).
//   LATENCY = 1 + DEGREE (ML + 2) + 3, ML = clog2(S_W)
`resetall
`default_nettype none

module acore_poly_correct #(
  parameter integer REG_W = 18,
  // Curve width, signed, S_F fraction bits.
  parameter integer S_W = 18,
  parameter integer S_F = 16,
  // Polynomial degree n.
  parameter integer DEGREE = 3,
  // 4 or 8 regions.
  parameter integer REGIONS = 4,
  // Fraction bits of a coefficient (REG_W-bit signed word).
  parameter integer COEF_F = 15,
  // Guard fraction bits and integer bits (incl. sign) of the Horner accumulator.
  parameter integer ACC_G = 4,
  parameter integer ACC_I = 6,
  // Which curve's coefficients: 0 = sine curve c13, 1 = cosine curve c24.
  parameter integer CURVE = 0,
  // 1 (8 regions only): the polynomial is in u = x -+ 3/8, centred in its half region.
  parameter integer XCENTER = 0,
  // 0: products on adders and shifters; 1: on hardware multipliers (acore_hw_mul.v, DSP blocks).
  parameter integer MULT = 0,
  // Derived, do not override.
  parameter integer RG_W = $clog2(REGIONS)
) (
  input  wire                clk_i,
  input  wire                en_i,
  // Polynomial argument and the curve to correct.
  input  wire [S_W-1:0]      x_i,
  input  wire [S_W-1:0]      s_i,
  input  wire [RG_W-1:0]     region_i,
  // The polynomial words of the map (from word 4: [region][curve][power]), first in the low bits.
  input  wire [acore_poly_words(acore_terms_poly(DEGREE), REGIONS)*REG_W-1:0] coef_i,
  // Corrected curve and "some step saturated".
  output wire [S_W-1:0]      y_o,
  output wire                ovf_o
);

`include "acore_derived.vh"

  // Derived, do not override.
  localparam integer TERMS = acore_terms_poly(DEGREE);
  localparam integer COEF_BUS_W = acore_poly_words(TERMS, REGIONS) * REG_W;
  localparam integer ACC_F = acore_acc_f(COEF_F, ACC_G);
  localparam integer ACC_W = acore_acc_w(COEF_F, ACC_G, ACC_I);
  localparam integer ML = acore_shift_add_mul_latency(S_W);
  localparam integer LATENCY = acore_poly_latency(DEGREE, S_W);
  localparam integer U_SH = S_F - XCENTER;
  localparam integer P_W = ACC_W + ((S_W > U_SH) ? (S_W - U_SH) : 0) + 1;
  localparam integer RN = ACC_F - S_F;      // rounding shift of the final accumulator
  // Bit offset on coef_i of the word of power j, region r, this curve (the map's address, counted
  // from the first polynomial word).
  function integer coef_off(input integer r, input integer j);
    coef_off = (acore_addr_poly(TERMS, r, CURVE, j) - acore_addr_poly(TERMS, 0, 0, 0)) * REG_W;
  endfunction

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(ACC_F >= S_F), .VALUE(ACC_F),
    .MSG("illegal parameter: acore_poly_correct: COEF_F+ACC_G must be >= S_F"))
    COEF_F_plus_ACC_G_must_be_at_least_S_F ();
  acore_check #(.OK(ACC_I >= REG_W - COEF_F + 1), .VALUE(ACC_I),
    .MSG("illegal parameter: acore_poly_correct: ACC_I must be >= REG_W-COEF_F+1"))
    ACC_I_must_be_at_least_REG_W_minus_COEF_F_plus_1 ();
  acore_check #(.OK(DEGREE >= 1), .VALUE(DEGREE),
    .MSG("illegal parameter: acore_poly_correct: DEGREE must be >= 1"))
    DEGREE_must_be_at_least_1 ();
  acore_check #(.OK(XCENTER == 0 || (XCENTER == 1 && REGIONS == 8 && S_F >= 3)), .VALUE(XCENTER),
    .MSG("illegal parameter: acore_poly_correct: XCENTER must be 0, or 1 with REGIONS=8 and S_F >= 3"))
    XCENTER_must_be_0_or_1_with_8_regions_and_S_F_at_least_3 ();

  // Per step m: inputs of the step (accumulator, argument, curve, region, overflow so far).
  wire [ACC_W-1:0] acc [0:DEGREE];
  wire [S_W-1:0]   xs  [0:DEGREE];
  wire [S_W-1:0]   ss  [0:DEGREE];
  wire [RG_W-1:0]  rs  [0:DEGREE];
  wire             ov  [0:DEGREE];

  // Coefficient of x^j for region r of this curve, sign-extended and shifted to ACC_F fraction
  // bits.
  function automatic [ACC_W-1:0] coef_acc(input [COEF_BUS_W-1:0] bus, input [RG_W-1:0] r,
                                          input integer j);
    reg [REG_W-1:0] w;
    integer k;
    begin
      w = {REG_W{1'b0}};
      for (k = 0; k < REGIONS; k = k + 1)
        if (r == k[RG_W-1:0]) w = bus[coef_off(k, j) +: REG_W];
      coef_acc = {{(ACC_W-REG_W-ACC_G){w[REG_W-1]}}, w, {ACC_G{1'b0}}};
    end
  endfunction

  // Clock 0: the leading coefficient of the sample's region, registered with the sample, and u.
  wire [S_W-1:0] u_next;
  generate
    if (XCENTER != 0) begin : g_centre
      localparam [S_W-1:0] CENTRE = {{(S_W-S_F+1){1'b0}}, 2'b11, {(S_F-3){1'b0}}};  // 3/8
      assign u_next = x_i[S_W-1] ? x_i + CENTRE : x_i - CENTRE;
    end else begin : g_raw
      assign u_next = x_i;
    end
  endgenerate
  reg [ACC_W-1:0] acc0_q;
  reg [S_W-1:0]   x0_q, s0_q;
  reg [RG_W-1:0]  r0_q;
  always @(posedge clk_i) begin
    if (en_i) begin
      acc0_q <= coef_acc(coef_i, region_i, DEGREE);
      x0_q   <= u_next;
      s0_q   <= s_i;
      r0_q   <= region_i;
    end
  end
  assign acc[0] = acc0_q;
  assign xs[0]  = x0_q;
  assign ss[0]  = s0_q;
  assign rs[0]  = r0_q;
  assign ov[0]  = 1'b0;

  genvar m;
  generate
    for (m = 0; m < DEGREE; m = m + 1) begin : g_step
      // ML clocks: acc times x on the adder tree. Beside it the region travels ML-1 clocks, then
      // picks a_j into a register (so no multiplexer sits in front of the adder).
      wire [P_W-1:0] prod;
      acore_shift_add_mul #(
        .A_W(ACC_W), .B_W(S_W), .B_SIGNED(1), .RSHIFT(U_SH), .P_W(P_W), .MULT(MULT)
      ) u_mul (
        .clk_i(clk_i), .en_i(en_i), .a_i(acc[m]), .b_i(xs[m]), .p_o(prod)
      );
      wire [RG_W-1:0] r_e;
      wire            ov_e;
      acore_delay #(.W(RG_W + 1), .DEPTH(ML - 1)) u_dr (
        .clk_i(clk_i), .en_i(en_i), .d_i({rs[m], ov[m]}), .q_o({r_e, ov_e}));
      acore_delay #(.W(S_W << 1), .DEPTH(ML + 2)) u_dxs (
        .clk_i(clk_i), .en_i(en_i), .d_i({xs[m], ss[m]}), .q_o({xs[m+1], ss[m+1]}));
      reg [ACC_W-1:0] a_j_q;
      reg [RG_W-1:0]  r_d_q, r_s_q, r_q;
      reg             ov_d_q, ov_s_q, ov_q;
      reg [P_W:0]     sum_q;
      reg [ACC_W-1:0] acc_q;
      // Clock ML+1: prod + a_j. Clock ML+2: saturate to ACC_W.
      wire [P_W:0] sum = {prod[P_W-1], prod} + {{(P_W+1-ACC_W){a_j_q[ACC_W-1]}}, a_j_q};
      wire [ACC_W-1:0] sum_sat;
      wire sum_ovf;
      acore_saturate #(.IN_W(P_W + 1), .OUT_W(ACC_W)) u_sat (.d_i(sum_q), .q_o(sum_sat), .ovf_o(sum_ovf));
      always @(posedge clk_i) begin
        if (en_i) begin
          a_j_q  <= coef_acc(coef_i, r_e, DEGREE - 1 - m);
          r_d_q  <= r_e;
          ov_d_q <= ov_e;
          sum_q  <= sum;
          r_s_q  <= r_d_q;
          ov_s_q <= ov_d_q;
          acc_q  <= sum_sat;
          r_q    <= r_s_q;
          ov_q   <= ov_s_q | sum_ovf;
        end
      end
      assign acc[m+1] = acc_q;
      assign rs[m+1]  = r_q;
      assign ov[m+1]  = ov_q;
    end
  endgenerate

  // y = saturate(s - round_shr(acc, RN), S_W): round, subtract, saturate, one clock each.
  acore_round_sub_sat #(.ACC_W(ACC_W), .RN(RN), .S_W(S_W)) u_out (
    .clk_i(clk_i), .en_i(en_i), .acc_i(acc[DEGREE]), .s_i(ss[DEGREE]), .ov_i(ov[DEGREE]), .y_o(y_o), .ovf_o(ovf_o));

endmodule

`resetall
