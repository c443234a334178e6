// SPDX-License-Identifier: MIT
// The bit-accurate chain (engine/fixed_model.*) on register images written here word by word, so
// every output has a closed form: a gain-2 image (offsets 0, R = 2^(R_SHIFT+1)) makes s = 2 d; a
// constant coefficient a_0 of region r, curve c makes y = s - 2 a_0 in exactly that region and
// curve (which checks the map's order); the CORDIC of the corrected curves stays within its bound
// of a long-double atan2; the ZERO word subtracts modulo a turn; the status flags follow the
// window.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "core/errors.hpp"
#include "core/fixed_point.hpp"
#include "engine/fixed_model.hpp"
#include "stages/cordic.hpp"
#include "stages/region_select.hpp"

namespace acore {
namespace {

constexpr long double kTwoPiL = 6.283185307179586476925286766559L;

// Offsets 0, reciprocals 2^(R_SHIFT+1) (s = 2 d exactly: the reciprocal has no bit the shift-add
// multiplier floors, and the CORDIC's accurate range starts at 2^(S_W-2), above any d), polynomial
// words 0, the CORDIC constants.
RegImage gain2_image(const DatapathConfig& cfg) {
  RegImage img;
  img.cfg = cfg;
  img.words.assign(static_cast<size_t>(cfg.words()), 0);
  for (int c = 0; c < 2; ++c) img.set_unsigned(cfg.addr_recip(c), int64_t{1} << (cfg.r_shift + 1));
  const auto table = cordic_atan_table(cfg.z_w, cfg.iterations);
  for (int i = 0; i < cfg.iterations; ++i) img.set_unsigned(cfg.addr_atan(i), table[i]);
  return img;
}

// Four channel codes whose differences are (d13, d24) = r (sin a, cos a), with a common mode.
ChannelCodes codes_at(double a, double r, int32_t common) {
  const int32_t s = static_cast<int32_t>(std::lround(r * std::sin(a) / 2));
  const int32_t c = static_cast<int32_t>(std::lround(r * std::cos(a) / 2));
  return {common + s, common + c, common - s, common - c};
}

TEST(FixedModel, StatusWindowDefaultsAreHalfAndOneAndAHalfTheGainedUnitVector) {
  for (int k : {12, 16, 20}) {
    DatapathConfig cfg;
    cfg.iterations = k;
    long double g = 1;
    for (int i = 0; i < k; ++i) g *= std::sqrt(1.0L + std::ldexp(1.0L, -2 * i));
    const long double unit = g * std::ldexp(1.0L, cfg.s_f);
    const StatusWindow w = StatusWindow::defaults(cfg);
    EXPECT_EQ(w.mag_lo, static_cast<int64_t>(std::floor(0.5L * unit + 0.5L))) << k;
    EXPECT_EQ(w.mag_hi, static_cast<int64_t>(std::floor(1.5L * unit + 0.5L))) << k;
  }
}

TEST(FixedModel, ToCodeRoundsToNearestEvenAndSaturates) {
  EXPECT_EQ(FixedModel::to_code(0.25, 8192, 16), 2048);
  EXPECT_EQ(FixedModel::to_code(0.5, 1, 16), 0);  // ties to even, the ADC's rule
  EXPECT_EQ(FixedModel::to_code(1.5, 1, 16), 2);
  EXPECT_EQ(FixedModel::to_code(-2.5, 1, 16), -2);
  EXPECT_EQ(FixedModel::to_code(-3.5, 1, 16), -4);
  EXPECT_EQ(FixedModel::to_code(32767.4, 1, 16), 32767);
  EXPECT_EQ(FixedModel::to_code(32767.6, 1, 16), 32767);  // saturates
  EXPECT_EQ(FixedModel::to_code(-1e12, 1, 16), -32768);
  EXPECT_EQ(FixedModel::to_code(1e12, 1, 18), 131071);
  EXPECT_EQ(FixedModel::to_code(std::nan(""), 1, 16), 32767);  // NaN: the top code, no UB
}

TEST(FixedModel, OutputPacksTheFlagsInTheirBits) {
  FixedSample s;
  s.angle = 12345;
  s.region = 6;
  for (int f = 0; f < 8; ++f) {
    s.ovf = f & 1;
    s.los = f & 2;
    s.dos = f & 4;
    const FixedOutput o = to_output(s);
    EXPECT_EQ(o.angle, 12345u);
    EXPECT_EQ(o.region, 6);
    EXPECT_EQ(o.flags, f);
  }
}

TEST(FixedModel, Gain2ImageIsTheCordicOfTwiceTheDifferences) {
  const DatapathConfig cfg;
  const FixedModel m(gain2_image(cfg));
  const CordicConfig cc = m.cordic_config();
  EXPECT_EQ(cc.in_w, cfg.s_w);
  EXPECT_FALSE(cc.normalize);
  const double bound = cordic_error_bound_lsb(cc);
  const long double turn = std::ldexp(1.0L, cfg.angle_w);
  std::mt19937_64 rng(81);
  // |s| from 93000 to 98000: the larger curve above 2^(S_W-2) (the bound's range) and the
  // magnitude inside the default status window (0.5 .. 1.5 times the gained unit vector).
  std::uniform_real_distribution<double> ang(0, 2 * M_PI), len(46500, 49000);
  std::uniform_int_distribution<int32_t> common(-1000, 1000);
  for (int k = 0; k < 20000; ++k) {
    const ChannelCodes c = codes_at(ang(rng), len(rng), common(rng));
    const FixedSample s = m.step(c);
    const int64_t d13 = c[0] - c[2], d24 = c[1] - c[3];
    ASSERT_EQ(s.s13, 2 * d13);
    ASSERT_EQ(s.s24, 2 * d24);
    ASSERT_EQ(s.y13, s.s13);  // zero polynomials
    ASSERT_EQ(s.y24, s.s24);
    ASSERT_EQ(s.region, select_region(d13, d24, cfg.regions).region);
    long double want =
        std::atan2(static_cast<long double>(d13), static_cast<long double>(d24)) / kTwoPiL * turn;
    long double err = s.angle - want;
    err -= turn * std::nearbyint(err / turn);
    ASSERT_LE(std::fabs(static_cast<double>(err)), bound) << k;
    ASSERT_EQ(s.uncorrected_angle, s.angle);
    ASSERT_EQ(s.cordic_angle, s.angle);
    ASSERT_FALSE(s.ovf || s.los || s.dos) << k;
  }
}

TEST(FixedModel, EachRegionAndCurveReadsItsOwnWords) {
  for (int correction : {kPoly, kPoly2d})
    for (int regions : {4, 8}) {
      DatapathConfig cfg;
      cfg.correction = correction;
      cfg.degree = correction == kPoly ? 3 : 2;
      cfg.regions = regions;
      RegImage img = gain2_image(cfg);
      // a_0 (the constant term: term 0 in both modes) = a distinct value per region and curve.
      auto a0 = [](int r, int c) { return int64_t{-700} + 97 * r + 31 * c; };
      for (int r = 0; r < regions; ++r)
        for (int c = 0; c < 2; ++c) img.set_signed(cfg.addr_poly(r, c, 0), a0(r, c));
      const FixedModel m(img);
      std::vector<int> seen(static_cast<size_t>(regions), 0);
      for (int k = 0; k < 720; ++k) {
        const FixedSample s = m.step(codes_at(2 * M_PI * (k + 0.5) / 720, 60000, 0));
        // P = a_0: acc_0 = a_0 2^ACC_G, so y = s - round(a_0 2^(S_F - COEF_F)) = s - 2 a_0.
        ASSERT_EQ(s.y13, s.s13 - 2 * a0(s.region, 0)) << "region " << s.region;
        ASSERT_EQ(s.y24, s.s24 - 2 * a0(s.region, 1)) << "region " << s.region;
        ++seen[static_cast<size_t>(s.region)];
      }
      for (int r = 0; r < regions; ++r) EXPECT_EQ(seen[static_cast<size_t>(r)], 720 / regions);
    }
  // Without correction words the curves go to the CORDIC as they are.
  DatapathConfig none;
  none.correction = kNone;
  const FixedModel m(gain2_image(none));
  const FixedSample s = m.step(codes_at(1.0, 60000, 5));
  EXPECT_EQ(s.y13, s.s13);
  EXPECT_EQ(s.y24, s.s24);
}

TEST(FixedModel, ZeroWordSubtractsModuloATurn) {
  DatapathConfig cfg;
  const FixedModel plain(gain2_image(cfg));
  cfg.zero_word = 1;
  const uint32_t mask = (uint32_t{1} << cfg.angle_w) - 1;
  for (uint32_t z : {0u, 1u, 12345u, 40000u, mask}) {
    RegImage img = gain2_image(cfg);
    img.set_unsigned(cfg.addr_zero(), z);
    const FixedModel m(img);
    for (int k = 0; k < 100; ++k) {
      const ChannelCodes c = codes_at(0.0628 * k, 50000, 0);
      const FixedSample a = plain.step(c), b = m.step(c);
      ASSERT_EQ(b.angle, (a.angle + (mask + 1) - z) & mask) << z;
      ASSERT_EQ(b.uncorrected_angle, (a.uncorrected_angle + (mask + 1) - z) & mask);
      ASSERT_EQ(b.cordic_angle, a.cordic_angle);  // before the adder
    }
  }
}

TEST(FixedModel, StatusFlagsFollowTheMagnitudeWindowAndSaturation) {
  const DatapathConfig cfg;
  const RegImage img = gain2_image(cfg);
  // Magnitude = CORDIC gain times the length of (s13, s24) = 1.6468 * 2 r.
  const int64_t lo = 60000, hi = 90000;
  const FixedModel m(img, StatusWindow{lo, hi});
  EXPECT_TRUE(m.step(codes_at(0.3, 15000, 0)).los);  // 49400 < 60000
  EXPECT_FALSE(m.step(codes_at(0.3, 15000, 0)).dos);
  EXPECT_FALSE(m.step(codes_at(0.3, 22000, 0)).los);  // 72460: inside
  EXPECT_FALSE(m.step(codes_at(0.3, 22000, 0)).dos);
  EXPECT_TRUE(m.step(codes_at(0.3, 30000, 0)).dos);  // 98800 > 90000
  EXPECT_TRUE(m.step({0, 0, 0, 0}).los);
  // A reciprocal of 2^(R_SHIFT+2) scales by 4: full-scale codes overflow S_W.
  RegImage loud = img;
  loud.set_unsigned(cfg.addr_recip(0), int64_t{1} << (cfg.r_shift + 2));
  const FixedModel ml(loud);
  const FixedSample s = ml.step({32767, 0, -32768, 0});
  EXPECT_TRUE(s.ovf);
  EXPECT_EQ(s.s13, fx::smax(cfg.s_w));
  EXPECT_FALSE(ml.step({1000, 0, -1000, 0}).ovf);
}

// A correction mode no row of the table has (core/correction_modes.hpp) is an InputError naming
// it, not a chain without correction.
TEST(FixedModel, AModeOutsideTheTableIsAnInputErrorNamingIt) {
  RegImage img;
  img.cfg.correction = 7;
  img.words.assign(static_cast<size_t>(4 + DatapathConfig{}.iterations), 0);
  try {
    FixedModel m(img);
    ADD_FAILURE() << "FixedModel took correction=7";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("correction=7"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace acore
