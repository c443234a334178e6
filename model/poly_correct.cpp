// SPDX-License-Identifier: MIT
#include "poly_correct.hpp"

#include "fixed_point.hpp"

namespace acore {

int64_t poly_eval(int64_t x, const int64_t* coef, const DatapathConfig& cfg, bool* ovf) {
  int64_t acc = coef[cfg.degree] * (int64_t{1} << cfg.acc_guard);
  for (int j = cfg.degree - 1; j >= 0; --j) {
    const int64_t prod = fx::shift_add_mul(acc, x, cfg.s_w, true, cfg.s_f);
    acc = fx::saturate(prod + coef[j] * (int64_t{1} << cfg.acc_guard), cfg.acc_w(), ovf);
  }
  return acc;
}

int64_t poly_correct(int64_t s, int64_t x, const int64_t* coef, const DatapathConfig& cfg, bool* ovf) {
  const int64_t p = poly_eval(x, coef, cfg, ovf);
  return fx::saturate(s - fx::round_shr(p, cfg.acc_f() - cfg.s_f), cfg.s_w, ovf);
}

}  // namespace acore
