// SPDX-License-Identifier: MIT
// Calibration (calibration/calibration.*) against closed forms: the zero offset is the circular
// mean of the angle error (exact for a constant one); the ADC gain is the largest power of two that
// keeps the peak within a quarter of full scale; offset and amplitude (paper Eq. 4) of the paper
// scenario's curves on a uniform grid are their Fourier content (computed here from the paper's
// table); the per-region fit satisfies the least-squares normal equations in the monomials of x.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "calibration/calibration.hpp"
#include "core/angle.hpp"
#include "core/errors.hpp"
#include "stages/region_select.hpp"
#include "support/paper_signals.hpp"

namespace acore {
namespace {

TEST(Calibration, ZeroOffsetIsTheCircularMeanOfTheAngleError) {
  std::mt19937_64 rng(101);
  std::uniform_real_distribution<double> th(-20.0, 20.0), amp(0.2, 3.0);
  for (int p : {1, 2, 3})
    for (double z : {0.0, 0.3, -2.9, 3.1, M_PI, -M_PI + 1e-3}) {
      std::vector<double> s13, s24, ref;
      for (int k = 0; k < 500; ++k) {
        const double t = th(rng), a = amp(rng);  // any length: only directions count
        ref.push_back(t);
        s13.push_back(a * std::sin(p * t + z));
        s24.push_back(a * std::cos(p * t + z));
      }
      s13.push_back(0);  // the zero vector has no angle and is skipped
      s24.push_back(0);
      ref.push_back(1.0);
      EXPECT_NEAR(std::remainder(zero_offset_estimate(s13, s24, ref, p) - z, 2 * M_PI), 0, 1e-12)
          << "p " << p << " z " << z;
      const double got = zero_offset_estimate(s13, s24, ref, p);
      EXPECT_GE(got, -M_PI);
      EXPECT_LT(got, M_PI);
    }
  // Errors +-0.2 around 0.5 in equal numbers: the mean direction is 0.5 exactly.
  std::vector<double> s13, s24, ref;
  for (int k = 0; k < 100; ++k) {
    const double t = 0.1 * k, e = 0.5 + (k % 2 ? 0.2 : -0.2);
    ref.push_back(t);
    s13.push_back(std::sin(t + e));
    s24.push_back(std::cos(t + e));
  }
  EXPECT_NEAR(zero_offset_estimate(s13, s24, ref, 1), 0.5, 1e-12);
  // An error that turns once per turn has no mean direction.
  std::vector<double> a13, a24, aref;
  for (int k = 0; k < 360; ++k) {
    const double t = 2 * M_PI * k / 360;
    aref.push_back(t);
    a13.push_back(std::sin(2 * t));
    a24.push_back(std::cos(2 * t));
  }
  EXPECT_THROW(zero_offset_estimate(a13, a24, aref, 1), InputError);
}

TEST(Calibration, InScaleIsThePowerOfTwoThatPutsThePeakAtMostAQuarterOfFullScale) {
  for (int in_w : {12, 16, 18})
    for (double peak : {1.0, 0.3, 3.7, 1000.0, 1.0 / 3, 2.0e-3}) {
      Recording r;
      r.channels = 4;
      for (int c = 0; c < 4; ++c) r.ch[c] = {0.1 * peak, c == 2 ? -peak : 0.5 * peak};
      const double s = choose_in_scale(r, in_w);
      EXPECT_EQ(std::exp2(std::round(std::log2(s))), s) << "a power of two";
      const double quarter = std::ldexp(1.0, in_w - 3);
      EXPECT_LE(peak * s, quarter) << peak;
      EXPECT_GT(2 * peak * s, quarter) << peak << ": the largest such power";
    }
  // Two channels: c3, c4 are not channels of the recording.
  Recording two;
  two.channels = 2;
  two.ch[0] = {0.5};
  two.ch[1] = {-0.25};
  two.ch[2] = {1000.0};
  EXPECT_EQ(choose_in_scale(two, 16), std::ldexp(1.0, 14));
  Recording silent;
  silent.channels = 2;
  silent.ch[0] = {0.0};
  silent.ch[1] = {0.0};
  EXPECT_THROW(choose_in_scale(silent, 16), InputError);
  silent.ch[1] = {INFINITY};
  EXPECT_THROW(choose_in_scale(silent, 16), InputError);
}

TEST(Calibration, OffsetAndAmplitudeAreTheCurvesFourierContent) {
  // The paper's curves (docs/contracts.md, paper scenario): c_k = ideal_k + sum_h AF_kh cos h th +
  // BF_kh sin h th. On a uniform grid over a turn the mean of d13 = c1 - c3 is 0 and Eq. 4's
  // amplitude sqrt(2 mean d^2) is the root of the sum of squared harmonic amplitudes.
  const double AF[4][5] = {{.11, .20, .13, 0, .03},
                           {.10, .19, .07, .09, .03},
                           {.50, .10, .17, .04, 0},
                           {.13, 0, .10, .01, .01}};
  const double BF[4][5] = {{.10, .11, .13, .06, .03},
                           {.10, .19, .13, .04, .04},
                           {.13, .17, 0, .07, .01},
                           {0, .13, .10, .03, .01}};
  // d13 = 2 sin + ...; d24 = 2 cos + ...: the fundamental's sine/cosine parts carry the ideal 2.
  double a13 = 0, a24 = 0;
  for (int h = 1; h <= 5; ++h) {
    const double c13 = AF[0][h - 1] - AF[2][h - 1], s13 = BF[0][h - 1] - BF[2][h - 1];
    const double c24 = AF[1][h - 1] - AF[3][h - 1], s24 = BF[1][h - 1] - BF[3][h - 1];
    a13 += std::pow(c13, 2) + std::pow(s13 + (h == 1 ? 2 : 0), 2);
    a24 += std::pow(c24 + (h == 1 ? 2 : 0), 2) + std::pow(s24, 2);
  }
  const FloatCoefficients fc = calibrate(test::paper_recording(4096), CalOptions{});
  EXPECT_NEAR(fc.offset[0], 0.0, 1e-13);
  EXPECT_NEAR(fc.offset[1], 0.0, 1e-13);
  EXPECT_NEAR(fc.amp[0], std::sqrt(a13), 1e-12);
  EXPECT_NEAR(fc.amp[1], std::sqrt(a24), 1e-12);
  // A constant added to both opposite channels cancels; one added to c1 alone is d13's offset.
  Recording shifted = test::paper_recording(4096);
  for (double& v : shifted.ch[0]) v += 0.25;
  const FloatCoefficients fs = calibrate(shifted, CalOptions{});
  EXPECT_NEAR(fs.offset[0], 0.25, 1e-13);
  EXPECT_NEAR(fs.amp[0], fc.amp[0], 1e-12);
}

TEST(Calibration, EachRegionsFitSatisfiesTheNormalEquations) {
  // Least squares per region and curve: the residual s - ideal - P(x) is orthogonal to every
  // monomial x^j of the fit (here computed from the fit's own outputs, in long double).
  const Recording rec = test::paper_recording(4096);
  for (int regions : {4, 8})
    for (int degree : {1, 3, 5}) {
      CalOptions o;
      o.degree = degree;
      o.regions = regions;
      const FloatCoefficients fc = calibrate(rec, o);
      std::vector<std::vector<long double>> dot(static_cast<size_t>(regions * 2),
                                                std::vector<long double>(degree + 1, 0.0L));
      for (size_t i = 0; i < rec.size(); ++i) {
        const double s13 = (rec.d13(i) - fc.offset[0]) / fc.amp[0];
        const double s24 = (rec.d24(i) - fc.offset[1]) / fc.amp[1];
        double x;
        const int r = select_region_real(s13, s24, regions, &x);
        const double e = rec.theta_ref[i] + fc.zero_offset;
        const double ideal[2] = {std::sin(e), std::cos(e)}, s[2] = {s13, s24};
        for (int c = 0; c < 2; ++c) {
          long double p = 0, pw = 1;
          for (int j = 0; j <= degree; ++j, pw *= x) p += fc.coef(r, c, j) * pw;
          const long double res = s[c] - ideal[c] - p;
          pw = 1;
          for (int j = 0; j <= degree; ++j, pw *= x)
            dot[static_cast<size_t>(2 * r + c)][static_cast<size_t>(j)] += res * pw;
        }
      }
      for (const auto& d : dot)
        for (long double v : d) EXPECT_NEAR(static_cast<double>(v), 0.0, 1e-9) << degree;
    }
}

TEST(Calibration, ZeroOffsetOfAShiftedReferenceAndTheOptionsThatSetIt) {
  // The reference 1 rad behind the sensor: the calibration reports it as the zero offset.
  Recording rec = test::paper_recording(4096);
  const FloatCoefficients base = calibrate(rec, CalOptions{});
  for (double& t : rec.theta_ref) t -= 1.0;
  const FloatCoefficients fc = calibrate(rec, CalOptions{});
  EXPECT_NEAR(std::remainder(fc.zero_offset - base.zero_offset - 1.0, 2 * M_PI), 0, 1e-12);
  // Given, not estimated: stored wrapped.
  CalOptions given;
  given.estimate_zero = false;
  given.zero_offset = 7.0;
  EXPECT_DOUBLE_EQ(calibrate(rec, given).zero_offset, wrap_pi(7.0));
  // The options of a datapath configuration.
  DatapathConfig cfg = DatapathConfig{}.with_rtl_params("CORRECTION=1 DEGREE=2 REGIONS=8");
  cfg.fourier_k = 3;
  const CalOptions o = cal_options_for(cfg, 2);
  EXPECT_EQ(o.correction, kPoly2d);
  EXPECT_EQ(o.degree, 2);
  EXPECT_EQ(o.regions, 8);
  EXPECT_EQ(o.periodicity, 2);
  EXPECT_EQ(o.fourier_k, 3);
  EXPECT_TRUE(o.estimate_zero);
}

TEST(Calibration, ImageIsTheQuantizedFitAtTheAutomaticScale) {
  const Recording rec = test::paper_recording(4096);
  FloatCoefficients fc;
  const RegImage img = calibrate_image(rec, DatapathConfig{}, 1, &fc);
  EXPECT_EQ(img.in_scale, choose_in_scale(rec, 16));
  EXPECT_EQ(static_cast<int>(img.words.size()), img.cfg.words());
  EXPECT_DOUBLE_EQ(img.zero_offset, fc.zero_offset);
  // The offset word is the fitted offset in input codes, the reciprocal 2^(S_F + R_SHIFT) / A.
  for (int c = 0; c < 2; ++c) {
    EXPECT_EQ(img.offset(c), std::llround(fc.offset[c] * img.in_scale)) << c;
    EXPECT_EQ(img.recip(c), std::llround(std::ldexp(1.0, img.cfg.s_f + img.cfg.r_shift) /
                                         (fc.amp[c] * img.in_scale)))
        << c;
  }
  // Too few samples for a Fourier fit of 40 harmonics: an input error, not a singular solve.
  CalOptions o;
  o.fourier_k = 40;
  EXPECT_THROW(calibrate(test::paper_recording(300), o), InputError);
}

// A correction mode no row of the table has is an InputError naming it, before any fit.
TEST(Calibration, AModeOutsideTheTableIsAnInputErrorNamingIt) {
  const Recording rec = test::paper_recording(4000);
  CalOptions opt;
  opt.correction = 4;
  try {
    calibrate(rec, opt);
    ADD_FAILURE() << "calibrate fitted correction 4";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("correction=4"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace acore
