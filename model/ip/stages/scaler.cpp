// SPDX-License-Identifier: MIT
#include "stages/scaler.hpp"

#include "core/fixed_point.hpp"

namespace acore {

int64_t scale_curve(int64_t d, int64_t offset, int64_t recip, const DatapathConfig& cfg,
                    bool* ovf) {
  const int64_t t = d - offset;
  // = fx::shift_add_mul(t, recip, cfg.reg_w, false, cfg.r_shift - cfg.scale_guard) (R unsigned).
  // MULT = 1: the full product, floored once.
  const int r = cfg.r_shift - cfg.scale_guard;
  const int64_t p =
      cfg.mult ? fx::hw_mul(t, recip, cfg.reg_w, false, r) : fx::shift_add_mul_split(t, recip, r);
  return fx::saturate(fx::round_shr(p, cfg.scale_guard), cfg.s_w, ovf);
}

}  // namespace acore
