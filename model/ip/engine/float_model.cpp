// SPDX-License-Identifier: MIT
#include "engine/float_model.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/errors.hpp"
#include "stages/correction.hpp"
#include "stages/fourier_correct.hpp"
#include "stages/region_select.hpp"

namespace acore {

namespace {
double wrap_turn(double a) { return a < 0 ? a + 2 * M_PI : a; }

// Each mode's float and basis kernels (the VALUE and BASIS columns of core/correction_modes.hpp),
// by ID.
using ValueKernel = double (*)(const DatapathConfig&, const double*, double, double);
using BasisKernel = void (*)(const DatapathConfig&, double, double, double*);
constexpr ValueKernel kValueKernels[] = {ACORE_CORRECTION_MODES(ACORE_MODE_VALUE)};
constexpr BasisKernel kBasisKernels[] = {ACORE_CORRECTION_MODES(ACORE_MODE_BASIS)};

}  // namespace

FloatSample float_estimate(double d13, double d24, const FloatCoefficients& fc) {
  if (!correction_mode(fc.correction).runs_on(kEngineFloat))
    throw InputError(fmt::format("the float model does not run the correction mode {}",
                                 correction_name(fc.correction)));
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

void correction_basis(const DatapathConfig& shape, double x, double y_other, double* out) {
  kBasisKernels[correction_mode(shape.correction).id](shape, x, y_other, out);
}

double correction_poly(const FloatCoefficients& fc, int r, int c, double x, double y_other) {
  const DatapathConfig shape = fc.shape();
  const double* coef = fc.poly.data() + static_cast<size_t>(r * 2 + c) * shape.coef_per_curve();
  return kValueKernels[correction_mode(shape.correction).id](shape, coef, x, y_other);
}

}  // namespace acore
