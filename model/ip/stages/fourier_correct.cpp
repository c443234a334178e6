// SPDX-License-Identifier: MIT
#include "stages/fourier_correct.hpp"

#include <cmath>

#include "core/fixed_point.hpp"
#include "stages/cordic_rotate.hpp"

namespace acore {

int64_t fourier_harmonic(int k, uint32_t theta, int64_t a, int64_t b, const int64_t* atan_table,
                         const DatapathConfig& cfg) {
  const int A = cfg.angle_w;
  const uint64_t u = (static_cast<uint64_t>(k) * theta) & ((uint64_t{1} << A) - 1);
  const int q = static_cast<int>(((u >> (A - 2)) + ((u >> (A - 3)) & 1u)) & 3u);
  const int64_t phi = fx::sext(static_cast<int64_t>(u), A - 2);
  const int64_t x = fx::sext(a, cfg.fourier_word_w) * (int64_t{1} << cfg.fourier_guard);
  const int64_t y = fx::sext(b, cfg.fourier_word_w) * (int64_t{1} << cfg.fourier_guard);
  int64_t x0 = x, y0 = y;
  switch (q) {
    case 1:
      x0 = y, y0 = ~x;
      break;
    case 2:
      x0 = ~x, y0 = ~y;
      break;
    case 3:
      x0 = ~y, y0 = x;
      break;
    default:
      break;
  }
  const int64_t z = phi * (int64_t{1} << (cfg.z_w - A));
  return cordic_rotate(x0, y0, z, cfg.fourier_iterations, cfg.z_w, atan_table).x;
}

int64_t fourier_delta(uint32_t theta, const int64_t* coef, const int64_t* atan_table,
                      const DatapathConfig& cfg) {
  int64_t d = coef[0] * (int64_t{1} << cfg.fourier_guard);
  for (int k = 1; k <= cfg.fourier_k; ++k)
    d += fourier_harmonic(k, theta, coef[2 * k - 1], coef[2 * k], atan_table, cfg);
  return d & ((int64_t{1} << cfg.fourier_f()) - 1);
}

uint32_t fourier_correct(uint32_t theta, const int64_t* coef, const int64_t* atan_table,
                         const DatapathConfig& cfg) {
  const int s = cfg.fourier_f() - cfg.angle_w;
  const int64_t v =
      (static_cast<int64_t>(theta) << s) - fourier_delta(theta, coef, atan_table, cfg);
  return static_cast<uint32_t>(fx::round_shr(v, s) & ((int64_t{1} << cfg.angle_w) - 1));
}

double fourier_series(double theta, const std::vector<double>& coef) {
  double d = coef.at(0);
  for (size_t k = 1; 2 * k < coef.size(); ++k)
    d += coef[2 * k - 1] * std::cos(k * theta) + coef[2 * k] * std::sin(k * theta);
  return d;
}

double fourier_gain(const DatapathConfig& cfg) {
  return cordic_rotate_gain(cfg.fourier_iterations);
}

double fourier_error_bound_turns(const int64_t* coef, const DatapathConfig& cfg) {
  const int m = cfg.fourier_iterations;
  const double g = fourier_gain(cfg);
  const double residual_rad =
      std::atan(std::ldexp(1.0, -(m - 1))) + m * 0.5 * 2 * M_PI * std::ldexp(1.0, -cfg.z_w);
  const double lsb = std::ldexp(1.0, -cfg.fourier_f());
  double bound = 0;
  for (int k = 1; k <= cfg.fourier_k; ++k) {
    const double r = g *
                     std::hypot(static_cast<double>(fx::sext(coef[2 * k - 1], cfg.fourier_word_w)),
                                static_cast<double>(fx::sext(coef[2 * k], cfg.fourier_word_w))) *
                     std::ldexp(1.0, -cfg.fourier_coef_f);
    bound += r * residual_rad + std::sqrt(2.0) * (m + 1) * g * lsb;
  }
  return bound;
}

}  // namespace acore
