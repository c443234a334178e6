// SPDX-License-Identifier: MIT
// acore_board: what a motor-drive board uses. The estimator in its APB register shell
// (rtl/acore_apb.v: the datapath, folded or serial, and its coefficient bank) feeding the tracking
// observer, whose compensated angle drives the interfaces; the interfaces' and the observer's
// registers are the board's own register block on the same APB bus:
//
//   c1..c4 --> acore_apb --angle--> acore_track --compensated angle--+--> acore_abz   A, B, Z
//                 ^ APB    |            |  velocity, turns, angle     +--> acore_uvw   U, V, W
//                 |        |            +--> TRK_VELOCITY, TRK_POSITION (APB)
//                 |        +--angle (ANGLEUNC)--+--> acore_spi_as5047 SCLK, CSn, MOSI -> MISO
//                 |        compensated (ANGLECOM), loss of tracking --+
//   APB --+--> the board's registers (0x060..0x097, rtl/acore_board_regblock.v): ABZ_N .. MAG_AGC
//         +--> every other address: the shell
//
// THE REGISTERS. The board's registers are generated, with their widths, ranges and reset values,
// from one description (rtl/acore_board_regs.txt, docs/register-board.md); the interfaces and the
// observer take their widths from it (N_W, SP_W, PP_W, LEAD_W, LEAD_F, TURN_W). The board decodes
// its own addresses and hands every other one to the shell, which knows nothing of the board: the
// two blocks answer on one bus with the same timing (decode in the setup phase, zero wait states)
// and the same error rules, as one slave would.
//
// The observer (rtl/acore_track.v) takes every sample of the estimator (its in_ready is the
// estimator's out_ready; it is high whenever the estimator can deliver, so the estimator never
// stalls: the time-shared observer is chosen only when its schedule fits in a sample's clocks) and
// its outputs are always taken. The estimator's angle is also on pins (angle_o,
// out_valid_o) for a logic analyser or a second consumer, the observer's on trk_*_o.
//
// WHICH ANGLE FEEDS THE DRIVE. ABZ and UVW take the compensated angle: the tracked angle
// extrapolated by its velocity over the estimator's latency (COMP_LATENCY whole samples) plus the
// LEAD register, the angle at the output instant rather than at the sample instant. A drive
// commutates and counts on the angle now, and the uncompensated angle lags it by LATENCY clocks
// (at 60 krpm one sample of the serial core at 50 MHz, 221 kS/s, is 1.6 degrees of mechanical
// angle, times the pole pairs electrically); the AS5047P feeds its ABI and UVW from the DAEC-compensated angle for the
// same reason. The compensated angle is the observer's filtered angle, so ABZ also sees less noise
// than the raw estimate (its hysteresis, ABZ_HYS, handles the rest).
//
// SPI (AS5047P registers): ANGLECOM = the compensated angle, ANGLEUNC = the estimator's angle,
// both with the zero (IF_ZERO) taken away and negated with IF_CTRL.DIR, as ABZ and UVW take it;
// the AS5047P's settings a driver writes (ZPOSM/ZPOSL, SETTINGS1/2) are the board's IF_ZERO,
// IF_CTRL, ABZ_N, UVW_PP and ABZ_HYS (rtl/acore_spi_as5047.v has the mapping);
// DIAAGC.LF = not loss of tracking (the AS5047P's LF: 1 when the angle is valid, its loop
// settled; here 0 while the observer's error of the last sample exceeds TRK_LOT), MAGL/MAGH/COF =
// the estimator's los/dos/ovf.
//
// MAG AND AGC (the AS5047P's CORDIC magnitude and automatic gain control, what a driver reads to
// check the magnet's placement). The estimator delivers its CORDIC magnitude m with each angle
// (rtl/acore_top.v's mag_o: MAG_W = S_W + 2 bits, the corrected vector length times the CORDIC
// gain 1.6468, 2^S_F per unit of the scaled inputs; below 2^(MAG_W-1) for any input, as the
// scaled curves saturate at 2^(S_W-1)). The scaler normalises the channels with the calibrated
// amplitude, so m near its nominal 1.6468 * 2^S_F is a healthy magnet and the field's strength
// relative to the calibration is m over the nominal.
//   MAG = m >> (MAG_W - 15): its upper 14 bits below the always-clear top bit (saturated at
//         0x3FFF should it ever be set). 1 LSB = 2^(MAG_W-15-S_F) / 1.6468 of the scaled vector
//         length (S_W = 18, S_F = 16: 2^-11 / 1.6468); the nominal reads 1.6468 * 2^(S_F+15-MAG_W)
//         (3373 at the defaults), half the field half of it.
//   AGC = 128 + 32 (S_F + 20/32 - lg m), clamped to 0..255, where lg m = e + f/32 is the base-2
//         logarithm of m by its leading one e and the 5 bits f below it (exact at powers of two,
//         linear between: at most 0.09 below log2 m, and f is truncated). The datasheet's sense:
//         the gain an AGC would set, high for a weak field and low for a strong one. 128 at
//         m = 1.625 * 2^S_F (20/32 is the CORDIC gain's mantissa 0.6468 to five bits: the nominal
//         field reads 128), 32 codes per factor of two of the field (half the field: +32), 255
//         for no field (m = 0) or one below about 1/16 of the nominal; 0 would be 16 times above
//         it, beyond the scaled curves' range (at the defaults AGC stays above 52).
// Both are taken with each estimator output (MAG with the angle; AGC from it one clock later, or,
// where a sample's clocks leave room (CYCLES > MAG_W), from a normaliser shifting one bit a clock:
// MAG_W - e clocks later, at most MAG_W (sooner for an m with AGC 255 whatever its low bits), the last
// sample's AGC until then), read over SPI (MAG, DIAAGC.AGC) and APB (the board's MAG_AGC register); the model is
// model/ip/stages/interfaces.cpp's as5047::mag_field and as5047::agc_field.
`resetall
`default_nettype none

