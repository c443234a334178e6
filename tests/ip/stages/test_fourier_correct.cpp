// SPDX-License-Identifier: MIT
// The Fourier correction after the CORDIC (model/ip/stages/fourier_correct.hpp): the bit-accurate
// stage against a double evaluation of the same series, the calibration against a known distortion,
// and the accuracy it reaches on the noise-free paper scenario.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "calibration/calibration.hpp"
#include "core/error_stats.hpp"
#include "engine/estimator.hpp"
#include "stages/cordic.hpp"
#include "stages/cordic_rotate.hpp"
#include "stages/fourier_correct.hpp"
#include "support/paper_signals.hpp"

namespace acore {
namespace {

DatapathConfig fourier_config(int k) {
  DatapathConfig cfg;
  cfg.fourier_k = k;
  cfg.validate();
  return cfg;
}

// The 2K+1 words' real values in turns: a_0, then G_M times a'_k, b'_k.
std::vector<double> real_turns(const std::vector<int64_t>& words, const DatapathConfig& cfg) {
  std::vector<double> v;
  for (size_t j = 0; j < words.size(); ++j)
    v.push_back((j == 0 ? 1.0 : fourier_gain(cfg)) *
                std::ldexp(static_cast<double>(words[j]), -cfg.fourier_coef_f));
  return v;
}

struct StageError {
  double rms_deg = 0, max_deg = 0, worst_margin = 1e9;  // margin: bound - |error| (turns), minimum
  double out_max_lsb = 0;  // corrected angle vs the exact one, ANGLE_W LSBs
};

// Every one of the 2^ANGLE_W input angles: D against the double series at the same angle, and the
// corrected angle against theta - series(theta).
StageError sweep_stage(const std::vector<int64_t>& words, const DatapathConfig& cfg) {
  const auto atan = cordic_atan_table(cfg.z_w, cfg.iterations);
  const std::vector<double> real = real_turns(words, cfg);
  const double bound = fourier_error_bound_turns(words.data(), cfg);
  const uint32_t turn = 1u << cfg.angle_w;
  StageError s;
  double ss = 0;
  for (uint32_t t = 0; t < turn; ++t) {
    const double exact = fourier_series(2 * M_PI * t / turn, real);
    const double d = std::ldexp(
        static_cast<double>(fourier_delta(t, words.data(), atan.data(), cfg)), -cfg.fourier_f());
    const double e = std::remainder(d - exact, 1.0);
    ss += e * e;
    s.max_deg = std::max(s.max_deg, std::fabs(e) * 360);
    s.worst_margin = std::min(s.worst_margin, bound - std::fabs(e));
    const uint32_t out = fourier_correct(t, words.data(), atan.data(), cfg);
    const double ideal = static_cast<double>(t) / turn - exact;
    s.out_max_lsb =
        std::max(s.out_max_lsb,
                 std::fabs(std::remainder(static_cast<double>(out) / turn - ideal, 1.0)) * turn);
  }
  s.rms_deg = std::sqrt(ss / turn) * 360;
  return s;
}

TEST(CordicRotate, TurnsClockwiseByTheAngleTimesTheGain) {
  // Against double rotation: the residual angle and the floors stay inside the stage's budget.
  const int m = 12, zw = 20;
  const auto atan = cordic_atan_table(zw, m);
  const double g = cordic_rotate_gain(m);
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int64_t> v(-(1 << 21), (1 << 21) - 1),
      z(-(1 << (zw - 3)), (1 << (zw - 3)) - 1);
  double worst = 0;
  for (int n = 0; n < 20000; ++n) {
    const int64_t x = v(rng), y = v(rng), a = z(rng);
    const RotateResult r = cordic_rotate(x, y, a, m, zw, atan.data());
    const double ang = 2 * M_PI * std::ldexp(static_cast<double>(a), -zw);
    const double ex = g * (x * std::cos(ang) + y * std::sin(ang)),
                 ey = g * (y * std::cos(ang) - x * std::sin(ang));
    const double len = std::hypot(static_cast<double>(x), static_cast<double>(y));
    const double budget =
        len * g * (std::atan(std::ldexp(1.0, -(m - 1))) + m * M_PI * std::ldexp(1.0, -zw)) +
        std::sqrt(2.0) * m * g;
    worst = std::max(worst, std::hypot(r.x - ex, r.y - ey) / budget);
  }
  EXPECT_LE(worst, 1.0);
  EXPECT_GT(worst, 0.05) << "the budget is not loose by orders of magnitude";
}

TEST(CordicRotate, AngleResidualFitsItsTrimmedWidthForEveryStartAngle) {
  // The z path in plain int64 over every start angle of the pre-rotated range [-1/8, 1/8) turn:
  // entering stage i it must fit cordic_rotate_z_width(Z_W, i) signed bits (the RTL's trimmed z).
  for (int zw : {20, 22}) {
    const int m = 16;
    const auto atan = cordic_atan_table(zw, m);
    std::vector<int64_t> lo(m, 0), hi(m, 0);
    for (int64_t z0 = -(int64_t{1} << (zw - 3)); z0 < (int64_t{1} << (zw - 3)); ++z0) {
      int64_t z = z0;
      for (int i = 0; i < m; ++i) {
        lo[i] = std::min(lo[i], z);
        hi[i] = std::max(hi[i], z);
        z += z >= 0 ? -atan[i] : atan[i];
      }
    }
    for (int i = 0; i < m; ++i) {
      const int64_t half = int64_t{1} << (cordic_rotate_z_width(zw, i) - 1);
      EXPECT_GE(lo[i], -half) << "Z_W=" << zw << " stage " << i;
      EXPECT_LT(hi[i], half) << "Z_W=" << zw << " stage " << i;
      if (i >= 3)
        EXPECT_LT(std::max(-lo[i], hi[i]), half * 3 / 4) << "the 1.5x margin, stage " << i;
    }
  }
}

TEST(FourierCorrect, RandomFullRangeWordsStayInsideTheBudgetAtEveryAngle) {
  // Full-range words are the worst case for the widths: no register may wrap (the double series
  // would then differ by a large amount), and the error must stay inside the documented bound.
  for (int k : {1, 5, 13}) {
    const DatapathConfig cfg = fourier_config(k);
    std::mt19937_64 rng(100 + k);
    std::vector<int64_t> words(cfg.fourier_words());
    for (size_t j = 0; j < words.size(); ++j) {
      const int w = j == 0 ? cfg.reg_w : cfg.fourier_word_w;  // a_0: REG_W bits, harmonics: W bits
      words[j] = std::uniform_int_distribution<int64_t>(-(1 << (w - 1)), (1 << (w - 1)) - 1)(rng);
    }
    const StageError s = sweep_stage(words, cfg);
    EXPECT_GE(s.worst_margin, 0.0) << "K=" << k << " max error " << s.max_deg << " deg";
    // Rounding to ANGLE_W adds half an LSB to the bound (in LSBs: bound * 2^ANGLE_W + 0.5).
    const double bound_lsb =
        fourier_error_bound_turns(words.data(), cfg) * (1 << cfg.angle_w) + 0.5;
    EXPECT_LE(s.out_max_lsb, bound_lsb + 1e-9) << "K=" << k;
  }
}

TEST(FourierCorrect, PaperCoefficientsWellInsideAnOutputLsb) {
  // The 21-harmonic fit of the noise-free paper scenario: the stage's own error is a fraction of
  // the 16-bit output LSB (0.0055 deg), so the correction is limited by the fit, not the hardware.
  CalOptions o;
  o.correction = kNone;
  o.fourier_k = 21;
  const Recording cal = test::paper_recording(4096);
  const RegImage img =
      quantize_auto_range(calibrate(cal, o), DatapathConfig{}, choose_in_scale(cal, 16));
  std::vector<int64_t> words;
  for (int j = 0; j < img.cfg.fourier_words(); ++j) words.push_back(img.fourier(j));
  const StageError s = sweep_stage(words, img.cfg);
  std::printf(
      "paper K=21, M=%d, G=%d: |D - series| RMS %.5f deg, max %.5f deg; output max %.3f LSB\n",
      img.cfg.fourier_iterations, img.cfg.fourier_guard, s.rms_deg, s.max_deg, s.out_max_lsb);
  EXPECT_GE(s.worst_margin, 0.0);
  EXPECT_LE(s.rms_deg, 0.0055 / 2);
  EXPECT_LE(s.out_max_lsb, 2.0);
}

TEST(FourierCalibration, RecoversAKnownDistortionExactly) {
  // An ideal sensor read at theta_est while the reference is theta_est - Delta(theta_est): the
  // remaining error is exactly the series, so the least squares must return its coefficients.
  const std::vector<double> truth = {0.02,   0.05,  -0.03, 0.0,   0.01,
                                     -0.004, 0.002, 0.0,   -0.001};  // K = 4, rad
  Recording rec;
  rec.channels = 2;
  const size_t n = 2048;
  for (size_t i = 0; i < n; ++i) {
    const double est = 2 * M_PI * (i + 0.5) / n;
    rec.ch[0].push_back(std::sin(est));
    rec.ch[1].push_back(std::cos(est));
    rec.theta_ref.push_back(est - fourier_series(est, truth));
  }
  for (int k : {4, 6}) {
    CalOptions o;
    o.correction = kNone;
    o.fourier_k = k;
    // With the zero offset estimated, it takes a share of a_0 and leaves the rest exactly.
    const FloatCoefficients aligned = calibrate(rec, o);
    EXPECT_NEAR(aligned.fourier[0] + aligned.zero_offset, truth[0], 1e-12) << "K=" << k;
    o.estimate_zero = false;  // the reference is theta_est - Delta exactly: a_0 is the series'
    const FloatCoefficients fc = calibrate(rec, o);
    ASSERT_EQ(fc.fourier_k(), k);
    for (size_t j = 0; j < fc.fourier.size(); ++j) {
      EXPECT_NEAR(fc.fourier[j], j < truth.size() ? truth[j] : 0.0, 1e-12)
          << "K=" << k << " j=" << j;
      if (j > 0) EXPECT_NEAR(aligned.fourier[j], fc.fourier[j], 1e-12) << "K=" << k << " j=" << j;
    }
    // Quantized: every word within half an LSB (times the gain) of the value.
    const RegImage img = quantize(fc, DatapathConfig{}, 8192);
    const FloatCoefficients back = dequantize(img);
    const double lsb_rad =
        2 * M_PI * std::ldexp(1.0, -img.cfg.fourier_coef_f) * fourier_gain(img.cfg);
    for (size_t j = 0; j < fc.fourier.size(); ++j)
      EXPECT_NEAR(back.fourier[j], fc.fourier[j], 0.5 * lsb_rad);
    // And the corrected float chain reproduces the reference.
    const ErrorStats e = error_stats(angle_error_deg(run_float(rec, fc).angle, rec.theta_ref));
    EXPECT_LE(e.max_abs, 1e-9);
  }
}

TEST(FourierCalibration, PaperNoiselessTargetWithoutPolynomial) {
  // The Fourier correction's accuracy target, at most 64 words: RMS <= 0.10 deg, max <= 0.35 deg on
  // a validation recording whose angles the calibration never saw. 21 harmonics and no polynomial:
  // 4 + 16 + 43 = 63 words.
  CalOptions o;
  o.correction = kNone;
  o.fourier_k = 21;
  const Recording cal = test::paper_recording(4096), val = test::paper_recording(5003);
  const FloatCoefficients fc = calibrate(cal, o);
  const RegImage img = quantize_auto_range(fc, DatapathConfig{}, choose_in_scale(cal, 16));
  EXPECT_EQ(img.cfg.words(), 63);
  const ErrorStats fl = error_stats(angle_error_deg(run_float(val, fc).angle, val.theta_ref));
  const AngleSeries fx = run_fixed(val, img);
  const ErrorStats sx = error_stats(angle_error_deg(fx.angle, val.theta_ref));
  std::printf(
      "paper-noiseless, K=21 without polynomial, validation: float %.4f / %.4f, bit-accurate %.4f "
      "/ %.4f deg\n",
      fl.rms, fl.max_abs, sx.rms, sx.max_abs);
  EXPECT_LE(sx.rms, 0.10);
  EXPECT_LE(sx.max_abs, 0.35);
  EXPECT_LE(std::fabs(sx.rms - fl.rms), 0.002);
  for (unsigned f : fx.flags) EXPECT_EQ(f, 0u);
  // The polynomial-only chain with the same words budget misses it by far (it needs the Fourier
  // stage).
  CalOptions p;
  p.degree = 3;
  const ErrorStats poly =
      error_stats(angle_error_deg(run_float(val, calibrate(cal, p)).angle, val.theta_ref));
  EXPECT_GT(poly.rms, 0.4);
}

TEST(FourierCorrect, StageOffLeavesTheChainAndImageUnchanged) {
  // fourier_k = 0: no words, no header keys, and the same angles as the chain without the stage.
  const Recording cal = test::paper_recording(4096);
  const RegImage img =
      quantize(calibrate(cal, CalOptions{}), DatapathConfig{}, choose_in_scale(cal, 16));
  EXPECT_EQ(img.words.size(), 52u);
  EXPECT_EQ(format_regimage(img).find("fourier"), std::string::npos);
  const FixedModel m(img);
  for (const ChannelCodes& c : to_codes(cal, img.in_scale, 16)) {
    const FixedSample s = m.step(c);
    ASSERT_EQ(s.angle, s.cordic_angle);
  }
}

TEST(FourierCorrect, ImageRoundTripAndBatchPath) {
  CalOptions o;
  o.degree = 2;
  o.fourier_k = 6;
  const Recording cal = test::paper_recording(4096);
  const RegImage img =
      quantize_auto_range(calibrate(cal, o), DatapathConfig{}, choose_in_scale(cal, 16));
  EXPECT_EQ(img.cfg.words(), 4 + 24 + 16 + 13);
  const RegImage back = parse_regimage(format_regimage(img), "roundtrip");
  EXPECT_EQ(back.cfg.describe(), img.cfg.describe());
  EXPECT_EQ(back.words, img.words);
  const FixedModel m(back);
  const auto codes = to_codes(cal, img.in_scale, 16);
  std::vector<FixedOutput> batch(codes.size());
  m.run_batch(codes.data(), codes.size(), batch.data());
  size_t corrected = 0;
  for (size_t i = 0; i < codes.size(); ++i) {
    const FixedSample s = m.step(codes[i]);
    ASSERT_EQ(batch[i], to_output(s)) << i;
    corrected += s.angle != s.cordic_angle;
  }
  EXPECT_GT(corrected, codes.size() / 2);
}

}  // namespace
}  // namespace acore
