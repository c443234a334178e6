// SPDX-License-Identifier: MIT
// Stage 4, 2-D polynomial correction (CORRECTION = poly2d): y = s - P(x, v), P of total degree d
// <= 3 in the linear curve x and the other curve's offset from the region's centre,
//   v = y_other - (y_other >= 0 ? 1 : -1)     exact: |v| <= 1 fits S_W bits
// read by the multiplier as 4 v (V_SH = S_F - kVShift). Why v and not y: near a region's centre
// x^2 + y^2 ~ 1, so the monomials x^i y^j are nearly dependent (least-squares condition number
// 1.7e6 on the paper scenario, coefficients up to 6.7: out of Q3.15's +-4); in x^i v^j it is 3.2e5
// (7.7), and with v read as 4 v (|4v| <= 1.4 there, like |x| <= 0.75) 1.1e5 and 0.93.
// Mirrors rtl/acore_poly2d_correct.v. Nested Horner, every product on the adder/shifter multiplier
// with each partial product floored on its own (fixed_point.hpp shift_add_mul):
//   inner, for every power i of x:  Q_i(v) = sum_j a_ij v^j, j = 0..d-i
//     q = a_{i,d-i} << ACC_G
//     q = saturate(shift_add_mul(q, v, S_W, V_SH) + (a_ij << ACC_G), ACC_W)
//   outer:  acc = Q_d;  acc = saturate(shift_add_mul(acc, u, S_W, U_SH) + Q_i, ACC_W), i = d-1..0
//   y = saturate(s - round_shr(acc, ACC_F - S_F), S_W)
// u, U_SH as in poly_correct.hpp (x itself unless XCENTER). Coefficient words in the order of
// DatapathConfig::term2d: (0,0), (0,1), .., (0,d), (1,0), .., (d,0). MULT = 1: every product is
// hw_mul (the full product, floored once) instead.
#pragma once
#include <cstdint>

#include "core/datapath_config.hpp"

namespace acore {

int64_t poly2d_v(int64_t y_other, const DatapathConfig& cfg);
// coef[term2d(i, j)] = a_ij (sign-extended REG_W-bit words, COEF_F fraction bits). Returns acc_0.
int64_t poly2d_eval(int64_t x, int64_t v, const int64_t* coef, const DatapathConfig& cfg,
                    bool* ovf);
int64_t poly2d_correct(int64_t s, int64_t x, int64_t v, const int64_t* coef,
                       const DatapathConfig& cfg, bool* ovf);

// The mode's kernels (its row in core/correction_modes.hpp; the signatures of
// stages/correction.hpp). Both curves of a sample: v from the other curve of the region (s24 where
// x is the sine curve), coef = the region's words, c13's terms then c24's.
void poly2d_correct_curves(int64_t s13, int64_t s24, int64_t x, int region, const int64_t* coef,
                           const DatapathConfig& cfg, int64_t* y13, int64_t* y24, bool* ovf);
// In double: v = 2^kVShift (y_other - sign(y_other)), P(u, v) of one curve by the datapath's
// nested Horner, and the basis u^i v^j (term2d order) that the calibration fits.
double correction_v(double y_other);
double poly2d_value(const DatapathConfig& shape, const double* coef, double x, double y_other);
void poly2d_basis(const DatapathConfig& shape, double x, double y_other, double* out);

}  // namespace acore
