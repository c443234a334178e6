// SPDX-License-Identifier: MIT
#include "stages/poly2d_correct.hpp"

#include "core/fixed_point.hpp"
#include "stages/poly_correct.hpp"

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
      const int64_t prod = fx::shift_add_mul(acc, v, cfg.s_w, true, v_shift);
      acc = fx::saturate(prod + coef[cfg.term2d(i, j)] * g, cfg.acc_w(), ovf);
    }
    q[i] = acc;
  }
  const PolyArg a = poly_argument(x, cfg);
  int64_t acc = q[d];
  for (int i = d - 1; i >= 0; --i)
    acc =
        fx::saturate(fx::shift_add_mul(acc, a.u, cfg.s_w, true, a.shift) + q[i], cfg.acc_w(), ovf);
  return acc;
}

int64_t poly2d_correct(int64_t s, int64_t x, int64_t v, const int64_t* coef,
                       const DatapathConfig& cfg, bool* ovf) {
  return poly_subtract(s, poly2d_eval(x, v, coef, cfg, ovf), cfg, ovf);
}

}  // namespace acore
