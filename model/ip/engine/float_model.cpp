// SPDX-License-Identifier: MIT
#include "engine/float_model.hpp"

#include <cmath>

#include "stages/fourier_correct.hpp"
#include "stages/region_select.hpp"

namespace acore {

namespace {
double wrap_turn(double a) { return a < 0 ? a + 2 * M_PI : a; }

}  // namespace

FloatSample float_estimate(double d13, double d24, const FloatCoefficients& fc) {
  FloatSample o;
  o.s13 = (d13 - fc.offset[0]) / fc.amp[0];
  o.s24 = (d24 - fc.offset[1]) / fc.amp[1];
  double x;
  o.region = select_region_real(o.s13, o.s24, fc.regions, &x);
  const double y_other = x_is_sine(o.region, fc.regions) ? o.s24 : o.s13;
  o.y13 = o.s13 - correction_poly(fc, o.region, 0, x, y_other);
  o.y24 = o.s24 - correction_poly(fc, o.region, 1, x, y_other);
  o.angle = wrap_turn(std::atan2(o.y13, o.y24));
  o.cordic_angle = o.angle;
  if (!fc.fourier.empty()) {
    o.angle = std::fmod(o.angle - fourier_series(o.angle, fc.fourier), 2 * M_PI);
    if (o.angle < 0) o.angle += 2 * M_PI;
  }
  o.uncorrected = wrap_turn(std::atan2(o.s13, o.s24));
  if (fc.zero_word) {  // the ZERO word's adder, on both outputs
    o.angle = wrap_turn(std::fmod(o.angle - fc.zero_offset, 2 * M_PI));
    o.uncorrected = wrap_turn(std::fmod(o.uncorrected - fc.zero_offset, 2 * M_PI));
  }
  return o;
}

double correction_u(double x, int xcenter) {
  if (!xcenter) return x;
  return 2 * (x >= 0 ? x - 0.375 : x + 0.375);
}

double correction_v(double y_other) {
  return std::ldexp(y_other >= 0 ? y_other - 1 : y_other + 1, kVShift);
}

void correction_basis(const DatapathConfig& shape, double x, double y_other, double* out) {
  const double u = correction_u(x, shape.xcenter);
  if (shape.correction == kPoly) {
    double pw = 1;
    for (int j = 0; j <= shape.degree; ++j, pw *= u) out[j] = pw;
  } else if (shape.correction == kPoly2d) {
    const double v = correction_v(y_other);
    double ui = 1;
    for (int i = 0; i <= shape.degree; ++i, ui *= u) {
      double vj = 1;
      for (int j = 0; i + j <= shape.degree; ++j, vj *= v) out[shape.term2d(i, j)] = ui * vj;
    }
  }
}

double correction_poly(const FloatCoefficients& fc, int r, int c, double x, double y_other) {
  const double u = correction_u(x, fc.xcenter);
  const int d = fc.degree;
  if (fc.correction == kPoly) {
    double acc = fc.coef(r, c, d);
    for (int j = d - 1; j >= 0; --j) acc = acc * u + fc.coef(r, c, j);
    return acc;
  }
  if (fc.correction != kPoly2d) return 0.0;
  const DatapathConfig shape = fc.shape();
  const double v = correction_v(y_other);
  double acc = 0;
  for (int i = d; i >= 0; --i) {
    double q = fc.coef(r, c, shape.term2d(i, d - i));
    for (int j = d - i - 1; j >= 0; --j) q = q * v + fc.coef(r, c, shape.term2d(i, j));
    acc = i == d ? q : acc * u + q;
  }
  return acc;
}

}  // namespace acore
