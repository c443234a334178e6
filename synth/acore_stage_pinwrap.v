// SPDX-License-Identifier: MIT
// Pin wrappers for place and route of the top's stages one at a time: the default acore_top needs
// about 10k LUT4, more than an iCE40 HX8K has (7680 logic cells), so its clock rate on that device
// is measured per stage (every path of the top is inside one stage or a register-to-register hop
// between stages). Each wrapper loads the stage's inputs (data and register-file words) through a
// serial shift register (sdi_i, shift_i), registers the enable, and puts the outputs on pins.
// <module>_pinwrap is the wrapper of <module> that scripts/synth.sh places for a registry line of
// that module with the pnr flow (rtl/configs.txt); the line's parameters are set on the wrapper, so
// a wrapper has the parameters such lines set, with the module's defaults.
`resetall
`default_nettype none

module acore_scaler_pinwrap (
  input  wire        clk_i,
  input  wire        sdi_i,
  input  wire        shift_i,
  input  wire        en_i,
  output wire [17:0] s_o,
  output wire        ovf_o
);
  localparam integer SR_W = 17 + 18 + 18;
  reg [SR_W-1:0] sr_q;
  reg en_q;
  always @(posedge clk_i) begin
    if (shift_i) sr_q <= {sr_q[SR_W-2:0], sdi_i};
    en_q <= en_i;
  end
  acore_scaler u_stage (
    .clk_i(clk_i), .en_i(en_q), .d_i(sr_q[16:0]), .offset_i(sr_q[34:17]), .recip_i(sr_q[52:35]),
    .s_o(s_o), .ovf_o(ovf_o));
endmodule

module acore_region_select_pinwrap (
  input  wire        clk_i,
  input  wire        sdi_i,
  input  wire        shift_i,
  input  wire        en_i,
  output wire [1:0]  region_o,
  output wire [17:0] x_o,
  output wire [17:0] s13_o,
  output wire [17:0] s24_o
);
  localparam integer SR_W = 2 * 18;
  reg [SR_W-1:0] sr_q;
  reg en_q;
  always @(posedge clk_i) begin
    if (shift_i) sr_q <= {sr_q[SR_W-2:0], sdi_i};
    en_q <= en_i;
  end
  acore_region_select u_stage (
    .clk_i(clk_i), .en_i(en_q), .s13_i(sr_q[17:0]), .s24_i(sr_q[35:18]), .region_o(region_o), .x_o(x_o),
    .s13_o(s13_o), .s24_o(s24_o));
endmodule

module acore_poly_correct_pinwrap (
  input  wire        clk_i,
  input  wire        sdi_i,
  input  wire        shift_i,
  input  wire        en_i,
  output wire [17:0] y_o,
  output wire        ovf_o
);
  localparam integer NC = 32 * 18;
  localparam integer SR_W = 18 + 18 + 2 + NC;
  reg [SR_W-1:0] sr_q;
  reg en_q;
  always @(posedge clk_i) begin
    if (shift_i) sr_q <= {sr_q[SR_W-2:0], sdi_i};
    en_q <= en_i;
  end
  acore_poly_correct u_stage (
    .clk_i(clk_i), .en_i(en_q), .x_i(sr_q[17:0]), .s_i(sr_q[35:18]), .region_i(sr_q[37:36]),
    .coef_i(sr_q[38 +: NC]), .y_o(y_o), .ovf_o(ovf_o));
endmodule

// The 2-D correction stage (CORRECTION = 1, 4 regions, curve c13) of total degree DEGREE: its
// coefficient words (4 regions x 2 curves x terms), x, s13, s24 and the region shifted in.
module acore_poly2d_correct_pinwrap #(
  parameter integer DEGREE = 3
) (
  input  wire        clk_i,
  input  wire        sdi_i,
  input  wire        shift_i,
  input  wire        en_i,
  output wire [17:0] y_o,
  output wire        ovf_o
);
  localparam integer TERMS = (DEGREE == 1) ? 3 : (DEGREE == 2) ? 6 : 10;
  localparam integer NC = 8 * TERMS * 18;
  localparam integer SR_W = 3 * 18 + 2 + NC;
  reg [SR_W-1:0] sr_q;
  reg en_q;
  always @(posedge clk_i) begin
    if (shift_i) sr_q <= {sr_q[SR_W-2:0], sdi_i};
    en_q <= en_i;
  end
  acore_poly2d_correct #(.DEGREE(DEGREE)) u_stage (
    .clk_i(clk_i), .en_i(en_q), .x_i(sr_q[17:0]), .s13_i(sr_q[35:18]), .s24_i(sr_q[53:36]),
    .region_i(sr_q[55:54]), .coef_i(sr_q[56 +: NC]), .y_o(y_o), .ovf_o(ovf_o));
endmodule

