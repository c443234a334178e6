// SPDX-License-Identifier: MIT
// Stage 6 (optional, FOURIER_K > 0): angle-domain Fourier correction after the CORDIC. Mirrors
// rtl/acore_fourier_correct.v.
//
//   angle_out = theta - Delta(theta),  Delta = a_0 + sum_{k=1..K} (a_k cos k theta + b_k sin k
//   theta)
//
// theta is the CORDIC's angle (ANGLE_W = A bits, one turn = 2^A). Every harmonic has its own
// rotation CORDIC (model/ip/stages/cordic_rotate.hpp), all in parallel; then one adder tree:
//
//   u_k = (k theta) mod 2^A                        shift-add of theta, exact modulo a turn
//   q   = u[A-1:A-2] + u[A-3] (mod 4), phi = sext(u[A-3:0])    u = q quarter turns + phi, |phi| <=
//   1/8 (x, y) = (a'_k, b'_k) << G turned clockwise by q quarter turns, -v taken as ~v = -v - 1 (no
//   adder):
//            q = 0: (x, y)   1: (y, ~x)   2: (~x, ~y)   3: (~y, x)
//   X_k = cordic_rotate(x, y, phi << (Z_W - A), M).x   ~= (a_k cos k theta + b_k sin k theta) << G
//   D   = ((a_0 << G) + sum_k X_k) mod 2^F          F = FOURIER_F = CF + G fraction bits of a turn
//   angle_out = round_shr((theta << (F - A)) - D, F - A) mod 2^A
//
// Register words (CF fraction bits of a turn): a_0 (signed REG_W), then a'_k, b'_k for k = 1..K
// with a'_k = a_k / G_M, b'_k = b_k / G_M, signed FOURIER_W (W) bits (the low W bits of the word;
// the calibration keeps the rest a sign extension): it divides by the rotation gain G_M, so the
// CORDIC starts from a gain-compensated vector and needs no scaling multiplier. X, Y are
// FOURIER_XY_W = W + 2 + G bits: |(x, y)| <= sqrt 2 * 2^(W-1+G) and the rotation grows it by G_M
// < 1.65, so no register can overflow whatever the words hold.
#pragma once
#include <cstdint>
#include <vector>

#include "core/datapath_config.hpp"

namespace acore {

// X_k for one harmonic: coefficient words a, b (their low W bits count), theta an A-bit angle.
int64_t fourier_harmonic(int k, uint32_t theta, int64_t a, int64_t b, const int64_t* atan_table,
                         const DatapathConfig& cfg);
// D in [0, 2^F): coef = the 2K+1 sign-extended words in register order.
int64_t fourier_delta(uint32_t theta, const int64_t* coef, const int64_t* atan_table,
                      const DatapathConfig& cfg);
// The corrected A-bit angle.
uint32_t fourier_correct(uint32_t theta, const int64_t* coef, const int64_t* atan_table,
                         const DatapathConfig& cfg);

// The series in double precision: coef = [a_0, a_1, b_1, ..., a_K, b_K] (any unit), theta in rad.
double fourier_series(double theta, const std::vector<double>& coef);

// The gain every rotation applies: G_M for M = cfg.fourier_iterations.
double fourier_gain(const DatapathConfig& cfg);

// Error budget of D against fourier_series() of the words' real values (a_0, G_M a'_k, G_M b'_k,
// times 2^-CF) at the exact angle theta, in turns: per harmonic, the residual angle of M stages
// (atan(2^-(M-1)) plus M half-LSBs of the table) times the harmonic's amplitude r_k, plus the
// floors: one per stage and word, each < 1 LSB, a vector of < sqrt 2 LSB grown by at most G_M, and
// the one's complement negation (the same): sqrt 2 (M + 1) G_M LSB of 2^-F. The output adds half an
// ANGLE_W LSB of rounding.
double fourier_error_bound_turns(const int64_t* coef, const DatapathConfig& cfg);

}  // namespace acore
