// SPDX-License-Identifier: MIT
// acore_top: the AngleCore estimator, one sample per clock (model/fixed_model.cpp, bit for bit).
//
//   c1..c4 -> prefilter -> scaler x2 -> region_select -> correction x2 -> cordic -> [fourier] -> [- zero] -> angle, flags
//                            ^ O, 1/A        (coef_regfile, 52 words)  ^ a_j        ^ atan_i    ^ a_k, b_k   ^ ZERO word
//
// The Fourier correction (acore_fourier_correct.v) is generated only when FOURIER_K > 0; with
// FOURIER_K = 0 (the default) the top is the chain without it, word for word and clock for clock.
// ZERO = 1 adds one register word after all others, the zero position z (its low ANGLE_W bits),
// and one subtractor in the output register: angle_o = (angle - z) mod 2^ANGLE_W, the angle in the
// reference frame of the calibration (README "Zero offset"); no extra clock.
//
// The correction stage is chosen by CORRECTION: 0 = acore_poly_correct (1-D in x, the paper's),
// 1 = acore_poly2d_correct (2-D in x and the other curve), 2 = none (the scaled curves go straight
// to the CORDIC, no coefficient words). LATENCY follows from the stages chosen.
//
// Streaming: a sample is taken when in_valid_i && in_ready_o and comes out LATENCY accepted-or-
// advancing clocks later on out_valid_o. The pipeline stalls as a whole when the output is held
// (out_valid_o && !out_ready_i), so in_ready_o = !stall and throughput is one sample per clock
// while out_ready_i is high; bubbles travel through with their valid bit low. in_ready_o is low
// while rst_i is high (a sample offered in reset is not taken).
//
//   clk        _|~|_|~|_|~|_|~|_|~|_|~|_
//   in_valid_i  ‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾      in_ready_o = !rst_i && !(out_valid_o && !out_ready_i)
//   c1..c4_i    | A | B | C | D | E |
//   out_valid_o  ... LATENCY clocks later: | A | B | C | ...
//
// Only the valid flops are reset (rst_i synchronous, active high); data flops are not, and every
// output is forced to zero while out_valid_o is low, so no unknown ever leaves the core.
// Flags: ovf_o = saturation in any stage; los_o = magnitude < mag_lo_i (loss of signal);
// dos_o = magnitude > mag_hi_i (degradation / saturation of signal). The magnitude is the CORDIC's
// X_K >>> CORDIC_G, the corrected vector length (1.0 = 2^S_F) times the CORDIC gain (1.6468).
`resetall
`default_nettype none

