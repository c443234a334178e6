// SPDX-License-Identifier: MIT
// FloatCoefficients (regmap/coefficients.hpp), the register map in real numbers: its shape is the
// datapath configuration of its correction, its term count is the map's words per curve, and
// coef(r, c, t) indexes the polynomial words in exactly the register map's order (address - 4,
// DatapathConfig::addr_poly), for every correction mode, degree and region count.
#include <gtest/gtest.h>

#include <cmath>

#include "core/datapath_config.hpp"
#include "regmap/coefficients.hpp"

namespace acore {
namespace {

FloatCoefficients make(int correction, int degree, int regions, int xcenter) {
  FloatCoefficients fc;
  fc.correction = correction;
  fc.degree = degree;
  fc.regions = regions;
  fc.xcenter = xcenter;
  return fc;
}

TEST(Coefficients, ShapeIsTheCorrectionsDatapathConfiguration) {
  const FloatCoefficients fc = make(kPoly2d, 2, 8, 1);
  const DatapathConfig s = fc.shape();
  EXPECT_EQ(s.correction, kPoly2d);
  EXPECT_EQ(s.degree, 2);
  EXPECT_EQ(s.regions, 8);
  EXPECT_EQ(s.xcenter, 1);
  // Everything else is the default datapath (the paper's widths, no Fourier stage, no ZERO word).
  const DatapathConfig d;
  EXPECT_EQ(s.in_w, d.in_w);
  EXPECT_EQ(s.reg_w, d.reg_w);
  EXPECT_EQ(s.coef_f, d.coef_f);
  EXPECT_EQ(s.iterations, d.iterations);
  EXPECT_EQ(s.fourier_k, 0);
  EXPECT_EQ(s.zero_word, 0);
  EXPECT_NO_THROW(s.validate());
}

TEST(Coefficients, TermsPerCurveAreTheMapsWords) {
  // poly: n + 1 powers of x; poly2d: the (d + 1)(d + 2) / 2 monomials of total degree <= d; none:
  // 0.
  for (int n = 1; n <= 7; ++n) EXPECT_EQ(make(kPoly, n, 4, 0).terms(), n + 1);
  for (int d = 1; d <= 3; ++d) EXPECT_EQ(make(kPoly2d, d, 4, 0).terms(), (d + 1) * (d + 2) / 2);
  EXPECT_EQ(make(kNone, 3, 4, 0).terms(), 0);
}

TEST(Coefficients, CoefIndexesInTheRegisterMapsOrder) {
  struct Shape {
    int correction, degree, regions;
  };
  for (const Shape sh : {Shape{kPoly, 3, 4}, Shape{kPoly, 1, 8}, Shape{kPoly, 7, 8},
                         Shape{kPoly2d, 1, 4}, Shape{kPoly2d, 3, 4}, Shape{kPoly2d, 2, 8}}) {
    FloatCoefficients fc = make(sh.correction, sh.degree, sh.regions, 0);
    const DatapathConfig cfg = fc.shape();
    fc.poly.assign(static_cast<size_t>(cfg.poly_words()), -1.0);
    // Each word holds its own register address: coef() must find it where the map puts it.
    for (size_t k = 0; k < fc.poly.size(); ++k) fc.poly[k] = 4.0 + static_cast<double>(k);
    int count = 0;
    for (int r = 0; r < sh.regions; ++r)
      for (int c = 0; c < 2; ++c)
        for (int t = 0; t < fc.terms(); ++t, ++count) {
          EXPECT_EQ(fc.coef(r, c, t), cfg.addr_poly(r, c, t)) << r << " " << c << " " << t;
          fc.coef(r, c, t) = -fc.coef(r, c, t);  // the writable overload reaches the same word
        }
    EXPECT_EQ(count, cfg.poly_words());
    for (size_t k = 0; k < fc.poly.size(); ++k) EXPECT_EQ(fc.poly[k], -(4.0 + k)) << k;
  }
  // The default map (docs/contracts.md, register image): word 4 + 8 r + 4 c + j.
  FloatCoefficients fc = make(kPoly, 3, 4, 0);
  fc.poly.assign(32, 0.0);
  fc.coef(2, 1, 3) = 1.5;
  EXPECT_EQ(fc.poly[8 * 2 + 4 * 1 + 3], 1.5);
  // poly2d: term2d(i, j) of x^i v^j, grouped by the power of x: (1, 1) is word 5 of 10.
  FloatCoefficients f2 = make(kPoly2d, 3, 4, 0);
  f2.poly.assign(80, 0.0);
  f2.coef(1, 0, f2.shape().term2d(1, 1)) = 2.5;
  EXPECT_EQ(f2.poly[10 * 2 + 5], 2.5);
}

TEST(Coefficients, FourierOrderAndZeroOffsetSplit) {
  FloatCoefficients fc;
  EXPECT_EQ(fc.fourier_k(), 0);
  fc.fourier = {0.1, 0.2, 0.3, 0.4, 0.5};  // a_0, (a_1, b_1), (a_2, b_2)
  EXPECT_EQ(fc.fourier_k(), 2);
  fc.zero_offset = -0.7;
  EXPECT_EQ(fc.software_zero_offset(), -0.7);  // no ZERO word: software subtracts it
  fc.zero_word = 1;
  EXPECT_EQ(fc.software_zero_offset(), 0.0);  // the chain does
}

}  // namespace
}  // namespace acore