// The top's CORDIC (acore_cordic's defaults are the top's CORDIC configuration), its arctangent words
// shifted in as the register file feeds them.
module acore_cordic_pinwrap (
  input  wire        clk_i,
  input  wire        sdi_i,
  input  wire        shift_i,
  input  wire        en_i,
  output wire [15:0] angle_o,
  output wire [19:0] mag_o
);
  localparam integer SR_W = 18 + 18 + 16 * 18;
  reg [SR_W-1:0] sr_q;
  reg en_q;
  always @(posedge clk_i) begin
    if (shift_i) sr_q <= {sr_q[SR_W-2:0], sdi_i};
    en_q <= en_i;
  end
  // The top's CORDIC configuration: IN_W = S_W = 18, CORDIC_G = 3, Z_W = 20, K = 16, NORM = 0.
  acore_cordic #(.IN_W(18), .G(3), .Z_W(20), .ANGLE_W(16), .K(16), .AT_W(18), .NORM(0)) u_stage (
    .clk_i(clk_i), .en_i(en_q), .x_i(sr_q[17:0]), .y_i(sr_q[35:18]), .atan_i(sr_q[36 +: 16 * 18]),
    .angle_o(angle_o), .mag_o(mag_o));
endmodule

// The Fourier correction (acore_fourier_correct.v) with the top's widths (ANGLE_W 16, REG_W 18,
// Z_W 20) and FOURIER_M = 12. The full 21-harmonic stage needs more logic cells than an HX8K has, so
// P&R places fewer harmonics (registry line stage_fourier_k4: K = 4): every register-to-register
// path lies inside one harmonic's pipeline (k theta, start vector, rotation stages), the adder tree
// or the output subtraction, and each of those is the same for any K but for the tree's depth (one
// adder per clock regardless).
module acore_fourier_correct_pinwrap #(
  // Harmonics placed (acore_fourier_correct's default).
  parameter integer K = 21
) (
  input  wire        clk_i,
  input  wire        sdi_i,
  input  wire        shift_i,
  input  wire        en_i,
  output wire [15:0] angle_o
);
  localparam integer NC = ((K << 1) + 1) * 18;
  localparam integer SR_W = 16 + NC + 12 * 18;
  reg [SR_W-1:0] sr_q;
  reg en_q;
  always @(posedge clk_i) begin
    if (shift_i) sr_q <= {sr_q[SR_W-2:0], sdi_i};
    en_q <= en_i;
  end
  acore_fourier_correct #(
    .ANGLE_W(16), .REG_W(18), .Z_W(20), .K(K), .M(12), .CF(22), .W(16), .G(2), .AT_W(18)
  ) u_stage (
    .clk_i(clk_i), .en_i(en_q), .angle_i(sr_q[15:0]), .coef_i(sr_q[16 +: NC]), .atan_i(sr_q[16 + NC +: 12 * 18]),
    .angle_o(angle_o));
endmodule

// The drive interfaces (rtl/acore_abz.v, acore_uvw.v, acore_spi_as5047.v): the angle and the
// configuration words through the shift register, the interface's own pins on pins.
module acore_abz_pinwrap #(
  parameter integer ANGLE_W = 16,
  parameter integer N_W = 13,
  parameter integer SP_W = 16,
  parameter integer HYS_W = 8
) (
  input  wire clk_i,
  input  wire rst_i,
  input  wire sdi_i,
  input  wire shift_i,
  input  wire en_i,
  output wire a_o,
  output wire b_o,
  output wire z_o,
  output wire settled_o
);
  localparam integer SR_W = ANGLE_W + N_W + (N_W + 1) + SP_W + HYS_W;
  reg [SR_W-1:0] sr_q;
  reg en_q;
  always @(posedge clk_i) begin
    if (shift_i) sr_q <= {sr_q[SR_W-2:0], sdi_i};
    en_q <= en_i;
  end
  wire [N_W:0] count;
  acore_abz #(.ANGLE_W(ANGLE_W), .N_W(N_W), .SP_W(SP_W), .HYS_W(HYS_W)) u_stage (
    .clk_i(clk_i), .rst_i(rst_i), .angle_valid_i(en_q), .angle_i(sr_q[ANGLE_W-1:0]),
    .n_i(sr_q[ANGLE_W +: N_W]), .index_i(sr_q[ANGLE_W + N_W +: N_W + 1]),
    .spacing_i(sr_q[ANGLE_W + 2 * N_W + 1 +: SP_W]), .hys_i(sr_q[ANGLE_W + 2 * N_W + 1 + SP_W +: HYS_W]),
    .a_o(a_o), .b_o(b_o), .z_o(z_o), .count_o(count), .settled_o(settled_o));
endmodule

