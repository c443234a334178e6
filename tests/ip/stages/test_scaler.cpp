// SPDX-License-Identifier: MIT
// Stage 2, scaling (stages/scaler.*): s = saturate(round(p / 2^SCALE_G), S_W), p the shift-add
// product of t = d - O and the reciprocal R. Checked bit for bit against closed forms: where R has
// no bit below R_SHIFT - SCALE_G the product is exact and s is t R / 2^R_SHIFT rounded to the
// nearest, half up; for any R against a second implementation in exact integer arithmetic (floor
// division per partial product, then the rounding in long double).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "core/datapath_config.hpp"
#include "core/fixed_point.hpp"
#include "stages/scaler.hpp"

namespace acore {
namespace {

// floor(a / 2^n) for n >= 0 by division, not by a shift.
int64_t floor_div_pow2(int64_t a, int n) {
  const int64_t d = int64_t{1} << n;
  const int64_t q = a / d;
  return (a % d != 0 && a < 0) ? q - 1 : q;
}

// round(x), half up, of a value that long double holds exactly.
int64_t round_half_up(long double x) { return static_cast<int64_t>(std::floor(x + 0.5L)); }

TEST(Scaler, RoundsTheExactQuotientToNearestHalfUp) {
  const DatapathConfig cfg;  // R_SHIFT 13, SCALE_G 4: bits 9 and up of R multiply exactly
  // R = 2^12: s = t / 2 exactly, so every odd t is a tie.
  const int64_t half = int64_t{1} << (cfg.r_shift - 1);
  const int64_t want[][2] = {{3, 2}, {-3, -1}, {1, 1}, {-1, 0}, {5, 3}, {-5, -2}, {4, 2}, {0, 0}};
  for (const auto& tw : want) {
    bool ovf = false;
    EXPECT_EQ(scale_curve(tw[0], 0, half, cfg, &ovf), tw[1]) << "t = " << tw[0];
    EXPECT_FALSE(ovf);
  }
  // Any R without bits below R_SHIFT - SCALE_G: s = round(t R / 2^R_SHIFT), ties up.
  std::mt19937_64 rng(41);
  std::uniform_int_distribution<int64_t> t_dist(-131072, 131071), r_hi(0, (1 << 9) - 1);
  int ties = 0, roundings_up = 0;
  for (int k = 0; k < 200000; ++k) {
    const int64_t t = t_dist(rng) / (1 + k % 64);  // small and large magnitudes
    const int64_t r = r_hi(rng) << (cfg.r_shift - cfg.scale_guard);
    const long double q = std::ldexp(static_cast<long double>(t) * r, -cfg.r_shift);
    int64_t s_want = round_half_up(q);
    bool ovf_want = false;
    s_want = fx::saturate(s_want, cfg.s_w, &ovf_want);
    bool ovf = false;
    ASSERT_EQ(scale_curve(t, 0, r, cfg, &ovf), s_want) << "t " << t << " R " << r;
    ASSERT_EQ(ovf, ovf_want) << "t " << t << " R " << r;
    ties += q - std::floor(q) == 0.5L;
    roundings_up += q - std::floor(q) >= 0.5L;
  }
  EXPECT_GT(ties, 1000);  // the ties are really exercised
  EXPECT_GT(roundings_up, 50000);
}

TEST(Scaler, AnyReciprocalMatchesTheFloorPerPartialProductThenRounding) {
  const DatapathConfig cfg;
  const int rs = cfg.r_shift - cfg.scale_guard;
  std::mt19937_64 rng(42);
  std::uniform_int_distribution<int64_t> d_dist(-65536, 65535), o_dist(-3000, 3000),
      r_dist(0, (int64_t{1} << cfg.reg_w) - 1);
  for (int k = 0; k < 200000; ++k) {
    const int64_t d = d_dist(rng), o = o_dist(rng), r = r_dist(rng) >> (k % 8);
    const int64_t t = d - o;
    // The adder tree: one floored partial product t 2^j / 2^rs per set bit j of R.
    int64_t p = 0;
    for (int j = 0; j < cfg.reg_w; ++j)
      if ((r >> j) & 1) p += j >= rs ? t * (int64_t{1} << (j - rs)) : floor_div_pow2(t, rs - j);
    bool ovf_want = false;
    const int64_t s_want =
        fx::saturate(round_half_up(std::ldexp(static_cast<long double>(p), -cfg.scale_guard)),
                     cfg.s_w, &ovf_want);
    bool ovf = false;
    ASSERT_EQ(scale_curve(d, o, r, cfg, &ovf), s_want) << d << " " << o << " " << r;
    ASSERT_EQ(ovf, ovf_want);
    // Only t = d - O matters.
    ASSERT_EQ(scale_curve(t, 0, r, cfg, nullptr), s_want);
  }
}

TEST(Scaler, HardwareMultiplierFloorsTheWholeProductOnce) {
  // MULT = 1: p = floor(t R / 2^(R_SHIFT - SCALE_G)) by division, then the same rounding.
  DatapathConfig cfg;
  cfg.mult = 1;
  const int rs = cfg.r_shift - cfg.scale_guard;
  std::mt19937_64 rng(43);
  std::uniform_int_distribution<int64_t> d_dist(-65536, 65535), o_dist(-3000, 3000),
      r_dist(0, (int64_t{1} << cfg.reg_w) - 1);
  int differ = 0;
  for (int k = 0; k < 200000; ++k) {
    const int64_t d = d_dist(rng), o = o_dist(rng), r = r_dist(rng) >> (k % 8);
    const int64_t p = floor_div_pow2((d - o) * r, rs);
    bool ovf_want = false;
    const int64_t s_want =
        fx::saturate(round_half_up(std::ldexp(static_cast<long double>(p), -cfg.scale_guard)),
                     cfg.s_w, &ovf_want);
    bool ovf = false;
    ASSERT_EQ(scale_curve(d, o, r, cfg, &ovf), s_want) << d << " " << o << " " << r;
    ASSERT_EQ(ovf, ovf_want);
    DatapathConfig adders = cfg;
    adders.mult = 0;
    differ += scale_curve(d, o, r, adders, nullptr) != s_want;
  }
  EXPECT_GT(differ, 1000);  // the rule is a different one: MULT = 0 rounds some samples apart
}

TEST(Scaler, SaturatesAtSWOnBothSidesAndTheFlagIsSticky) {
  const DatapathConfig cfg;
  const int64_t one = int64_t{1} << cfg.r_shift;  // R = 2^13: s = t (gain 1)
  const int64_t hi = fx::smax(cfg.s_w), lo = fx::smin(cfg.s_w);
  bool ovf = false;
  EXPECT_EQ(scale_curve(hi, 0, one, cfg, &ovf), hi);
  EXPECT_EQ(scale_curve(lo, 0, one, cfg, &ovf), lo);
  EXPECT_FALSE(ovf);  // the bounds themselves fit
  EXPECT_EQ(scale_curve(hi + 1, 0, one, cfg, &ovf), hi);
  EXPECT_TRUE(ovf);
  ovf = false;
  EXPECT_EQ(scale_curve(lo - 1, 0, one, cfg, &ovf), lo);
  EXPECT_TRUE(ovf);
  // A later sample that fits leaves the flag set: it is the stage's, per sample, OR-ed.
  EXPECT_EQ(scale_curve(7, 0, one, cfg, &ovf), 7);
  EXPECT_TRUE(ovf);
  // The widest t (T_W = D_W + 1 bits) with the largest R: far beyond S_W, clamped.
  ovf = false;
  const int64_t rmax = (int64_t{1} << cfg.reg_w) - 1;
  EXPECT_EQ(scale_curve(fx::smax(cfg.d_w()), fx::smin(cfg.d_w()), rmax, cfg, &ovf), hi);
  EXPECT_TRUE(ovf);
  ovf = false;
  EXPECT_EQ(scale_curve(fx::smin(cfg.d_w()), fx::smax(cfg.d_w()), rmax, cfg, &ovf), lo);
  EXPECT_TRUE(ovf);
}

}  // namespace
}  // namespace acore
