// SPDX-License-Identifier: MIT
// acore_cordic_serial: word-serial CORDIC arctangent over the full circle, angle only: one stage
// unit iterates K times on one vector, a vector every K clocks. The same arithmetic as
// acore_cordic's angle (model/ip/stages/cordic.cpp, bit for bit), so the model and its exhaustive
// accuracy figures hold for it too:
//
//   accept:  ax = |x|, ay = |y|, yr = x < 0 ? -y : y, sx = (x < 0)                    (clock A)
//   NORM=1:  L = IN_W-2 - msb(ax | ay) when positive, else 0 (NORM=0: L = 0)          (clock B)
//   load:    X = ax << L << G, Y = yr << L << G, Z = sx 2^(Z_W-1) + 2^(DROP-1)
//   i = 0..K-1, one per clock, s = (Y < 0):
//       X += (Y >>> i) ^ {s} + s,  Y += (X >> i) ^ {~s} + ~s,  Z += atan_i ^ {s} + s  (mod 2^Z_W)
//   angle = Z[Z_W-1:DROP]
// The pre-rotation of the pipelined CORDIC (X < 0: negate both, add half a turn) is the |x| and
// the sign-selected y of clock A, and its output rounding, round_shr(Z, DROP) = (Z + 2^(DROP-1))
// >> DROP, is the 2^(DROP-1) in Z's initial value (Z adds modulo 2^Z_W, so the order does not
// matter): no adder of its own. The shifts by i are barrel shifters on the iteration counter; the
// arctangent word i is chosen from atan_i by the same counter (a ROM when atan_i is constant).
//
// Clock A, clock B and the iterations are an elastic pipeline (valid/ready): a vector is accepted
// while the previous one iterates, so in steady state one vector leaves every K clocks
// (CYCLES = K); LATENCY = K + 3 from the accepting clock edge to out_valid_o without stalls.
// out_valid_o/angle_o hold while out_ready_i is low (the unit then waits at its last iteration).
`resetall
`default_nettype none

module acore_cordic_serial #(
  // Width of the signed x/y inputs.
  parameter integer IN_W = 16,
  // Guard fraction bits of the x/y registers.
  parameter integer G = 4,
  // Angle accumulator, one turn = 2^Z_W.
  parameter integer Z_W = 21,
  // Output angle width, unsigned, one turn = 2^ANGLE_W.
  parameter integer ANGLE_W = 16,
  // Iterations (clocks per vector).
  parameter integer K = 17,
  // Width of one arctangent word on atan_i (zero-extended to Z_W, or used modulo 2^Z_W).
  parameter integer AT_W = 20,
  // 1: leading-bit normalization so short vectors keep full angle precision.
  parameter integer NORM = 1,
  // Derived, do not override.
  parameter integer XY_W = acore_xy_w(IN_W, G)
) (
  input  wire                clk_i,
  // Synchronous reset: empties the pipeline (no vector in flight, out_valid_o low).
  input  wire                rst_i,
  input  wire                in_valid_i,
  output wire                in_ready_o,
  // Cosine-like input x and sine-like input y.
  input  wire [IN_W-1:0]     x_i,
  input  wire [IN_W-1:0]     y_i,
  // atan_i for i = 0..K-1, word i at bits [i AT_W +: AT_W].
  input  wire [K*AT_W-1:0]   atan_i,
  output reg                 out_valid_o,
  input  wire                out_ready_i,
  output reg  [ANGLE_W-1:0]  angle_o
);

