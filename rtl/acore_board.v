// SPDX-License-Identifier: MIT
// acore_board: what a motor-drive board uses. The estimator in its APB register shell
// (rtl/acore_apb.v with IFACE = 1: the datapath, folded or serial, its coefficient bank, and the
// interfaces' configuration registers) feeding the drive interfaces on its angle stream:
//
//   c1..c4 --> acore_apb (estimator) --angle--+--> acore_abz        A, B, Z
//                 ^ APB (config, status)      +--> acore_uvw        U, V, W
//                                             +--> acore_spi_as5047 SCLK, CSn, MOSI -> MISO
//
// The output stream is always taken (out_ready high): the interfaces accept every sample, and the
// angle is also on pins (angle_o, out_valid_o) for a logic analyser or a second consumer.
//
// THE TRACKER'S PLACE. The tracking observer with latency compensation (rtl/acore_track.v) is not
// part of this top yet. Until it is wired in, the signals of the block marked "tracker" below stand
// for it: the compensated angle is the estimator's angle (the SPI's ANGLECOM reads the same as
// ANGLEUNC), and loss of tracking is 0 (DIAAGC.LF reads 1). The block's four wires are the ports
// the tracker takes and gives: trk_valid/trk_angle (compensated angle stream, ANGLE_W bits),
// trk_lot (loss of tracking); ABZ and UVW then take the compensated angle. The estimator has no
// magnitude output, so MAG and DIAAGC's AGC read 0.
`resetall
`default_nettype none

module acore_board #(
  // The estimator (rtl/acore_apb.v, rtl/acore_top.v document each).
  parameter integer SERIAL = 0,
  parameter integer CORRECTION = 0,
  parameter integer DEGREE = 3,
  parameter integer REGIONS = 4,
  parameter integer K = 16,
  parameter integer FOLD = 1,
  parameter integer ZERO = 0,
  parameter INIT_FILE = "",
  // The angle (the estimator's default) and the interfaces' widths.
  parameter integer ANGLE_W = 16,
  parameter integer IN_W = 16,
  parameter integer REG_W = 18,
  parameter integer S_W = 18,
  parameter integer RG_W = $clog2(REGIONS)
) (
  input  wire               clk_i,
  input  wire               rst_i,
  // APB4 slave (rtl/acore_apb.v; the interface registers at 0x060..0x070).
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
  localparam integer LATENCY = (SERIAL != 0) ? acore_serial_latency(REG_W, S_W, DEGREE, K, ZERO) :
      acore_top_latency(REG_W, S_W, CORRECTION, DEGREE, K, 0, 12, FOLD);
  localparam integer CYCLES = (SERIAL != 0) ? acore_serial_cycles(REG_W, S_W, DEGREE, K, ZERO) :
      acore_top_cycles(FOLD);

  // ---- the estimator and its register shell ----
  wire est_valid, est_ovf, est_los, est_dos, est_tag;
  wire [ANGLE_W-1:0] est_angle;
  wire [RG_W-1:0] est_region;
  wire [12:0] abz_n;
  wire [13:0] abz_index;
  wire [15:0] abz_spacing;
  wire [4:0] uvw_pp;
  wire [ANGLE_W-1:0] uvw_offset;
  acore_apb #(
    .SERIAL(SERIAL), .CORRECTION(CORRECTION), .DEGREE(DEGREE), .REGIONS(REGIONS), .K(K), .FOLD(FOLD),
    .ZERO(ZERO), .INIT_FILE(INIT_FILE), .ANGLE_W(ANGLE_W), .IN_W(IN_W), .REG_W(REG_W), .S_W(S_W),
    .IFACE(1)
  ) u_shell (
    .clk_i(clk_i), .rst_i(rst_i), .psel_i(psel_i), .penable_i(penable_i), .pwrite_i(pwrite_i),
    .paddr_i(paddr_i), .pwdata_i(pwdata_i), .pstrb_i(pstrb_i), .prdata_o(prdata_o),
    .pready_o(pready_o), .pslverr_o(pslverr_o), .irq_o(irq_o), .in_valid_i(in_valid_i),
    .in_ready_o(in_ready_o), .c1_i(c1_i), .c2_i(c2_i), .c3_i(c3_i), .c4_i(c4_i),
    .out_valid_o(est_valid), .out_ready_i(1'b1), .angle_o(est_angle), .region_o(est_region),
    .ovf_o(est_ovf), .los_o(est_los), .dos_o(est_dos), .out_tag_o(est_tag),
    .abz_n_o(abz_n), .abz_index_o(abz_index), .abz_spacing_o(abz_spacing), .uvw_pp_o(uvw_pp),
    .uvw_offset_o(uvw_offset));
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
    end else if (est_valid) begin
      los_q <= est_los;
      dos_q <= est_dos;
      ovf_q <= est_ovf;
    end
  end
  // The uncompensated angle last delivered (ANGLEUNC).
  reg [ANGLE_W-1:0] unc_q;
  always @(posedge clk_i) if (est_valid) unc_q <= est_angle;

  // ==== tracker (rtl/acore_track.v goes here) =====================================================
  // Until the tracker is wired: the compensated stream is the estimator's, no loss of tracking.
  wire trk_valid = est_valid;
  wire [ANGLE_W-1:0] trk_angle = est_angle;
  wire trk_lot = 1'b0;
  reg [ANGLE_W-1:0] com_q;
  always @(posedge clk_i) if (trk_valid) com_q <= trk_angle;
  // ================================================================================================

  // ---- the interfaces ----
  wire [13:0] abz_count;
  wire abz_settled;
  acore_abz #(.ANGLE_W(ANGLE_W), .N_W(13), .SP_W(16)) u_abz (
    .clk_i(clk_i), .rst_i(rst_i), .angle_valid_i(trk_valid), .angle_i(trk_angle), .n_i(abz_n),
    .index_i(abz_index), .spacing_i(abz_spacing), .a_o(a_o), .b_o(b_o), .z_o(z_o),
    .count_o(abz_count), .settled_o(abz_settled));
  wire [2:0] uvw_sector;
  wire uvw_valid;
  acore_uvw #(.ANGLE_W(ANGLE_W), .PP_W(5)) u_uvw (
    .clk_i(clk_i), .rst_i(rst_i), .angle_valid_i(trk_valid), .angle_i(trk_angle), .pp_i(uvw_pp),
    .offset_i(uvw_offset), .u_o(u_o), .v_o(v_o), .w_o(w_o), .sector_o(uvw_sector), .valid_o(uvw_valid));
  wire spi_frame;
  wire [2:0] spi_errfl;
  acore_spi_as5047 #(.ANGLE_W(ANGLE_W), .SYNC(2)) u_spi (
    .clk_i(clk_i), .rst_i(rst_i), .sclk_i(sclk_i), .csn_i(csn_i), .mosi_i(mosi_i), .miso_o(miso_o),
    .miso_oe_o(miso_oe_o), .angle_unc_i(unc_q), .angle_com_i(com_q), .mag_i(14'd0), .agc_i(8'd0),
    .los_i(los_q), .dos_i(dos_q), .ovf_i(ovf_q), .lot_i(trk_lot), .frame_o(spi_frame),
    .errfl_o(spi_errfl));

endmodule

`resetall
