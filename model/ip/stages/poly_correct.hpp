// SPDX-License-Identifier: MIT
// Stage 4, polynomial correction (paper Eq. 6): y = s - P(x), P of degree n by Horner's scheme on
// the adder/shifter multiplier. Mirrors rtl/acore_poly_correct.v:
//   acc_n = a_n << ACC_G                                              ACC_F = COEF_F + ACC_G
//   acc_j = saturate(shift_add_mul(acc_{j+1}, u, S_W signed, U_SH) + (a_j << ACC_G), ACC_W)
//   y     = saturate(s - round_shr(acc_0, ACC_F - S_F), S_W)
// with the argument u = x, U_SH = S_F (XCENTER = 0, the paper's), or with XCENTER = 1 (8 regions)
//   u = x - (x >= 0 ? 3/8 : -3/8),  U_SH = S_F - 1     (exact: moving towards zero cannot overflow)
// i.e. the polynomial is in 2 (x -+ 3/8), centred in its half region and spanning about [-0.75,
// 0.7]: at degree 7 the raw-x coefficients reach 200 (and need COEF_F = 9), the centred ones stay
// < 1.2. MULT = 1: hw_mul (the full product, floored once) in place of shift_add_mul.
#pragma once
#include <cstdint>

#include "core/datapath_config.hpp"

namespace acore {

// The polynomial argument u and the multiplier's right shift U_SH for it (see above).
struct PolyArg {
  int64_t u;
  int shift;
};
PolyArg poly_argument(int64_t x, const DatapathConfig& cfg);

// coef[j] is the coefficient of u^j (sign-extended REG_W-bit word, COEF_F fraction bits).
int64_t poly_eval(int64_t x, const int64_t* coef, const DatapathConfig& cfg, bool* ovf);
int64_t poly_correct(int64_t s, int64_t x, const int64_t* coef, const DatapathConfig& cfg,
                     bool* ovf);
// y = saturate(s - round_shr(acc_0, ACC_F - S_F), S_W): the last step of both correction modes.
int64_t poly_subtract(int64_t s, int64_t acc0, const DatapathConfig& cfg, bool* ovf);

// The mode's kernels (its row in core/correction_modes.hpp; the signatures of
// stages/correction.hpp). Both curves of a sample: coef = the region's words, c13's n + 1 terms
// then c24's.
void poly_correct_curves(int64_t s13, int64_t s24, int64_t x, int region, const int64_t* coef,
                         const DatapathConfig& cfg, int64_t* y13, int64_t* y24, bool* ovf);
// In double: the argument u of x (x itself, or 2 (x -+ 3/8) with xcenter), P(u) of one curve by
// Horner like the datapath, and the basis u^j (j = 0..n) that the calibration fits.
double correction_u(double x, int xcenter);
double poly_value(const DatapathConfig& shape, const double* coef, double x, double y_other);
void poly_basis(const DatapathConfig& shape, double x, double y_other, double* out);

}  // namespace acore