module acore_uvw_pinwrap #(
  parameter integer ANGLE_W = 16,
  parameter integer PP_W = 5
) (
  input  wire       clk_i,
  input  wire       rst_i,
  input  wire       sdi_i,
  input  wire       shift_i,
  input  wire       en_i,
  output wire       u_o,
  output wire       v_o,
  output wire       w_o,
  output wire [2:0] sector_o,
  output wire       valid_o
);
  localparam integer SR_W = 2 * ANGLE_W + PP_W;
  reg [SR_W-1:0] sr_q;
  reg en_q;
  always @(posedge clk_i) begin
    if (shift_i) sr_q <= {sr_q[SR_W-2:0], sdi_i};
    en_q <= en_i;
  end
  acore_uvw #(.ANGLE_W(ANGLE_W), .PP_W(PP_W)) u_stage (
    .clk_i(clk_i), .rst_i(rst_i), .angle_valid_i(en_q), .angle_i(sr_q[ANGLE_W-1:0]),
    .pp_i(sr_q[ANGLE_W +: PP_W]), .offset_i(sr_q[ANGLE_W + PP_W +: ANGLE_W]), .u_o(u_o), .v_o(v_o),
    .w_o(w_o), .sector_o(sector_o), .valid_o(valid_o));
endmodule

// The SPI port's settings written by a driver (the board's registers) leave through a second
// shift register, loaded when any of them is written, shifted out on sdo_o.
module acore_spi_as5047_pinwrap #(
  parameter integer ANGLE_W = 16,
  parameter integer SYNC = 2,
  parameter integer SCLK_MIN = 4,
  parameter integer N_W = 13,
  parameter integer PP_W = 5,
  parameter integer HYS_W = 8
) (
  input  wire       clk_i,
  input  wire       rst_i,
  input  wire       sdi_i,
  input  wire       shift_i,
  input  wire       sclk_i,
  input  wire       csn_i,
  input  wire       mosi_i,
  output wire       miso_o,
  output wire       miso_oe_o,
  output wire       frame_o,
  output wire [2:0] errfl_o,
  output wire       sdo_o
);
  localparam integer CFG_W = 14 + 1 + 1 + N_W + PP_W + HYS_W;
  localparam integer SR_W = 2 * ANGLE_W + 14 + 8 + 4 + CFG_W;
  localparam integer OUT_W = CFG_W + 6;
  reg [SR_W-1:0] sr_q;
  always @(posedge clk_i) if (shift_i) sr_q <= {sr_q[SR_W-2:0], sdi_i};
  wire [CFG_W-1:0] cfg_i = sr_q[2 * ANGLE_W + 26 +: CFG_W];
  wire [CFG_W-1:0] cfg_o;
  wire [5:0] cfg_we;
  acore_spi_as5047 #(.ANGLE_W(ANGLE_W), .SYNC(SYNC), .SCLK_MIN(SCLK_MIN), .N_W(N_W), .PP_W(PP_W),
                     .HYS_W(HYS_W)) u_stage (
    .clk_i(clk_i), .rst_i(rst_i), .sclk_i(sclk_i), .csn_i(csn_i), .mosi_i(mosi_i), .miso_o(miso_o),
    .miso_oe_o(miso_oe_o), .angle_unc_i(sr_q[ANGLE_W-1:0]), .angle_com_i(sr_q[ANGLE_W +: ANGLE_W]),
    .mag_i(sr_q[2 * ANGLE_W +: 14]), .agc_i(sr_q[2 * ANGLE_W + 14 +: 8]),
    .los_i(sr_q[2 * ANGLE_W + 22]), .dos_i(sr_q[2 * ANGLE_W + 23]), .ovf_i(sr_q[2 * ANGLE_W + 24]),
    .lot_i(sr_q[2 * ANGLE_W + 25]),
    .cfg_zero_i(cfg_i[13:0]), .cfg_dir_i(cfg_i[14]), .cfg_daec_i(cfg_i[15]),
    .cfg_n_i(cfg_i[16 +: N_W]), .cfg_pp_i(cfg_i[16 + N_W +: PP_W]),
    .cfg_hys_i(cfg_i[16 + N_W + PP_W +: HYS_W]),
    .cfg_zero_we_o(cfg_we[0]), .cfg_zero_o(cfg_o[13:0]), .cfg_dir_we_o(cfg_we[1]), .cfg_dir_o(cfg_o[14]),
    .cfg_daec_we_o(cfg_we[2]), .cfg_daec_o(cfg_o[15]), .cfg_n_we_o(cfg_we[3]),
    .cfg_n_o(cfg_o[16 +: N_W]), .cfg_pp_we_o(cfg_we[4]), .cfg_pp_o(cfg_o[16 + N_W +: PP_W]),
    .cfg_hys_we_o(cfg_we[5]), .cfg_hys_o(cfg_o[16 + N_W + PP_W +: HYS_W]),
    .frame_o(frame_o), .errfl_o(errfl_o));
  reg [OUT_W-1:0] out_q;
  always @(posedge clk_i)
    if (|cfg_we) out_q <= {cfg_we, cfg_o};
    else if (shift_i) out_q <= {out_q[OUT_W-2:0], 1'b0};
  assign sdo_o = out_q[OUT_W-1];
endmodule

`resetall
