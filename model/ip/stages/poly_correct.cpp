// SPDX-License-Identifier: MIT
#include "stages/poly_correct.hpp"

#include "core/fixed_point.hpp"

namespace acore {

PolyArg poly_argument(int64_t x, const DatapathConfig& cfg) {
  if (!cfg.xcenter) return {x, cfg.s_f};
  const int64_t centre = int64_t{3} << (cfg.s_f - 3);  // 3/8, moved towards zero: never overflows
  return {x >= 0 ? x - centre : x + centre, cfg.s_f - 1};
}

int64_t poly_eval(int64_t x, const int64_t* coef, const DatapathConfig& cfg, bool* ovf) {
  const PolyArg a = poly_argument(x, cfg);
  int64_t acc = coef[cfg.degree] * (int64_t{1} << cfg.acc_guard);
  for (int j = cfg.degree - 1; j >= 0; --j) {
    // = fx::shift_add_mul(acc, a.u, cfg.s_w, true, a.shift): a.shift <= S_F <= S_W - 2.
    // MULT = 1: fx::hw_mul, the full product floored once.
    const int64_t prod = cfg.mult ? fx::hw_mul(acc, a.u, cfg.s_w, true, a.shift)
                                  : fx::shift_add_mul_split(acc, a.u, a.shift);
    acc = fx::saturate(prod + coef[j] * (int64_t{1} << cfg.acc_guard), cfg.acc_w(), ovf);
  }
  return acc;
}

int64_t poly_subtract(int64_t s, int64_t acc0, const DatapathConfig& cfg, bool* ovf) {
  return fx::saturate(s - fx::round_shr(acc0, cfg.acc_f() - cfg.s_f), cfg.s_w, ovf);
}

int64_t poly_correct(int64_t s, int64_t x, const int64_t* coef, const DatapathConfig& cfg,
                     bool* ovf) {
  return poly_subtract(s, poly_eval(x, coef, cfg, ovf), cfg, ovf);
}

void poly_correct_curves(int64_t s13, int64_t s24, int64_t x, int /*region*/, const int64_t* coef,
                         const DatapathConfig& cfg, int64_t* y13, int64_t* y24, bool* ovf) {
  *y13 = poly_correct(s13, x, coef, cfg, ovf);
  *y24 = poly_correct(s24, x, coef + cfg.degree + 1, cfg, ovf);
}

double correction_u(double x, int xcenter) {
  if (!xcenter) return x;
  return 2 * (x >= 0 ? x - 0.375 : x + 0.375);
}

double poly_value(const DatapathConfig& shape, const double* coef, double x, double /*y_other*/) {
  const double u = correction_u(x, shape.xcenter);
  double acc = coef[shape.degree];
  for (int j = shape.degree - 1; j >= 0; --j) acc = acc * u + coef[j];
  return acc;
}

void poly_basis(const DatapathConfig& shape, double x, double /*y_other*/, double* out) {
  const double u = correction_u(x, shape.xcenter);
  double pw = 1;
  for (int j = 0; j <= shape.degree; ++j, pw *= u) out[j] = pw;
}

}  // namespace acore
