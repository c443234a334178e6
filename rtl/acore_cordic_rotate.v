// SPDX-License-Identifier: MIT
// acore_cordic_rotate: pipelined rotation-mode CORDIC (model/ip/stages/cordic_rotate.cpp, bit for bit): turns
// (x, y) clockwise by the angle z and returns X_M, the building block of the Fourier correction.
//
//   stage i = 0..M-1, s = (z_i < 0):                       (1 clock each, one adder per word)
//       X += (Y >>> i) ^ {s}  + s        i.e. X += s ? -(Y>>>i) : (Y>>>i)
//       Y += (X >>> i) ^ {~s} + ~s       i.e. Y -= s ? -(X>>>i) : (X>>>i)
//       z += atan_i ^ {~s} + ~s          i.e. z -= s ? -atan_i : atan_i
//   x_o = X_M = G_M (x, y) turned clockwise by z, G_M = prod sqrt(1 + 2^-2i) < 1.65
//
// z (one turn = 2^Z_W) enters on Z_W-2 signed bits, |z| < 2^(Z_W-3) (1/8 turn). Entering stage i,
// |z_i| <= sum_{j>=i} atan(2^-j) < 2^(1-i) rad, so stage i keeps z on ZW(i) = min(Z_W-2, Z_W-i) bits
// (1.5x above the bound, tests/ip/stages/test_fourier_correct.cpp checks it for every start angle); a stage
// computes only the ZW(i+1) bits the next one reads. Words that are not arctangents make z wrap
// there, as in the model. X and Y never overflow for |x|, |y| < 2^(XY_W-3): the vector grows by
// at most sqrt 2 G_M < 2.33 (the caller sizes XY_W; see acore_fourier_correct.v).
`resetall
`default_nettype none

module acore_cordic_rotate #(
  // Width of the signed x/y words.
  parameter integer XY_W = 24,
  // Angle scale: one turn = 2^Z_W.
  parameter integer Z_W = 20,
  // Stages (iterations).
  parameter integer M = 12,
  // Width of one arctangent word on atan_i (unsigned, atan_i = round(atan(2^-i)/2pi 2^Z_W)).
  parameter integer AT_W = 18
) (
  input  wire                clk_i,
  // Pipeline advance (the whole pipeline stalls together).
  input  wire                en_i,
  input  wire [XY_W-1:0]     x_i,
  input  wire [XY_W-1:0]     y_i,
  // Angle to turn clockwise, signed, |z_i| < 2^(Z_W-3).
  input  wire [Z_W-3:0]      z_i,
  // atan_i for i = 0..M-1, word i at bits [i AT_W +: AT_W].
  input  wire [M*AT_W-1:0]   atan_i,
  // X after M stages, LATENCY = M advancing clocks after x_i/y_i/z_i.
  output wire [XY_W-1:0]     x_o
);

`include "acore_derived.vh"

  // Derived, do not override.
  localparam integer ZI_W = Z_W - 2;
  localparam integer LATENCY = acore_cordic_rotate_latency(M);

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(M >= 2 && M < XY_W && M <= Z_W - 4), .VALUE(M),
    .MSG("illegal parameter: acore_cordic_rotate: M must be 2..min(XY_W-1, Z_W-4)"))
    M_must_be_2_to_min_XY_W_minus_1_Z_W_minus_4 ();

  // Stage registers (stage i reads x_q[i], ...; stage 0 reads the inputs). z is stored
  // sign-extended to ZI_W bits; only its low ZW(i) bits are computed.
  reg [XY_W-1:0] x_q [1:M];
  reg [XY_W-1:0] y_q [1:M-1];
  reg [ZI_W-1:0] z_q [1:M-1];

  genvar i;
  generate
    for (i = 0; i < M; i = i + 1) begin : g_stage
      wire [XY_W-1:0] x_c, y_c;
      wire [ZI_W-1:0] z_c;
      if (i == 0) begin : g_in
        assign x_c = x_i;
        assign y_c = y_i;
        assign z_c = z_i;
      end else begin : g_reg
        assign x_c = x_q[i];
        assign y_c = y_q[i];
        assign z_c = z_q[i];
      end
      // s = (z < 0): turn counter-clockwise by atan_i instead.
      wire s = z_c[ZI_W-1];
      wire [XY_W-1:0] ys = $signed(y_c) >>> i;
      // {a, 1} + {b, c}: bit 0 carries c into the real sum, so this is a + b + c in one adder.
      wire [XY_W:0] x_sum = {x_c, 1'b1} + {ys ^ {XY_W{s}}, s};
      always @(posedge clk_i) if (en_i) x_q[i+1] <= x_sum[XY_W:1];
      // The last stage's Y and z are never read.
      if (i < M - 1) begin : g_yz
        localparam integer ZWN = (i + 1 <= 2) ? ZI_W : Z_W - i - 1;
        wire [XY_W-1:0] xs = $signed(x_c) >>> i;
        wire [XY_W:0] y_sum = {y_c, 1'b1} + {xs ^ {XY_W{~s}}, ~s};
        localparam integer AT_OFF = i * AT_W;
        // Only the low bits count (z wraps modulo a turn): a word wider than Z_W is cut.
        wire [Z_W-1:0] at;
        if (AT_W > Z_W) begin : g_at_low
          assign at = atan_i[AT_OFF +: Z_W];
        end else begin : g_at_ext
          assign at = {{(Z_W-AT_W){1'b0}}, atan_i[AT_OFF +: AT_W]};
        end
        wire [ZWN:0] z_sum = {z_c[ZWN-1:0], 1'b1} + {at[ZWN-1:0] ^ {ZWN{~s}}, ~s};
        always @(posedge clk_i) begin
          if (en_i) begin
            y_q[i+1] <= y_sum[XY_W:1];
            z_q[i+1] <= {{(ZI_W-ZWN){z_sum[ZWN]}}, z_sum[ZWN:1]};
          end
        end
      end
    end
  endgenerate

  assign x_o = x_q[M];

endmodule

`resetall
