// SPDX-License-Identifier: MIT
// acore_cordic16: the stand-alone 16-bit CORDIC measured by synth/ (the `cordic16` line of
// rtl/configs.txt: 16-bit x/y, 16-bit angle over the full circle, NORM=1) with its arctangent table
// as constants, like a core with a ROM table. Its parameters and atan words are in
// synth/acore_cordic16_atan.vh, written from the model's cordic_atan_table() by acore_gen_tables
// (checked in; the CTest gen_tables_current fails when it is not what the model writes). The
// inputs are registered once here (one clock more than acore_cordic's LATENCY) so that every timed
// path is register to register. 69 I/O pins: no pin wrapper needed.
`resetall
`default_nettype none

module acore_cordic16 (
  input  wire        clk_i,
  input  wire        en_i,
  input  wire [15:0] x_i,
  input  wire [15:0] y_i,
  output wire [15:0] angle_o,
  output wire [17:0] mag_o
);
`include "acore_cordic16_atan.vh"

  reg [15:0] x_q, y_q;
  always @(posedge clk_i) begin
    if (en_i) begin
      x_q <= x_i;
      y_q <= y_i;
    end
  end

  acore_cordic #(
    .IN_W(C16_IN_W), .G(C16_G), .Z_W(C16_Z_W), .ANGLE_W(C16_ANGLE_W), .K(C16_K), .AT_W(C16_AT_W),
    .NORM(C16_NORM), .SPLIT(C16_SPLIT)
  ) u_cordic (
    .clk_i(clk_i), .en_i(en_i), .x_i(x_q), .y_i(y_q), .atan_i(C16_ATAN), .angle_o(angle_o), .mag_o(mag_o)
  );

endmodule

`resetall
