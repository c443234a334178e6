// SPDX-License-Identifier: MIT
#include "stages/cordic_rotate.hpp"

#include <cmath>

#include "core/fixed_point.hpp"

namespace acore {

RotateResult cordic_rotate(int64_t x, int64_t y, int64_t z, int stages, int z_w,
                           const int64_t* atan_table) {
  for (int i = 0; i < stages; ++i) {
    z = fx::sext(z, cordic_rotate_z_width(z_w, i));
    const int64_t xs = x >> i, ys = y >> i;
    if (z >= 0) {
      x += ys;
      y -= xs;
      z -= atan_table[i];
    } else {
      x -= ys;
      y += xs;
      z += atan_table[i];
    }
  }
  return {x, y};
}

double cordic_rotate_gain(int stages) {
  double g = 1.0;
  for (int i = 0; i < stages; ++i) g *= std::sqrt(1.0 + std::ldexp(1.0, -2 * i));
  return g;
}

}  // namespace acore
