// SPDX-License-Identifier: MIT
// Calibration (paper section II.B): pre-filter, scaling (offset = mean, amplitude per Eq. 4),
// domain selection (region_select.hpp), the zero offset z (the constant electrical angle between
// the sensor and the reference: circular mean of wrap(atan2(s13, s24) - p theta_ref)), and a
// least-squares fit per region of the differences of Eq. 6 against the aligned reference:
// d13 = s13 - sin(p theta_ref + z) and d24 = s24 - cos(p theta_ref + z) against powers of x.
// Then quantization of everything into the register image (regmap/codec.hpp).
#pragma once
#include <string>
#include <vector>

#include "core/datapath_config.hpp"
#include "core/recording.hpp"
#include "regmap/codec.hpp"
#include "regmap/coefficients.hpp"
#include "regmap/regimage.hpp"

namespace acore {

struct CalOptions {
  int correction = kPoly;
  int degree = 3;
  int regions = 4;
  int xcenter = 0;      // 8 regions: fit in u = 2 (x -+ 3/8) (poly_correct.hpp)
  int periodicity = 1;  // electrical periods per turn: the reference is sin/cos(p theta_ref)
  int fourier_k = 0;    // harmonics of the Fourier correction fitted after the correction; 0 = none
  // Zero offset: estimate it from the calibration recording (circular mean of the uncorrected angle
  // error) and fit against the aligned reference; or, false, take `zero_offset` as given (rad; 0 =
  // fit against theta_ref itself, Eq. 6 as printed: the polynomials absorb any constant offset).
  bool estimate_zero = true;
  double zero_offset = 0;
  // Scaling: false = Eq. 4 (mean and RMS amplitude of the recording); true = the offsets and
  // amplitudes below (the self-calibration's ellipse fit, which a non-uniform speed does not bias).
  bool given_scaling = false;
  double offset[2] = {0, 0}, amp[2] = {1, 1};  // O13, O24; A13, A24
};

// The zero offset of scaled curves against a reference: the circular mean of
// wrap(atan2(s13, s24) - p theta_ref), rad in [-pi, pi). Throws InputError when the errors have no
// mean direction (resultant length below 1e-9: no constant offset to speak of).
double zero_offset_estimate(const std::vector<double>& s13, const std::vector<double>& s24,
                            const std::vector<double>& theta_ref, int periodicity);

// The calibration options a datapath configuration asks for (its correction mode, degree, regions).
CalOptions cal_options_for(const DatapathConfig& cfg, int periodicity);

// Throws InputError when the recording has no theta_ref or too few samples in a region.
// With opt.fourier_k > 0, after the polynomial: least squares of the remaining angle error
// (float estimate - p theta_ref - zero offset, wrapped) against 1, cos k theta, sin k theta
// (k = 1..K) of the float estimate theta.
FloatCoefficients calibrate(const Recording& rec, const CalOptions& opt);

// The "ADC" gain: the largest power of two that maps the recording's largest |channel| to at most
// a quarter of the IN_W-bit full scale (headroom for samples the calibration never saw).
double choose_in_scale(const Recording& rec, int in_w);

// calibrate() with cal_options_for(cfg), then quantize_auto_range() at the automatic in_scale: the
// one-call path of the sweep and the co-sim tests. *fc (optional) receives the float coefficients.
RegImage calibrate_image(const Recording& rec, const DatapathConfig& cfg, int periodicity,
                         FloatCoefficients* fc = nullptr);

}  // namespace acore
