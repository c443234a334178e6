// SPDX-License-Identifier: MIT
// acore_top: the AngleCore estimator, one sample per clock (model/ip/engine/fixed_model.cpp, bit for bit), or
// with FOLD > 1 one sample every FOLD clocks on folded hardware (acore_fold_datapath.v).
//
//   c1..c4 -> prefilter -> scaler x2 -> region_select -> correction x2 -> cordic -> [fourier] -> [- zero] -> angle, flags
//                            ^ O, 1/A        (coef_regfile, 52 words)  ^ a_j        ^ atan_i    ^ a_k, b_k   ^ ZERO word
//
// The Fourier correction (acore_fourier_correct.v) is generated only when FOURIER_K > 0; with
// FOURIER_K = 0 (the default) the top is the chain without it, word for word and clock for clock.
// ZERO = 1 adds one register word after all others, the zero position z (its low ANGLE_W bits),
// and one subtractor in the output register: angle_o = (angle - z) mod 2^ANGLE_W, the angle in the
// reference frame of the calibration (docs/datapath.md "Zero offset"); no extra clock.
//
// The correction stage is chosen by CORRECTION, a mode of the table (rtl/acore_modes.vh, generated
// from model/ip/core/correction_modes.hpp): ACORE_CORR_POLY = acore_poly_correct (1-D in x, the
// paper's), ACORE_CORR_POLY2D = acore_poly2d_correct (2-D in x and the other curve),
// ACORE_CORR_NONE = no stage (the scaled curves go straight to the CORDIC, no coefficient words).
// LATENCY follows from the stages chosen.
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
// FOLD > 1: nothing stalls. in_ready_o (a register, low in reset) is high when FOLD clocks have
// passed since the last sample taken and fewer samples are in flight or waiting than the output
// FIFO holds (256, block RAM); a taken sample is computed and written into the FIFO, which feeds
// the output port (one sample a clock while out_ready_i is high). LATENCY is then the accepting
// edge to out_valid_o with the FIFO empty; CYCLES = FOLD clocks per sample at full rate.
//
// Only the valid flops are reset (rst_i synchronous, active high); data flops are not, and every
// output is forced to zero while out_valid_o is low, so no unknown ever leaves the core.
// Flags: ovf_o = saturation in any stage; los_o = magnitude < mag_lo_i (loss of signal);
// dos_o = magnitude > mag_hi_i (degradation / saturation of signal). The magnitude is the CORDIC's
// X_K >>> CORDIC_G, the corrected vector length (1.0 = 2^S_F) times the CORDIC gain (1.6468), and
// mag_o delivers it with the angle (same beat; 1 LSB = 2^-S_F / 1.6468 of the corrected, i.e.
// scaled, vector length: a field at the calibrated amplitude reads about 1.6468 * 2^S_F).
`resetall
`default_nettype none

module acore_top #(
  // The datapath parameters (IN_W .. MULT; generated from the model's field table, each with its
  // default and meaning). FOLD: 1 = one sample per clock (the pipeline below, with a stall
  // enable); above 1 (acore_fold_legal()) the folded datapath (acore_fold_datapath.v: the hardware reused FOLD
  // times per sample, an output FIFO and credits instead of the stall), the same contract and
  // register map at any FOLD. ZERO = 1: one more register word (the last) holding the zero
  // position, subtracted from the output angle. MULT = 1: every product on the hardware
  // multiplier (acore_hw_mul.v), the full product floored once; the same LATENCY and CYCLES.
