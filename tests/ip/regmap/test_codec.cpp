// SPDX-License-Identifier: MIT
// The register map's codec table: one field per address in the map's order, each kind's encoding
// against its closed form, quantize() -> dequantize() within half an LSB of every field, values
// out of range refused naming the register, and quantize_auto_range() against the stepping search
// it replaces (which caught quantize()'s errors and read their text).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/angle.hpp"
#include "core/datapath_config.hpp"
#include "core/errors.hpp"
#include "regmap/codec.hpp"
#include "support/map_shapes.hpp"

namespace acore {
namespace {

using test::kMapShapes;

DatapathConfig shape(const char* p) { return DatapathConfig{}.with_rtl_params(p); }

// The rotation CORDIC's gain over m stages, prod sqrt(1 + 2^-2i), from its definition.
double rotation_gain(int m) {
  double g = 1;
  for (int i = 0; i < m; ++i) g *= std::sqrt(1 + std::ldexp(1.0, -2 * i));
  return g;
}

// Real coefficients of configuration cfg's shape: offsets, amplitudes, polynomial and Fourier
// coefficients of magnitude up to poly_max / fourier_max (rad), a zero offset.
FloatCoefficients random_coefficients(const DatapathConfig& cfg, std::mt19937_64& rng,
                                      double poly_max, double fourier_max) {
  std::uniform_real_distribution<double> u(-1, 1);
  FloatCoefficients fc;
  fc.correction = cfg.correction;
  fc.degree = cfg.degree;
  fc.regions = cfg.regions;
  fc.xcenter = cfg.xcenter;
  for (int c = 0; c < 2; ++c) {
    fc.offset[c] = 0.05 * u(rng);
    fc.amp[c] = 0.7 + 0.3 * std::fabs(u(rng));
  }
  fc.poly.resize(cfg.poly_words());
  for (double& v : fc.poly) v = poly_max * u(rng) * (rng() % 4 ? 0.1 : 1.0);
  if (cfg.fourier_k > 0) fc.fourier.resize(2 * cfg.fourier_k + 1);
  for (double& v : fc.fourier) v = fourier_max * u(rng) * (rng() % 4 ? 0.1 : 1.0);
  fc.zero_offset = M_PI * u(rng);
  fc.zero_word = cfg.zero_word;
  return fc;
}

TEST(Codec, TableIsTheMapInAddressOrder) {
  for (const char* p : kMapShapes) {
    const DatapathConfig c = shape(p);
    ASSERT_NO_THROW(c.validate()) << p;
    const auto t = codec_table(c);
    ASSERT_EQ(static_cast<int>(t.size()), c.words()) << p;
    for (size_t a = 0; a < t.size(); ++a) EXPECT_EQ(t[a].addr, static_cast<int>(a)) << p;
    // Each kind at DatapathConfig's addresses, with its coordinates.
    for (int k = 0; k < 2; ++k) {
      EXPECT_EQ(t[c.addr_offset(k)].kind, CodecKind::kOffset);
      EXPECT_EQ(t[c.addr_offset(k)].curve, k);
      EXPECT_EQ(t[c.addr_recip(k)].kind, CodecKind::kRecip);
      EXPECT_EQ(t[c.addr_recip(k)].curve, k);
    }
    for (int r = 0; r < c.regions; ++r)
      for (int k = 0; k < 2; ++k)
        for (int j = 0; j < c.coef_per_curve(); ++j) {
          const CodecField& f = t[c.addr_poly(r, k, j)];
          EXPECT_EQ(f.kind, CodecKind::kPoly);
          EXPECT_EQ(f.region, r);
          EXPECT_EQ(f.curve, k);
          EXPECT_EQ(f.term, j);
        }
    for (int i = 0; i < c.iterations; ++i) {
      EXPECT_EQ(t[c.addr_atan(i)].kind, CodecKind::kAtan);
      EXPECT_EQ(t[c.addr_atan(i)].index, i);
    }
    for (int j = 0; j < c.fourier_words(); ++j) {
      EXPECT_EQ(t[c.addr_fourier(j)].kind, j ? CodecKind::kFourierHarmonic : CodecKind::kFourierA0);
      EXPECT_EQ(t[c.addr_fourier(j)].index, j);
    }
    if (c.zero_word) EXPECT_EQ(t[c.addr_zero()].kind, CodecKind::kZero);
    // Word width, sign and fraction bits of each kind (the contract of the fixed-point datapath:
    // datapath_config.hpp's comments and the RTL's parameters).
    for (const CodecField& f : t) {
      EXPECT_EQ(f.word_w, c.reg_w);
      switch (f.kind) {
        case CodecKind::kOffset:
          EXPECT_TRUE(f.is_signed && f.width == c.reg_w && f.frac == 0);
          break;
        case CodecKind::kRecip:
          EXPECT_TRUE(!f.is_signed && f.width == c.reg_w && f.frac == c.s_f + c.r_shift);
          break;
        case CodecKind::kPoly:
          EXPECT_TRUE(f.is_signed && f.width == c.reg_w && f.frac == c.coef_f);
          break;
        case CodecKind::kAtan:
          EXPECT_TRUE(!f.is_signed && f.width == c.reg_w && f.frac == c.z_w);
          break;
        case CodecKind::kFourierA0:
          EXPECT_TRUE(f.is_signed && f.width == c.reg_w && f.frac == c.fourier_coef_f);
          EXPECT_EQ(f.gain, 1.0);
          break;
        case CodecKind::kFourierHarmonic:
          EXPECT_TRUE(f.is_signed && f.width == c.fourier_word_w && f.frac == c.fourier_coef_f);
          EXPECT_NEAR(f.gain, rotation_gain(c.fourier_iterations), 1e-12);
          break;
        case CodecKind::kZero:
          EXPECT_TRUE(!f.is_signed && f.width == c.angle_w && f.frac == c.angle_w);
          break;
      }
    }
  }
}

TEST(Codec, NamesAreTheImagesWords) {
  const DatapathConfig c = shape(
      "REG_W=22 COEF_F=19 K=20 CORDIC_G=5 Z_W=24 ANGLE_W=20 ZERO=1 "
      "FOURIER_K=3");
  EXPECT_EQ(offset_field(c, 1).name(c), "offset O24");
  EXPECT_EQ(recip_field(c, 0).name(c), "1/A13");
  EXPECT_EQ(poly_field(c, 2, 1, 3).name(c), "region 2 c24 x^3");
  EXPECT_EQ(atan_field(c, 4).name(c), "atan(2^-4)");
  EXPECT_EQ(fourier_field(c, 0).name(c), "fourier a_0");
  EXPECT_EQ(fourier_field(c, 5).name(c), "fourier a_3");
  EXPECT_EQ(fourier_field(c, 6).name(c), "fourier b_3");
  EXPECT_EQ(zero_field(c).name(c), "zero position");
  const DatapathConfig p2 = shape("CORRECTION=1 DEGREE=1 REGIONS=8 XCENTER=1");
  // poly2d, degree 1: terms (0,0), (0,1), (1,0); centred regions name the argument u.
  EXPECT_EQ(poly_field(p2, 7, 0, 1).name(p2), "region 7 c13 u^0 v^1");
  EXPECT_EQ(poly_field(p2, 7, 0, 2).name(p2), "region 7 c13 u^1 v^0");
}

TEST(Codec, EachKindEncodesAndDecodesItsClosedForm) {
  const DatapathConfig c = shape("FOURIER_K=4 ZERO=1");
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(-1, 1);
  const uint64_t reg_mask = (uint64_t{1} << c.reg_w) - 1;
  for (int n = 0; n < 2000; ++n) {
    // Offset: an integer of input codes, two's complement in REG_W bits.
    const CodecField off = offset_field(c, n % 2);
    const auto codes = static_cast<int64_t>(std::ldexp(u(rng), c.reg_w - 1));
    const uint64_t ow = off.word(off.quantize(static_cast<double>(codes)), c);
    EXPECT_EQ(ow, static_cast<uint64_t>(codes) & reg_mask);
    EXPECT_EQ(off.field(ow), codes);
    EXPECT_EQ(off.value(ow), static_cast<double>(codes));
    // Reciprocal: R = round(2^(S_F + R_SHIFT) / A), A in input codes; R stands for 1/A.
    const CodecField rec = recip_field(c, n % 2);
    const double amp = 2048 + 30000 * std::fabs(u(rng));
    const int64_t r = rec.quantize(1.0 / amp);
    EXPECT_EQ(r, std::llround(std::ldexp(1.0, c.s_f + c.r_shift) / amp));
    EXPECT_EQ(rec.value(rec.word(r, c)), std::ldexp(static_cast<double>(r), -c.s_f - c.r_shift));
    // Polynomial coefficient: Q3.15.
    const CodecField poly = poly_field(c, n % 4, n % 2, n % 4);
    const double v = 3.99 * u(rng);
    const int64_t q = poly.quantize(v);
    EXPECT_EQ(q, std::llround(v * 32768));
    EXPECT_EQ(poly.field(poly.word(q, c)), q);
    EXPECT_EQ(poly.value(poly.word(q, c)), static_cast<double>(q) / 32768);
    // atan(2^-i) in turns of 2^Z_W, in degrees with per_unit 360.
    const CodecField at = atan_field(c, n % c.iterations);
    const int64_t a = at.quantize(std::atan(std::ldexp(1.0, -at.index)) / (2 * M_PI));
    EXPECT_EQ(a, std::llround(std::atan(std::ldexp(1.0, -at.index)) / (2 * M_PI) * (1 << 20)));
    EXPECT_NEAR(at.value(at.word(a, c), 360.0), std::atan(std::ldexp(1.0, -at.index)) * 180 / M_PI,
                360.0 / (1 << 21));
    // Fourier a_0 (REG_W bits) and a harmonic (FOURIER_W bits, the word holding value / G_M),
    // both word * 2^-FOURIER_CF turn; given in radians with per_unit 2 pi.
    const double g = rotation_gain(c.fourier_iterations);
    const CodecField a0 = fourier_field(c, 0), h = fourier_field(c, 1 + n % 8);
    const double rad = 0.02 * u(rng);
    EXPECT_EQ(a0.quantize(rad, 2 * M_PI), std::llround(rad / (2 * M_PI) * (1 << 22)));
    const int64_t hq = h.quantize(rad, 2 * M_PI);
    EXPECT_LE(std::fabs(static_cast<double>(hq) - rad / (2 * M_PI) / g * (1 << 22)), 0.5 + 1e-9);
    EXPECT_NEAR(h.value(h.word(hq, c), 2 * M_PI), 2 * M_PI * g * hq / (1 << 22), 1e-15);
    // A harmonic's word repeats its sign above FOURIER_W bits; reading takes the low bits.
    const uint64_t hw = h.word(hq, c);
    EXPECT_EQ(hw, static_cast<uint64_t>(hq) & reg_mask);
    EXPECT_EQ(h.field(hw ^ (uint64_t{1} << (c.reg_w - 1))), hq);  // the upper bits do not count
    // Zero position: the low ANGLE_W bits, a code of 2^-ANGLE_W turn; upper bits ignored.
    const CodecField z = zero_field(c);
    const auto code = static_cast<uint32_t>(rng() & 0xffff);
    EXPECT_EQ(z.field(code | (uint64_t{3} << 16)), code);
    EXPECT_EQ(z.value(code, 360.0), code * 360.0 / 65536);
  }
}

TEST(Codec, QuantizeThenDequantizeIsWithinHalfAnLsbOfEveryField) {
  std::mt19937_64 rng(22);
  for (const char* p : kMapShapes) {
    const DatapathConfig c = shape(p);
    for (int n = 0; n < 30; ++n) {
      const FloatCoefficients fc = random_coefficients(c, rng, 0.3, 0.01);
      const double in_scale = std::ldexp(1.0, 12 + static_cast<int>(rng() % 3));
      const RegImage img = quantize(fc, c, in_scale);
      ASSERT_TRUE(img.cfg == c) << p;
      const FloatCoefficients back = dequantize(img);
      const double eps = 1e-12;
      for (int k = 0; k < 2; ++k) {
        EXPECT_LE(std::fabs(back.offset[k] - fc.offset[k]) * in_scale, 0.5 + eps) << p;
        // The reciprocal's LSB, 2^-(S_F + R_SHIFT) per input code.
        const double lsb = std::ldexp(1.0, -c.s_f - c.r_shift);
        EXPECT_LE(std::fabs(1 / (back.amp[k] * in_scale) - 1 / (fc.amp[k] * in_scale)),
                  (0.5 + eps) * lsb)
            << p;
      }
      ASSERT_EQ(back.poly.size(), fc.poly.size());
      for (size_t k = 0; k < fc.poly.size(); ++k)
        EXPECT_LE(std::fabs(back.poly[k] - fc.poly[k]), std::ldexp(0.5 + eps, -c.coef_f)) << p;
      ASSERT_EQ(back.fourier.size(), fc.fourier.size());
      const double g = rotation_gain(c.fourier_iterations);
      for (size_t j = 0; j < fc.fourier.size(); ++j)
        EXPECT_LE(std::fabs(back.fourier[j] - fc.fourier[j]),
                  2 * M_PI * (j ? g : 1.0) * std::ldexp(0.5 + eps, -c.fourier_coef_f))
            << p << " j=" << j;
      // The atan words are the CORDIC's constants, round(atan(2^-i) / 2 pi * 2^Z_W).
      for (int i = 0; i < c.iterations; ++i)
        EXPECT_EQ(img.atan(i), std::llround(std::atan(std::ldexp(1.0, -i)) / (2 * M_PI) *
                                            std::ldexp(1.0, c.z_w)));
      // The zero offset: with the ZERO word, the word's angle, within half a code.
      if (c.zero_word)
        EXPECT_LE(std::fabs(wrap_pi(back.zero_offset - fc.zero_offset)),
                  std::ldexp(M_PI, -c.angle_w) * (1 + eps))
            << p;
    }
  }
}

void expect_refused(const FloatCoefficients& fc, const DatapathConfig& c, double in_scale,
                    const std::string& fragment) {
  try {
    quantize(fc, c, in_scale);
    ADD_FAILURE() << "no error, expected " << fragment;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(Codec, OutOfRangeValuesAreRefusedNamingTheRegister) {
  const DatapathConfig c = shape("FOURIER_K=4 ZERO=1");
  // The codec itself: one past each end of every field, the register's address and name.
  for (const CodecField& f : codec_table(c)) {
    const int64_t hi = f.is_signed ? (int64_t{1} << (f.width - 1)) : (int64_t{1} << f.width);
    const int64_t lo = f.is_signed ? -(int64_t{1} << (f.width - 1)) - 1 : -1;
    EXPECT_NO_THROW(f.word(hi - 1, c));
    EXPECT_NO_THROW(f.word(lo + 1, c));
    for (int64_t bad : {hi, lo}) {
      try {
        f.word(bad, c);
        ADD_FAILURE() << f.addr;
      } catch (const InputError& e) {
        const std::string want = "register " + std::to_string(f.addr) + " (" + f.name(c) + ")";
        EXPECT_NE(std::string(e.what()).find(want), std::string::npos) << e.what();
      }
    }
  }
  // quantize(): the value, its register and what to change.
  std::mt19937_64 rng(23);
  const FloatCoefficients good = random_coefficients(c, rng, 0.3, 0.01);
  EXPECT_NO_THROW(quantize(good, c, 8192));
  FloatCoefficients fc = good;
  fc.offset[1] = 20.0;  // 20 * 8192 codes > 2^17
  expect_refused(fc, c, 8192, "offset of c24 = 20 does not fit the 18-bit register");
  fc = good;
  fc.amp[0] = 0.001;  // R = 2^29 / 8.2 codes > 2^18
  expect_refused(fc, c, 8192, "amplitude of c13 = 8.2 codes is out of the reciprocal register");
  fc = good;
  fc.coef(1, 0, 2) = -4.5;  // Q3.15 holds [-4, 4)
  expect_refused(fc, c, 8192, "polynomial coefficient region 1 curve c13 x^2 = -4.5000");
  fc = good;
  fc.fourier[3] = 0.2;  // a_2 = 11.5 deg; the 16-bit word holds +-2.8 deg * G_M = +-4.6 deg
  expect_refused(fc, c, 8192, "fourier coefficient 3 = 11.4592 deg exceeds the 16-bit range");
}

// quantize_auto_range() as it was: quantize(), and on an error whose text names a polynomial or a
// Fourier coefficient, one fraction bit less, again.
RegImage stepping_search(const FloatCoefficients& coef, DatapathConfig cfg, double in_scale) {
  for (;;) {
    try {
      return quantize(coef, cfg, in_scale);
    } catch (const InputError& e) {
      if (std::string(e.what()).find("fourier coefficient") != std::string::npos &&
          cfg.fourier_coef_f >= cfg.reg_w) {
        --cfg.fourier_coef_f;
        continue;
      }
      if (cfg.coef_f <= 8 ||
          std::string(e.what()).find("polynomial coefficient") == std::string::npos)
        throw;
      const int acc_f = cfg.acc_f();
      --cfg.coef_f;
      cfg.acc_guard = acc_f - cfg.coef_f;
      cfg.acc_int = std::max(cfg.acc_int, cfg.reg_w - cfg.coef_f + 1);
    }
  }
}

TEST(Codec, AutoRangeGivesTheSteppingSearchsResultAndErrors) {
  // Shapes whose search ends in range, at the lowest fraction bits, or in an error met on the
  // way: an accumulator too wide for a lower coef_f (REG_W=26), a Fourier word whose lowest
  // fraction bits leave no guard above the angle (FOURIER_G=0 ANGLE_W=18 REG_W=18 Z_W=20).
  const std::vector<std::string> shapes = {
      "",
      "DEGREE=5 REGIONS=8",
      "DEGREE=7 REGIONS=8",
      "CORRECTION=1",
      "CORRECTION=2 FOURIER_K=6",
      "FOURIER_K=3 ZERO=1",
      "IN_W=20 REG_W=26 S_W=22 S_F=18 COEF_F=23 ACC_G=4 ACC_I=4 Z_W=22 K=18 FOURIER_K=2 "
      "FOURIER_CF=27",
      "FOURIER_K=2 FOURIER_G=0 ANGLE_W=18 Z_W=20 FOURIER_CF=20",
      "COEF_F=7 ACC_G=9 ACC_I=12"};
  std::mt19937_64 rng(24);
  int fitted = 0, lowered = 0, fourier_lowered = 0, failed = 0;
  for (const std::string& p : shapes) {
    const DatapathConfig c = shape(p.c_str());
    ASSERT_NO_THROW(c.validate()) << p;
    for (int n = 0; n < 150; ++n) {
      // Coefficients from well inside Q3.15 to far outside Q(REG_W-8).8, Fourier words from
      // fitting to out of range at any fraction bits.
      const double poly_max = std::ldexp(1.0, static_cast<int>(rng() % 12) - 1);
      const double fourier_max = std::ldexp(0.001, static_cast<int>(rng() % 12));
      FloatCoefficients fc = random_coefficients(c, rng, poly_max, fourier_max);
      if (rng() % 25 == 0) fc.offset[rng() % 2] = 1e3;  // an offset out of range besides
      std::string want_error, got_error;
      RegImage want, got;
      try {
        want = stepping_search(fc, c, 8192);
      } catch (const InputError& e) {
        want_error = e.what();
      }
      try {
        got = quantize_auto_range(fc, c, 8192);
      } catch (const InputError& e) {
        got_error = e.what();
      }
      ASSERT_EQ(got_error, want_error) << p << " n=" << n;
      if (!want_error.empty()) {
        ++failed;
        continue;
      }
      ASSERT_TRUE(got.cfg == want.cfg) << got.cfg.describe() << " vs " << want.cfg.describe();
      ASSERT_EQ(got.cfg.describe(), want.cfg.describe());
      ASSERT_EQ(got.words, want.words) << p;
      fitted += got.cfg.coef_f == c.coef_f && got.cfg.fourier_coef_f == c.fourier_coef_f;
      lowered += got.cfg.coef_f < c.coef_f;
      fourier_lowered += got.cfg.fourier_coef_f < c.fourier_coef_f;
    }
  }
  // Every outcome occurred.
  EXPECT_GT(fitted, 50);
  EXPECT_GT(lowered, 50);
  EXPECT_GT(fourier_lowered, 20);
  EXPECT_GT(failed, 50);
}

// A correction mode no row of the table has is an InputError naming it: the map has no shape.
TEST(Codec, AModeOutsideTheTableIsAnInputErrorNamingIt) {
  DatapathConfig cfg;
  cfg.correction = 9;
  try {
    codec_table(cfg);
    ADD_FAILURE() << "codec_table sized correction 9";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("correction mode 9"), std::string::npos) << e.what();
  }
  FloatCoefficients fc;
  fc.correction = 9;
  EXPECT_THROW(quantize(fc, cfg, 8192.0), InputError);
}

}  // namespace
}  // namespace acore
