// SPDX-License-Identifier: MIT
#include "core/angle.hpp"

#include <cmath>

#include "core/fixed_point.hpp"

namespace acore {

double wrap_pi(double rad) {
  const double w = rad - 2 * M_PI * std::floor((rad + M_PI) / (2 * M_PI));
  return w >= M_PI ? w - 2 * M_PI : w;  // rounding can land on +pi
}

uint32_t angle_code(double rad, int angle_w) {
  const double turns = rad / (2 * M_PI) - std::floor(rad / (2 * M_PI));  // [0, 1]
  const int64_t mask = (int64_t{1} << angle_w) - 1;
  return static_cast<uint32_t>(std::llround(std::ldexp(turns, angle_w)) & mask);
}

double code_angle(uint32_t code, int angle_w) {
  const int64_t c = fx::sext(code, angle_w);  // [-2^(A-1), 2^(A-1)): [-pi, pi)
  return std::ldexp(static_cast<double>(c), -angle_w) * 2 * M_PI;
}

}  // namespace acore