`include "acore_datapath_params.vh"
  // $readmemh register image for the power-up contents ("" = none).
  parameter INIT_FILE = "",
  // Derived, do not override (rtl/acore_derived.vh).
  parameter integer RG_W = $clog2(REGIONS),
  // Coefficients per region and curve: the mode's (rtl/acore_modes.vh), 0 without a polynomial.
  parameter integer TERMS = acore_terms(CORRECTION, DEGREE),
  // 4 + 2 REGIONS TERMS + K, plus 2 FOURIER_K + 1 Fourier words when FOURIER_K > 0, plus the ZERO
  // word.
  parameter integer WORDS = acore_words(TERMS, REGIONS, K, FOURIER_K, ZERO),
  parameter integer ADDR_W = $clog2(WORDS),
  parameter integer MAG_W = acore_mag_w(S_W)
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
  output wire               dos_o,
  // Magnitude, unsigned, with the angle: the CORDIC's X_K >>> CORDIC_G (header; the LOS/DOS
  // window compares it), the corrected vector length (1.0 = 2^S_F) times the CORDIC gain.
  output wire [MAG_W-1:0]   mag_o
);

`include "acore_derived.vh"

  // Derived, do not override: the stages' latencies (rtl/acore_derived.vh, each module declares
  // its own from the same function) and the top's.
  localparam integer D_W = acore_d_w(IN_W);
  localparam integer REGION_LATENCY = acore_region_select_latency();
  localparam integer POLY_LATENCY = acore_correction_latency(CORRECTION, DEGREE, S_W);
  localparam integer CORDIC_LATENCY = acore_cordic_latency(K, 0, 0);
  localparam integer FOURIER_LATENCY = acore_fourier_latency(FOURIER_K, FOURIER_M);
  // The folded datapath is built only for a legal folded configuration; an illegal one (FOLD not
  // a value of acore_fold_legal(), or folded poly2d/Fourier) elaborates the pipeline, and acore_config_check stops it.
  localparam integer FOLDED = acore_folded(FOLD, CORRECTION, FOURIER_K);
  // Pipelined: the stages in a row; folded (acore_fold_datapath.v's schedule): the accepting edge
  // to out_valid_o with the output FIFO empty.
  localparam integer LATENCY = acore_top_latency(REG_W, S_W, CORRECTION, DEGREE, K, FOURIER_K,
                                                 FOURIER_M, FOLD, MULT);
  // Clocks per sample at full rate (Verilator public, read by the tests).
  localparam integer CYCLES = acore_top_cycles(FOLD);

  // Parameter rules: the model's DatapathConfig::validate() (acore_config_check.v), and the derived
  // parameters. An illegal configuration stops elaboration in Verilator, Icarus and Yosys.
  acore_config_check #(
