// SPDX-License-Identifier: MIT
// The correction stage across its modes (stages/correction.hpp, the kernels named in the rows of
// core/correction_modes.hpp): each mode's bit-accurate kernel corrects both curves as its per-curve
// stage does, with the region's words (c13's, then c24's) and, for poly2d, v from the other curve
// (s24 where x is the sine curve: regions 0 and 2 of four, docs/datapath.md); `none` passes the
// curves through; and every mode's float value equals the sum of its coefficients times its basis
// values (a second evaluation of the same polynomial).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/correction_modes.hpp"
#include "stages/correction.hpp"

namespace acore {
namespace {

TEST(Correction, Poly2dKernelTakesVFromTheOtherCurveOfTheRegion) {
  DatapathConfig cfg;
  cfg.correction = kPoly2d;
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int64_t> s(-(int64_t{1} << 16), int64_t{1} << 16),
      a(-(1 << 15), 1 << 15);
  const int terms = cfg.coef_per_curve();
  std::vector<int64_t> coef(static_cast<size_t>(2 * terms));
  for (int k = 0; k < 400; ++k) {
    for (auto& c : coef) c = a(rng);
    const int64_t s13 = s(rng), s24 = s(rng), x = s(rng) / 2;
    const int region = k % 4;
    const int64_t other = (region == 0 || region == 2) ? s24 : s13;  // docs/datapath.md
    bool ovf = false, ovf_want = false;
    int64_t y13 = 0, y24 = 0;
    poly2d_correct_curves(s13, s24, x, region, coef.data(), cfg, &y13, &y24, &ovf);
    const int64_t v = poly2d_v(other, cfg);
    EXPECT_EQ(y13, poly2d_correct(s13, x, v, coef.data(), cfg, &ovf_want));
    EXPECT_EQ(y24, poly2d_correct(s24, x, v, coef.data() + terms, cfg, &ovf_want));
    EXPECT_EQ(ovf, ovf_want);
  }
}

TEST(Correction, PolyKernelCorrectsEachCurveWithItsOwnWords) {
  DatapathConfig cfg;
  cfg.degree = 5;
  std::mt19937_64 rng(6);
  std::uniform_int_distribution<int64_t> s(-(int64_t{1} << 16), int64_t{1} << 16),
      a(-(1 << 15), 1 << 15);
  std::vector<int64_t> coef(12);
  for (int k = 0; k < 400; ++k) {
    for (auto& c : coef) c = a(rng);
    const int64_t s13 = s(rng), s24 = s(rng), x = s(rng) / 2;
    bool ovf = false, ovf_want = false;
    int64_t y13 = 0, y24 = 0;
    poly_correct_curves(s13, s24, x, k % 4, coef.data(), cfg, &y13, &y24, &ovf);
    EXPECT_EQ(y13, poly_correct(s13, x, coef.data(), cfg, &ovf_want));
    EXPECT_EQ(y24, poly_correct(s24, x, coef.data() + 6, cfg, &ovf_want));
    EXPECT_EQ(ovf, ovf_want);
  }
}

TEST(Correction, NonePassesTheCurvesThrough) {
  DatapathConfig cfg;
  cfg.correction = kNone;
  bool ovf = false;
  int64_t y13 = 0, y24 = 0;
  none_correct_curves(-12345, 54321, 7, 2, nullptr, cfg, &y13, &y24, &ovf);
  EXPECT_EQ(y13, -12345);
  EXPECT_EQ(y24, 54321);
  EXPECT_FALSE(ovf);
  EXPECT_EQ(none_value(cfg, nullptr, 0.3, 0.9), 0.0);
  double out[1] = {42.0};
  none_basis(cfg, 0.3, 0.9, out);
  EXPECT_EQ(out[0], 42.0);  // no term written
}

// The float kernels of every row, through the VALUE and BASIS columns.
using ValueKernel = double (*)(const DatapathConfig&, const double*, double, double);
using BasisKernel = void (*)(const DatapathConfig&, double, double, double*);
constexpr ValueKernel kValue[] = {ACORE_CORRECTION_MODES(ACORE_MODE_VALUE)};
constexpr BasisKernel kBasis[] = {ACORE_CORRECTION_MODES(ACORE_MODE_BASIS)};

TEST(Correction, EveryModesValueIsItsCoefficientsTimesItsBasis) {
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> xd(-0.72, 0.72), yd(0.69, 1.05), cd(-1.5, 1.5);
  for (const CorrectionMode& m : correction_modes())
    for (int d = m.degree_min; d <= m.degree_max; ++d)
      for (int xcenter : {0, 1}) {
        DatapathConfig shape;
        shape.correction = m.id;
        shape.degree = d;
        shape.regions = 8;
        shape.xcenter = xcenter;
        std::vector<double> coef(static_cast<size_t>(m.terms(d)) + 1, 0.0);
        for (int k = 0; k < 200; ++k) {
          for (double& c : coef) c = cd(rng);
          const double x = xd(rng), y = (k % 2 ? 1 : -1) * yd(rng);
          double basis[64];
          kBasis[m.id](shape, x, y, basis);
          double want = 0;
          for (int t = 0; t < m.terms(d); ++t) want += coef[static_cast<size_t>(t)] * basis[t];
          ASSERT_NEAR(kValue[m.id](shape, coef.data(), x, y), want, 1e-12)
              << m.name << " degree " << d << " xcenter " << xcenter;
        }
      }
}

}  // namespace
}  // namespace acore
