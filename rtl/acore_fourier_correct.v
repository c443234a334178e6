// SPDX-License-Identifier: MIT
// acore_fourier_correct: stage 6 (optional), the angle-domain Fourier correction after the CORDIC
// (model/ip/stages/fourier_correct.cpp, bit for bit):
//
//   angle_o = angle_i - Delta(angle_i),  Delta = a_0 + sum_{k=1..K} (a_k cos k theta + b_k sin k theta)
//
// One rotation CORDIC per harmonic, all K in parallel, then one adder tree (A = ANGLE_W):
//
//   u_k = (k theta) mod 2^A                           shift-add of theta (acore_shift_add_mul)
//   q = u[A-1:A-2] + u[A-3], phi = u[A-3:0] signed    u = q quarter turns + phi, |phi| <= 1/8 turn
//   (x, y) = (a'_k, b'_k) << G turned clockwise by q quarter turns, -v as ~v (no adder):
//            (a'_k, b'_k: the low W bits of their words, signed)
//            q = 0: (x, y)   1: (y, ~x)   2: (~x, ~y)   3: (~y, x)
//   X_k = acore_cordic_rotate(x, y, phi << (Z_W - A))  ~= (a_k cos k theta + b_k sin k theta) << G
//   D   = ((a_0 << G) + sum_k X_k) mod 2^F             F = CF + G fraction bits of a turn
//   angle_o = round_shr((theta << (F - A)) - D, F - A) mod 2^A
//
// The words are a_0 (REG_W bits) and a'_k = a_k / G_M, b'_k = b_k / G_M (W bits), CF fraction bits of
// a turn: the rotation gain G_M < 1.65 is compensated in the start vector by the calibration, so
// there is no scaling multiplier. |(x, y)| <= sqrt 2 2^(W-1+G) and the rotation grows it by G_M,
// below 2.33 2^(W-1+G), so XY_W = W + 2 + G bits hold any register contents. D and the output are
// modulo a turn.
//
//   clocks: KL (k theta, clog2(KB) adder levels) + 1 (quadrant, start vector) + M (rotation)
//           + clog2(K+1) (sum) + 1 (round and subtract) = LATENCY
`resetall
`default_nettype none

module acore_fourier_correct #(
  // Angle width, unsigned, one turn = 2^ANGLE_W (the CORDIC's output).
  parameter integer ANGLE_W = 16,
  // Register word width (the coefficient words, signed).
  parameter integer REG_W = 18,
  // Scale of the arctangent words: one turn = 2^Z_W.
  parameter integer Z_W = 20,
  // Harmonics K, >= 1 (2K+1 coefficient words).
  parameter integer K = 21,
  // Rotation-CORDIC stages per harmonic (the first M arctangent words).
  parameter integer M = 12,
  // Coefficient fraction bits, in turns (word * 2^-CF turn).
  parameter integer CF = 22,
  // Significant bits of a harmonic's word (signed, the low W bits of the REG_W word).
  parameter integer W = 16,
  // Guard fraction bits of the rotation x/y registers.
  parameter integer G = 2,
  // Width of one arctangent word on atan_i.
  parameter integer AT_W = 18,
  // 0: products on adders and shifters; 1: on hardware multipliers (acore_hw_mul.v, DSP blocks).
  parameter integer MULT = 0
) (
  input  wire                        clk_i,
  // Pipeline advance (the whole pipeline stalls together).
  input  wire                        en_i,
  // The CORDIC's angle.
  input  wire [ANGLE_W-1:0]          angle_i,
  // The Fourier words of the map, a_0, a'_1, b'_1, ..., a'_K, b'_K; word j at bits [j REG_W +: REG_W].
  input  wire [acore_fourier_words(K)*REG_W-1:0] coef_i,
  // atan(2^-i) for i = 0..M-1 (the register file's first M CORDIC words).
  input  wire [M*AT_W-1:0]           atan_i,
  // Corrected angle, LATENCY advancing clocks after angle_i.
  output reg  [ANGLE_W-1:0]          angle_o
);

