// SPDX-License-Identifier: MIT
// acore_board_sg48wrap: the board top (rtl/acore_board.v) for place and route on an iCE40 UP5K in
// the SG48 package (39 user I/O). As in acore_apb_sg48wrap.v, the APB control (psel, penable,
// pwrite) stays on pins and passes through one register, the slowly changing wide inputs (address,
// write data, strobes, the channel codes) are loaded through a serial shift register (sdi_i,
// shift_i), and the read data and the angle stream are captured into a shift register (cap_i) and
// shifted out on sdo_o; the interfaces' pins (A, B, Z, U, V, W, SCLK, CSn, MOSI, MISO and its
// enable) are on pins as they are. 26 pins; every timed path is register to register.
`resetall
`default_nettype none

module acore_board_sg48wrap #(
  // The estimator's top (acore_board's SERIAL), its datapath parameters and power-up register
  // image (a registry line's parameters mean the same here); the shift registers' widths follow them.
  parameter integer SERIAL = 0,
`include "acore_datapath_params.vh"
  parameter INIT_FILE = ""
) (
  input  wire clk_i,
  input  wire rst_i,
  input  wire sdi_i,
  input  wire shift_i,
  input  wire psel_i,
  input  wire penable_i,
  input  wire pwrite_i,
  output reg  pready_o,
  output reg  pslverr_o,
  output wire irq_o,
  input  wire in_valid_i,
  output wire in_ready_o,
  output wire out_valid_o,
  input  wire cap_i,
  output wire sdo_o,
  output wire a_o,
  output wire b_o,
  output wire z_o,
  output wire u_o,
  output wire v_o,
  output wire w_o,
  input  wire sclk_i,
  input  wire csn_i,
  input  wire mosi_i,
  output wire miso_o,
  output wire miso_oe_o
);

  // paddr (12), pwdata (32), pstrb (4), c1..c4 (4 x IN_W).
  localparam integer SI_W = 12 + 32 + 4 + 4 * IN_W;
  reg [SI_W-1:0] si_q;
  always @(posedge clk_i) if (shift_i) si_q <= {si_q[SI_W-2:0], sdi_i};

  reg psel_q, penable_q, pwrite_q;
  wire [31:0] prdata;
  wire pready, pslverr;
  always @(posedge clk_i) begin
    psel_q <= psel_i;
    penable_q <= penable_i;
    pwrite_q <= pwrite_i;
    pready_o <= pready;
    pslverr_o <= pslverr;
  end

  wire [ANGLE_W-1:0] angle;
  wire los, dos;
  acore_board #(
`include "acore_datapath_pass.vh"
    .SERIAL(SERIAL), .INIT_FILE(INIT_FILE)
  ) u_board (
    .clk_i(clk_i), .rst_i(rst_i), .psel_i(psel_q), .penable_i(penable_q), .pwrite_i(pwrite_q),
    .paddr_i(si_q[11:0]), .pwdata_i(si_q[43:12]), .pstrb_i(si_q[47:44]), .prdata_o(prdata),
    .pready_o(pready), .pslverr_o(pslverr), .irq_o(irq_o), .in_valid_i(in_valid_i),
    .in_ready_o(in_ready_o), .c1_i(si_q[48 +: IN_W]), .c2_i(si_q[48+IN_W +: IN_W]),
    .c3_i(si_q[48+2*IN_W +: IN_W]), .c4_i(si_q[48+3*IN_W +: IN_W]),
    .out_valid_o(out_valid_o), .angle_o(angle), .los_o(los), .dos_o(dos),
    .a_o(a_o), .b_o(b_o), .z_o(z_o), .u_o(u_o), .v_o(v_o), .w_o(w_o),
    .sclk_i(sclk_i), .csn_i(csn_i), .mosi_i(mosi_i), .miso_o(miso_o), .miso_oe_o(miso_oe_o));

  // Read data and the angle stream: captured, then shifted out msb first.
  localparam integer SO_W = 32 + ANGLE_W + 2;
  reg [SO_W-1:0] so_q;
  always @(posedge clk_i) begin
    if (cap_i) so_q <= {prdata, angle, los, dos};
    else so_q <= {so_q[SO_W-2:0], 1'b0};
  end
  assign sdo_o = so_q[SO_W-1];

endmodule

`resetall
