// SPDX-License-Identifier: MIT
// acore_board_pinwrap: the board top (rtl/acore_board.v) on an iCE40-HX8K's pins
// (synth/acore_board_hx8k_ct256.pcf). As in acore_apb_pinwrap.v, the APB signals pass through one
// register each way (a bus bridge's flops), and the channel codes come through a serial shift
// register (sdi_i, shift_i); the interfaces' pins (A, B, Z, U, V, W, SCLK, CSn, MOSI, MISO) and
// the angle stream are on pins as they are. MISO is a plain output with its enable on a pin
// (miso_oe_o, high while CSn is low): a board sharing the SPI bus puts a tri-state buffer there.
`resetall
`default_nettype none

module acore_board_pinwrap #(
  // The estimator's top (acore_board's SERIAL), its datapath parameters and power-up register
  // image (a registry line's parameters mean the same here); the port widths follow them.
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
  output wire [ANGLE_W-1:0] angle_o,
  output wire        los_o,
  output wire        dos_o,
  output wire        a_o,
  output wire        b_o,
  output wire        z_o,
  output wire        u_o,
  output wire        v_o,
  output wire        w_o,
  input  wire        sclk_i,
  input  wire        csn_i,
  input  wire        mosi_i,
  output wire        miso_o,
  output wire        miso_oe_o
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

  acore_board #(
`include "acore_datapath_pass.vh"
    .SERIAL(SERIAL), .INIT_FILE(INIT_FILE)
  ) u_board (
    .clk_i(clk_i), .rst_i(rst_i), .psel_i(psel_q), .penable_i(penable_q), .pwrite_i(pwrite_q),
    .paddr_i(paddr_q), .pwdata_i(pwdata_q), .pstrb_i(pstrb_q), .prdata_o(prdata), .pready_o(pready),
    .pslverr_o(pslverr), .irq_o(irq_o), .in_valid_i(in_valid_i), .in_ready_o(in_ready_o),
    .c1_i(sr_q[0 +: IN_W]), .c2_i(sr_q[IN_W +: IN_W]), .c3_i(sr_q[2*IN_W +: IN_W]),
    .c4_i(sr_q[3*IN_W +: IN_W]),
    .out_valid_o(out_valid_o), .angle_o(angle_o), .los_o(los_o), .dos_o(dos_o),
    .a_o(a_o), .b_o(b_o), .z_o(z_o), .u_o(u_o), .v_o(v_o), .w_o(w_o),
    .sclk_i(sclk_i), .csn_i(csn_i), .mosi_i(mosi_i), .miso_o(miso_o), .miso_oe_o(miso_oe_o));

endmodule

`resetall
