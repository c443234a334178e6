// SPDX-License-Identifier: MIT
// Stage 5, CORDIC arctangent in vectoring mode over the full circle. Mirrors rtl/acore_cordic.v.
//
//   (optional) normalize: x, y <<= L, L = IN_W-2 - msb(|x| | |y|) when positive (same shift for
//              both, so the angle is unchanged and small vectors keep their precision)
//   X = x << G, Y = y << G                                   XY_W = IN_W + 2 + G bits
//   quadrant pre-rotation: X < 0 -> (X, Y) = (-X, -Y), Z = 2^(Z_W-1) (half a turn); else Z = 0
//   stage i = 0..K-1:  d = (Y >= 0)
//       X += d ? (Y >>> i) : -(Y >>> i)
//       Y -= d ? (X >>> i) : -(X >>> i)      (X, Y of the previous stage)
//       Z += d ? atan_i : -atan_i            (mod 2^Z_W)
//   angle = round_shr(Z, Z_W - ANGLE_W) mod 2^ANGLE_W   unsigned, one turn = 2^ANGLE_W
//   magnitude = X_K >>> G  (vector length times the CORDIC gain 1.6468 for K >= 8)
// atan_i = round(atan(2^-i) / 2pi * 2^Z_W), read from the register file.
#pragma once
#include <cstdint>
#include <vector>

namespace acore {

struct CordicConfig {
  int in_w = 18;           // IN_W: width of the signed x/y inputs
  int guard = 3;           // G: guard fraction bits
  int z_w = 20;            // Z_W: angle accumulator, one turn = 2^Z_W
  int angle_w = 16;        // ANGLE_W: output angle width
  int iterations = 16;     // K
  bool normalize = false;  // NORM: leading-bit normalization before the iterations
  int xy_w() const { return in_w + 2 + guard; }
};

struct CordicResult {
  uint32_t angle;     // unsigned ANGLE_W bits
  int64_t magnitude;  // X_K >>> G
};

// The arctangent table, atan_i = round(atan(2^-i) / (2 pi) * 2^z_w), i = 0..iterations-1.
std::vector<int64_t> cordic_atan_table(int z_w, int iterations);

// x is the cosine-like input, y the sine-like input (angle = atan2(y, x)).
CordicResult cordic_vector(int64_t x, int64_t y, const CordicConfig& cfg,
                           const int64_t* atan_table);

// Analytic bound of |angle error| in output LSBs for this configuration, against atan2 of the
// (integer) inputs, for inputs whose larger magnitude is at least 2^(IN_W-2) (or any input with
// NORM).
double cordic_error_bound_lsb(const CordicConfig& cfg);

}  // namespace acore
