// SPDX-License-Identifier: MIT
// Per-order spectrum of any measured angle-error series (an `estimate` run, a recording with
// theta_ref): joint least squares on 1, cos k theta, sin k theta for k = 1..max_order, so the
// samples may be non-uniform and need not span whole turns evenly. On a uniform grid over whole
// turns it equals the one-sided DFT (harmonics.hpp, dft_amplitudes).
#pragma once
#include <vector>

namespace acore {

// One order of an angle-error spectrum: err(theta) ~ amplitude sin(order theta + phase), i.e.
// cos_coef cos(order theta) + sin_coef sin(order theta). For order 0, cos_coef is the signed mean.
struct OrderAmplitude {
  int order = 0;
  double amplitude_deg = 0;
  double phase_rad = 0;
  double cos_deg = 0, sin_deg = 0;
};

// theta: reference angle (rad, any range, e.g. Recording::theta_ref); err_deg: angle error (deg) at
// each theta. Returns orders 0..max_order. Throws InputError on size mismatch, non-finite values,
// fewer than 2 max_order + 2 samples, or samples that do not cover the turn well enough to
// separate the orders (ill-conditioned fit).
std::vector<OrderAmplitude> error_spectrum(const std::vector<double>& theta,
                                           const std::vector<double>& err_deg, int max_order);

// RMS of err_deg minus the fitted series (what the orders up to max_order do not explain).
double spectrum_residual_rms(const std::vector<double>& theta, const std::vector<double>& err_deg,
                             const std::vector<OrderAmplitude>& spectrum);

}  // namespace acore
