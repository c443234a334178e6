// SPDX-License-Identifier: MIT
// The double-precision chain (engine/float_model.*) against closed forms: the correction arguments
// u = x or 2 (x -+ 3/8) and v = 4 (y_other -+ 1); every basis value is the monomial u^i v^j of its
// register-map term; the Horner evaluation equals a long-double sum of coefficient times monomial;
// the angle is atan2 of the corrected curves in [0, 2 pi), invariant under the offset and amplitude
// it removes; the Fourier stage and the ZERO word subtract what they hold.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/errors.hpp"
#include "engine/float_model.hpp"
#include "stages/region_select.hpp"

namespace acore {
namespace {

TEST(FloatModel, CorrectionArguments) {
  for (double x : {-0.7, -0.375, -0.1, 0.0, 0.2, 0.375, 0.7}) {
    EXPECT_EQ(correction_u(x, 0), x);
    EXPECT_DOUBLE_EQ(correction_u(x, 1), 2 * (x >= 0 ? x - 0.375 : x + 0.375)) << x;
  }
  EXPECT_EQ(correction_u(0.0, 1), -0.75);  // x = 0 belongs to the upper half region
  EXPECT_DOUBLE_EQ(correction_v(1.0), 0.0);
  EXPECT_DOUBLE_EQ(correction_v(-1.0), 0.0);
  EXPECT_DOUBLE_EQ(correction_v(0.9), -0.4);  // 4 (0.9 - 1)
  EXPECT_DOUBLE_EQ(correction_v(-0.8), 0.8);  // 4 (-0.8 + 1)
  EXPECT_DOUBLE_EQ(correction_v(0.0), -4.0);
}

// The map's term order (DatapathConfig::term2d) as explicit (power of u, power of v) pairs.
std::vector<std::pair<int, int>> terms_of(const DatapathConfig& shape) {
  std::vector<std::pair<int, int>> t(static_cast<size_t>(shape.coef_per_curve()));
  if (shape.correction == kPoly)
    for (int j = 0; j <= shape.degree; ++j) t[static_cast<size_t>(j)] = {j, 0};
  else
    for (int i = 0; i <= shape.degree; ++i)
      for (int j = 0; i + j <= shape.degree; ++j)
        t[static_cast<size_t>(shape.term2d(i, j))] = {i, j};
  return t;
}

TEST(FloatModel, BasisAndHornerEqualTheMonomialSum) {
  std::mt19937_64 rng(91);
  std::uniform_real_distribution<double> xd(-0.72, 0.72), yd(0.69, 1.05), cd(-1.5, 1.5);
  struct Shape {
    int correction, degree, regions, xcenter;
  };
  for (const Shape sh :
       {Shape{kPoly, 1, 4, 0}, Shape{kPoly, 3, 4, 0}, Shape{kPoly, 7, 8, 1},
        Shape{kPoly2d, 1, 4, 0}, Shape{kPoly2d, 3, 8, 0}, Shape{kPoly2d, 2, 8, 1}}) {
    FloatCoefficients fc;
    fc.correction = sh.correction;
    fc.degree = sh.degree;
    fc.regions = sh.regions;
    fc.xcenter = sh.xcenter;
    const DatapathConfig shape = fc.shape();
    const auto terms = terms_of(shape);
    fc.poly.resize(static_cast<size_t>(sh.regions * 2 * fc.terms()));
    for (double& c : fc.poly) c = cd(rng);
    for (int k = 0; k < 2000; ++k) {
      const double x = xd(rng), y = (k % 2 ? 1 : -1) * yd(rng);
      const long double u = correction_u(x, sh.xcenter);
      const long double v = sh.correction == kPoly2d ? correction_v(y) : 0.0;
      double basis[64];
      correction_basis(shape, x, y, basis);
      for (size_t t = 0; t < terms.size(); ++t)
        ASSERT_NEAR(basis[t], std::pow(u, terms[t].first) * std::pow(v, terms[t].second), 1e-14)
            << "term " << t;
      const int r = k % sh.regions, c = (k / sh.regions) % 2;
      long double want = 0;
      for (size_t t = 0; t < terms.size(); ++t)
        want += fc.coef(r, c, static_cast<int>(t)) * std::pow(u, terms[t].first) *
                std::pow(v, terms[t].second);
      ASSERT_NEAR(correction_poly(fc, r, c, x, y), static_cast<double>(want), 1e-12);
    }
  }
  FloatCoefficients none;
  none.correction = kNone;
  EXPECT_EQ(correction_poly(none, 0, 0, 0.3, 0.9), 0.0);
}

TEST(FloatModel, UncorrectedChainIsAtan2InvariantUnderOffsetAndAmplitude) {
  FloatCoefficients fc;
  fc.poly.assign(static_cast<size_t>(4 * 2 * fc.terms()), 0.0);
  fc.offset[0] = 0.31;
  fc.offset[1] = -1.7;
  fc.amp[0] = 2.5;
  fc.amp[1] = 0.4;
  for (int k = 0; k < 3600; ++k) {
    const double th = 2 * M_PI * (k + 0.25) / 3600;
    const FloatSample s = float_estimate(fc.offset[0] + fc.amp[0] * std::sin(th),
                                         fc.offset[1] + fc.amp[1] * std::cos(th), fc);
    ASSERT_NEAR(s.angle, th, 1e-12) << k;  // in [0, 2 pi): no wrap needed for th
    ASSERT_GE(s.angle, 0.0);
    ASSERT_LT(s.angle, 2 * M_PI);
    ASSERT_NEAR(s.s13, std::sin(th), 1e-12);
    ASSERT_NEAR(s.s24, std::cos(th), 1e-12);
    ASSERT_EQ(s.uncorrected, s.angle);
    ASSERT_EQ(s.cordic_angle, s.angle);
    double x;
    ASSERT_EQ(s.region, select_region_real(s.s13, s.s24, 4, &x));
  }
}

TEST(FloatModel, CorrectionSubtractsThePolynomialOfItsRegion) {
  FloatCoefficients fc;  // poly, degree 3, 4 regions
  fc.poly.assign(static_cast<size_t>(4 * 2 * fc.terms()), 0.0);
  for (int r = 0; r < 4; ++r) {
    fc.coef(r, 0, 0) = 0.01 * (r + 1);   // a constant per region and curve
    fc.coef(r, 1, 1) = -0.02 * (r + 1);  // and a slope in x on the cosine curve
  }
  for (int k = 0; k < 720; ++k) {
    const double th = 2 * M_PI * (k + 0.5) / 720;
    const FloatSample s = float_estimate(std::sin(th), std::cos(th), fc);
    double x;
    const int r = select_region_real(std::sin(th), std::cos(th), 4, &x);
    ASSERT_EQ(s.region, r);
    ASSERT_NEAR(s.y13, std::sin(th) - 0.01 * (r + 1), 1e-15);
    ASSERT_NEAR(s.y24, std::cos(th) + 0.02 * (r + 1) * x, 1e-15);
    double want = std::atan2(s.y13, s.y24);
    if (want < 0) want += 2 * M_PI;
    ASSERT_EQ(s.angle, want);
    ASSERT_NEAR(s.uncorrected, th, 1e-12);
  }
}

TEST(FloatModel, FourierAndZeroWordSubtractFromTheAngle) {
  FloatCoefficients fc;
  fc.correction = kNone;
  fc.fourier = {0.01, 0.002, -0.003, 0.0, 0.001};  // a_0, a_1, b_1, a_2, b_2 (rad)
  fc.zero_offset = 0.4;
  fc.zero_word = 1;
  for (int k = 0; k < 1000; ++k) {
    const double th = 2 * M_PI * (k + 0.5) / 1000;
    const FloatSample s = float_estimate(std::sin(th), std::cos(th), fc);
    const double delta =
        0.01 + 0.002 * std::cos(th) - 0.003 * std::sin(th) + 0.001 * std::sin(2 * th);
    const double want = std::remainder(th - delta - 0.4, 2 * M_PI);
    ASSERT_NEAR(std::remainder(s.angle - want, 2 * M_PI), 0.0, 1e-12) << k;
    ASSERT_GE(s.angle, 0.0);
    ASSERT_LT(s.angle, 2 * M_PI);
    ASSERT_NEAR(std::remainder(s.cordic_angle - th, 2 * M_PI), 0.0, 1e-12);
    ASSERT_NEAR(std::remainder(s.uncorrected - (th - 0.4), 2 * M_PI), 0.0, 1e-12);
  }
  // Without the ZERO word the chain leaves the offset to software.
  fc.zero_word = 0;
  EXPECT_EQ(fc.software_zero_offset(), 0.4);
  const FloatSample s = float_estimate(std::sin(1.0), std::cos(1.0), fc);
  EXPECT_NEAR(s.uncorrected, 1.0, 1e-12);
}

// A correction mode no row of the table has is an InputError naming it, not a zero correction.
TEST(FloatModel, AModeOutsideTheTableIsAnInputErrorNamingIt) {
  FloatCoefficients fc;
  fc.correction = 5;
  try {
    float_estimate(0.3, 0.9, fc);
    ADD_FAILURE() << "float_estimate ran correction 5";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("correction mode 5"), std::string::npos) << e.what();
  }
  double basis[64];
  EXPECT_THROW(correction_basis(fc.shape(), 0.3, 0.9, basis), InputError);
  EXPECT_THROW(correction_poly(fc, 0, 0, 0.3, 0.9), InputError);
}

}  // namespace
}  // namespace acore