module acore_board #(
  // The estimator (rtl/acore_apb.v): its top (0 acore_top, 1 the serial core) and the datapath
  // parameters (IN_W .. FOLD, generated from the model's field table; ANGLE_W is also the
  // interfaces' width), its power-up register image.
  parameter integer SERIAL = 0,
`include "acore_datapath_params.vh"
  parameter INIT_FILE = "",
  parameter integer RG_W = $clog2(REGIONS),
  // The observer's fraction bits below the angle (rtl/acore_track.v's FRAC_W): its velocity word
  // has ANGLE_W + TRK_FRAC_W bits, of which TRK_VELOCITY reads the upper 32.
  parameter integer TRK_FRAC_W = 25
) (
  input  wire               clk_i,
  input  wire               rst_i,
  // APB4 slave (the shell's map, docs/register-shell.md, and the board's, docs/register-board.md).
  input  wire               psel_i,
  input  wire               penable_i,
  input  wire               pwrite_i,
  input  wire [11:0]        paddr_i,
  input  wire [31:0]        pwdata_i,
  input  wire [3:0]         pstrb_i,
  output wire [31:0]        prdata_o,
  output wire               pready_o,
  output wire               pslverr_o,
  output wire               irq_o,
  // The sensor's channel codes.
  input  wire               in_valid_i,
  output wire               in_ready_o,
  input  wire [IN_W-1:0]    c1_i,
  input  wire [IN_W-1:0]    c2_i,
  input  wire [IN_W-1:0]    c3_i,
  input  wire [IN_W-1:0]    c4_i,
  // The angle stream, observed.
  output wire               out_valid_o,
  output wire [ANGLE_W-1:0] angle_o,
  output wire               los_o,
  output wire               dos_o,
  // The observer's stream, observed (rtl/acore_track.v's outputs: tracked and compensated angle,
  // velocity in 2^-(ANGLE_W+TRK_FRAC_W) turns a sample, signed turn count, loss of tracking).
  output wire               trk_valid_o,
  output wire [ANGLE_W-1:0] trk_angle_o,
  output wire [ANGLE_W-1:0] trk_angle_comp_o,
  output wire [ANGLE_W+TRK_FRAC_W-1:0] trk_velocity_o,
  output wire [15:0]        trk_turns_o,
  output wire               trk_lot_o,
  // ABZ, UVW, SPI.
  output wire               a_o,
  output wire               b_o,
  output wire               z_o,
  output wire               u_o,
  output wire               v_o,
  output wire               w_o,
  input  wire               sclk_i,
  input  wire               csn_i,
  input  wire               mosi_i,
  output wire               miso_o,
  output wire               miso_oe_o
);

`include "acore_derived.vh"

  // The estimator's timing (the shell's): clocks from a sample taken to its angle on angle_o, and
  // clocks per sample at full rate (the interfaces take one sample a clock).
  localparam integer LATENCY = (SERIAL != 0) ? acore_serial_latency(REG_W, S_W, DEGREE, K, ZERO, MULT) :
      acore_top_latency(REG_W, S_W, CORRECTION, DEGREE, K, FOURIER_K, FOURIER_M, FOLD, MULT);
  localparam integer CYCLES = (SERIAL != 0) ? acore_serial_cycles(REG_W, S_W, DEGREE, K, ZERO, MULT) :
      acore_top_cycles(FOLD);

  // ---- the board's registers (generated from rtl/acore_board_regs.txt: field positions and
  // widths <REG>_<FIELD>[_W], ranges, a wire rg_<reg>_<field> per port of the register block and its
  // instance u_regs); what they read: the APB width, the loss-of-tracking threshold's width (the
  // largest error is half a turn) and the bandwidth codes the observer takes (rtl/acore_derived.vh,
  // the same as rtl/acore_track.v's K_MIN..K_MAX) ----
  localparam integer APB_AW = 12;
  localparam integer TRK_LOT_W = ANGLE_W - 1;
  localparam integer TRK_BW_MIN = acore_track_k_min();
  localparam integer TRK_BW_MAX = acore_track_k_max(TRK_FRAC_W);
