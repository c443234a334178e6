// SPDX-License-Identifier: MIT
// The static sensor model: recovers the paper's Fourier coefficients (docs/contracts.md, paper
// scenario) and noise level.
#include <gtest/gtest.h>

#include <random>

#include "core/errors.hpp"
#include "diagnose/sensor_fit.hpp"
#include "support/paper_signals.hpp"

namespace acore {
namespace {

TEST(SensorFit, RecoversThePaperTableAndNoise) {
  Recording rec = test::paper_recording(8192);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> n(0, 0.05);
  for (size_t i = 0; i < rec.size(); ++i) {
    const double common = n(rng);  // common-mode: cancels in the differences
    for (int c = 0; c < 4; ++c) rec.ch[c][i] += common;
  }
  const SensorFit f = fit_sensor(rec, 8, 1);
  // c1 = sin + e1s: cos(theta) coefficient AF1 = 0.11, sin(theta) coefficient 1 + BF1 = 1.10.
  EXPECT_NEAR(f.coef[0][1], 0.11, 0.005);
  EXPECT_NEAR(f.coef[0][2], 1.10, 0.005);
  // c3 = -sin + e3s: AF1 = 0.50, BF1 - 1 = -0.87; order 2 of c2: AF2 0.19, BF2 0.19.
  EXPECT_NEAR(f.coef[2][1], 0.50, 0.005);
  EXPECT_NEAR(f.coef[2][2], -0.87, 0.005);
  EXPECT_NEAR(f.coef[1][3], 0.19, 0.005);
  EXPECT_NEAR(f.coef[1][4], 0.19, 0.005);
  for (double s : f.noise_sigma) EXPECT_NEAR(s, 0.05, 0.002);
  EXPECT_GT(f.noise_corr[0], 0.95);       // common-mode noise is fully correlated
  EXPECT_LT(f.diff_noise_sigma(), 0.01);  // and cancels in the differences
  EXPECT_NEAR(f.value(3, 1.0), rec.ch[3][0] * 0 + f.value(3, 1.0 + 2 * M_PI), 1e-12);
}

TEST(SensorFit, DerivativeMatchesFiniteDifference) {
  const SensorFit f = fit_sensor(test::paper_recording(2048), 6, 2);
  for (double th : {0.1, 1.3, 4.0})
    for (int c = 0; c < 4; ++c)
      EXPECT_NEAR(f.derivative(c, th), (f.value(c, th + 1e-6) - f.value(c, th - 1e-6)) / 2e-6,
                  1e-5);
}

TEST(SensorFit, RejectsLessThanATurn) {
  Recording rec = test::paper_recording(4096);
  for (auto* v : {&rec.theta_ref, &rec.ch[0], &rec.ch[1], &rec.ch[2], &rec.ch[3]}) v->resize(3000);
  EXPECT_THROW(fit_sensor(rec, 5, 1), InputError);
}

}  // namespace
}  // namespace acore
