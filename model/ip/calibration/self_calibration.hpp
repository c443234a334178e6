// SPDX-License-Identifier: MIT
// Self-calibration: the calibration without a reference encoder (docs/calibration.md,
// self-calibration). From the two differential pairs and the sample times alone:
//  1. offsets, amplitudes and the phase between the pairs from the Lissajous figure, by a direct
//     least-squares ellipse fit (Halir and Flusser's numerically stable form of Fitzgibbon's);
//  2. the ellipse-corrected electrical angle psi, unwrapped; refused when it covers less than one
//     turn, or stops or turns back;
//  3. a reference angle estimated from the recording itself: a sensor error repeats every turn, a
//     speed variation does not, so psi(t) is fitted (linear least squares) by a smooth speed
//     profile (Legendre polynomial in t, order chosen by BIC among the orders the recording can
//     separate from the error) plus harmonics 1..K of the angle; the harmonics are evaluated at
//     the corrected angle psi - e(.) and the fit repeated (fixed point, three passes). The
//     reference is psi minus the fitted periodic error: what is not periodic in the angle (noise,
//     the speed) stays in the reference and out of the correction;
//  4. calibrate() against it (every correction mode), with the ellipse's offsets and amplitudes.
// The zero offset is unknown without a reference: the reference's zero is arbitrary, the
// calibration's zero offset only aligns the correction with it.
#pragma once
#include <string>
#include <vector>

#include "calibration/calibration.hpp"
#include "core/recording.hpp"

namespace acore {

struct SelfCalOptions {
  int periodicity = 1;
  int harmonics = 0;          // K of the error model; 0: automatic (16, fewer on a short turn)
  int max_profile_order = 0;  // cap of the speed profile's polynomial order; 0: automatic
};

// The Lissajous ellipse: d13 = O13 + A13 sin(phi + delta), d24 = O24 + A24 cos(phi).
struct EllipseFit {
  double offset[2] = {0, 0};  // O13, O24
  double amp[2] = {1, 1};     // A13, A24
  double delta = 0;           // rad
  // The ellipse-corrected angle of a sample, rad in (-pi, pi].
  double angle(double d13, double d24) const;
};

// Throws InputError when the points do not lie near an ellipse (fewer than 6 points, a degenerate
// or non-elliptic conic).
EllipseFit fit_ellipse(const std::vector<double>& d13, const std::vector<double>& d24);

// What the self-calibration assumed and how well it held (calibrate --json "self_calibration").
struct SelfCalReport {
  EllipseFit ellipse;
  bool uniform_time = false;    // no t column: samples taken as equally spaced
  double turns = 0;             // electrical turns covered (one sample step counted at each end)
  int profile_order = 0;        // order of the speed profile polynomial (1: constant speed)
  int max_separable_order = 0;  // the highest order the recording can tell from the error
  int harmonics = 0;            // K
  std::vector<double> ripple_tones;  // speed ripple tones found, cycles over the recording
  double residual_deg = 0;           // RMS of the joint fit's residual, electrical deg
  double noise_deg = 0;              // the angle noise estimated from second differences
  double radius_rms = 0;             // RMS deviation of the ellipse-corrected radius from 1
  double error_rms_deg = 0;          // RMS of the fitted periodic error (the sensor's)
  double speed_variation_pct = 0;    // peak-to-peak of the fitted speed / its mean, percent
  double consistency_deg = -1;  // RMS difference of the error fitted on each half (-1: < 2 turns)
  double confidence = 0;        // 0..1 (see docs/calibration.md)
  std::vector<std::string> assumptions;  // one sentence each
  std::vector<double> theta;             // the estimated reference, mechanical rad (psi - e) / p
};

// Steps 1-3. Throws InputError with the reason for a refusal: less than one turn, a reversal or a
// stop, a speed variation it cannot separate, no time base (t not increasing).
SelfCalReport estimate_reference(const Recording& rec, const SelfCalOptions& opt);

// Steps 1-4: the coefficients and the report. The recording's theta_ref, if any, is ignored.
FloatCoefficients self_calibrate(const Recording& rec, const CalOptions& opt,
                                 SelfCalReport* report = nullptr, int harmonics = 0);

}  // namespace acore
