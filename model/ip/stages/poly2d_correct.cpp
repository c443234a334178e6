// SPDX-License-Identifier: MIT
#include "stages/poly2d_correct.hpp"

#include <cmath>

#include "core/fixed_point.hpp"
#include "stages/poly_correct.hpp"
#include "stages/region_select.hpp"

namespace acore {

int64_t poly2d_v(int64_t y_other, const DatapathConfig& cfg) {
  const int64_t one = int64_t{1} << cfg.s_f;
  return y_other >= 0 ? y_other - one : y_other + one;
}

int64_t poly2d_eval(int64_t x, int64_t v, const int64_t* coef, const DatapathConfig& cfg,
                    bool* ovf) {
  const int d = cfg.degree;
  const int64_t g = int64_t{1} << cfg.acc_guard;
  const int v_shift = cfg.s_f - kVShift;
  // Q_i(v) for every power i of x (the RTL computes them side by side).
  int64_t q[4] = {0, 0, 0, 0};  // d <= 3
  for (int i = 0; i <= d; ++i) {
    int64_t acc = coef[cfg.term2d(i, d - i)] * g;
    for (int j = d - i - 1; j >= 0; --j) {
      const int64_t prod = fx::datapath_mul(cfg.mult, acc, v, cfg.s_w, true, v_shift);
      acc = fx::saturate(prod + coef[cfg.term2d(i, j)] * g, cfg.acc_w(), ovf);
    }
    q[i] = acc;
  }
  const PolyArg a = poly_argument(x, cfg);
  int64_t acc = q[d];
  for (int i = d - 1; i >= 0; --i)
    acc = fx::saturate(fx::datapath_mul(cfg.mult, acc, a.u, cfg.s_w, true, a.shift) + q[i],
                       cfg.acc_w(), ovf);
  return acc;
}

int64_t poly2d_correct(int64_t s, int64_t x, int64_t v, const int64_t* coef,
                       const DatapathConfig& cfg, bool* ovf) {
  return poly_subtract(s, poly2d_eval(x, v, coef, cfg, ovf), cfg, ovf);
}

void poly2d_correct_curves(int64_t s13, int64_t s24, int64_t x, int region, const int64_t* coef,
                           const DatapathConfig& cfg, int64_t* y13, int64_t* y24, bool* ovf) {
  const int64_t v = poly2d_v(x_is_sine(region, cfg.regions) ? s24 : s13, cfg);
  *y13 = poly2d_correct(s13, x, v, coef, cfg, ovf);
  *y24 = poly2d_correct(s24, x, v, coef + cfg.coef_per_curve(), cfg, ovf);
}

double correction_v(double y_other) {
  return std::ldexp(y_other >= 0 ? y_other - 1 : y_other + 1, kVShift);
}

double poly2d_value(const DatapathConfig& shape, const double* coef, double x, double y_other) {
  const double u = correction_u(x, shape.xcenter);
  const double v = correction_v(y_other);
  const int d = shape.degree;
  double acc = 0;
  for (int i = d; i >= 0; --i) {
    double q = coef[shape.term2d(i, d - i)];
    for (int j = d - i - 1; j >= 0; --j) q = q * v + coef[shape.term2d(i, j)];
    acc = i == d ? q : acc * u + q;
  }
  return acc;
}

void poly2d_basis(const DatapathConfig& shape, double x, double y_other, double* out) {
  const double u = correction_u(x, shape.xcenter);
  const double v = correction_v(y_other);
  double ui = 1;
  for (int i = 0; i <= shape.degree; ++i, ui *= u) {
    double vj = 1;
    for (int j = 0; i + j <= shape.degree; ++j, vj *= v) out[shape.term2d(i, j)] = ui * vj;
  }
}

}  // namespace acore
