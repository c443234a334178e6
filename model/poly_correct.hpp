// SPDX-License-Identifier: MIT
// Stage 4, polynomial correction (paper Eq. 6): y = s - P(x), P of degree n by Horner's scheme on the
// adder/shifter multiplier. Mirrors rtl/acore_poly_correct.v:
//   acc_n = a_n << ACC_G                                              ACC_F = COEF_F + ACC_G
//   acc_j = saturate(shift_add_mul(acc_{j+1}, x, S_W signed, S_F) + (a_j << ACC_G), ACC_W)
//   y     = saturate(s - round_shr(acc_0, ACC_F - S_F), S_W)
#pragma once
#include <cstdint>

#include "datapath_config.hpp"

namespace acore {

// coef[j] is the coefficient of x^j (sign-extended REG_W-bit word, COEF_F fraction bits).
int64_t poly_eval(int64_t x, const int64_t* coef, const DatapathConfig& cfg, bool* ovf);
int64_t poly_correct(int64_t s, int64_t x, const int64_t* coef, const DatapathConfig& cfg, bool* ovf);

}  // namespace acore
