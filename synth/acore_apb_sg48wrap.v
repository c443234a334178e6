// SPDX-License-Identifier: MIT
// acore_apb_sg48wrap: the APB register shell and its core (rtl/acore_apb.v) for place and route on
// an iCE40 UP5K in the SG48 package (39 user I/O: the pin wrapper of acore_apb_pinwrap.v needs
// 110). The APB control (psel, penable, pwrite) and the stream handshake stay on pins and pass
// through one register, as in acore_apb_pinwrap.v; the slowly changing wide inputs (address, write
// data, strobes, the channel codes) are loaded through a serial shift register (sdi_i, shift_i);
// the read data and the results are captured into a shift register (cap_i) and shifted out on
// sdo_o. 16 pins; every timed path is register to register.
`resetall
`default_nettype none

module acore_apb_sg48wrap #(
  // The shell's top (acore_apb's SERIAL), the datapath parameters and the power-up register image
  // (a registry line's parameters mean the same here); the shift registers' widths follow them.
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
  input  wire out_ready_i,
  input  wire cap_i,
  output wire sdo_o
);

  // paddr (12), pwdata (32), pstrb (4), c1..c4 (4 x IN_W).
  localparam integer SI_W = 12 + 32 + 4 + 4 * IN_W;
  localparam integer RG_W = $clog2(REGIONS);
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
  wire [RG_W-1:0] region;
  wire ovf, los, dos, tag;
  acore_apb #(
`include "acore_datapath_pass.vh"
    .SERIAL(SERIAL), .INIT_FILE(INIT_FILE)
  ) u_shell (
    .clk_i(clk_i), .rst_i(rst_i), .psel_i(psel_q), .penable_i(penable_q), .pwrite_i(pwrite_q),
    .paddr_i(si_q[11:0]), .pwdata_i(si_q[43:12]), .pstrb_i(si_q[47:44]), .prdata_o(prdata),
    .pready_o(pready), .pslverr_o(pslverr), .irq_o(irq_o), .in_valid_i(in_valid_i),
    .in_ready_o(in_ready_o), .c1_i(si_q[48 +: IN_W]), .c2_i(si_q[48+IN_W +: IN_W]),
    .c3_i(si_q[48+2*IN_W +: IN_W]), .c4_i(si_q[48+3*IN_W +: IN_W]), .out_valid_o(out_valid_o), .out_ready_i(out_ready_i), .angle_o(angle),
    .region_o(region), .ovf_o(ovf), .los_o(los), .dos_o(dos), .out_tag_o(tag));

  // Read data and results: captured, then shifted out msb first.
  localparam integer SO_W = 32 + ANGLE_W + RG_W + 4;
  reg [SO_W-1:0] so_q;
  always @(posedge clk_i) begin
    if (cap_i) so_q <= {prdata, angle, region, ovf, los, dos, tag};
    else so_q <= {so_q[SO_W-2:0], 1'b0};
  end
  assign sdo_o = so_q[SO_W-1];

endmodule

`resetall
