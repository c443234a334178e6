// SPDX-License-Identifier: MIT
#include "diagnose/noise_floor.hpp"

#include <cmath>

#include "core/errors.hpp"

namespace acore {

double crlb_rms_deg(const Recording& clean, double sigma_d) {
  const size_t n = clean.size();
  if (n < 8 || !clean.has_theta())
    throw InputError("noise floor: need a clean recording with theta_ref");
  double acc = 0;
  for (size_t i = 0; i < n; ++i) {
    // Central difference on the circle (wrap the neighbours).
    const size_t a = (i + n - 1) % n, b = (i + 1) % n;
    double dth = clean.theta_ref[b] - clean.theta_ref[a];
    dth = std::remainder(dth, 2 * M_PI);
    if (dth == 0) throw InputError("noise floor: repeated theta_ref values");
    const double g13 = (clean.d13(b) - clean.d13(a)) / dth,
                 g24 = (clean.d24(b) - clean.d24(a)) / dth;
    acc += sigma_d * sigma_d / (g13 * g13 + g24 * g24);
  }
  return std::sqrt(acc / n) * 180.0 / M_PI;
}

double differential_noise_sigma(const Recording& noisy, const Recording& clean) {
  if (noisy.size() != clean.size() || noisy.size() == 0)
    throw InputError("noise sigma: recordings differ in length");
  double ss = 0;
  for (size_t i = 0; i < noisy.size(); ++i) {
    const double e13 = noisy.d13(i) - clean.d13(i), e24 = noisy.d24(i) - clean.d24(i);
    ss += e13 * e13 + e24 * e24;
  }
  return std::sqrt(ss / (2.0 * noisy.size()));
}

}  // namespace acore
