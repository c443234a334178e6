// SPDX-License-Identifier: MIT
// Angle-error statistics (core/error_stats.*, docs/contracts.md: error = estimate - reference,
// wrapped to (-180, 180] degrees) against closed forms and a long-double second implementation.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/error_stats.hpp"

namespace acore {
namespace {

TEST(ErrorStats, WrapDegIsHalfOpenAtMinus180AndMovesByWholeTurns) {
  EXPECT_EQ(wrap_deg(180.0), 180.0);
  EXPECT_EQ(wrap_deg(-180.0), 180.0);
  EXPECT_EQ(wrap_deg(540.0), 180.0);
  EXPECT_EQ(wrap_deg(-540.0), 180.0);
  EXPECT_EQ(wrap_deg(360.0), 0.0);
  EXPECT_EQ(wrap_deg(-0.25), -0.25);
  EXPECT_EQ(wrap_deg(179.5), 179.5);
  EXPECT_EQ(wrap_deg(181.0), -179.0);
  EXPECT_EQ(wrap_deg(-181.0), 179.0);
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> any(-1e5, 1e5);
  for (int k = 0; k < 20000; ++k) {
    const double d = any(rng), w = wrap_deg(d);
    ASSERT_GT(w, -180.0) << d;
    ASSERT_LE(w, 180.0) << d;
    const double turns = (d - w) / 360.0;
    ASSERT_NEAR(turns, std::nearbyint(turns), 1e-12) << d;
  }
}

TEST(ErrorStats, AngleErrorIsEstimateMinusPTimesReferenceInDegrees) {
  const double deg = M_PI / 180;
  // 10 deg estimated where the reference is 350 deg: +20 deg, not -340 deg.
  EXPECT_NEAR(angle_error_deg({10 * deg}, {350 * deg})[0], 20.0, 1e-12);
  EXPECT_NEAR(angle_error_deg({350 * deg}, {10 * deg})[0], -20.0, 1e-12);
  // Periodicity p: the electrical reference is p theta_ref (here 2 * 100 deg = 200 deg).
  EXPECT_NEAR(angle_error_deg({201 * deg}, {100 * deg}, 2)[0], 1.0, 1e-12);
  EXPECT_NEAR(angle_error_deg({199 * deg}, {100 * deg}, 2)[0], -1.0, 1e-12);
  // Unwrapped references (many turns) give the same error as wrapped ones.
  EXPECT_NEAR(angle_error_deg({0.3}, {0.25 + 14 * M_PI})[0], 0.05 / deg, 1e-9);
}

TEST(ErrorStats, StatisticsMatchALongDoubleSum) {
  EXPECT_EQ(error_stats({}).rms, 0.0);
  EXPECT_EQ(error_stats({}).max_abs, 0.0);
  const ErrorStats two = error_stats({3.0, -4.0});
  EXPECT_DOUBLE_EQ(two.mean, -0.5);
  EXPECT_DOUBLE_EQ(two.rms, std::sqrt(12.5));
  EXPECT_DOUBLE_EQ(two.max_abs, 4.0);
  std::mt19937_64 rng(22);
  std::normal_distribution<double> g(0.3, 2.0);
  std::vector<double> e(100001);
  long double sum = 0, sq = 0, mx = 0;
  for (double& v : e) {
    v = g(rng);
    sum += v;
    sq += static_cast<long double>(v) * v;
    mx = std::max(mx, std::fabs(static_cast<long double>(v)));
  }
  const ErrorStats s = error_stats(e);
  const double n = static_cast<double>(e.size());
  EXPECT_NEAR(s.mean, static_cast<double>(sum / n), 1e-12);
  EXPECT_NEAR(s.rms, static_cast<double>(std::sqrt(sq / n)), 1e-12);
  EXPECT_EQ(s.max_abs, static_cast<double>(mx));
}

TEST(ErrorStats, ASineOverWholeTurnsHasRmsAmplitudeOverRootTwo) {
  // err = a sin(theta) + m on a uniform grid: mean m, rms sqrt(m^2 + a^2 / 2), max |m| + a.
  const double a = 1.7, m = -0.2;
  std::vector<double> e;
  for (int k = 0; k < 4096; ++k) e.push_back(m + a * std::sin(2 * M_PI * (k + 0.5) / 4096 + 0.3));
  const ErrorStats s = error_stats(e);
  EXPECT_NEAR(s.mean, m, 1e-12);
  EXPECT_NEAR(s.rms, std::sqrt(m * m + a * a / 2), 1e-12);
  EXPECT_NEAR(s.max_abs, std::fabs(m) + a, 1e-6);
}

}  // namespace
}  // namespace acore
