// SPDX-License-Identifier: MIT
// The Cramér–Rao floor of the angle error for white noise on the differential pair: no unbiased
// estimator does better. For a noise-free pair v(theta) = (d13, d24) and independent noise of
// standard deviation sigma_d on each curve, var(theta_hat) >= sigma_d^2 / |dv/dtheta|^2 per sample;
// the floor reported is the RMS of that bound over the recording, in degrees.
#pragma once
#include "core/recording.hpp"

namespace acore {

// clean: the noise-free recording (theta_ref needed, one sample per angle, at least 8 samples per
// turn); sigma_d: noise standard deviation of each differential curve, in recording units.
double crlb_rms_deg(const Recording& clean, double sigma_d);

// The per-curve noise standard deviation of `noisy`, measured against `clean` on the same angles.
double differential_noise_sigma(const Recording& noisy, const Recording& clean);

}  // namespace acore
