// SPDX-License-Identifier: MIT
// The sim-to-real gap (diagnose/gap.*) on recordings made here from the paper's table
// (tests/support/paper_signals.hpp) and from the fitted model itself, so the expected figures have
// closed forms: angular velocity by central differences (exact for a quadratic trajectory); the gap
// basis is cos/sin k theta times its factors; identical recordings have no gap; an angle shift of
// delta shows as a gap of |delta|; each domain score finds the factor the gap was made of; only the
// stage that was changed diverges.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "diagnose/gap.hpp"
#include "support/paper_signals.hpp"

namespace acore {
namespace {

constexpr double kDeg = 180.0 / M_PI;

// The paper sensor over one uniform turn with independent noise sigma per channel.
Recording noisy_paper(size_t n, double sigma, uint64_t seed) {
  Recording r = test::paper_recording(n);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0, sigma);
  for (int c = 0; c < 4; ++c)
    for (double& v : r.ch[c]) v += g(rng);
  return r;
}

const GapModel& model() {
  static const GapModel m = build_gap_model(noisy_paper(4000, 0.01, 1), 1);
  return m;
}

// Angles of a recording to compare at: random, several turns, with t and a temperature ramp.
Recording angles(size_t n, uint64_t seed) {
  Recording r;
  r.channels = 4;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 2 * M_PI);
  for (size_t k = 0; k < n; ++k) {
    r.t.push_back(0.001 * k);
    r.theta_ref.push_back(u(rng));
    r.temp.push_back(20 + 30.0 * k / n);
  }
  return model().sensor.resample(r);
}

TEST(Gap, AngularVelocityIsTheCentralDifference) {
  // theta = a t^2 + b t on uneven times: central differences of a quadratic on a uniform grid are
  // exact, and at the ends the one-sided difference is the slope at the midpoint.
  Recording r;
  const double a = 3.0, b = -2.0, h = 0.01;
  for (int k = 0; k < 50; ++k) {
    const double t = 0.5 + h * k;
    r.t.push_back(t);
    r.theta_ref.push_back(a * t * t + b * t);
  }
  r.ch[0].resize(50);
  const std::vector<double> w = angular_velocity(r);
  for (int k = 1; k < 49; ++k) EXPECT_NEAR(w[k], 2 * a * r.t[k] + b, 1e-9) << k;
  EXPECT_NEAR(w[0], a * (r.t[0] + r.t[1]) + b, 1e-9);
  EXPECT_NEAR(w[49], a * (r.t[48] + r.t[49]) + b, 1e-9);
  // Without t: radians per sample.
  r.t.clear();
  EXPECT_NEAR(angular_velocity(r)[10], (r.theta_ref[11] - r.theta_ref[9]) / 2, 1e-15);
  Recording one;
  one.theta_ref = {1.0};
  one.ch[0] = {0.0};
  EXPECT_EQ(angular_velocity(one), std::vector<double>{0.0});
}

TEST(Gap, BasisIsTheAngleHarmonicsTimesEachFactor) {
  // Forward only, no temperature: factors 1 and speed, 2 x 33 columns.
  Recording r;
  for (int k = 0; k < 200; ++k) {
    r.t.push_back(0.01 * k);
    r.theta_ref.push_back(0.03 * k + 0.001 * k * k);
  }
  r.ch[0].resize(200);
  const GapBasis b = make_gap_basis(r);
  ASSERT_EQ(b.X.rows(), 200);
  ASSERT_EQ(b.X.cols(), 66);
  const std::vector<double> w = angular_velocity(r);
  double wmax = 0;
  for (double v : w) wmax = std::max(wmax, std::fabs(v));
  for (int i = 0; i < 200; i += 17)
    for (int k = 1; k <= 16; ++k) {
      EXPECT_NEAR(b.X(i, 2 * k - 1), std::cos(k * r.theta_ref[i]), 1e-12);
      EXPECT_NEAR(b.X(i, 2 * k), std::sin(k * r.theta_ref[i]), 1e-12);
      EXPECT_NEAR(b.X(i, 33 + 2 * k), w[i] / wmax * std::sin(k * r.theta_ref[i]), 1e-12);
    }
  // A reversal and a temperature ramp add the direction and temperature factors.
  const Recording full = angles(300, 2);
  EXPECT_EQ(make_gap_basis(full).X.cols(), 4 * 33);
}

