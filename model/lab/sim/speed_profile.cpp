// SPDX-License-Identifier: MIT
#include "sim/speed_profile.hpp"

#include <cmath>
#include <random>

#include "core/angle.hpp"

namespace acore {

double speed_variation_angle(const SpeedVariation& sv, double u, double total_turns) {
  std::mt19937_64 rng(sv.seed);
  std::uniform_real_distribution<double> phase(0, kTwoPi), weight(0.2, 1.0);
  const double ripple_phase = phase(rng);
  double turns = 0;  // integral of (v / v0 - 1) du, in turns
  if (sv.ripple_pct != 0 && sv.ripple_cycles > 0) {
    const double w = kTwoPi * sv.ripple_cycles;
    turns += sv.ripple_pct / 100 * (std::cos(ripple_phase) - std::cos(w * u + ripple_phase)) / w;
  }
  if (sv.drift_pct != 0 && total_turns > 0) {
    double a[3], ph[3], sum = 0;
    for (int j = 0; j < 3; ++j) {
      a[j] = weight(rng);
      ph[j] = phase(rng);
      sum += a[j];
    }
    for (int j = 0; j < 3; ++j) {
      // sin(pi (j + 1) u / U + ph), normalized so that the sum of |a| is 1 (|g| <= 1).
      const double w = M_PI * (j + 1) / total_turns;
      turns += sv.drift_pct / 100 * a[j] / sum * (std::cos(ph[j]) - std::cos(w * u + ph[j])) / w;
    }
  }
  return kTwoPi * turns;
}

}  // namespace acore
