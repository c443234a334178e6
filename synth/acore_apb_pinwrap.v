// SPDX-License-Identifier: MIT
// acore_apb_pinwrap: the APB register shell (rtl/acore_apb.v) for place and route. The APB signals
// pass through one register on the way in and out, as a bus interconnect's flops would drive and
// sample them, so the shell's address decode and read mux are timed register to register; the
// channel codes are loaded through a serial shift register (sdi_i, shift_i) as in
// acore_serial_top_pinwrap.v; the stream handshake, the results and the interrupt stay on pins.
`resetall
`default_nettype none

module acore_apb_pinwrap #(
  // 0: around acore_top (with the default correction it does not fit an HX8K); 1: around the
  // serial core. The datapath parameters and the power-up register image, passed to the shell (a
  // registry line's parameters mean the same here); the port widths follow them.
  parameter integer SERIAL = 0,
`include "acore_datapath_params.vh"
  parameter INIT_FILE = ""
) (
  input  wire        clk_i,
  input  wire        rst_i,
  input  wire        psel_i,
  input  wire        penable_i,
  input  wire        pwrite_i,
  input  wire [11:0] paddr_i,
  input  wire [31:0] pwdata_i,
  input  wire [3:0]  pstrb_i,
  output reg  [31:0] prdata_o,
  output reg         pready_o,
  output reg         pslverr_o,
  output wire        irq_o,
  input  wire        sdi_i,
  input  wire        shift_i,
  input  wire        in_valid_i,
  output wire        in_ready_o,
  output wire        out_valid_o,
  input  wire        out_ready_i,
  output wire [ANGLE_W-1:0] angle_o,
  output wire [$clog2(REGIONS)-1:0] region_o,
  output wire        ovf_o,
  output wire        los_o,
  output wire        dos_o,
  output wire        out_tag_o
);

  reg psel_q, penable_q, pwrite_q;
  reg [11:0] paddr_q;
  reg [31:0] pwdata_q;
  reg [3:0] pstrb_q;
  wire [31:0] prdata;
  wire pready, pslverr;
  always @(posedge clk_i) begin
    psel_q <= psel_i;
    penable_q <= penable_i;
    pwrite_q <= pwrite_i;
    paddr_q <= paddr_i;
    pwdata_q <= pwdata_i;
    pstrb_q <= pstrb_i;
    prdata_o <= prdata;
    pready_o <= pready;
    pslverr_o <= pslverr;
  end

  // c1..c4.
  reg [4*IN_W-1:0] sr_q;
  always @(posedge clk_i) if (shift_i) sr_q <= {sr_q[4*IN_W-2:0], sdi_i};

  acore_apb #(
`include "acore_datapath_pass.vh"
    .SERIAL(SERIAL), .INIT_FILE(INIT_FILE)
  ) u_shell (
    .clk_i(clk_i), .rst_i(rst_i), .psel_i(psel_q), .penable_i(penable_q), .pwrite_i(pwrite_q),
    .paddr_i(paddr_q), .pwdata_i(pwdata_q), .pstrb_i(pstrb_q), .prdata_o(prdata), .pready_o(pready),
    .pslverr_o(pslverr), .irq_o(irq_o), .in_valid_i(in_valid_i), .in_ready_o(in_ready_o),
    .c1_i(sr_q[0 +: IN_W]), .c2_i(sr_q[IN_W +: IN_W]), .c3_i(sr_q[2*IN_W +: IN_W]),
    .c4_i(sr_q[3*IN_W +: IN_W]),
    .out_valid_o(out_valid_o), .out_ready_i(out_ready_i), .angle_o(angle_o), .region_o(region_o),
    .ovf_o(ovf_o), .los_o(los_o), .dos_o(dos_o), .out_tag_o(out_tag_o));

endmodule

`resetall