module acore_top #(
  // Channel code width, signed.
  parameter integer IN_W = 16,
  // Register word width.
  parameter integer REG_W = 18,
  // Scaled/corrected curve width (signed) and its fraction bits.
  parameter integer S_W = 18,
  parameter integer S_F = 16,
  // Extra scale of the amplitude reciprocal, and guard bits of the scaling product.
  parameter integer R_SHIFT = 13,
  parameter integer SCALE_G = 4,
  // Correction mode: 0 = poly (1-D), 1 = poly2d (2-D, total degree DEGREE <= 3), 2 = none.
  parameter integer CORRECTION = 0,
  // Polynomial degree and number of regions (4 or 8).
  parameter integer DEGREE = 3,
  parameter integer REGIONS = 4,
  // 1 (8 regions only): the polynomials are in u = x -+ 3/8, centred in their half region.
  parameter integer XCENTER = 0,
  // Coefficient fraction bits; Horner accumulator guard and integer bits.
  parameter integer COEF_F = 15,
  parameter integer ACC_G = 4,
  parameter integer ACC_I = 6,
  // CORDIC iterations (= stages), guard bits, angle accumulator width, output angle width.
  parameter integer K = 16,
  parameter integer CORDIC_G = 3,
  parameter integer Z_W = 20,
  parameter integer ANGLE_W = 16,
  // Angle-domain Fourier correction after the CORDIC: harmonics (0 = none), rotation stages per
  // harmonic (<= K), coefficient fraction bits (turns), significant bits of a harmonic's word, guard
  // bits of the rotations.
  parameter integer FOURIER_K = 0,
  parameter integer FOURIER_M = 12,
  parameter integer FOURIER_CF = 22,
  parameter integer FOURIER_W = 16,
  parameter integer FOURIER_G = 2,
  // 1: one more register word (the last) holding the zero position, subtracted from the output
  // angle; 0: none (the paper's map).
  parameter integer ZERO = 0,
  // $readmemh register image for the power-up contents ("" = none).
  parameter INIT_FILE = "",
  // Derived, do not override.
  parameter integer RG_W = $clog2(REGIONS),
  // Coefficients per region and curve: DEGREE + 1 (poly), (DEGREE + 1)(DEGREE + 2) / 2 (poly2d), 0.
  parameter integer TERMS = (CORRECTION == 2) ? 0 :
                            (CORRECTION == 1) ? ((DEGREE == 1) ? 3 : (DEGREE == 2) ? 6 : 10) : DEGREE + 1,
  // 4 + 2 REGIONS TERMS + K (REGIONS is a power of two, so the product is a shift), plus
  // 2 FOURIER_K + 1 Fourier words when FOURIER_K > 0, plus the ZERO word.
  parameter integer WORDS = 4 + (TERMS << ($clog2(REGIONS) + 1)) + K +
                            ((FOURIER_K > 0) ? (FOURIER_K << 1) + 1 : 0) + ((ZERO != 0) ? 1 : 0),
  parameter integer ADDR_W = $clog2(WORDS),
  parameter integer MAG_W = S_W + 2
) (
  input  wire               clk_i,
  input  wire               rst_i,
  // Register file host port: a write taken at a clock edge lands at the next one (ignored while
  // rst_i is high); reg_rdata_o is the word at reg_addr_i of two clocks before (0 past the last).
  input  wire [ADDR_W-1:0]  reg_addr_i,
  input  wire [REG_W-1:0]   reg_wdata_i,
  input  wire               reg_we_i,
  output wire [REG_W-1:0]   reg_rdata_o,
  // Status window on the magnitude (unsigned).
  input  wire [MAG_W-1:0]   mag_lo_i,
  input  wire [MAG_W-1:0]   mag_hi_i,
  // Input stream: four channel codes (two-channel sensors: c3 = c4 = 0).
  input  wire               in_valid_i,
  output wire               in_ready_o,
  input  wire [IN_W-1:0]    c1_i,
  input  wire [IN_W-1:0]    c2_i,
  input  wire [IN_W-1:0]    c3_i,
  input  wire [IN_W-1:0]    c4_i,
  // Output stream.
  output wire               out_valid_o,
  input  wire               out_ready_i,
  // Angle, unsigned, one turn = 2^ANGLE_W.
  output wire [ANGLE_W-1:0] angle_o,
  output wire [RG_W-1:0]    region_o,
  output wire               ovf_o,
  output wire               los_o,
  output wire               dos_o
);

  // Constant product by repeated addition, for widths and offsets at elaboration only: the RTL
  // has no multiplication operator at all (the datapath multiplies on adders and shifters).
  function integer top_cmul(input integer a, input integer b);
    integer n;
    begin
      top_cmul = 0;
      for (n = 0; n < b; n = n + 1) top_cmul = top_cmul + a;
    end
  endfunction

  // Derived, do not override: stage latencies (each module documents its own) and the total.
  localparam integer D_W = IN_W + 1;
  localparam integer PRE_LATENCY = 1;
  localparam integer SCALER_LATENCY = $clog2(REG_W) + 3;
  localparam integer REGION_LATENCY = 2;
  localparam integer POLY_LATENCY = (CORRECTION == 2) ? 0 :
                                    (CORRECTION == 1) ? 6 + top_cmul(DEGREE, $clog2(S_W) + 2) :
                                    1 + top_cmul(DEGREE, $clog2(S_W) + 2) + 3;
  localparam integer CORDIC_LATENCY = 1 + K + 1;
  // acore_fourier_correct: clog2(KB) + 1 + FOURIER_M + clog2(FOURIER_K + 1) + 1, KB = bits of K.
  localparam integer FOURIER_KB = ($clog2(FOURIER_K + 1) > 2) ? $clog2(FOURIER_K + 1) : 2;
  localparam integer FOURIER_LATENCY = (FOURIER_K > 0) ?
      $clog2(FOURIER_KB) + 1 + FOURIER_M + $clog2(FOURIER_K + 1) + 1 : 0;
  localparam integer OUT_LATENCY = 1;
  localparam integer LATENCY = PRE_LATENCY + SCALER_LATENCY + REGION_LATENCY + POLY_LATENCY +
                               CORDIC_LATENCY + FOURIER_LATENCY + OUT_LATENCY;
  localparam integer NCOEF = top_cmul(REGIONS << 1, TERMS);
  localparam integer NFOURIER = (FOURIER_K > 0) ? (FOURIER_K << 1) + 1 : 0;

  // Parameter rules: the model's DatapathConfig::validate() (acore_config_check.v), and the derived
  // parameters. An illegal configuration stops elaboration in Verilator, Icarus and Yosys.
  acore_config_check #(
    .IN_W(IN_W), .REG_W(REG_W), .S_W(S_W), .S_F(S_F), .R_SHIFT(R_SHIFT), .SCALE_G(SCALE_G),
    .CORRECTION(CORRECTION), .DEGREE(DEGREE), .REGIONS(REGIONS), .XCENTER(XCENTER), .COEF_F(COEF_F),
    .ACC_G(ACC_G), .ACC_I(ACC_I), .K(K), .CORDIC_G(CORDIC_G), .Z_W(Z_W), .ANGLE_W(ANGLE_W),
    .FOURIER_K(FOURIER_K), .FOURIER_M(FOURIER_M), .FOURIER_CF(FOURIER_CF), .FOURIER_W(FOURIER_W),
    .FOURIER_G(FOURIER_G), .ZERO(ZERO)
  ) u_config ();
  acore_check #(.OK(RG_W == $clog2(REGIONS)), .VALUE(RG_W),
    .MSG("illegal parameter: RG_W is derived (clog2(REGIONS)), do not override"))
    RG_W_is_derived ();
  // (The same expressions as the defaults: only an override differs.)
  acore_check #(
    .OK(TERMS == ((CORRECTION == 2) ? 0 : (CORRECTION == 1) ?
                  ((DEGREE == 1) ? 3 : (DEGREE == 2) ? 6 : 10) : DEGREE + 1)),
    .VALUE(TERMS),
    .MSG("illegal parameter: TERMS is derived (coefficients per region and curve), do not override"))
    TERMS_is_derived ();
  acore_check #(
    .OK(WORDS == 4 + (TERMS << ($clog2(REGIONS) + 1)) + K + ((FOURIER_K > 0) ? (FOURIER_K << 1) + 1 : 0) +
              ((ZERO != 0) ? 1 : 0)),
    .VALUE(WORDS),
    .MSG("illegal parameter: WORDS is derived (4 + 2 REGIONS TERMS + K + Fourier words + ZERO word), do not override"))
    WORDS_is_derived ();
  acore_check #(.OK(ADDR_W == $clog2(WORDS)), .VALUE(ADDR_W),
    .MSG("illegal parameter: ADDR_W is derived (clog2(WORDS)), do not override"))
    ADDR_W_is_derived ();
  acore_check #(.OK(MAG_W == S_W + 2), .VALUE(MAG_W),
    .MSG("illegal parameter: MAG_W is derived (S_W+2), do not override"))
    MAG_W_is_derived ();

  // ---- handshake: one enable for the whole pipeline ----
  reg  [LATENCY-1:0] vld_q;
  wire stall = vld_q[LATENCY-1] & ~out_ready_i;
  wire en = ~stall;
  assign in_ready_o = en & ~rst_i;
  always @(posedge clk_i) begin
    if (rst_i) vld_q <= {LATENCY{1'b0}};
    else if (en) vld_q <= {vld_q[LATENCY-2:0], in_valid_i};
  end

  // ---- register file ----
  localparam integer BUS_W = top_cmul(WORDS, REG_W);
  localparam integer AT_BUS_W = top_cmul(K, REG_W);
  localparam integer OFF_RCP24 = top_cmul(3, REG_W);
  localparam integer OFF_ATAN = top_cmul(4 + NCOEF, REG_W);
  wire [BUS_W-1:0] words;
  acore_coef_regfile #(.REG_W(REG_W), .WORDS(WORDS), .INIT_FILE(INIT_FILE)) u_regs (
    .clk_i(clk_i), .rst_i(rst_i), .addr_i(reg_addr_i), .wdata_i(reg_wdata_i), .we_i(reg_we_i),
    .rdata_o(reg_rdata_o), .words_o(words));
  wire [REG_W-1:0] off13 = words[0 +: REG_W];
  wire [REG_W-1:0] off24 = words[REG_W +: REG_W];
  wire [REG_W-1:0] rcp13 = words[(REG_W << 1) +: REG_W];
  wire [REG_W-1:0] rcp24 = words[OFF_RCP24 +: REG_W];
  wire [AT_BUS_W-1:0] atan = words[OFF_ATAN +: AT_BUS_W];

  // ---- 1: pre-filter ----
  wire [D_W-1:0] d13, d24;
  acore_prefilter #(.IN_W(IN_W)) u_pre (
    .clk_i(clk_i), .en_i(en), .c1_i(c1_i), .c2_i(c2_i), .c3_i(c3_i), .c4_i(c4_i),
    .d13_o(d13), .d24_o(d24));

  // ---- 2: scaling ----
  wire [S_W-1:0] s13, s24;
  wire sc_ovf13, sc_ovf24;
  acore_scaler #(.D_W(D_W), .REG_W(REG_W), .S_W(S_W), .R_SHIFT(R_SHIFT), .SCALE_G(SCALE_G)) u_sc13 (
    .clk_i(clk_i), .en_i(en), .d_i(d13), .offset_i(off13), .recip_i(rcp13), .s_o(s13), .ovf_o(sc_ovf13));
  acore_scaler #(.D_W(D_W), .REG_W(REG_W), .S_W(S_W), .R_SHIFT(R_SHIFT), .SCALE_G(SCALE_G)) u_sc24 (
    .clk_i(clk_i), .en_i(en), .d_i(d24), .offset_i(off24), .recip_i(rcp24), .s_o(s24), .ovf_o(sc_ovf24));

  // ---- 3: domain selection ----
  wire [RG_W-1:0] region;
  wire [S_W-1:0] x, s13_r, s24_r;
  acore_region_select #(.S_W(S_W), .REGIONS(REGIONS)) u_rs (
    .clk_i(clk_i), .en_i(en), .s13_i(s13), .s24_i(s24),
    .region_o(region), .x_o(x), .s13_o(s13_r), .s24_o(s24_r));

  // ---- 4: correction (CORRECTION), coefficients from word 4 on ----
  wire [S_W-1:0] y13, y24;
  wire pc_ovf13, pc_ovf24;
  generate
    if (CORRECTION == 2) begin : g_none
      // No polynomial: x is not needed (named unused_* for lint).
      wire unused_x = ^x;
      assign y13 = s13_r;
      assign y24 = s24_r;
      assign pc_ovf13 = 1'b0;
      assign pc_ovf24 = 1'b0;
    end else begin : g_coef
      localparam integer COEF_BUS_W = top_cmul(NCOEF, REG_W);
      wire [COEF_BUS_W-1:0] coef = words[(REG_W << 2) +: COEF_BUS_W];
      if (CORRECTION == 1) begin : g_poly2d
        acore_poly2d_correct #(
          .REG_W(REG_W), .S_W(S_W), .S_F(S_F), .DEGREE(DEGREE), .REGIONS(REGIONS), .XCENTER(XCENTER),
          .COEF_F(COEF_F), .ACC_G(ACC_G), .ACC_I(ACC_I), .CURVE(0)
        ) u_pc13 (
          .clk_i(clk_i), .en_i(en), .x_i(x), .s13_i(s13_r), .s24_i(s24_r), .region_i(region),
          .coef_i(coef), .y_o(y13), .ovf_o(pc_ovf13));
        acore_poly2d_correct #(
          .REG_W(REG_W), .S_W(S_W), .S_F(S_F), .DEGREE(DEGREE), .REGIONS(REGIONS), .XCENTER(XCENTER),
          .COEF_F(COEF_F), .ACC_G(ACC_G), .ACC_I(ACC_I), .CURVE(1)
        ) u_pc24 (
          .clk_i(clk_i), .en_i(en), .x_i(x), .s13_i(s13_r), .s24_i(s24_r), .region_i(region),
          .coef_i(coef), .y_o(y24), .ovf_o(pc_ovf24));
      end else begin : g_poly
        acore_poly_correct #(
          .REG_W(REG_W), .S_W(S_W), .S_F(S_F), .DEGREE(DEGREE), .REGIONS(REGIONS), .COEF_F(COEF_F),
          .ACC_G(ACC_G), .ACC_I(ACC_I), .CURVE(0), .XCENTER(XCENTER)
        ) u_pc13 (
          .clk_i(clk_i), .en_i(en), .x_i(x), .s_i(s13_r), .region_i(region), .coef_i(coef),
          .y_o(y13), .ovf_o(pc_ovf13));
        acore_poly_correct #(
          .REG_W(REG_W), .S_W(S_W), .S_F(S_F), .DEGREE(DEGREE), .REGIONS(REGIONS), .COEF_F(COEF_F),
          .ACC_G(ACC_G), .ACC_I(ACC_I), .CURVE(1), .XCENTER(XCENTER)
        ) u_pc24 (
          .clk_i(clk_i), .en_i(en), .x_i(x), .s_i(s24_r), .region_i(region), .coef_i(coef),
          .y_o(y24), .ovf_o(pc_ovf24));
      end
    end
  endgenerate

  // ---- 5: CORDIC, x = corrected cosine curve, y = corrected sine curve ----
  wire [ANGLE_W-1:0] angle;
  wire [MAG_W-1:0] mag;
  acore_cordic #(
    .IN_W(S_W), .G(CORDIC_G), .Z_W(Z_W), .ANGLE_W(ANGLE_W), .K(K), .AT_W(REG_W), .NORM(0)
  ) u_cordic (
    .clk_i(clk_i), .en_i(en), .x_i(y24), .y_i(y13), .atan_i(atan), .angle_o(angle), .mag_o(mag));

  // ---- 6 (optional): Fourier correction of the angle ----
  wire [ANGLE_W-1:0] angle_c;
  wire [MAG_W-1:0] mag_c;
  generate
    if (FOURIER_K > 0) begin : g_fourier
      localparam integer OFF_FOURIER = top_cmul(4 + NCOEF + K, REG_W);
      localparam integer FOURIER_BUS_W = top_cmul(NFOURIER, REG_W);
      localparam integer FOURIER_AT_W = top_cmul(FOURIER_M, REG_W);
      acore_fourier_correct #(
        .ANGLE_W(ANGLE_W), .REG_W(REG_W), .Z_W(Z_W), .K(FOURIER_K), .M(FOURIER_M), .CF(FOURIER_CF),
        .W(FOURIER_W), .G(FOURIER_G), .AT_W(REG_W)
      ) u_fourier (
        .clk_i(clk_i), .en_i(en), .angle_i(angle), .coef_i(words[OFF_FOURIER +: FOURIER_BUS_W]),
        .atan_i(atan[FOURIER_AT_W-1:0]), .angle_o(angle_c));
      // The magnitude travels beside the correction.
      acore_delay #(.W(MAG_W), .DEPTH(FOURIER_LATENCY)) u_d_mag (
        .clk_i(clk_i), .en_i(en), .d_i(mag), .q_o(mag_c));
    end else begin : g_no_fourier
      assign angle_c = angle;
      assign mag_c = mag;
    end
  endgenerate

  // ---- sideband: scaler overflow, region and correction overflow, aligned to the angle ----
  wire sc_ovf_d, pc_ovf_d;
  wire [RG_W-1:0] region_d;
  acore_delay #(.W(1), .DEPTH(REGION_LATENCY + POLY_LATENCY + CORDIC_LATENCY + FOURIER_LATENCY)) u_d_scovf (
    .clk_i(clk_i), .en_i(en), .d_i(sc_ovf13 | sc_ovf24), .q_o(sc_ovf_d));
  acore_delay #(.W(RG_W), .DEPTH(POLY_LATENCY + CORDIC_LATENCY + FOURIER_LATENCY)) u_d_region (
    .clk_i(clk_i), .en_i(en), .d_i(region), .q_o(region_d));
  acore_delay #(.W(1), .DEPTH(CORDIC_LATENCY + FOURIER_LATENCY)) u_d_pcovf (
    .clk_i(clk_i), .en_i(en), .d_i(pc_ovf13 | pc_ovf24), .q_o(pc_ovf_d));

  // ---- zero position (ZERO): the last word's low ANGLE_W bits, else 0 ----
  wire [ANGLE_W-1:0] zero_pos;
  generate
    if (ZERO != 0) begin : g_zero
      localparam integer OFF_ZERO = top_cmul(WORDS - 1, REG_W);
      wire [REG_W-1:0] zero_word = words[OFF_ZERO +: REG_W];
      // The word's upper bits are not part of the zero position (named unused_* for lint).
      wire unused_zero_hi = ^{1'b0, zero_word[REG_W-1:ANGLE_W-1]};
      assign zero_pos = zero_word[ANGLE_W-1:0];
    end else begin : g_no_zero
      assign zero_pos = {ANGLE_W{1'b0}};
    end
  endgenerate

  // ---- output register: angle - zero position (modulo a turn), status window compare ----
  reg [ANGLE_W-1:0] angle_q;
  reg [RG_W-1:0] region_q;
  reg ovf_q, los_q, dos_q;
  always @(posedge clk_i) begin
    if (en) begin
      angle_q  <= angle_c - zero_pos;
      region_q <= region_d;
      ovf_q    <= sc_ovf_d | pc_ovf_d;
      los_q    <= mag_c < mag_lo_i;
      dos_q    <= mag_c > mag_hi_i;
    end
  end

  assign out_valid_o = vld_q[LATENCY-1];
  assign angle_o  = angle_q & {ANGLE_W{out_valid_o}};
  assign region_o = region_q & {RG_W{out_valid_o}};
  assign ovf_o    = ovf_q & out_valid_o;
  assign los_o    = los_q & out_valid_o;
  assign dos_o    = dos_q & out_valid_o;

endmodule

`resetall
