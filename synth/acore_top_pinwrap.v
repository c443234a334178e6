// SPDX-License-Identifier: MIT
// acore_top_pinwrap: acore_top for place and route on a device with fewer pins than the top has
// ports. The wide, slowly changing inputs (register port data/address, status window) and the
// channel codes are loaded through a serial shift register (sdi_i, shift_i); the handshake and the
// results stay on pins. The shift register adds flops, not logic on the datapath's paths.
`resetall
`default_nettype none

module acore_top_pinwrap #(
  parameter integer DEGREE = 3,
  // Clocks per sample of the top (1, 2, 4, 8).
  parameter integer FOLD = 1
) (
  input  wire        clk_i,
  input  wire        rst_i,
  input  wire        sdi_i,
  input  wire        shift_i,
  input  wire        reg_we_i,
  output wire [17:0] reg_rdata_o,
  input  wire        in_valid_i,
  output wire        in_ready_o,
  output wire        out_valid_o,
  input  wire        out_ready_i,
  output wire [15:0] angle_o,
  output wire [1:0]  region_o,
  output wire        ovf_o,
  output wire        los_o,
  output wire        dos_o
);

  localparam integer WORDS = 4 + 8 * (DEGREE + 1) + 16;
  localparam integer ADDR_W = $clog2(WORDS);
  // c1..c4, mag_lo, mag_hi, register data and address.
  localparam integer SR_W = 4 * 16 + 2 * 20 + 18 + ADDR_W;
  reg [SR_W-1:0] sr_q;
  always @(posedge clk_i) if (shift_i) sr_q <= {sr_q[SR_W-2:0], sdi_i};

  acore_top #(.DEGREE(DEGREE), .FOLD(FOLD)) u_top (
    .clk_i(clk_i), .rst_i(rst_i),
    .reg_addr_i(sr_q[ADDR_W-1:0]), .reg_wdata_i(sr_q[ADDR_W +: 18]), .reg_we_i(reg_we_i),
    .reg_rdata_o(reg_rdata_o),
    .mag_lo_i(sr_q[ADDR_W+18 +: 20]), .mag_hi_i(sr_q[ADDR_W+38 +: 20]),
    .in_valid_i(in_valid_i), .in_ready_o(in_ready_o),
    .c1_i(sr_q[ADDR_W+58 +: 16]), .c2_i(sr_q[ADDR_W+74 +: 16]), .c3_i(sr_q[ADDR_W+90 +: 16]),
    .c4_i(sr_q[ADDR_W+106 +: 16]),
    .out_valid_o(out_valid_o), .out_ready_i(out_ready_i),
    .angle_o(angle_o), .region_o(region_o), .ovf_o(ovf_o), .los_o(los_o), .dos_o(dos_o));

endmodule

`resetall
