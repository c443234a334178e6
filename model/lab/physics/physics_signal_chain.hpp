// SPDX-License-Identifier: MIT
// The analog-to-digital chain after each sensing element (physics scenarios, docs/diagnosis.md
// "Physics benchmark"): a first-order RC anti-alias filter per channel, an ADC of B bits, and a
// multiplexed ADC that converts the channels one after another.
//
// RC filter: tau dy/dt = x - y, integrated exactly for an input that is linear between samples
// (first-order hold): with a = exp(-h / tau),
//   y[k+1] = a y[k] + (1 - a) x[k] + (x[k+1] - x[k]) (1 - tau (1 - a) / h).
// The state is carried from sample to sample, so the filter's lag (atan(omega tau) / omega, tau at
// low speed) and gain (1 / sqrt(1 + (omega tau)^2)) follow the speed. It starts settled on x[0].
//
// ADC: `bits` bits over [-full_scale, +full_scale): step = 2 full_scale / 2^bits; the input plus
// `offset` is rounded to the nearest step (ties to even) and clamped to [-full_scale, full_scale -
// step]; bits = 0 is an ideal converter (the input plus offset, unrounded).
//
// Multiplexer: the channel in slot s (0-based conversion order) is sampled `s * slot_s` after the
// frame start, where the reference encoder is read; slot_s = 0 samples every channel at once.
#pragma once
#include <vector>

namespace acore {

class RcFilter {
 public:
  // tau_s = 0 passes the input through; h_s is the sample period.
  RcFilter(double tau_s, double h_s);
  double step(double x);  // the output at the time of x

 private:
  double tau_, a_ = 0, b_ = 0;
  bool started_ = false;
  double x_ = 0, y_ = 0;
};

struct Adc {
  int bits = 0;           // 0: ideal
  double full_scale = 1;  // output units
  double offset = 0;      // added before conversion, output units
  double convert(double x) const;
  double step() const;  // 2 full_scale / 2^bits (0 for an ideal converter)
};

// Per-channel sampling delays after the frame start of a multiplexed ADC: channel c is converted in
// slot order[c]. Throws InputError unless order is a permutation of 0..n-1 and slot_s >= 0.
std::vector<double> multiplex_delays(const std::vector<int>& order, double slot_s);

}  // namespace acore
