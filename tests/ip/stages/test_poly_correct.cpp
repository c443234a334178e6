// SPDX-License-Identifier: MIT
// Stage 4, polynomial correction (stages/poly_correct.*): y = saturate(s - round(acc_0 / 2^(ACC_F -
// S_F)), S_W), acc_0 the Horner sum on the shift-add multiplier. Bit for bit against closed forms:
// at x = +-1/2 and +-1 every product is exact, so acc_0 = 2^ACC_G sum a_j x^j and y is s minus its
// nearest S_F step (half up); the subtraction's rounding alone on every residue of the dropped
// bits; the XCENTER argument u = 2 (x -+ 3/8); the accumulator's saturation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "core/datapath_config.hpp"
#include "core/fixed_point.hpp"
#include "stages/poly_correct.hpp"

namespace acore {
namespace {

int64_t round_half_up(long double x) { return static_cast<int64_t>(std::floor(x + 0.5L)); }

// acc_0 at an exactly representable x (a power of two times an integer) in exact arithmetic:
// 2^ACC_G sum_j a_j x^j, x in units of 2^-S_F, a_j in units of 2^-COEF_F, result in 2^-ACC_F.
long double exact_acc(const int64_t* coef, int degree, long double x_real, int acc_guard) {
  long double acc = 0, pw = 1;
  for (int j = 0; j <= degree; ++j, pw *= x_real) acc += coef[j] * pw;
  return std::ldexp(acc, acc_guard);
}

TEST(PolyCorrect, ExactPointsRoundToTheNearestStepHalfUp) {
  DatapathConfig cfg;  // S_F 16, COEF_F 15, ACC_G 4: y = s - round(acc_0 / 8)
  std::mt19937_64 rng(51);
  std::uniform_int_distribution<int64_t> coef_dist(-20000, 20000), s_dist(-90000, 90000);
  int ties = 0, fractions = 0;
  for (int degree : {1, 2, 3, 5, 7}) {
    cfg.degree = degree;
    for (int k = 0; k < 20000; ++k) {
      int64_t coef[8];
      for (int j = 0; j <= degree; ++j) coef[j] = coef_dist(rng);
      // x = +-1/2: every partial product of an even accumulator is exact; acc_n = a_n 2^ACC_G and
      // the multiplier halves it degree times (ACC_G = 4 keeps up to 4 halvings exact; beyond
      // that, x = +-1 keeps everything exact).
      const int64_t half = int64_t{1} << (cfg.s_f - 1), one = int64_t{1} << cfg.s_f;
      const int64_t x = degree <= cfg.acc_guard ? (k % 2 ? half : -half) : (k % 2 ? one : -one);
      const long double xr = std::ldexp(static_cast<long double>(x), -cfg.s_f);
      const long double acc = exact_acc(coef, degree, xr, cfg.acc_guard);
      bool ovf = false;
      ASSERT_EQ(poly_eval(x, coef, cfg, &ovf), static_cast<int64_t>(acc)) << degree << " " << k;
      ASSERT_FALSE(ovf);
      const int64_t s = s_dist(rng);
      const long double drop = std::ldexp(acc, -(cfg.acc_f() - cfg.s_f));
      bool ovf_want = false;
      const int64_t want = fx::saturate(s - round_half_up(drop), cfg.s_w, &ovf_want);
      ASSERT_EQ(poly_correct(s, x, coef, cfg, &ovf), want)
          << "degree " << degree << " acc " << static_cast<double>(acc);
      ASSERT_EQ(ovf, ovf_want);
      ties += drop - std::floor(drop) == 0.5L;
      fractions += drop != std::floor(drop);
    }
  }
  EXPECT_GT(ties, 1000);
  EXPECT_GT(fractions, 10000);
}

TEST(PolyCorrect, SubtractionRoundsEveryResidueOfTheDroppedBits) {
  DatapathConfig cfg;
  const int drop = cfg.acc_f() - cfg.s_f;  // 3 bits
  const int64_t step = int64_t{1} << drop;
  for (int64_t base : {int64_t{0}, int64_t{40}, int64_t{-40}, int64_t{123456}, int64_t{-123456}})
    for (int64_t r = 0; r < step; ++r) {
      const int64_t acc0 = base * step + r;
      // r / 8 < 1/2 rounds to base, >= 1/2 to base + 1 (also for negative acc0: half up).
      const int64_t want_round = r * 2 < step ? base : base + 1;
      bool ovf = false;
      EXPECT_EQ(poly_subtract(1000, acc0, cfg, &ovf), 1000 - want_round) << acc0;
      EXPECT_FALSE(ovf);
    }
  // The subtraction saturates at S_W on both sides.
  bool ovf = false;
  EXPECT_EQ(poly_subtract(fx::smax(cfg.s_w), -step, cfg, &ovf), fx::smax(cfg.s_w));
  EXPECT_TRUE(ovf);
  ovf = false;
  EXPECT_EQ(poly_subtract(fx::smin(cfg.s_w), step, cfg, &ovf), fx::smin(cfg.s_w));
  EXPECT_TRUE(ovf);
  ovf = false;
  EXPECT_EQ(poly_subtract(fx::smax(cfg.s_w), 0, cfg, &ovf), fx::smax(cfg.s_w));
  EXPECT_FALSE(ovf);
}

TEST(PolyCorrect, ZeroPolynomialLeavesTheCurveAndAConstantShiftsIt) {
  const DatapathConfig cfg;
  const int64_t zero[4] = {0, 0, 0, 0};
  for (int64_t s : {-131072, -1, 0, 5, 131071})
    for (int64_t x : {-40000, 0, 40000}) EXPECT_EQ(poly_correct(s, x, zero, cfg, nullptr), s);
  // a_0 alone: y = s - round(a_0 2^(S_F - COEF_F)) = s - 2 a_0, whatever x.
  for (int64_t a0 : {-7, 1, 300}) {
    const int64_t c[4] = {a0, 0, 0, 0};
    for (int64_t x : {-46341, 0, 12345})
      EXPECT_EQ(poly_correct(100, x, c, cfg, nullptr), 100 - 2 * a0);
  }
}

TEST(PolyCorrect, XcenterArgumentIsTwiceTheDistanceToThreeEighths) {
  DatapathConfig cfg;
  cfg.regions = 8;
  cfg.xcenter = 1;
  const long double lsb = std::ldexp(1.0L, -cfg.s_f);
  for (int64_t x = -(int64_t{1} << cfg.s_f); x <= (int64_t{1} << cfg.s_f); x += 97) {
    const PolyArg a = poly_argument(x, cfg);
    EXPECT_EQ(a.shift, cfg.s_f - 1);
    const long double xr = x * lsb, want = 2 * (xr >= 0 ? xr - 0.375L : xr + 0.375L);
    EXPECT_EQ(std::ldexp(static_cast<long double>(a.u), -a.shift), want) << x;
  }
  cfg.xcenter = 0;
  EXPECT_EQ(poly_argument(-777, cfg).u, -777);
  EXPECT_EQ(poly_argument(-777, cfg).shift, cfg.s_f);
  // Centred evaluation at x = +-5/8 (u = +-1/2): exact, so P = a_0 +- a_1/2 + a_2/4 +- a_3/8.
  cfg.xcenter = 1;
  const int64_t c[4] = {1000, -2000, 4000, 800};
  const int64_t x = (int64_t{5} << (cfg.s_f - 3));  // 5/8
  EXPECT_EQ(poly_eval(x, c, cfg, nullptr), (1000 - 1000 + 1000 + 100) << cfg.acc_guard);
  EXPECT_EQ(poly_eval(-x, c, cfg, nullptr), (1000 + 1000 + 1000 - 100) << cfg.acc_guard);
}

// floor(v / 2^n) by 128-bit division, not by a shift.
int64_t floor_div_pow2(__int128 v, int n) {
  const __int128 d = static_cast<__int128>(1) << n;
  __int128 q = v / d;
  if (v % d != 0 && v < 0) --q;
  return static_cast<int64_t>(q);
}

TEST(PolyCorrect, HardwareMultiplierFloorsEachWholeProductOnce) {
  // MULT = 1: acc_j = saturate(floor(acc_{j+1} u / 2^U_SH) + (a_j << ACC_G), ACC_W), the product
  // exact before its one floor; against that recurrence in 128-bit division, any x and degree,
  // raw and centred arguments.
  DatapathConfig cfg;
  cfg.mult = 1;
  std::mt19937_64 rng(52);
  std::uniform_int_distribution<int64_t> coef_dist(-131072, 131071), x_dist(-65536, 65536);
  int differ = 0;
  for (int xc : {0, 1}) {
    cfg.regions = xc ? 8 : 4;
    cfg.xcenter = xc;
    for (int degree : {1, 3, 5, 7}) {
      cfg.degree = degree;
      for (int k = 0; k < 5000; ++k) {
        int64_t coef[8];
        for (int j = 0; j <= degree; ++j) coef[j] = coef_dist(rng) >> (k % 6);
        const int64_t x = x_dist(rng);
        const int64_t centre = int64_t{3} << (cfg.s_f - 3);
        const int64_t u = !xc ? x : x >= 0 ? x - centre : x + centre;
        const int sh = xc ? cfg.s_f - 1 : cfg.s_f;
        const int64_t g = int64_t{1} << cfg.acc_guard;
        bool ovf_want = false;
        int64_t acc = coef[degree] * g;
        for (int j = degree - 1; j >= 0; --j)
          acc = fx::saturate(floor_div_pow2(static_cast<__int128>(acc) * u, sh) + coef[j] * g,
                             cfg.acc_w(), &ovf_want);
        bool ovf = false;
        ASSERT_EQ(poly_eval(x, coef, cfg, &ovf), acc) << degree << " " << x;
        ASSERT_EQ(ovf, ovf_want);
        DatapathConfig adders = cfg;
        adders.mult = 0;
        differ += poly_eval(x, coef, adders, nullptr) != acc;
      }
    }
  }
  EXPECT_GT(differ, 20000);  // the shift-add tree's rule is a different one
}

TEST(PolyCorrect, AccumulatorSaturatesAtAccW) {
  DatapathConfig cfg;
  cfg.degree = 1;
  const int64_t big = fx::smax(cfg.reg_w);  // Q3.15: almost 4
  // a_0 + a_1 x at x = 1: 8 in an accumulator of ACC_I = 6 integer bits (+-32): fits.
  const int64_t c[2] = {big, big};
  const int64_t one = int64_t{1} << cfg.s_f;
  bool ovf = false;
  EXPECT_EQ(poly_eval(one, c, cfg, &ovf), 2 * big * (int64_t{1} << cfg.acc_guard));
  EXPECT_FALSE(ovf);
  // With ACC_I = 3 (+-4) the same sum saturates to the accumulator's bound.
  cfg.acc_int = 3;
  ovf = false;
  EXPECT_EQ(poly_eval(one, c, cfg, &ovf), fx::smax(cfg.acc_w()));
  EXPECT_TRUE(ovf);
  ovf = false;
  const int64_t n[2] = {-big - 1, -big - 1};
  EXPECT_EQ(poly_eval(one, n, cfg, &ovf), fx::smin(cfg.acc_w()));
  EXPECT_TRUE(ovf);
}

}  // namespace
}  // namespace acore
