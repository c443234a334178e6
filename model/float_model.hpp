// SPDX-License-Identifier: MIT
// The estimator in double precision: the algorithm's ideal, same stages as the bit-accurate model
// (pre-filter, scaling, domain selection, polynomial correction, atan2 in place of the CORDIC, the
// optional Fourier correction angle - Delta(angle), and with the ZERO word angle - zero_offset).
#pragma once
#include "calibration.hpp"

namespace acore {

struct FloatSample {
  double angle;         // corrected electrical angle (minus the ZERO word's), rad in [0, 2 pi)
  double cordic_angle;  // atan2 of the corrected curves (the angle before the Fourier correction)
  double uncorrected;   // atan2 of the scaled curves (minus the ZERO word's), rad in [0, 2 pi)
  int region;
  double s13, s24;  // scaled curves
  double y13, y24;  // corrected curves
};

// d13 = c1 - c3 (or sin), d24 = c2 - c4 (or cos), in recording units.
FloatSample float_estimate(double d13, double d24, const FloatCoefficients& fc);

}  // namespace acore
