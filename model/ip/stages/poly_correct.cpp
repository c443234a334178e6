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
    const int64_t prod = fx::shift_add_mul_split(acc, a.u, a.shift);
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

}  // namespace acore
