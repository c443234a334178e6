// SPDX-License-Identifier: MIT
// The simulator's speed variation (model/lab/sim/speed_profile.hpp): a ripple and a slow random
// change around the nominal speed, integrated in closed form, checked against a numerical
// derivative, its period and its bounds; and the trajectory fields that carry it.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/angle.hpp"
#include "sim/simulator.hpp"
#include "sim/speed_profile.hpp"

namespace acore {
namespace {

// The relative speed change v / v0 - 1 by central differences of the angle.
double rel_speed(const SpeedVariation& sv, double u, double total) {
  const double h = 1e-5;
  return (speed_variation_angle(sv, u + h, total) - speed_variation_angle(sv, u - h, total)) /
         (2 * h) / kTwoPi;
}

TEST(SpeedProfile, NoVariationIsNoAngle) {
  SpeedVariation sv;
  for (double u : {0.0, 0.3, 2.7}) EXPECT_EQ(speed_variation_angle(sv, u, 3), 0.0);
}

TEST(SpeedProfile, StartsAtZero) {
  SpeedVariation sv;
  sv.ripple_pct = 10;
  sv.drift_pct = 10;
  EXPECT_NEAR(speed_variation_angle(sv, 0, 3), 0, 1e-15);
}

TEST(SpeedProfile, RippleIsASineOfItsAmplitudeAndPeriod) {
  SpeedVariation sv;
  sv.ripple_pct = 10;
  sv.ripple_cycles = 3.7;
  double lo = 1, hi = -1;
  for (int i = 1; i < 4000; ++i) {
    const double u = i * 1e-3;
    const double v = rel_speed(sv, u, 4);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    // Periodic with 1 / f turns.
    EXPECT_NEAR(v, rel_speed(sv, u + 1 / sv.ripple_cycles, 4), 1e-6);
  }
  EXPECT_NEAR(hi, 0.10, 1e-4);
  EXPECT_NEAR(lo, -0.10, 1e-4);
}

TEST(SpeedProfile, SlowChangeStaysWithinItsPeakAndIsSlow) {
  SpeedVariation sv;
  sv.drift_pct = 10;
  sv.seed = 5;
  double lo = 1, hi = -1, steepest = 0;
  const double total = 3;
  for (int i = 1; i < 3000; ++i) {
    const double u = i * 1e-3, v = rel_speed(sv, u, total);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    steepest = std::max(steepest, std::fabs(rel_speed(sv, u + 1e-3, total) - v) / 1e-3);
  }
  EXPECT_LE(hi, 0.10 + 1e-9);
  EXPECT_GE(lo, -0.10 - 1e-9);
  EXPECT_GT(hi - lo, 0.02);  // it does change
  // At most 1.5 cycles over the recording: slope below 2 pi * 1.5 / total * peak.
  EXPECT_LE(steepest, kTwoPi * 1.5 / total * 0.10 * 1.01);
  SpeedVariation other = sv;
  other.seed = 6;
  EXPECT_NE(speed_variation_angle(sv, 1.5, total), speed_variation_angle(other, 1.5, total));
}

TEST(SpeedProfile, TrajectoryCarriesItAndJsonRoundTrips) {
  Scenario s = builtin_scenario("ideal");
  s.trajectory.kind = "constant";
  s.trajectory.turns = 2;
  s.trajectory.speed.ripple_pct = 5;
  const Recording r = simulate(s, 2000, 1);
  const TrajectoryModel tm(s.trajectory, 2000);
  double worst = 0;
  for (size_t k = 0; k < r.size(); ++k)
    worst = std::max(worst, std::fabs(r.theta_ref[k] - kTwoPi * 2 * r.t[k] -
                                      speed_variation_angle(s.trajectory.speed, 2 * r.t[k], 2)));
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(std::fabs(tm.varied(0.3)), 1e-4);
  const Scenario back = Scenario::from_json(s.to_json());
  EXPECT_EQ(back.trajectory.speed.ripple_pct, 5);
  EXPECT_EQ(back.trajectory.speed.ripple_cycles, s.trajectory.speed.ripple_cycles);
  nlohmann::json bad = s.to_json();
  bad["trajectory"]["speed_ripple_pct"] = 60;
  bad["trajectory"]["speed_drift_pct"] = 50;
  EXPECT_THROW(Scenario::from_json(bad), std::exception);
}

}  // namespace
}  // namespace acore
