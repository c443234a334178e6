// SPDX-License-Identifier: MIT
// Stage 2, scaling (paper Eq. 5 read as (c - O) / A). Mirrors rtl/acore_scaler.v.
//   t = d - O                          T_W = D_W + 1 bits, exact
//   p = shift_add_mul(t, R, REG_W unsigned, R_SHIFT - SCALE_G)   S_F + SCALE_G fraction bits
//   s = saturate(round_shr(p, SCALE_G), S_W)                      Q2.16 by default
// with R = round(2^(S_F + R_SHIFT) / A) the amplitude reciprocal from the register file. MULT = 1:
// hw_mul (the full product, floored once) in place of shift_add_mul.
#pragma once
#include <cstdint>

#include "core/datapath_config.hpp"

namespace acore {

int64_t scale_curve(int64_t d, int64_t offset, int64_t recip, const DatapathConfig& cfg, bool* ovf);

}  // namespace acore