`include "acore_board_regs.vh"

  // The observer: its turn count and LEAD as wide as their fields (TRK_POSITION.TURNS, TRK_LEAD);
  // the loop over two clocks when the estimator delivers a sample every CYCLES >= 2 clocks (a
  // shorter clock period, nothing lost), time-shared on one adder when it delivers one every
  // acore_track_serial_cycles() clocks or fewer often (the serial core: a quarter of the area),
  // else time-shared with coarse shifts when one every acore_track_shift_cycles() clocks with the
  // error shifted at most 8 bits a clock (the fewest that fit: FOLD 32, about the time-shared
  // form's area), else word-serial when one every acore_track_word_cycles() clocks with at most 4
  // bits of D a clock (the fewest that fit: FOLD 16, about half the area of the loop a clock), and
  // the estimator's LATENCY in whole samples compensated.
  localparam integer TRK_TURN_W = TRK_POSITION_TURNS_W;
  localparam integer TRK_LOOP_CLOCKS = (CYCLES >= 2) ? 2 : 1;
  localparam integer COMP_LATENCY = acore_comp_latency(LATENCY, CYCLES);
  localparam integer TRK_PROD_BITS =
      acore_track_word_prod_bits(CYCLES, COMP_LATENCY, TRK_LEAD_LEAD_W, TRK_LEAD_LEAD_F);
  localparam integer TRK_SHIFT_BITS =
      acore_track_shift_bits(CYCLES, TRK_FRAC_W, COMP_LATENCY, TRK_LEAD_LEAD_W, TRK_LEAD_LEAD_F);
  localparam integer TRK_SERIAL =
      (CYCLES >= acore_track_serial_cycles(ANGLE_W, TRK_FRAC_W, TRK_LEAD_LEAD_W)) ? 1 :
      (TRK_SHIFT_BITS != 0) ? 3 : (TRK_PROD_BITS != 0) ? 2 : 0;
  localparam integer TRK_P_W = ANGLE_W + TRK_FRAC_W;
  // MAG and AGC (the header): the magnitude's width, the SPI fields' widths and AGC's constants
  // (the middle code, codes per factor of two, and 20/32 = the CORDIC gain's mantissa 0.6468).
  localparam integer MAG_W = acore_mag_w(S_W);
  localparam integer MAG_F_W = MAG_AGC_MAG_W;
  localparam integer AGC_W = MAG_AGC_AGC_W;
  localparam integer AGC_MID = 128;
  localparam integer AGC_OCTAVE = 32;
  localparam integer AGC_GAIN_F = 20;

  acore_check #(.OK(ANGLE_W >= TRK_POSITION_ANGLE_W), .VALUE(ANGLE_W),
    .MSG("illegal parameter: ANGLE_W must be >= 16 (TRK_POSITION reads its upper 16 bits)"))
    ANGLE_W_must_be_at_least_16 ();
  acore_check #(.OK(ANGLE_W + TRK_FRAC_W >= TRK_VELOCITY_VELOCITY_W), .VALUE(ANGLE_W + TRK_FRAC_W),
    .MSG("illegal parameter: ANGLE_W+TRK_FRAC_W must be >= 32 (TRK_VELOCITY reads 32 bits)"))
    ANGLE_W_plus_TRK_FRAC_W_must_be_at_least_32 ();
  acore_check #(.OK(MAG_W >= MAG_F_W + 1), .VALUE(S_W),
    .MSG("illegal parameter: S_W must be >= 13 (MAG reads the magnitude's upper 14 bits)"))
    S_W_must_be_at_least_13 ();
  // The description's ranges are what the interfaces take (acore_abz.v and acore_uvw.v clamp N and
  // the pole pairs to 1 .. 2^(W-1) of their input's width W): a write the board accepts reaches
  // them unchanged.
  acore_check #(.OK(ABZ_N_N_MIN == 1 && ABZ_N_N_MAX == (1 << (ABZ_N_N_W - 1))), .VALUE(ABZ_N_N_MAX),
    .MSG("illegal description: ABZ_N.N's range must be 1..2^(its bits - 1), acore_abz's N"))
    ABZ_N_range_must_match_acore_abz ();
  acore_check #(.OK(UVW_PP_POLE_PAIRS_MIN == 1 && UVW_PP_POLE_PAIRS_MAX == (1 << (UVW_PP_POLE_PAIRS_W - 1))),
    .VALUE(UVW_PP_POLE_PAIRS_MAX),
    .MSG("illegal description: UVW_PP.POLE_PAIRS's range must be 1..2^(its bits - 1), acore_uvw's"))
    UVW_PP_range_must_match_acore_uvw ();

  // ---- the APB split: the board's addresses to its registers, every other one to the shell ----
  // (Each block's PRDATA and PSLVERR are zero unless it answers the transfer; PREADY is always high.)
  wire brd_sel = (paddr_i[APB_AW-1:8] == {(APB_AW-8){1'b0}}) & REGS_ALL[paddr_i[7:2]];
  wire [31:0] sh_prdata;
  wire sh_pslverr;
  assign rg_psel = psel_i & brd_sel;
  assign prdata_o = sh_prdata | rg_prdata;
  assign pslverr_o = sh_pslverr | rg_pslverr;

  // ---- the estimator and its register shell ----
  wire est_valid, est_ovf, est_los, est_dos, est_tag;
  wire [ANGLE_W-1:0] est_angle;
  wire [MAG_W-1:0] est_mag;
  wire [RG_W-1:0] est_region;
  wire trk_ready;
  acore_apb #(
`include "acore_datapath_pass.vh"
    .SERIAL(SERIAL), .INIT_FILE(INIT_FILE)
  ) u_shell (
    .clk_i(clk_i), .rst_i(rst_i), .psel_i(psel_i & ~brd_sel), .penable_i(penable_i),
    .pwrite_i(pwrite_i), .paddr_i(paddr_i), .pwdata_i(pwdata_i), .pstrb_i(pstrb_i),
    .prdata_o(sh_prdata), .pready_o(pready_o), .pslverr_o(sh_pslverr), .irq_o(irq_o),
    .in_valid_i(in_valid_i), .in_ready_o(in_ready_o), .c1_i(c1_i), .c2_i(c2_i), .c3_i(c3_i), .c4_i(c4_i),
    .out_valid_o(est_valid), .out_ready_i(trk_ready), .angle_o(est_angle), .region_o(est_region),
    .ovf_o(est_ovf), .los_o(est_los), .dos_o(est_dos), .out_tag_o(est_tag), .mag_o(est_mag));
  wire est_take = est_valid & trk_ready;
  assign out_valid_o = est_valid;
  assign angle_o = est_angle;
  assign los_o = est_los;
  assign dos_o = est_dos;

  // The flags last delivered (DIAAGC reads them between samples).
  reg los_q, dos_q, ovf_q;
  always @(posedge clk_i) begin
    if (rst_i) begin
      los_q <= 1'b0;
      dos_q <= 1'b0;
      ovf_q <= 1'b0;
    end else if (est_take) begin
      los_q <= est_los;
      dos_q <= est_dos;
      ovf_q <= est_ovf;
    end
  end
  // The uncompensated angle last delivered (ANGLEUNC), held complemented: the interfaces' adders
  // below take ~x (the flop's cell inverts for free: its LUT would pass the bit through otherwise).
  reg [ANGLE_W-1:0] unc_n_q;
  always @(posedge clk_i) if (est_take) unc_n_q <= ~est_angle;

  // ---- MAG and AGC (the header): the magnitude last delivered, its upper bits and its logarithm ----
  // MAG is taken with the sample. lg m = e + f/32 needs the leading one e of m and the 5 bits f
  // below it: when a sample's clocks leave room (MAG_NORM_SEQ: CYCLES > MAG_W), a normaliser
  // shifts m left one bit a clock until its top bit is set, counting e down from the top (at most
  // MAG_W - 1 clocks after the take), and AGC is taken from e and f when it stops (until then
  // AGC holds the last sample's); else a priority encoder and a shifter find them in one clock
  // (AGC the clock after the take).
  localparam integer MAG_E_W = $clog2(MAG_W);
  localparam integer MAG_TOP_I = MAG_W - 1;
  localparam [MAG_E_W-1:0] MAG_TOP = MAG_TOP_I[MAG_E_W-1:0];
  localparam integer MAG_NORM_SEQ = (CYCLES > MAG_W) ? 1 : 0;
  localparam integer AGC_D_W = MAG_E_W + 5 + 3;  // signed, holds AGC_REF - lg m
  localparam integer AGC_REF = AGC_MID + AGC_OCTAVE * S_F + AGC_GAIN_F;
  // The normaliser's lowest bit: AGC is 255 whatever f for a leading one at AGC_E_SAT or below
  // (AGC_REF - 32 e - 31 > 255), so only the bits f can take above it matter (from AGC_E_SAT - 4
  // up) and the count stops there (m below it: AGC 255, as it would be lower down).
  localparam integer AGC_E_SAT = (AGC_REF - 31 - (1 << AGC_W)) / AGC_OCTAVE;
  localparam integer MAG_LOW_I = (AGC_REF - 31 - (1 << AGC_W) < 0 || AGC_E_SAT < 4) ? 0 :
      (AGC_E_SAT - 4 > MAG_W - 6) ? MAG_W - 6 : AGC_E_SAT - 4;
  localparam [MAG_E_W-1:0] MAG_LOW = MAG_LOW_I[MAG_E_W-1:0];
  localparam integer NORM_W = MAG_W - MAG_LOW_I;
  wire [MAG_F_W-1:0] mag_field;
  wire [MAG_E_W-1:0] mag_e;  // lg m in 1/32: the leading one's position e (0 for m = 0 too)
  wire [4:0] mag_f;          // and the 5 bits below it
  wire mag_lg_ok;            // e and f are the last sample's
  generate
    if (MAG_NORM_SEQ != 0) begin : g_mag_seq
      // (norm_q: m's bits MAG_W-1 .. MAG_LOW, e counting down to MAG_LOW)
      reg [MAG_F_W-1:0] field_q;
      reg [NORM_W-1:0] norm_q;
      reg [MAG_E_W-1:0] e_q;
      wire stop = norm_q[NORM_W-1] | (e_q == MAG_LOW);
      always @(posedge clk_i) begin
        if (rst_i) begin
          field_q <= {MAG_F_W{1'b0}};
          norm_q <= {NORM_W{1'b0}};
          e_q <= MAG_LOW;
        end else if (est_take) begin
          field_q <= est_mag[MAG_W-1] ? {MAG_F_W{1'b1}} : est_mag[MAG_W-2 -: MAG_F_W];
          norm_q <= est_mag[MAG_W-1 -: NORM_W];
          e_q <= MAG_TOP;
        end else if (!stop) begin
          norm_q <= {norm_q[NORM_W-2:0], 1'b0};
          e_q <= e_q - 1'b1;
        end
      end
      assign mag_field = field_q;
      assign mag_e = e_q;
      assign mag_f = norm_q[NORM_W-2 -: 5];
      assign mag_lg_ok = stop;
      // The leading one itself and the bits below f are not part of lg m (named unused_* for lint).
      wire unused_norm = ^{norm_q[NORM_W-1], norm_q[NORM_W-7:0]};
      if (MAG_LOW_I > 0) begin : g_low
        // The bits below MAG_LOW only in MAG (named unused_* for lint).
        wire unused_mag_low = ^est_mag[MAG_LOW_I-1:0];
      end
    end else begin : g_mag_comb
      reg [MAG_W-1:0] mag_q;
      always @(posedge clk_i) begin
        if (rst_i) mag_q <= {MAG_W{1'b0}};
        else if (est_take) mag_q <= est_mag;
      end
      assign mag_field = mag_q[MAG_W-1] ? {MAG_F_W{1'b1}} : mag_q[MAG_W-2 -: MAG_F_W];
      reg [MAG_E_W-1:0] lead;
      always @* begin : p_lead
        integer i;
        lead = {MAG_E_W{1'b0}};
        for (i = 0; i < MAG_W; i = i + 1) if (mag_q[i]) lead = i[MAG_E_W-1:0];
      end
      wire [MAG_W-1:0] mag_norm = mag_q << (MAG_TOP - lead);  // leading one at the top
      assign mag_e = lead;
      assign mag_f = mag_norm[MAG_W-2 -: 5];
      assign mag_lg_ok = 1'b1;
      // The leading one itself and the bits below f are not part of lg m (named unused_* for lint).
      wire unused_mag_norm = ^{mag_norm[MAG_W-1], mag_norm[MAG_W-7:0]};
    end
  endgenerate
  localparam [AGC_D_W-1:0] AGC_REF_W = AGC_REF[AGC_D_W-1:0];
  // AGC_REF - lg m as ~(lg m + ~AGC_REF): a constant operand, not lg m's complement, on the carry
  // chain (an inverted operand costs a LUT a bit in front of it; the outer ~ folds into the sums).
  wire [AGC_D_W-1:0] agc_d = ~({3'b000, mag_e, mag_f} + ~AGC_REF_W);
  reg [AGC_W-1:0] agc_q;
  always @(posedge clk_i) begin
    if (rst_i) agc_q <= {AGC_W{1'b1}};
    else if (mag_lg_ok) begin
      if (agc_d[AGC_D_W-1]) agc_q <= {AGC_W{1'b0}};  // a strong field: 0
      else if (|agc_d[AGC_D_W-2:AGC_W]) agc_q <= {AGC_W{1'b1}};  // weak or none: 255
      else agc_q <= agc_d[AGC_W-1:0];
    end
  end
  assign rg_mag_agc_mag = mag_field;
  assign rg_mag_agc_agc = agc_q;

  // ---- the tracking observer ----
  wire trk_valid, trk_lot;
  wire [ANGLE_W-1:0] trk_tracked, trk_angle;  // tracked; compensated (the drive's angle)
  wire [TRK_P_W-1:0] trk_velocity;
  wire [TRK_TURN_W-1:0] trk_turns;
  acore_track #(
    .ANGLE_W(ANGLE_W), .FRAC_W(TRK_FRAC_W), .TURN_W(TRK_TURN_W), .COMP_LATENCY(COMP_LATENCY),
    .LEAD_W(TRK_LEAD_LEAD_W), .LEAD_F(TRK_LEAD_LEAD_F), .LOOP_CLOCKS(TRK_LOOP_CLOCKS),
    .SERIAL(TRK_SERIAL), .PROD_BITS((TRK_PROD_BITS != 0) ? TRK_PROD_BITS : 1),
    .SHIFT_BITS((TRK_SHIFT_BITS != 0) ? TRK_SHIFT_BITS : 2)
  ) u_track (
    .clk_i(clk_i), .rst_i(rst_i), .in_valid_i(est_valid), .in_ready_o(trk_ready),
    .in_angle_i(est_angle), .bw_i(rg_trk_bw_bw), .lead_i(rg_trk_lead_lead),
    .lot_thr_i(rg_trk_lot_threshold),
    .out_valid_o(trk_valid), .out_ready_i(1'b1), .out_angle_o(trk_tracked),
    .out_angle_comp_o(trk_angle), .out_velocity_o(trk_velocity), .out_turns_o(trk_turns),
    .out_lot_o(trk_lot));
  // The observer's outputs hold between its samples: the APB reads them as they are (the
  // word-serial form writes velocity and position a few clocks before its valid: the newest).
  assign rg_trk_velocity_velocity = trk_velocity[TRK_P_W-1 -: TRK_VELOCITY_VELOCITY_W];
  assign rg_trk_position_turns = trk_turns;
  assign rg_trk_position_angle = trk_tracked[ANGLE_W-1 -: TRK_POSITION_ANGLE_W];
  assign trk_valid_o = trk_valid;
  assign trk_angle_o = trk_tracked;
  assign trk_angle_comp_o = trk_angle;
  assign trk_velocity_o = trk_velocity;
  assign trk_turns_o = trk_turns;
  assign trk_lot_o = trk_lot;
  // The loss of tracking last delivered (DIAAGC.LF; the word-serial observer sets its LOT output
  // before the sample's other outputs). The compensated angle last delivered (ANGLECOM) is the
  // observer's output itself: it changes only with the observer's valid, in every form.
  reg lot_q;
  always @(posedge clk_i) begin
    if (rst_i) lot_q <= 1'b0;
    else if (trk_valid) lot_q <= trk_lot;
  end
  // The interfaces' angle (IF_ZERO, IF_CTRL: the AS5047P's ZPOS, DIR, DAECDIS): the compensated
  // angle (with DAEC 0 the estimator's last), the zero taken away, negated with DIR. ABZ and UVW
  // take it with each observer output; the SPI port reads it at once (a new zero or direction
  // shows in the next ANGLECOM, as on the AS5047P).
  wire [ANGLE_W-1:0] if_zero = {rg_if_zero_zero, {(ANGLE_W-14){1'b0}}};
  // (ANGLECOM is the same angle: one adder for both.) x - zero = ~(~x + zero) and, with DIR,
  // zero - x = ~x + zero + 1: each angle takes one adder, ~x + zero + DIR, complemented without
  // DIR. Its operands reach the carry chain as they are: ~x comes from a LUT that is there anyway
  // (the DAEC select; ANGLEUNC's flop, held complemented) and the zero is the register itself, so
  // no LUT inverts an operand in front of the carry chain, and the complement of the sum folds
  // into the sum bits' logic.
  wire [ANGLE_W-1:0] if_ninv = {ANGLE_W{~rg_if_ctrl_dir}};
  wire [ANGLE_W-1:0] if_ci = {{(ANGLE_W-1){1'b0}}, rg_if_ctrl_dir};
  wire [ANGLE_W-1:0] if_src_n = rg_if_ctrl_daec ? ~trk_angle : unc_n_q;
  wire [ANGLE_W-1:0] if_angle = (if_src_n + if_zero + if_ci) ^ if_ninv;
  wire [ANGLE_W-1:0] if_com = if_angle;
  wire [ANGLE_W-1:0] if_unc = (unc_n_q + if_zero + if_ci) ^ if_ninv;

  // ---- the interfaces ----
  // Their inputs as wide as their registers' fields (ABZ_INDEX.POS has one bit more than N: a
  // count 0..4N-1).
  wire [ABZ_N_N_W:0] abz_count;
  wire abz_settled;
  // (ABZ_N and UVW_PP hold only values of their ranges, the ones the interfaces take: the APB
  // refuses others, the SPI port writes table entries within them; so no clamp.)
  acore_abz #(.ANGLE_W(ANGLE_W), .N_W(ABZ_N_N_W), .SP_W(ABZ_SPACING_SPACING_W), .HYS_W(ABZ_HYS_WIDTH_W),
    .N_IN_RANGE(1)) u_abz (
    .clk_i(clk_i), .rst_i(rst_i), .angle_valid_i(trk_valid), .angle_i(if_angle), .n_i(rg_abz_n_n),
    .index_i(rg_abz_index_pos), .spacing_i(rg_abz_spacing_spacing), .hys_i(rg_abz_hys_width),
    .a_o(a_o), .b_o(b_o), .z_o(z_o),
    .count_o(abz_count), .settled_o(abz_settled));
  wire [2:0] uvw_sector;
  wire uvw_valid;
  acore_uvw #(.ANGLE_W(ANGLE_W), .PP_W(UVW_PP_POLE_PAIRS_W), .PP_IN_RANGE(1)) u_uvw (
    .clk_i(clk_i), .rst_i(rst_i), .angle_valid_i(trk_valid), .angle_i(if_angle),
    .pp_i(rg_uvw_pp_pole_pairs), .offset_i(rg_uvw_offset_offset), .u_o(u_o), .v_o(v_o), .w_o(w_o),
    .sector_o(uvw_sector), .valid_o(uvw_valid));
  wire spi_frame;
  wire [2:0] spi_errfl;
  // The AS5047P's settings written over SPI are the board's registers (their hardware write ports).
  acore_spi_as5047 #(.ANGLE_W(ANGLE_W), .SYNC(2), .SCLK_MIN(4), .N_W(ABZ_N_N_W),
    .PP_W(UVW_PP_POLE_PAIRS_W), .HYS_W(ABZ_HYS_WIDTH_W)) u_spi (
    .clk_i(clk_i), .rst_i(rst_i), .sclk_i(sclk_i), .csn_i(csn_i), .mosi_i(mosi_i), .miso_o(miso_o),
    .miso_oe_o(miso_oe_o), .angle_unc_i(if_unc), .angle_com_i(if_com), .mag_i(mag_field), .agc_i(agc_q),
    .los_i(los_q), .dos_i(dos_q), .ovf_i(ovf_q), .lot_i(lot_q),
    .cfg_zero_i(rg_if_zero_zero), .cfg_dir_i(rg_if_ctrl_dir), .cfg_daec_i(rg_if_ctrl_daec),
    .cfg_n_i(rg_abz_n_n), .cfg_pp_i(rg_uvw_pp_pole_pairs), .cfg_hys_i(rg_abz_hys_width),
    .cfg_zero_we_o(rg_if_zero_zero_hw_we), .cfg_zero_o(rg_if_zero_zero_hw_d),
    .cfg_dir_we_o(rg_if_ctrl_dir_hw_we), .cfg_dir_o(rg_if_ctrl_dir_hw_d),
    .cfg_daec_we_o(rg_if_ctrl_daec_hw_we), .cfg_daec_o(rg_if_ctrl_daec_hw_d),
    .cfg_n_we_o(rg_abz_n_n_hw_we), .cfg_n_o(rg_abz_n_n_hw_d),
    .cfg_pp_we_o(rg_uvw_pp_pole_pairs_hw_we), .cfg_pp_o(rg_uvw_pp_pole_pairs_hw_d),
    .cfg_hys_we_o(rg_abz_hys_width_hw_we), .cfg_hys_o(rg_abz_hys_width_hw_d),
    .frame_o(spi_frame), .errfl_o(spi_errfl));

endmodule

`resetall
