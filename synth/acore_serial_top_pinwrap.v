// SPDX-License-Identifier: MIT
// acore_serial_top_pinwrap: acore_serial_top for place and route, as acore_top_pinwrap.v does for
// the pipelined top: the wide, slowly changing inputs (register port data/address, status window)
// and the channel codes are loaded through a serial shift register (sdi_i, shift_i), so every timed
// path starts and ends at a flop (the core reads the channel codes straight into its adder in the
// accepting clock); the handshake and the results stay on pins.
`resetall
`default_nettype none

module acore_serial_top_pinwrap #(
  // The datapath parameters (a registry line's parameters mean the same here as on the top) and
  // the power-up register image; the port widths follow them.
`include "acore_datapath_params.vh"
  parameter INIT_FILE = ""
) (
  input  wire        clk_i,
  input  wire        rst_i,
  input  wire        sdi_i,
  input  wire        shift_i,
  input  wire        reg_we_i,
  output wire [REG_W-1:0] reg_rdata_o,
  input  wire        in_valid_i,
  output wire        in_ready_o,
  output wire        out_valid_o,
  input  wire        out_ready_i,
  output wire [ANGLE_W-1:0] angle_o,
  output wire [$clog2(REGIONS)-1:0] region_o,
  output wire        ovf_o,
  output wire        los_o,
  output wire        dos_o
);

`include "acore_derived.vh"

  // The top's map and status window width (rtl/acore_derived.vh, the top's own functions).
  localparam integer WORDS = acore_words(acore_terms(CORRECTION, DEGREE), REGIONS, K, FOURIER_K, ZERO);
  localparam integer ADDR_W = $clog2(WORDS);
  localparam integer MAG_W = acore_mag_w(S_W);
  // c1..c4, mag_lo, mag_hi, register data and address.
  localparam integer SR_W = 4 * IN_W + 2 * MAG_W + REG_W + ADDR_W;
  localparam integer C_AT = ADDR_W + REG_W + 2 * MAG_W;  // c1's first bit
  reg [SR_W-1:0] sr_q;
  always @(posedge clk_i) if (shift_i) sr_q <= {sr_q[SR_W-2:0], sdi_i};

  acore_serial_top #(
`include "acore_datapath_pass.vh"
    .INIT_FILE(INIT_FILE)
  ) u_top (
    .clk_i(clk_i), .rst_i(rst_i),
    .reg_addr_i(sr_q[ADDR_W-1:0]), .reg_wdata_i(sr_q[ADDR_W +: REG_W]), .reg_we_i(reg_we_i),
    .reg_rdata_o(reg_rdata_o),
    .mag_lo_i(sr_q[ADDR_W+REG_W +: MAG_W]), .mag_hi_i(sr_q[ADDR_W+REG_W+MAG_W +: MAG_W]),
    .in_valid_i(in_valid_i), .in_ready_o(in_ready_o),
    .c1_i(sr_q[C_AT +: IN_W]), .c2_i(sr_q[C_AT+IN_W +: IN_W]), .c3_i(sr_q[C_AT+2*IN_W +: IN_W]),
    .c4_i(sr_q[C_AT+3*IN_W +: IN_W]),
    .out_valid_o(out_valid_o), .out_ready_i(out_ready_i),
    .angle_o(angle_o), .region_o(region_o), .ovf_o(ovf_o), .los_o(los_o), .dos_o(dos_o));

endmodule

`resetall
