// SPDX-License-Identifier: MIT
#include "physics/physics_signal_chain.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace acore {

RcFilter::RcFilter(double tau_s, double h_s) : tau_(tau_s) {
  if (!(tau_s >= 0) || !(h_s > 0))
    throw InputError(
        fmt::format("RC filter: tau {} s must be >= 0 and the sample period {} s > 0", tau_s, h_s));
  if (tau_s > 0) {
    a_ = std::exp(-h_s / tau_s);
    b_ = 1 - tau_s * (1 - a_) / h_s;
  }
}

double RcFilter::step(double x) {
  if (tau_ == 0) return x;
  if (!started_) {
    started_ = true;
    x_ = y_ = x;
    return y_;
  }
  y_ = a_ * y_ + (1 - a_) * x_ + (x - x_) * b_;
  x_ = x;
  return y_;
}

double Adc::step() const { return bits > 0 ? 2 * full_scale / std::ldexp(1.0, bits) : 0.0; }

double Adc::convert(double x) const {
  if (bits <= 0) return x + offset;
  const double q = step();
  const double code = std::nearbyint((x + offset) / q);  // default rounding: ties to even
  const double top = std::ldexp(1.0, bits - 1);
  return std::clamp(code, -top, top - 1) * q;
}

std::vector<double> multiplex_delays(const std::vector<int>& order, double slot_s) {
  const int n = static_cast<int>(order.size());
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (int k = 0; k < n; ++k)
    if (sorted[static_cast<size_t>(k)] != k)
      throw InputError("multiplexer: the slot order must be a permutation of 0..n-1");
  if (!(slot_s >= 0)) throw InputError("multiplexer: the slot time must be >= 0");
  std::vector<double> d(order.size());
  for (size_t c = 0; c < order.size(); ++c) d[c] = order[c] * slot_s;
  return d;
}

}  // namespace acore
