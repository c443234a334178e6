// SPDX-License-Identifier: MIT
// The estimator in double precision: the algorithm's ideal, same stages as the bit-accurate model
// (pre-filter, scaling, domain selection, polynomial correction, atan2 in place of the CORDIC, the
// optional Fourier correction angle - Delta(angle), and with the ZERO word angle - zero_offset).
#pragma once
#include "core/datapath_config.hpp"
#include "regmap/coefficients.hpp"
#include "stages/correction.hpp"

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

// The correction in double, through the mode's kernels (stages/correction.hpp; correction_u() and
// correction_v() there are its arguments): every term's basis value at (x, y_other) in the register
// map's order (1-D: u^j; 2-D: u^i v^j), and P_region,curve(x, y_other) by (nested) Horner like
// the datapath. Both throw InputError for a mode no row of the table has.
void correction_basis(const DatapathConfig& shape, double x, double y_other, double* out);
double correction_poly(const FloatCoefficients& fc, int region, int curve, double x,
                       double y_other);

}  // namespace acore