`include "acore_derived.vh"

  // Derived, do not override.
  localparam integer LATENCY = K + 3;
  localparam integer CYCLES = K;
  localparam integer DROP = Z_W - ANGLE_W;
  localparam integer SH_W = $clog2(IN_W);
  localparam integer CNT_W = $clog2(K);
  localparam integer CNT_LAST = K - 1;

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(Z_W >= ANGLE_W), .VALUE(Z_W),
    .MSG("illegal parameter: acore_cordic_serial: Z_W must be >= ANGLE_W"))
    Z_W_must_be_at_least_ANGLE_W ();
  acore_check #(.OK(K >= 2 && K < XY_W), .VALUE(K),
    .MSG("illegal parameter: acore_cordic_serial: K must be 2..XY_W-1"))
    K_must_be_2_to_XY_W_minus_1 ();
  acore_check #(.OK(XY_W == acore_xy_w(IN_W, G)), .VALUE(XY_W),
    .MSG("illegal parameter: acore_cordic_serial: XY_W is derived (IN_W+2+G), do not override"))
    XY_W_is_derived ();

  // ---- clock A: absolute values and the pre-rotated y ----
  // Conditional negation as (v ^ {s}) + s, one adder each (bit 0 of the wider add makes the carry-in).
  wire sx = x_i[IN_W-1];
  wire sy = y_i[IN_W-1];
  wire [IN_W:0]   ax_sum = {x_i ^ {IN_W{sx}}, 1'b1} + {{IN_W{1'b0}}, sx};
  wire [IN_W:0]   ay_sum = {y_i ^ {IN_W{sy}}, 1'b1} + {{IN_W{1'b0}}, sy};
  wire [IN_W:0]   y_ext = {sy, y_i};
  wire [IN_W+1:0] yr_sum = {y_ext ^ {(IN_W+1){sx}}, 1'b1} + {{(IN_W+1){1'b0}}, sx};

  reg              a_v, b_v, busy;
  reg              a_sx, b_sx;
  reg [IN_W-1:0]   a_ax, a_ay, b_ax;
  reg [IN_W:0]     a_yr, b_yr;
  reg [SH_W-1:0]   b_sh;
  reg [CNT_W-1:0]  cnt;
  reg [XY_W-2:0]   x_q;   // X never goes negative (acore_cordic: no sign bit)
  reg [XY_W-1:0]   y_q;
  reg [Z_W-1:0]    z_q;

  // ---- handshake ----
  wire last = (cnt == CNT_LAST[CNT_W-1:0]);
  wire out_free = !out_valid_o || out_ready_i;
  wire finish = busy && last && out_free;      // the last iteration writes the angle
  wire step = busy && (!last || out_free);     // an iteration happens this clock
  wire load = b_v && (!busy || finish);        // the next vector enters the unit
  wire b_ready = !b_v || load;
  wire a_ready = !a_v || b_ready;
  assign in_ready_o = a_ready;
  wire accept = in_valid_i && a_ready;

  // ---- clock B: the normalization shift ----
  // L = IN_W-2 - msb(m) when positive, m = |x| | |y| (the model's shift); 0 for m = 0.
  function automatic [SH_W-1:0] norm_shift(input [IN_W-1:0] m);
    integer b, l;
    begin
      norm_shift = {SH_W{1'b0}};
      for (b = 0; b < IN_W; b = b + 1) begin
        l = (b < IN_W - 2) ? IN_W - 2 - b : 0;
        if (m[b]) norm_shift = l[SH_W-1:0];
      end
    end
  endfunction
  wire [SH_W-1:0] sh_d = (NORM != 0) ? norm_shift(a_ax | a_ay) : {SH_W{1'b0}};

  always @(posedge clk_i) begin
    if (rst_i) begin
      a_v <= 1'b0;
      b_v <= 1'b0;
    end else begin
      if (a_ready) a_v <= in_valid_i;
      if (b_ready) b_v <= a_v;
    end
    if (accept) begin
      a_sx <= sx;
      a_ax <= ax_sum[IN_W:1];
      a_ay <= ay_sum[IN_W:1];
      a_yr <= yr_sum[IN_W+1:1];
    end
    if (b_ready) begin
      b_sx <= a_sx;
      b_ax <= a_ax;
      b_yr <= a_yr;
      b_sh <= sh_d;
    end
  end

  // ---- the stage unit ----
  wire s = y_q[XY_W-1];
  wire [XY_W-1:0] ys_full = $signed(y_q) >>> cnt;
  wire [XY_W-2:0] ys = ys_full[XY_W-2:0];
  wire [XY_W-1:0] xs = {1'b0, x_q >> cnt};
  // Word cnt of atan_i (a K:1 choice; counts past K-1 are never used).
  reg [AT_W-1:0] at_word;
  integer w;
  always @* begin
    at_word = atan_i[AT_W-1:0];
    for (w = 1; w < K; w = w + 1)
      if ({{(32-CNT_W){1'b0}}, cnt} == w) at_word = atan_i[w * AT_W +: AT_W];
  end
  wire [Z_W-1:0]  at;
  generate
    if (AT_W > Z_W) begin : g_at_low
      // Z counts modulo a turn: a word's bits above Z_W do not change it (as acore_cordic).
      assign at = at_word[Z_W-1:0];
      wire unused_at_high = ^at_word[AT_W-1:Z_W];
    end else begin : g_at_ext
      assign at = {{(Z_W-AT_W){1'b0}}, at_word};
    end
  endgenerate
  // {a, 1} + {b, c}: bit 0 carries c into the real sum, so this is a + b + c in one adder.
  wire [XY_W-1:0] x_sum = {x_q, 1'b1} + {ys ^ {(XY_W-1){s}}, s};
  wire [XY_W:0]   y_sum = {y_q, 1'b1} + {xs ^ {XY_W{~s}}, ~s};
  wire [Z_W:0]    z_sum = {z_q, 1'b1} + {at ^ {Z_W{s}}, s};

  // The loaded vector: shifted by L (no overflow: the msb lands at IN_W-2 unless L = 0), then G
  // guard bits. Z starts at half a turn when x < 0, plus the output rounding's half LSB.
  wire [IN_W:0] ax_sh = {1'b0, b_ax} << b_sh;
  wire [IN_W:0] yr_sh = b_yr << b_sh;
  wire [Z_W-1:0] z_init;
  generate
    if (DROP > 0) begin : g_rnd
      assign z_init = {b_sx, {(Z_W-1){1'b0}}} | ({{(Z_W-1){1'b0}}, 1'b1} << (DROP - 1));
    end else begin : g_nornd
      assign z_init = {b_sx, {(Z_W-1){1'b0}}};
    end
  endgenerate

  always @(posedge clk_i) begin
    if (rst_i) begin
      busy <= 1'b0;
      out_valid_o <= 1'b0;
    end else begin
      if (load) busy <= 1'b1;
      else if (finish) busy <= 1'b0;
      if (finish) out_valid_o <= 1'b1;
      else if (out_ready_i) out_valid_o <= 1'b0;
    end
    if (load) begin
      x_q <= {ax_sh, {G{1'b0}}};
      y_q <= {yr_sh[IN_W], yr_sh, {G{1'b0}}};
      z_q <= z_init;
      cnt <= {CNT_W{1'b0}};
    end else if (step) begin
      x_q <= x_sum[XY_W-1:1];
      y_q <= y_sum[XY_W:1];
      z_q <= z_sum[Z_W:1];
      cnt <= cnt + 1'b1;
    end
    if (finish) angle_o <= z_sum[Z_W:DROP+1];
  end

endmodule

`resetall
