// SPDX-License-Identifier: MIT
// A static sensor model fitted to a recording: each channel as a Fourier series in the electrical
// angle p*theta_ref (least squares, Eigen), plus the residual noise level per channel. This is how
// the gap diagnosis turns a simulated recording on any trajectory into "the designer's model":
// it can then be re-sampled at another recording's angles.
#pragma once
#include <vector>

#include "core/recording.hpp"

namespace acore {

struct SensorFit {
  int channels = 4;
  int periodicity = 1;
  int order = 0;  // highest harmonic
  // coef[c] = {C0, a1, b1, a2, b2, ...}: value = C0 + sum_k a_k cos(k e) + b_k sin(k e), e = p
  // theta
  std::vector<std::vector<double>> coef;
  std::vector<double> noise_sigma;  // residual standard deviation per channel
  std::vector<double>
      noise_corr;  // correlation of the residuals of channel pairs (c1,c3) and (c2,c4)

  double value(int channel, double theta) const;
  double derivative(int channel, double theta) const;  // d value / d theta (mechanical)
  // The model's noise-free channels at the angles (and with the t, temp columns) of `like`.
  Recording resample(const Recording& like) const;
  // Per-curve noise standard deviation of the differential pair (d13, d24), from noise_sigma and
  // noise_corr: the noise level the estimator sees.
  double diff_noise_sigma() const;
};

// Throws InputError when the recording lacks theta_ref, covers less than a turn, or has too few
// samples for the order.
SensorFit fit_sensor(const Recording& rec, int order, int periodicity);

}  // namespace acore
