// SPDX-License-Identifier: MIT
// calibration/calibrate_options: the whole `calibrate` command as one call. Its image must be what
// the steps it wraps make when called one by one (calibrate, quantize_auto_range), its refusals
// must name the option, and the self-calibration must say its zero is unknown.
#include <gtest/gtest.h>

#include <string>

#include "calibration/calibrate_options.hpp"
#include "core/errors.hpp"
#include "regmap/codec.hpp"
#include "support/paper_signals.hpp"

namespace acore {
namespace {

std::string refusal(const CalibrateSpec& s) {
  try {
    s.validate();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CalibrateOptions, DefaultImageIsTheStepsOneByOne) {
  const Recording rec = test::paper_recording(4096);
  const CalibrateOutcome c = calibrate_recording(rec, CalibrateSpec{}, "paper", "test");
  CalOptions opt;
  opt.periodicity = 1;
  const FloatCoefficients fc = calibrate(rec, opt);
  const DatapathConfig cfg = cordic_width_preset(16);
  const RegImage img = quantize_auto_range(fc, cfg, choose_in_scale(rec, cfg.in_w));
  EXPECT_EQ(c.image.words, img.words);
  EXPECT_EQ(c.image.in_scale, img.in_scale);
  EXPECT_EQ(c.report["words"], img.cfg.words());
  EXPECT_EQ(c.report["reference"], "theta_ref");
  EXPECT_FALSE(c.image.zero_reference_unknown());
  // The correction does what the paper reports (Table 3: 9.01 -> 0.76 deg RMS, under a tenth).
  EXPECT_LT(c.fit_fixed.rms, 0.15 * c.fit_uncorrected.rms);
}

TEST(CalibrateOptions, RefusalsNameTheOption) {
  CalibrateSpec s;
  s.degree = 9;
  EXPECT_EQ(refusal(s).rfind("--degree 9", 0), 0u) << refusal(s);
  s = CalibrateSpec{};
  s.regions = 6;
  EXPECT_EQ(refusal(s).rfind("--regions 6", 0), 0u) << refusal(s);
  s = CalibrateSpec{};
  s.xcenter = true;
  EXPECT_NE(refusal(s).find("--xcenter needs --regions 8"), std::string::npos);
  s = CalibrateSpec{};
  s.correction = "poly2d";
  s.degree = 4;
  EXPECT_NE(refusal(s).find("poly2d"), std::string::npos);
  s = CalibrateSpec{};
  s.reference = "encoder";
  EXPECT_EQ(refusal(s).rfind("--reference encoder", 0), 0u) << refusal(s);
  s = CalibrateSpec{};
  s.reference = "none";
  s.zero_offset = "0";
  EXPECT_NE(refusal(s).find("the zero is unknown"), std::string::npos);
  EXPECT_EQ(refusal(CalibrateSpec{}), "");
}

TEST(CalibrateOptions, SelfCalibrationSaysItsZeroIsUnknown) {
  const Recording rec = test::paper_recording(4096);
  CalibrateSpec s;
  s.reference = "none";
  const CalibrateOutcome c = calibrate_recording(rec, s, "paper", "test");
  EXPECT_TRUE(c.self);
  EXPECT_TRUE(c.image.zero_reference_unknown());
  EXPECT_EQ(c.report["reference"], "none");
  EXPECT_EQ(c.report["zero_reference"], "none");
  EXPECT_TRUE(c.report["fit_error_deg"]["about_mean"].get<bool>());
  EXPECT_TRUE(c.report.contains("self_calibration"));
  EXPECT_GT(c.selfcal.turns, 0.99);
}

}  // namespace
}  // namespace acore
