// SPDX-License-Identifier: MIT
#include "float_model.hpp"

#include <cmath>

#include "fourier_correct.hpp"
#include "region_select.hpp"

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

}  // namespace acore