TEST(Gap, IdenticalRecordingsHaveNoGapAndAnAngleShiftIsItsSize) {
  const GapModel& m = model();
  const Recording pred = angles(3000, 3);
  const StageSeries same = compare(m, pred, pred);
  EXPECT_EQ(same.raw_rms_deg, 0.0);
  EXPECT_EQ(same.gap_deg, 0.0);
  EXPECT_EQ(same.excess_noise_deg, 0.0);
  for (double g : same.g) ASSERT_EQ(g, 0.0);
  EXPECT_GT(same.noise_deg, 0.0);  // the simulation's noise, through the estimator
  // The same channels seen 0.5 deg further on: the estimator follows, g = 0.5 deg + the change of
  // its own (small) error over 0.5 deg.
  const double delta = 0.5 / kDeg;
  Recording moved = pred;
  for (int c = 0; c < 4; ++c)
    for (size_t i = 0; i < pred.size(); ++i)
      moved.ch[c][i] = m.sensor.value(c, pred.theta_ref[i] + delta);
  const StageSeries s = compare(m, moved, pred);
  double mean = 0;
  for (double g : s.g) mean += g / s.g.size();
  EXPECT_NEAR(mean, 0.5, 0.01);
  EXPECT_NEAR(s.gap_deg, 0.5, 0.02);
  EXPECT_NEAR(s.systematic_deg, s.gap_deg, 1e-9) << "no excess noise in a shift";
  EXPECT_LT(s.slow_deg, 0.01) << "a shift is a function of angle, not of time";
}

TEST(Gap, DomainScoresFindTheFactorOfTheGap) {
  const Recording rec = angles(2000, 4);
  auto best = [&](const std::vector<double>& g) {
    const auto d = gap_domains(rec, g, 1);
    std::string name;
    double r2 = -1;
    for (const auto& s : d)
      if (s.r2 > r2) r2 = s.r2, name = s.domain;
    return std::make_pair(name, r2);
  };
  std::vector<double> by_angle, by_temp;
  for (size_t i = 0; i < rec.size(); ++i) {
    by_angle.push_back(0.3 * std::sin(2 * rec.theta_ref[i] + 1.0));
    by_temp.push_back(0.01 * (rec.temp[i] - 20) * std::cos(rec.theta_ref[i]));
  }
  const auto a = best(by_angle), t = best(by_temp);
  EXPECT_EQ(a.first, "angle");
  EXPECT_NEAR(a.second, 1.0, 1e-9);
  EXPECT_EQ(t.first, "time_temperature");
  EXPECT_GT(t.second, 0.99);
  // No gap has nothing to explain; too short a recording neither.
  EXPECT_TRUE(gap_domains(rec, std::vector<double>(rec.size(), 0.0), 1).empty());
  Recording shorter = rec;
  for (auto* v : {&shorter.theta_ref, &shorter.t, &shorter.temp, &shorter.ch[0], &shorter.ch[1],
                  &shorter.ch[2], &shorter.ch[3]})
    v->resize(50);
  EXPECT_TRUE(gap_domains(shorter, std::vector<double>(by_angle.begin(), by_angle.begin() + 50), 1)
                  .empty());
}

TEST(Gap, OnlyTheChangedStageDiverges) {
  const GapModel& m = model();
  const Recording pred = angles(3000, 5);
  // Noise at the simulation's level on every channel: nothing diverges.
  Recording real = pred;
  std::mt19937_64 rng(6);
  std::normal_distribution<double> g(0, 0.01);
  for (int c = 0; c < 4; ++c)
    for (double& v : real.ch[c]) v += g(rng);
  auto run = [&](const Recording& r) { return stage_divergence(m, r, pred, compare(m, r, pred)); };
  for (const StageDivergence& d : run(real)) EXPECT_FALSE(d.diverges) << d.stage;
  // c2 and c4 both shifted by 0.05: a common mode of the cosine pair. The raw channels diverge
  // (c2, c4 only), the pre-filter's differences do not.
  Recording common = real;
  for (int c : {1, 3})
    for (double& v : common.ch[c]) v += 0.05;
  const auto sd = run(common);
  ASSERT_EQ(sd.size(), 5u);
  EXPECT_EQ(sd[0].stage, "raw");
  EXPECT_TRUE(sd[0].diverges);
  EXPECT_LT(sd[0].ratio[0], 1.2);
  EXPECT_GT(sd[0].ratio[1], 3);
  EXPECT_LT(sd[0].ratio[2], 1.2);
  EXPECT_GT(sd[0].ratio[3], 3);
  EXPECT_EQ(sd[1].stage, "prefilter");
  EXPECT_FALSE(sd[1].diverges);
  EXPECT_EQ(sd[4].stage, "angle");
  EXPECT_FALSE(sd[4].diverges);
}

}  // namespace
}  // namespace acore
