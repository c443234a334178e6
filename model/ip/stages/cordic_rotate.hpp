// SPDX-License-Identifier: MIT
// Rotation-mode CORDIC: turns a vector clockwise by a given angle, the building block of the
// Fourier correction (model/ip/stages/fourier_correct.hpp). Mirrors rtl/acore_cordic_rotate.v:
//
//   z_0 = z  (Z_W units, one turn = 2^Z_W, |z| <= 1/8 turn after the quadrant pre-rotation)
//   stage i = 0..M-1:  d = (z_i >= 0)
//       X += d ? (Y >>> i) : -(Y >>> i)
//       Y -= d ? (X >>> i) : -(X >>> i)      (X, Y of the previous stage)
//       z_{i+1} = sext(z_i - (d ? atan_i : -atan_i), ZW(i+1))
//   ZW(i) = min(Z_W - 2, Z_W - i): entering stage i, |z_i| <= sum_{j>=i} atan(2^-j) < 2^(1-i) rad,
//   i.e. below 2^(Z_W-1.65-i) (and |z_0|, |z_1| <= 1/8 turn), so z_i fits ZW(i) signed bits with a
//   margin of 1.5x over the bound, which also covers the table rounding. Only words that are not
//   arctangents (a host writing anything) can leave that range; then z wraps there, in the model as
//   in the RTL.
//   result: X_M, Y_M = G_M * (x, y) turned clockwise by z, up to the residual angle z_M
//           (|z_M| <= atan(2^-(M-1)) plus the table rounding) and one floor per stage and word;
//           G_M = prod_{i<M} sqrt(1 + 2^-2i) (1.6468 for M >= 8).
// atan_i = round(atan(2^-i) / 2pi * 2^Z_W), the CORDIC constants of the register file.
#pragma once
#include <cstdint>

namespace acore {

struct RotateResult {
  int64_t x, y;
};

// z: signed, |z| < 2^(Z_W-3). The atan words are REG_W-bit unsigned register words.
RotateResult cordic_rotate(int64_t x, int64_t y, int64_t z, int stages, int z_w,
                           const int64_t* atan_table);

// ZW(i), the width of z entering stage i (i = 0..M-1).
inline int cordic_rotate_z_width(int z_w, int i) { return i <= 2 ? z_w - 2 : z_w - i; }

// G_M, the gain of M stages.
double cordic_rotate_gain(int stages);

}  // namespace acore
