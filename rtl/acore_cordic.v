// SPDX-License-Identifier: MIT
// acore_cordic: stage 5, pipelined CORDIC arctangent in vectoring mode over the full circle
// (model/cordic.cpp, bit for bit). angle = atan2(y, x), one turn = 2^ANGLE_W.
//
//   NORM=1: x, y <<= L, L = IN_W-2 - msb(|x| | |y|) when positive     (2 clocks)
//   X = x << G, Y = y << G                               XY_W = IN_W + 2 + G bits
//   pre-rotation: X < 0 -> (X, Y) = (-X, -Y), Z = 2^(Z_W-1); else Z = 0   (1 clock)
//   stage i = 0..K-1, s = (Y < 0):                        (1 clock each, reads x_q[i])
//       X += (Y >>> i) ^ {s}  + s        i.e. X += s ? -(Y>>>i) : (Y>>>i)
//       Y += (X >>> i) ^ {~s} + ~s       i.e. Y -= s ? -(X>>>i) : (X>>>i)
//       Z += atan_i ^ {s} + s             (mod 2^Z_W)
//   angle = round_shr(Z, Z_W - ANGLE_W) mod 2^ANGLE_W;  mag = X_K >>> G   (1 clock)
// Each stage register is fed by exactly one adder per word: the conditional negation is the XOR
// and the carry-in of the same adder, written as one (W+1)-bit add whose bit 0 makes the carry.
// atan_i = round(atan(2^-i) / 2pi * 2^Z_W) comes in on a bus (the register file's last K words).
// X never goes negative and |(X, Y)| grows by the CORDIC gain (< 1.65), so XY_W cannot overflow.
`resetall
`default_nettype none

