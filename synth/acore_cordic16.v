// SPDX-License-Identifier: MIT
// acore_cordic16: the stand-alone 16-bit CORDIC measured by synth/ (the `cordic16` line of
// rtl/configs.txt: 16-bit x/y, 16-bit angle over the full circle, NORM=1) with its arctangent table
// as constants, like a core with a ROM table (ZTAB=1: the angle updates of each 4 stages are one
// lookup in a table of their sums; the registry line cordic16_ztab simulates that). Its parameters and atan words are in
// synth/acore_cordic16_atan.vh, written from the model's cordic_atan_table() by acore_gen_tables
// (checked in; the CTest gen_tables_current fails when it is not what the model writes). The
// inputs are registered once here (one clock more than acore_cordic's LATENCY) so that every timed
// path is register to register. acore_cordic16_pinwrap (below) is what the pnr flow places.
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
    .NORM(C16_NORM), .SPLIT(C16_SPLIT), .ZTAB(1)
  ) u_cordic (
    .clk_i(clk_i), .en_i(en_i), .x_i(x_q), .y_i(y_q), .atan_i(C16_ATAN), .angle_o(angle_o), .mag_o(mag_o)
  );

endmodule

// acore_cordic16_pinwrap: the 16-bit CORDIC for place and route, measured as the angle-only
// CORDICs it is compared with: x and y are loaded through a serial shift register (sdi_i, shift_i),
// so the pin count does not limit the placement, the enable is registered, and only the angle is
// on pins (the magnitude is not read, so its output register and the last X adder are trimmed).
module acore_cordic16_pinwrap (
  input  wire        clk_i,
  input  wire        sdi_i,
  input  wire        shift_i,
  input  wire        en_i,
  output wire [15:0] angle_o
);
  reg [31:0] sr_q;
  reg en_q;
  always @(posedge clk_i) begin
    if (shift_i) sr_q <= {sr_q[30:0], sdi_i};
    en_q <= en_i;
  end
  wire [17:0] mag_unused;
  acore_cordic16 u_cordic (
    .clk_i(clk_i), .en_i(en_q), .x_i(sr_q[15:0]), .y_i(sr_q[31:16]), .angle_o(angle_o),
    .mag_o(mag_unused));
endmodule

// acore_cordic16_serial: the word-serial, angle-only CORDIC (rtl/acore_cordic_serial.v) in the same
// 16-bit configuration (the `cordic16` line's parameters, so the model's exhaustive accuracy holds
// for it) with its arctangent table as constants (a ROM indexed by the iteration counter).
module acore_cordic16_serial (
  input  wire        clk_i,
  input  wire        rst_i,
  input  wire        in_valid_i,
  output wire        in_ready_o,
  input  wire [15:0] x_i,
  input  wire [15:0] y_i,
  output wire        out_valid_o,
  input  wire        out_ready_i,
  output wire [15:0] angle_o
);
`include "acore_cordic16_atan.vh"

  acore_cordic_serial #(
    .IN_W(C16_IN_W), .G(C16_G), .Z_W(C16_Z_W), .ANGLE_W(C16_ANGLE_W), .K(C16_K), .AT_W(C16_AT_W),
    .NORM(C16_NORM)
  ) u_cordic (
    .clk_i(clk_i), .rst_i(rst_i), .in_valid_i(in_valid_i), .in_ready_o(in_ready_o), .x_i(x_i),
    .y_i(y_i), .atan_i(C16_ATAN), .out_valid_o(out_valid_o), .out_ready_i(out_ready_i),
    .angle_o(angle_o)
  );
endmodule

// acore_cordic16_serial_pinwrap: the word-serial CORDIC for place and route, measured as the
// pipelined one (acore_cordic16_pinwrap): x and y loaded through a serial shift register, the
// handshake and the angle on pins.
module acore_cordic16_serial_pinwrap (
  input  wire        clk_i,
  input  wire        rst_i,
  input  wire        sdi_i,
  input  wire        shift_i,
  input  wire        in_valid_i,
  output wire        in_ready_o,
  output wire        out_valid_o,
  input  wire        out_ready_i,
  output wire [15:0] angle_o
);
  reg [31:0] sr_q;
  always @(posedge clk_i) if (shift_i) sr_q <= {sr_q[30:0], sdi_i};
  acore_cordic16_serial u_cordic (
    .clk_i(clk_i), .rst_i(rst_i), .in_valid_i(in_valid_i), .in_ready_o(in_ready_o),
    .x_i(sr_q[15:0]), .y_i(sr_q[31:16]), .out_valid_o(out_valid_o), .out_ready_i(out_ready_i),
    .angle_o(angle_o));
endmodule

`resetall
