// SPDX-License-Identifier: MIT
// The bit-accurate primitives and stages against exact arithmetic and their analytic error bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/fixed_point.hpp"
#include "stages/cordic.hpp"
#include "stages/poly_correct.hpp"
#include "stages/scaler.hpp"

namespace acore {
namespace {

TEST(ShiftAddMul, EqualsTheExactProductWhenNoBitIsDropped) {
  std::mt19937_64 rng(1);
  std::uniform_int_distribution<int64_t> a(-(1 << 20), 1 << 20), b(-(1 << 17), (1 << 17) - 1);
  for (int k = 0; k < 20000; ++k) {
    const int64_t x = a(rng), y = b(rng);
    ASSERT_EQ(fx::shift_add_mul(x, y, 18, true, 0), x * y);
    ASSERT_EQ(fx::shift_add_mul(x, y & 0x3ffff, 18, false, 0), x * (y & 0x3ffff));
  }
}

TEST(ShiftAddMul, TruncationStaysWithinOneLsbPerDroppedPartialProduct) {
  std::mt19937_64 rng(2);
  std::uniform_int_distribution<int64_t> a(-(1 << 22), 1 << 22), b(-(1 << 17), (1 << 17) - 1);
  const int rshift = 16, bw = 18;
  for (int k = 0; k < 20000; ++k) {
    const int64_t x = a(rng), y = b(rng);
    const double exact = std::ldexp(static_cast<double>(x) * y, -rshift);
    const int64_t got = fx::shift_add_mul(x, y, bw, true, rshift);
    // Each of the 16 right-shifted partial products floors (error in [-1, 0]); the negative-weight
    // top bit is left-shifted here, so the sum errs by at most 16 LSB, downwards for y >= 0.
    ASSERT_LE(std::fabs(got - exact), 16.0);
  }
}

TEST(ShiftAddMul, SplitAtTheShiftEqualsTheBitLoop) {
  // The split form of the product (shift_add_mul_split: the stages and the batch path) against the
  // partial-product loop, signed b (the corrections) and unsigned b (the scaler's reciprocal), at
  // the shifts in use (9, 16: the table path) and around them, on random words and the extremes.
  std::mt19937_64 rng(3);
  for (int r : {3, 9, 15, 16, 17, 20}) {
    const int bw = r + 2 + static_cast<int>(rng() % 4);
    const int64_t bmin = -(int64_t{1} << (bw - 1)), bmax = (int64_t{1} << (bw - 1)) - 1;
    std::uniform_int_distribution<int64_t> a(-(1 << 24), 1 << 24), b(bmin, bmax);
    std::vector<int64_t> as{0, 1, -1, (1 << 24) - 1, -(1 << 24)}, bs{0, 1, -1, bmin, bmax};
    for (int k = 0; k < 20000; ++k) as.push_back(a(rng)), bs.push_back(b(rng));
    for (size_t k = 0; k < as.size(); ++k) {
      ASSERT_EQ(fx::shift_add_mul_split(as[k], bs[k], r),
                fx::shift_add_mul(as[k], bs[k], bw, true, r))
          << "a " << as[k] << " b " << bs[k] << " r " << r;
      const int64_t u = bs[k] & ((int64_t{1} << bw) - 1);  // the same bits read unsigned
      ASSERT_EQ(fx::shift_add_mul_split(as[k], u, r), fx::shift_add_mul(as[k], u, bw, false, r))
          << "a " << as[k] << " unsigned b " << u << " r " << r;
    }
  }
}

// floor(v / 2^n) of an exact 128-bit product by division, not by a shift.
int64_t floor_div_pow2_128(__int128 v, int n) {
  const __int128 d = static_cast<__int128>(1) << n;
  __int128 q = v / d;
  if (v % d != 0 && v < 0) --q;
  return static_cast<int64_t>(q);
}

TEST(HwMul, IsTheExactProductFlooredOnce) {
  // MULT = 1: floor(a b / 2^r) of the exact (128-bit) product, b read signed or unsigned from its
  // b_w bits, at the datapath's shifts (the scaler's 9, the corrections' 14..16) and around them.
  std::mt19937_64 rng(4);
  for (int r : {0, 1, 9, 14, 16, 17, 20}) {
    for (int bw : {18, 20, 22}) {
      std::uniform_int_distribution<int64_t> a(-(int64_t{1} << 30), int64_t{1} << 30);
      std::uniform_int_distribution<int64_t> b(-(int64_t{1} << (bw - 1)),
                                               (int64_t{1} << (bw - 1)) - 1);
      for (int k = 0; k < 5000; ++k) {
        const int64_t x = a(rng) >> (k % 20), y = b(rng);
        ASSERT_EQ(fx::hw_mul(x, y, bw, true, r),
                  floor_div_pow2_128(static_cast<__int128>(x) * y, r))
            << x << " " << y << " " << r;
        const int64_t u = y & ((int64_t{1} << bw) - 1);  // the same bits read unsigned
        ASSERT_EQ(fx::hw_mul(x, u, bw, false, r),
                  floor_div_pow2_128(static_cast<__int128>(x) * u, r));
        // Given as a negative int64, the signed b is the same value.
        ASSERT_EQ(fx::hw_mul(x, u, bw, true, r), fx::hw_mul(x, y, bw, true, r));
      }
    }
  }
}

TEST(HwMul, ExceedsTheShiftAddTreeByTheFloorOfTheDroppedFractions) {
  // hw_mul - shift_add_mul = floor(sum over the set bits j < r of b of frac(a 2^(j-r))), so it is
  // 0 when b has no bit below r, and 0..c-1 for c such bits; the two rules are different ones.
  std::mt19937_64 rng(5);
  const int bw = 18, r = 16;
  std::uniform_int_distribution<int64_t> a(-(1 << 24), 1 << 24), b(-(1 << 17), (1 << 17) - 1);
  int differ = 0;
  for (int k = 0; k < 50000; ++k) {
    const int64_t x = a(rng), y = b(rng);
    const int64_t hw = fx::hw_mul(x, y, bw, true, r), sa = fx::shift_add_mul(x, y, bw, true, r);
    // The dropped fractions in units of 2^-r, summed exactly.
    int64_t frac = 0;
    int c = 0;
    for (int j = 0; j < r; ++j)
      if ((y >> j) & 1) frac += (x * (int64_t{1} << j)) & ((int64_t{1} << r) - 1), ++c;
    ASSERT_EQ(hw - sa, frac >> r) << x << " " << y;
    ASSERT_GE(hw - sa, 0);
    ASSERT_LE(hw - sa, c > 0 ? c - 1 : 0);
    const int64_t yh = y & ~((int64_t{1} << r) - 1);  // no bit below r: the rules agree
    ASSERT_EQ(fx::hw_mul(x, yh, bw, true, r), fx::shift_add_mul(x, yh, bw, true, r));
    differ += hw != sa;
    ASSERT_EQ(fx::datapath_mul(1, x, y, bw, true, r), hw);
    ASSERT_EQ(fx::datapath_mul(0, x, y, bw, true, r), sa);
  }
  EXPECT_GT(differ, 40000);  // they differ on most operands
}

TEST(FixedHelpers, RoundSaturateSignExtend) {
  EXPECT_EQ(fx::round_shr(5, 1), 3);    // 2.5 -> 3 (half up)
  EXPECT_EQ(fx::round_shr(-5, 1), -2);  // -2.5 -> -2 (half up)
  EXPECT_EQ(fx::round_shr(-7, 2), -2);  // -1.75 -> -2
  bool ovf = false;
  EXPECT_EQ(fx::saturate(131072, 18, &ovf), 131071);
  EXPECT_TRUE(ovf);
  ovf = false;
  EXPECT_EQ(fx::saturate(-131072, 18, &ovf), -131072);
  EXPECT_FALSE(ovf);
  EXPECT_EQ(fx::sext(0x3ffff, 18), -1);
  EXPECT_EQ(fx::sext(0x1ffff, 18), 131071);
}

// mask(w) has exactly w low bits set, at both ends of its range; the widest word sign-extends
// from the top bit (the observer's 41-bit registers and the 64-bit model words use both).
TEST(FixedHelpers, MaskAndSignExtendOverEveryWidth) {
  EXPECT_EQ(fx::mask(0), 0u);
  EXPECT_EQ(fx::mask(64), ~uint64_t{0});
  for (int w = 1; w <= 64; ++w) {
    EXPECT_EQ(__builtin_popcountll(fx::mask(w)), w) << w;
    EXPECT_EQ(fx::mask(w) >> (w - 1), 1u) << w;
    EXPECT_EQ(fx::sext(static_cast<int64_t>(fx::mask(w)), w), -1) << w;
    // The largest positive w-bit value stays itself.
    if (w > 1 && w < 64)
      EXPECT_EQ(fx::sext(static_cast<int64_t>(fx::mask(w - 1)), w), fx::smax(w)) << w;
  }
}

TEST(Scaler, MatchesTheRealQuotientWithinHalfAnLsbPlusTruncation) {
  DatapathConfig cfg;
  const double amp = 8000.0;
  const int64_t recip = std::llround(std::ldexp(1.0, cfg.s_f + cfg.r_shift) / amp);
  const double amp_q = std::ldexp(1.0, cfg.s_f + cfg.r_shift) / recip;  // what R really encodes
  for (int64_t d = -15000; d <= 15000; d += 37) {
    bool ovf = false;
    const int64_t s = scale_curve(d, 120, recip, cfg, &ovf);
    const double want = (d - 120) / amp_q * std::ldexp(1.0, cfg.s_f);
    // round (0.5) + floor of each of the guard-extended partial products (reg_w / 2^guard).
    EXPECT_LE(std::fabs(s - want), 0.5 + cfg.reg_w * std::ldexp(1.0, -cfg.scale_guard)) << d;
    EXPECT_FALSE(ovf);
  }
  bool ovf = false;
  scale_curve(60000, 0, recip, cfg, &ovf);  // 7.5 full scales: saturates
  EXPECT_TRUE(ovf);
}

TEST(PolyCorrect, HornerOnShiftAddMatchesDoubleEvaluation) {
  DatapathConfig cfg;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> cd(-0.9, 0.9), xd(-0.75, 0.75);
  for (int k = 0; k < 5000; ++k) {
    int64_t coef[4];
    double cr[4];
    for (int j = 0; j < 4; ++j) {
      coef[j] = std::llround(std::ldexp(cd(rng), cfg.coef_f));
      cr[j] = std::ldexp(static_cast<double>(coef[j]), -cfg.coef_f);
    }
    const int64_t x = std::llround(std::ldexp(xd(rng), cfg.s_f));
    const double xr = std::ldexp(static_cast<double>(x), -cfg.s_f);
    const double want = ((cr[3] * xr + cr[2]) * xr + cr[1]) * xr + cr[0];
    bool ovf = false;
    const double got = std::ldexp(static_cast<double>(poly_eval(x, coef, cfg, &ovf)), -cfg.acc_f());
    // Three products, each at most 16 floored partial products of 2^-ACC_F.
    EXPECT_LE(std::fabs(got - want), 3 * 17 * std::ldexp(1.0, -cfg.acc_f()));
    EXPECT_FALSE(ovf);
  }
}

TEST(Cordic, WithinItsAnalyticBoundOverTheCircle) {
  CordicConfig cfg;  // the chain's: 18-bit Q2.16 inputs, 16 iterations, 16-bit angle
  const auto table = cordic_atan_table(cfg.z_w, cfg.iterations);
  const double bound = cordic_error_bound_lsb(cfg);
  EXPECT_LT(bound, 2.0);
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> ang(0, 2 * M_PI), len(0.25, 1.9);
  double worst = 0, sq = 0;
  const int n = 200000;
  for (int k = 0; k < n; ++k) {
    const double a = ang(rng), r = len(rng) * 65536;
    const int64_t x = std::llround(r * std::cos(a)), y = std::llround(r * std::sin(a));
    const CordicResult c = cordic_vector(x, y, cfg, table.data());
    double want = std::atan2(static_cast<double>(y), static_cast<double>(x)) / (2 * M_PI) * 65536;
    if (want < 0) want += 65536;
    double err = c.angle - want;
    err -= 65536 * std::round(err / 65536);
    worst = std::max(worst, std::fabs(err));
    sq += err * err;
  }
  EXPECT_LE(worst, bound);
  std::printf("CORDIC chain config: max %.3f LSB, RMS %.3f LSB, bound %.3f LSB\n", worst,
              std::sqrt(sq / n), bound);
}

TEST(Cordic, NormalizationKeepsSmallVectorsAccurate) {
  CordicConfig cfg;
  cfg.in_w = 16;
  cfg.normalize = true;
  const auto table = cordic_atan_table(cfg.z_w, cfg.iterations);
  const double bound = cordic_error_bound_lsb(cfg);
  for (int y = -40; y <= 40; ++y)
    for (int x = -40; x <= 40; ++x) {
      if (x == 0 && y == 0) continue;
      const CordicResult c = cordic_vector(x, y, cfg, table.data());
      double want = std::atan2(y, x) / (2 * M_PI) * 65536;
      if (want < 0) want += 65536;
      double err = c.angle - want;
      err -= 65536 * std::round(err / 65536);
      ASSERT_LE(std::fabs(err), bound) << x << "," << y;
    }
}

TEST(Cordic, MagnitudeIsTheGainTimesTheLength) {
  CordicConfig cfg;
  const auto table = cordic_atan_table(cfg.z_w, cfg.iterations);
  double gain = 1;
  for (int i = 0; i < cfg.iterations; ++i) gain *= std::sqrt(1 + std::ldexp(1.0, -2 * i));
  for (int k = 0; k < 64; ++k) {
    const double a = 2 * M_PI * k / 64;
    const CordicResult c = cordic_vector(std::llround(60000 * std::cos(a)),
                                         std::llround(60000 * std::sin(a)), cfg, table.data());
    EXPECT_NEAR(c.magnitude, gain * 60000, 20);
  }
}

}  // namespace
}  // namespace acore