`include "acore_derived.vh"

  // Derived, do not override.
  localparam integer F = CF + G;                              // fraction bits of D (turns)
  localparam integer S = F - ANGLE_W;                         // rounding shift of the output
  localparam integer XY_W = acore_xy_w(W, G);
  localparam integer KB = acore_fourier_kb(K);                // bits of the constant k
  localparam integer LATENCY = acore_fourier_latency(K, M);

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(K >= 1 && K <= 31), .VALUE(K),
    .MSG("illegal parameter: acore_fourier_correct: K must be 1..31"))
    K_must_be_1_to_31 ();
  acore_check #(.OK(S >= 1), .VALUE(F),
    .MSG("illegal parameter: acore_fourier_correct: CF+G must exceed ANGLE_W"))
    CF_plus_G_must_exceed_ANGLE_W ();
  acore_check #(.OK(CF >= REG_W - 1), .VALUE(CF),
    .MSG("illegal parameter: acore_fourier_correct: CF must be >= REG_W-1"))
    CF_must_be_at_least_REG_W_minus_1 ();
  acore_check #(.OK(ANGLE_W >= 4 && ANGLE_W < Z_W), .VALUE(ANGLE_W),
    .MSG("illegal parameter: acore_fourier_correct: ANGLE_W must be 4..Z_W-1"))
    ANGLE_W_must_be_4_to_Z_W_minus_1 ();
  acore_check #(.OK(W >= 8 && W <= REG_W), .VALUE(W),
    .MSG("illegal parameter: acore_fourier_correct: W must be 8..REG_W"))
    W_must_be_8_to_REG_W ();

  // ---- per harmonic: k theta, quadrant and start vector, rotation ----
  localparam integer TERMS_W = (K + 1) * F;
  wire [TERMS_W-1:0] terms;
  // Term 0: a_0 << G, sign-extended (or wrapped) to F bits.
  wire [REG_W+G-1:0] a0_g = {coef_i[REG_W-1:0], {G{1'b0}}};
  wire [F+REG_W+G-1:0] a0_ext = {{F{a0_g[REG_W+G-1]}}, a0_g};
  assign terms[F-1:0] = a0_ext[F-1:0];

  genvar k;
  generate
    for (k = 1; k <= K; k = k + 1) begin : g_harm
      // u = k theta mod 2^A on the shift-add multiplier (theta as a positive signed word).
      localparam integer KP_W = ANGLE_W + KB + 2;
      localparam [KB-1:0] KC = k;
      wire [KP_W-1:0] kp;
      acore_shift_add_mul #(
        .A_W(ANGLE_W + 1), .B_W(KB), .B_SIGNED(0), .RSHIFT(0), .P_W(KP_W), .MULT(MULT)
      ) u_ktheta (
        .clk_i(clk_i), .en_i(en_i), .a_i({1'b0, angle_i}), .b_i(KC), .p_o(kp)
      );
      wire [ANGLE_W-1:0] u = kp[ANGLE_W-1:0];
      wire [1:0] q = u[ANGLE_W-1:ANGLE_W-2] + {1'b0, u[ANGLE_W-3]};
      // Start vector (a'_k, b'_k) << G.
      localparam integer OFF_A = acore_fourier_a(k) * REG_W;
      localparam integer OFF_B = acore_fourier_b(k) * REG_W;
      wire [XY_W-1:0] xa = {{2{coef_i[OFF_A + W - 1]}}, coef_i[OFF_A +: W], {G{1'b0}}};
      wire [XY_W-1:0] yb = {{2{coef_i[OFF_B + W - 1]}}, coef_i[OFF_B +: W], {G{1'b0}}};
      reg [XY_W-1:0] x0_q, y0_q;
      reg [Z_W-3:0]  z0_q;
      always @(posedge clk_i) begin
        if (en_i) begin
          case (q)
            2'd0: begin x0_q <= xa;  y0_q <= yb;  end
            2'd1: begin x0_q <= yb;  y0_q <= ~xa; end
            2'd2: begin x0_q <= ~xa; y0_q <= ~yb; end
            default: begin x0_q <= ~yb; y0_q <= xa; end
          endcase
          z0_q <= {u[ANGLE_W-3:0], {(Z_W-ANGLE_W){1'b0}}};
        end
      end
      wire [XY_W-1:0] xk;
      acore_cordic_rotate #(.XY_W(XY_W), .Z_W(Z_W), .M(M), .AT_W(AT_W)) u_rot (
        .clk_i(clk_i), .en_i(en_i), .x_i(x0_q), .y_i(y0_q), .z_i(z0_q), .atan_i(atan_i), .x_o(xk));
      // Sign-extended (or wrapped) to F bits: the sum is modulo a turn.
      wire [F+XY_W-1:0] xk_ext = {{F{xk[XY_W-1]}}, xk};
      localparam integer OFF_T = k * F;
      assign terms[OFF_T +: F] = xk_ext[F-1:0];
    end
  endgenerate

  // ---- D = sum of the terms mod 2^F ----
  wire [F-1:0] d;
  acore_adder_tree #(.N(K + 1), .W(F)) u_sum (.clk_i(clk_i), .en_i(en_i), .terms_i(terms), .sum_o(d));

  // ---- angle_o = round_shr((theta << S) - D, S): half an LSB is a constant bit below theta ----
  wire [ANGLE_W-1:0] theta_d;
  // theta beside k theta, the rotations and the sum, to the round-and-subtract clock.
  acore_delay #(.W(ANGLE_W), .DEPTH(LATENCY - 1)) u_dtheta (
    .clk_i(clk_i), .en_i(en_i), .d_i(angle_i), .q_o(theta_d));
  localparam [F-1:0] HALF = {{(F-1){1'b0}}, 1'b1} << (S - 1);
  wire [F-1:0] theta_half = {theta_d, {S{1'b0}}} | HALF;
  wire [F-1:0] v = theta_half - d;
  always @(posedge clk_i) if (en_i) angle_o <= v[F-1:S];

endmodule

`resetall
