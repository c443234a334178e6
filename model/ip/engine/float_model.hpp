// SPDX-License-Identifier: MIT
// The estimator in double precision: the algorithm's ideal, same stages as the bit-accurate model
// (pre-filter, scaling, domain selection, polynomial correction, atan2 in place of the CORDIC, the
// optional Fourier correction angle - Delta(angle), and with the ZERO word angle - zero_offset).
#pragma once
#include "core/datapath_config.hpp"
#include "regmap/coefficients.hpp"

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

// The real-valued arguments of the correction polynomials, as the datapath forms them:
// u = x, or 2 (x -+ 3/8) with xcenter; v = 2^kVShift (y_other - sign(y_other)) (poly2d).
double correction_u(double x, int xcenter);
double correction_v(double y_other);
// Every term's basis value at (x, y_other) in the register map's order (1-D: u^j; 2-D: u^i v^j).
void correction_basis(const DatapathConfig& shape, double x, double y_other, double* out);
// P_region,curve(x, y_other) in double, by (nested) Horner like the datapath.
double correction_poly(const FloatCoefficients& fc, int region, int curve, double x,
                       double y_other);

}  // namespace acore