module acore_cordic #(
  // Width of the signed x/y inputs.
  parameter integer IN_W = 18,
  // Guard fraction bits of the x/y registers.
  parameter integer G = 3,
  // Angle accumulator, one turn = 2^Z_W.
  parameter integer Z_W = 20,
  // Output angle width, unsigned, one turn = 2^ANGLE_W.
  parameter integer ANGLE_W = 16,
  // Iterations = pipeline stages.
  parameter integer K = 16,
  // Width of one arctangent word on atan_i (unsigned, zero-extended to Z_W).
  parameter integer AT_W = 18,
  // 1: leading-bit normalization so short vectors keep full angle precision.
  parameter integer NORM = 0,
  // Derived, do not override.
  parameter integer XY_W = IN_W + 2 + G,
  parameter integer MAG_W = IN_W + 2
) (
  input  wire               clk_i,
  input  wire               en_i,
  // Cosine-like input x and sine-like input y.
  input  wire [IN_W-1:0]    x_i,
  input  wire [IN_W-1:0]    y_i,
  // atan_i for i = 0..K-1, word i at bits [i*AT_W +: AT_W].
  input  wire [K*AT_W-1:0]  atan_i,
  output reg  [ANGLE_W-1:0] angle_o,
  // X_K >>> G: vector length times the CORDIC gain, never negative.
  output reg  [MAG_W-1:0]   mag_o
);

  // Derived, do not override.
  localparam integer NL = (NORM != 0) ? 2 : 0;
  localparam integer LATENCY = NL + 1 + K + 1;
  localparam integer DROP = Z_W - ANGLE_W;

  initial begin
    if (Z_W < ANGLE_W) $error("acore_cordic: Z_W=%0d < ANGLE_W=%0d (instance %m)", Z_W, ANGLE_W);
    if (AT_W > Z_W) $error("acore_cordic: AT_W=%0d > Z_W=%0d (instance %m)", AT_W, Z_W);
    if (K < 1 || K >= XY_W) $error("acore_cordic: K=%0d must be 1..XY_W-1 (instance %m)", K);
    if (XY_W != IN_W + 2 + G || MAG_W != IN_W + 2) $error("acore_cordic: XY_W/MAG_W are derived (instance %m)");
  end

  // ---- optional normalization ----
  wire [IN_W-1:0] xn, yn;
  generate
    if (NORM != 0) begin : g_norm
      localparam integer SH_W = $clog2(IN_W);
      wire [IN_W-1:0] ax = x_i[IN_W-1] ? ({IN_W{1'b0}} - x_i) : x_i;
      wire [IN_W-1:0] ay = y_i[IN_W-1] ? ({IN_W{1'b0}} - y_i) : y_i;
      wire [IN_W-1:0] mag = ax | ay;
      // L = IN_W-2 - msb(mag) if positive: the highest set bit wins.
      reg [SH_W-1:0] sh;
      integer b, l;
      always @* begin
        sh = {SH_W{1'b0}};
        for (b = 0; b < IN_W - 2; b = b + 1) begin
          l = IN_W - 2 - b;
          if (mag[b]) sh = l[SH_W-1:0];
        end
        if (mag[IN_W-1] | mag[IN_W-2]) sh = {SH_W{1'b0}};
      end
      reg [IN_W-1:0] x_n0_q, y_n0_q, x_n1_q, y_n1_q;
      reg [SH_W-1:0] sh_q;
      always @(posedge clk_i) begin
        if (en_i) begin
          x_n0_q <= x_i;
          y_n0_q <= y_i;
          sh_q   <= sh;
          x_n1_q <= x_n0_q << sh_q;
          y_n1_q <= y_n0_q << sh_q;
        end
      end
      assign xn = x_n1_q;
      assign yn = y_n1_q;
    end else begin : g_nonorm
      assign xn = x_i;
      assign yn = y_i;
    end
  endgenerate

  // ---- quadrant pre-rotation and the K stages ----
  reg [XY_W-1:0] x_q [0:K];
  reg [XY_W-1:0] y_q [0:K-1];
  reg [Z_W-1:0]  z_q [0:K];

  wire [XY_W-1:0] x0 = {{2{xn[IN_W-1]}}, xn, {G{1'b0}}};
  wire [XY_W-1:0] y0 = {{2{yn[IN_W-1]}}, yn, {G{1'b0}}};
  wire neg0 = xn[IN_W-1];
  always @(posedge clk_i) begin
    if (en_i) begin
      x_q[0] <= neg0 ? ({XY_W{1'b0}} - x0) : x0;
      y_q[0] <= neg0 ? ({XY_W{1'b0}} - y0) : y0;
      z_q[0] <= {neg0, {(Z_W-1){1'b0}}};
    end
  end

  genvar i;
  generate
    for (i = 0; i < K; i = i + 1) begin : g_stage
      wire s = y_q[i][XY_W-1];
      wire [XY_W-1:0] ys = $signed(y_q[i]) >>> i;
      wire [Z_W-1:0]  at = {{(Z_W-AT_W){1'b0}}, atan_i[i*AT_W +: AT_W]};
      // {a, 1} + {b, c}: bit 0 carries c into the real sum, so this is a + b + c in one adder.
      wire [XY_W:0] x_sum = {x_q[i], 1'b1} + {ys ^ {XY_W{s}}, s};
      wire [Z_W:0]  z_sum = {z_q[i], 1'b1} + {at ^ {Z_W{s}}, s};
      always @(posedge clk_i) begin
        if (en_i) begin
          x_q[i+1] <= x_sum[XY_W:1];
          z_q[i+1] <= z_sum[Z_W:1];
        end
      end
      // The last stage's Y is never read.
      if (i < K - 1) begin : g_y
        wire [XY_W-1:0] xs = $signed(x_q[i]) >>> i;
        wire [XY_W:0] y_sum = {y_q[i], 1'b1} + {xs ^ {XY_W{~s}}, ~s};
        always @(posedge clk_i) if (en_i) y_q[i+1] <= y_sum[XY_W:1];
      end
    end
  endgenerate

  // ---- output: round the angle, drop the guard bits of the magnitude ----
  wire [Z_W-1:0] z_k = z_q[K];
  wire [Z_W-1:0] z_rnd;
  generate
    if (DROP > 0) begin : g_rnd
      assign z_rnd = z_k + ({{(Z_W-1){1'b0}}, 1'b1} << (DROP - 1));
    end else begin : g_nornd
      assign z_rnd = z_k;
    end
  endgenerate
  wire [XY_W-1:0] x_k = x_q[K];
  always @(posedge clk_i) begin
    if (en_i) begin
      angle_o <= z_rnd[Z_W-1:DROP];
      mag_o   <= x_k[XY_W-1:G];
    end
  end

endmodule

`resetall