`include "acore_datapath_pass.vh"
    .SERIAL(0)
  ) u_config ();
  // (The same functions as the defaults: only an override differs.)
  acore_check #(.OK(RG_W == $clog2(REGIONS)), .VALUE(RG_W),
    .MSG("illegal parameter: RG_W is derived (clog2(REGIONS)), do not override"))
    RG_W_is_derived ();
  acore_check #(.OK(TERMS == acore_terms(CORRECTION, DEGREE)), .VALUE(TERMS),
    .MSG("illegal parameter: TERMS is derived (coefficients per region and curve), do not override"))
    TERMS_is_derived ();
  acore_check #(.OK(WORDS == acore_words(acore_terms(CORRECTION, DEGREE), REGIONS, K, FOURIER_K, ZERO)),
    .VALUE(WORDS),
    .MSG("illegal parameter: WORDS is derived (4 + 2 REGIONS TERMS + K + Fourier words + ZERO word), do not override"))
    WORDS_is_derived ();
  acore_check #(.OK(ADDR_W == $clog2(WORDS)), .VALUE(ADDR_W),
    .MSG("illegal parameter: ADDR_W is derived (clog2(WORDS)), do not override"))
    ADDR_W_is_derived ();
  acore_check #(.OK(MAG_W == acore_mag_w(S_W)), .VALUE(MAG_W),
    .MSG("illegal parameter: MAG_W is derived (S_W+2), do not override"))
    MAG_W_is_derived ();

  // ---- datapath: one sample per clock (FOLD = 1) or folded (FOLD > 1, acore_fold_*.v); both end
  // in the output register below ----
  wire               out_en;  // the output register advances
  wire [ANGLE_W-1:0] angle_c;
  wire [MAG_W-1:0]   mag_c;
  wire               sc_ovf_d, pc_ovf_d;
  wire [RG_W-1:0]    region_d;
  // The output register's word and the word on the output pins: {mag, dos, los, ovf, region, angle}.
  localparam integer OUT_W = ANGLE_W + RG_W + 3 + MAG_W;
  wire [OUT_W-1:0]   out_word_q, out_word;
  // The ZERO word (ZERO = 1; else zero), from either datapath's register file.
  wire [REG_W-1:0]   zero_word;
  generate
    if (FOLDED == 0) begin : g_pipe
    // ---- handshake: one enable for the whole pipeline ----
    reg  [LATENCY-1:0] vld_q;
    wire stall = vld_q[LATENCY-1] & ~out_ready_i;
    wire en = ~stall;
    assign in_ready_o = en & ~rst_i;
    always @(posedge clk_i) begin
      if (rst_i) vld_q <= {LATENCY{1'b0}};
      else if (en) vld_q <= {vld_q[LATENCY-2:0], in_valid_i};
    end

    // ---- register file: the map's words on a flat bus, word a at bits [a REG_W +: REG_W] ----
    localparam integer AT_BUS_W = K * REG_W;
    wire [WORDS*REG_W-1:0] words;
    acore_coef_regfile #(.REG_W(REG_W), .WORDS(WORDS), .INIT_FILE(INIT_FILE)) u_regs (
      .clk_i(clk_i), .rst_i(rst_i), .addr_i(reg_addr_i), .wdata_i(reg_wdata_i), .we_i(reg_we_i),
      .rdata_o(reg_rdata_o), .words_o(words));
    wire [REG_W-1:0] off13 = words[acore_addr_offset(0) * REG_W +: REG_W];
    wire [REG_W-1:0] off24 = words[acore_addr_offset(1) * REG_W +: REG_W];
    wire [REG_W-1:0] rcp13 = words[acore_addr_recip(0) * REG_W +: REG_W];
    wire [REG_W-1:0] rcp24 = words[acore_addr_recip(1) * REG_W +: REG_W];
    wire [AT_BUS_W-1:0] atan = words[acore_addr_atan(TERMS, REGIONS, 0) * REG_W +: AT_BUS_W];
    if (ZERO != 0) begin : g_zero_word
      assign zero_word = words[acore_addr_zero(TERMS, REGIONS, K, FOURIER_K) * REG_W +: REG_W];
    end else begin : g_no_zero_word
      assign zero_word = {REG_W{1'b0}};
    end

    // ---- 1: pre-filter ----
    wire [D_W-1:0] d13, d24;
    acore_prefilter #(.IN_W(IN_W)) u_pre (
      .clk_i(clk_i), .en_i(en), .c1_i(c1_i), .c2_i(c2_i), .c3_i(c3_i), .c4_i(c4_i),
      .d13_o(d13), .d24_o(d24));

    // ---- 2: scaling ----
    wire [S_W-1:0] s13, s24;
    wire sc_ovf13, sc_ovf24;
    acore_scaler #(.D_W(D_W), .REG_W(REG_W), .S_W(S_W), .R_SHIFT(R_SHIFT), .SCALE_G(SCALE_G), .MULT(MULT)) u_sc13 (
      .clk_i(clk_i), .en_i(en), .d_i(d13), .offset_i(off13), .recip_i(rcp13), .s_o(s13), .ovf_o(sc_ovf13));
    acore_scaler #(.D_W(D_W), .REG_W(REG_W), .S_W(S_W), .R_SHIFT(R_SHIFT), .SCALE_G(SCALE_G), .MULT(MULT)) u_sc24 (
      .clk_i(clk_i), .en_i(en), .d_i(d24), .offset_i(off24), .recip_i(rcp24), .s_o(s24), .ovf_o(sc_ovf24));

    // ---- 3: domain selection ----
    wire [RG_W-1:0] region;
    wire [S_W-1:0] x, s13_r, s24_r;
    acore_region_select #(.S_W(S_W), .REGIONS(REGIONS)) u_rs (
      .clk_i(clk_i), .en_i(en), .s13_i(s13), .s24_i(s24),
      .region_o(region), .x_o(x), .s13_o(s13_r), .s24_o(s24_r));

    // ---- 4: correction (CORRECTION), the polynomial words ----
    wire [S_W-1:0] y13, y24;
    wire pc_ovf13, pc_ovf24;
    if (CORRECTION != ACORE_CORR_POLY && CORRECTION != ACORE_CORR_POLY2D) begin : g_none
      // No polynomial (ACORE_CORR_NONE; a CORRECTION no mode has is built alike, TERMS = 0, and
      // acore_config_check stops it): x is not needed (named unused_* for lint).
      wire unused_x = ^x;
      assign y13 = s13_r;
      assign y24 = s24_r;
      assign pc_ovf13 = 1'b0;
      assign pc_ovf24 = 1'b0;
    end else begin : g_coef
      localparam integer COEF_BUS_W = acore_poly_words(TERMS, REGIONS) * REG_W;
      wire [COEF_BUS_W-1:0] coef = words[acore_addr_poly(TERMS, 0, 0, 0) * REG_W +: COEF_BUS_W];
      if (CORRECTION == ACORE_CORR_POLY2D) begin : g_poly2d
        acore_poly2d_correct #(
          .REG_W(REG_W), .S_W(S_W), .S_F(S_F), .DEGREE(DEGREE), .REGIONS(REGIONS), .XCENTER(XCENTER),
          .COEF_F(COEF_F), .ACC_G(ACC_G), .ACC_I(ACC_I), .CURVE(0), .MULT(MULT)
        ) u_pc13 (
          .clk_i(clk_i), .en_i(en), .x_i(x), .s13_i(s13_r), .s24_i(s24_r), .region_i(region),
          .coef_i(coef), .y_o(y13), .ovf_o(pc_ovf13));
        acore_poly2d_correct #(
          .REG_W(REG_W), .S_W(S_W), .S_F(S_F), .DEGREE(DEGREE), .REGIONS(REGIONS), .XCENTER(XCENTER),
          .COEF_F(COEF_F), .ACC_G(ACC_G), .ACC_I(ACC_I), .CURVE(1), .MULT(MULT)
        ) u_pc24 (
          .clk_i(clk_i), .en_i(en), .x_i(x), .s13_i(s13_r), .s24_i(s24_r), .region_i(region),
          .coef_i(coef), .y_o(y24), .ovf_o(pc_ovf24));
      end else begin : g_poly
        acore_poly_correct #(
          .REG_W(REG_W), .S_W(S_W), .S_F(S_F), .DEGREE(DEGREE), .REGIONS(REGIONS), .COEF_F(COEF_F),
          .ACC_G(ACC_G), .ACC_I(ACC_I), .CURVE(0), .XCENTER(XCENTER), .MULT(MULT)
        ) u_pc13 (
          .clk_i(clk_i), .en_i(en), .x_i(x), .s_i(s13_r), .region_i(region), .coef_i(coef),
          .y_o(y13), .ovf_o(pc_ovf13));
        acore_poly_correct #(
          .REG_W(REG_W), .S_W(S_W), .S_F(S_F), .DEGREE(DEGREE), .REGIONS(REGIONS), .COEF_F(COEF_F),
          .ACC_G(ACC_G), .ACC_I(ACC_I), .CURVE(1), .XCENTER(XCENTER), .MULT(MULT)
        ) u_pc24 (
          .clk_i(clk_i), .en_i(en), .x_i(x), .s_i(s24_r), .region_i(region), .coef_i(coef),
          .y_o(y24), .ovf_o(pc_ovf24));
      end
    end

    // ---- 5: CORDIC, x = corrected cosine curve, y = corrected sine curve ----
    wire [ANGLE_W-1:0] angle;
    wire [MAG_W-1:0] mag;
    acore_cordic #(
      .IN_W(S_W), .G(CORDIC_G), .Z_W(Z_W), .ANGLE_W(ANGLE_W), .K(K), .AT_W(REG_W), .NORM(0)
    ) u_cordic (
      .clk_i(clk_i), .en_i(en), .x_i(y24), .y_i(y13), .atan_i(atan), .angle_o(angle), .mag_o(mag));

    // ---- 6 (optional): Fourier correction of the angle ----
    if (FOURIER_K > 0) begin : g_fourier
      localparam integer OFF_FOURIER = acore_addr_fourier(TERMS, REGIONS, K, 0) * REG_W;
      localparam integer FOURIER_BUS_W = acore_fourier_words(FOURIER_K) * REG_W;
      localparam integer FOURIER_AT_W = FOURIER_M * REG_W;
      acore_fourier_correct #(
        .ANGLE_W(ANGLE_W), .REG_W(REG_W), .Z_W(Z_W), .K(FOURIER_K), .M(FOURIER_M), .CF(FOURIER_CF),
        .W(FOURIER_W), .G(FOURIER_G), .AT_W(REG_W), .MULT(MULT)
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

    // ---- sideband: scaler overflow, region and correction overflow, aligned to the angle ----
    acore_delay #(.W(1), .DEPTH(REGION_LATENCY + POLY_LATENCY + CORDIC_LATENCY + FOURIER_LATENCY)) u_d_scovf (
      .clk_i(clk_i), .en_i(en), .d_i(sc_ovf13 | sc_ovf24), .q_o(sc_ovf_d));
    acore_delay #(.W(RG_W), .DEPTH(POLY_LATENCY + CORDIC_LATENCY + FOURIER_LATENCY)) u_d_region (
      .clk_i(clk_i), .en_i(en), .d_i(region), .q_o(region_d));
    acore_delay #(.W(1), .DEPTH(CORDIC_LATENCY + FOURIER_LATENCY)) u_d_pcovf (
      .clk_i(clk_i), .en_i(en), .d_i(pc_ovf13 | pc_ovf24), .q_o(pc_ovf_d));
      assign out_en = en;
      assign out_valid_o = vld_q[LATENCY-1];
      assign out_word = out_word_q;
    end else begin : g_fold
      // ---- handshake: a sample at least FOLD clocks after the previous one, while the output
      // FIFO can take every sample in flight (credits); the datapath itself never stalls ----
      localparam integer FIFO_DEPTH = acore_fold_fifo_depth();
      localparam integer OCC_W = $clog2(FIFO_DEPTH) + 1;
      localparam integer CNT_W = $clog2(FOLD);
      localparam integer CNT_FULL_I = FOLD - 1;
      localparam [CNT_W-1:0] CNT_FULL = CNT_FULL_I[CNT_W-1:0];
      localparam [OCC_W-1:0] OCC_MAX = FIFO_DEPTH[OCC_W-1:0];
      reg [CNT_W-1:0] cnt_q;  // clocks since the last accepted sample, up to FOLD - 1
      reg [OCC_W-1:0] occ_q;  // samples accepted and not yet delivered
      reg             rdy_q;
      wire accept = in_valid_i & rdy_q;  // (rst_i resets the datapath's valid bits anyway)
      wire deliver = out_valid_o & out_ready_i;
      wire [CNT_W-1:0] cnt_d = accept ? {CNT_W{1'b0}} : (cnt_q == CNT_FULL) ? cnt_q : cnt_q + 1'b1;
      wire [OCC_W-1:0] occ_d = occ_q + {{(OCC_W-1){1'b0}}, accept} - {{(OCC_W-1){1'b0}}, deliver};
      always @(posedge clk_i) begin
        if (rst_i) begin
          cnt_q <= CNT_FULL;
          occ_q <= {OCC_W{1'b0}};
          rdy_q <= 1'b0;
        end else begin
          cnt_q <= cnt_d;
          occ_q <= occ_d;
          rdy_q <= (cnt_d == CNT_FULL) && (occ_d < OCC_MAX);
        end
      end
      // Registered (no path from out_ready_i), and low while rst_i is high.
      assign in_ready_o = rdy_q & ~rst_i;

      // ---- the folded estimator, with its register file (the same map, host port and timing; the
      // words in block RAM) ----
      wire dp_valid, dp_ovf;
      acore_fold_datapath #(
        .IN_W(IN_W), .REG_W(REG_W), .S_W(S_W), .S_F(S_F), .R_SHIFT(R_SHIFT), .SCALE_G(SCALE_G),
        .CORRECTION(CORRECTION), .DEGREE(DEGREE), .REGIONS(REGIONS), .XCENTER(XCENTER), .COEF_F(COEF_F),
        .ACC_G(ACC_G), .ACC_I(ACC_I), .K(K), .CORDIC_G(CORDIC_G), .Z_W(Z_W), .ANGLE_W(ANGLE_W),
        .ZERO(ZERO), .FOLD(FOLD), .MULT(MULT), .WORDS(WORDS), .INIT_FILE(INIT_FILE)
      ) u_dp (
        .clk_i(clk_i), .rst_i(rst_i), .reg_addr_i(reg_addr_i), .reg_wdata_i(reg_wdata_i),
        .reg_we_i(reg_we_i), .reg_rdata_o(reg_rdata_o), .accept_i(accept), .c1_i(c1_i), .c2_i(c2_i),
        .c3_i(c3_i), .c4_i(c4_i), .valid_o(dp_valid), .angle_o(angle_c), .mag_o(mag_c),
        .region_o(region_d), .ovf_o(dp_ovf), .last_o(zero_word));
      assign sc_ovf_d = dp_ovf;
      assign pc_ovf_d = 1'b0;
      // The output register advances every clock; the FIFO takes its sample one clock later.
      assign out_en = 1'b1;
      reg out_vld_q;
      always @(posedge clk_i) begin
        if (rst_i) out_vld_q <= 1'b0;
        else out_vld_q <= dp_valid;
      end
      // The FIFO's word: the output register's, but where the datapath's outputs hold past valid_o
      // (acore_fold_out_held) the fields the register only copies are taken from the datapath
      // itself, the clock after valid_o: the same word, without their flops (the limits' compares
      // and the ZERO subtraction stay registered, so their inputs are read at the same clock).
      wire [OUT_W-1:0] fifo_word;
      if (acore_fold_out_held(K, FOLD) != 0) begin : g_held
        wire [ANGLE_W-1:0] angle_f = (ZERO != 0) ? out_word_q[ANGLE_W-1:0] : angle_c;
        assign fifo_word = {mag_c, out_word_q[ANGLE_W + RG_W + 1 +: 2], dp_ovf, region_d, angle_f};
        // (The register's copies, left to synthesis to remove.)
        wire unused_copies = ^{out_word_q[ANGLE_W + RG_W + 3 +: MAG_W], out_word_q[ANGLE_W +: RG_W + 1],
                               out_word_q[ANGLE_W-1:0]};
      end else begin : g_reg
        assign fifo_word = out_word_q;
      end
      acore_fold_fifo #(.W(OUT_W), .DEPTH(FIFO_DEPTH)) u_fifo (
        .clk_i(clk_i), .rst_i(rst_i), .wr_i(out_vld_q), .wdata_i(fifo_word), .valid_o(out_valid_o),
        .ready_i(out_ready_i), .data_o(out_word));
    end
  endgenerate

  // ---- zero position (ZERO): the ZERO word's low ANGLE_W bits, else 0 ----
  wire [ANGLE_W-1:0] zero_pos;
  generate
    if (ZERO != 0) begin : g_zero
      // The word's upper bits are not part of the zero position (named unused_* for lint).
      wire unused_zero_hi = ^{1'b0, zero_word[REG_W-1:ANGLE_W-1]};
      assign zero_pos = zero_word[ANGLE_W-1:0];
    end else begin : g_no_zero
      wire unused_zero = ^zero_word;
      assign zero_pos = {ANGLE_W{1'b0}};
    end
  endgenerate

  // ---- output register: angle - zero position (modulo a turn), status window compare ----
  reg [ANGLE_W-1:0] angle_q;
  reg [RG_W-1:0] region_q;
  reg ovf_q, los_q, dos_q;
  reg [MAG_W-1:0] mag_q;
  always @(posedge clk_i) begin
    if (out_en) begin
      angle_q  <= angle_c - zero_pos;
      mag_q    <= mag_c;
      region_q <= region_d;
      ovf_q    <= sc_ovf_d | pc_ovf_d;
      los_q    <= mag_c < mag_lo_i;
      dos_q    <= mag_c > mag_hi_i;
    end
  end

  assign out_word_q = {mag_q, dos_q, los_q, ovf_q, region_q, angle_q};
  assign angle_o  = out_word[ANGLE_W-1:0] & {ANGLE_W{out_valid_o}};
  assign region_o = out_word[ANGLE_W +: RG_W] & {RG_W{out_valid_o}};
  assign ovf_o    = out_word[ANGLE_W + RG_W] & out_valid_o;
  assign los_o    = out_word[ANGLE_W + RG_W + 1] & out_valid_o;
  assign dos_o    = out_word[ANGLE_W + RG_W + 2] & out_valid_o;
  assign mag_o    = out_word[ANGLE_W + RG_W + 3 +: MAG_W] & {MAG_W{out_valid_o}};

endmodule

`resetall
