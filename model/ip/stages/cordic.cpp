// SPDX-License-Identifier: MIT
#include "stages/cordic.hpp"

#include <cmath>

#include "core/fixed_point.hpp"

namespace acore {

std::vector<int64_t> cordic_atan_table(int z_w, int iterations) {
  std::vector<int64_t> t(iterations);
  const double turn = std::ldexp(1.0, z_w);
  for (int i = 0; i < iterations; ++i)
    t[i] = static_cast<int64_t>(std::llround(std::atan(std::ldexp(1.0, -i)) / (2 * M_PI) * turn));
  return t;
}

static int msb_index(uint64_t v) { return v ? 63 - __builtin_clzll(v) : -1; }

CordicResult cordic_vector(int64_t x, int64_t y, const CordicConfig& cfg,
                           const int64_t* atan_table) {
  if (cfg.normalize) {
    const uint64_t mag =
        static_cast<uint64_t>(x < 0 ? -x : x) | static_cast<uint64_t>(y < 0 ? -y : y);
    const int shift = (cfg.in_w - 2) - msb_index(mag);
    if (mag != 0 && shift > 0) {
      x = fx::shr(x, -shift);
      y = fx::shr(y, -shift);
    }
  }
  int64_t X = x * (int64_t{1} << cfg.guard);
  int64_t Y = y * (int64_t{1} << cfg.guard);
  const uint64_t zmask = (uint64_t{1} << cfg.z_w) - 1;
  uint64_t Z = 0;
  if (X < 0) {
    X = -X;
    Y = -Y;
    Z = uint64_t{1} << (cfg.z_w - 1);
  }
  for (int i = 0; i < cfg.iterations; ++i) {
    const int64_t xs = X >> i, ys = Y >> i;
    if (Y >= 0) {
      X += ys;
      Y -= xs;
      Z += static_cast<uint64_t>(atan_table[i]);
    } else {
      X -= ys;
      Y += xs;
      Z -= static_cast<uint64_t>(atan_table[i]);
    }
    Z &= zmask;
  }
  const int drop = cfg.z_w - cfg.angle_w;
  const uint64_t angle = (drop > 0 ? ((Z + (uint64_t{1} << (drop - 1))) >> drop) : Z) &
                         ((uint64_t{1} << cfg.angle_w) - 1);
  return {static_cast<uint32_t>(angle), X >> cfg.guard};
}

double cordic_error_bound_lsb(const CordicConfig& cfg) {
  // Residual rotation after K steps, atan table rounding (K half-LSBs of Z), x/y truncation
  // (about 2 LSB of the guard-extended word per step, seen against a vector of length >=
  // 2^(IN_W-2)), and the final rounding to ANGLE_W.
  const double lsb_rad = 2 * M_PI / std::ldexp(1.0, cfg.angle_w);
  const double residual = std::atan(std::ldexp(1.0, -(cfg.iterations - 1)));
  const double table = cfg.iterations * 0.5 * 2 * M_PI / std::ldexp(1.0, cfg.z_w);
  const double min_len = std::ldexp(1.0, cfg.in_w - 2 + cfg.guard);
  const double trunc = 2.0 * cfg.iterations / min_len;
  return (residual + table + trunc) / lsb_rad + 0.5;
}

}  // namespace acore
