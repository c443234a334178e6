// SPDX-License-Identifier: MIT
// The physics benchmark (model/lab/diagnose/physics_bench.hpp): its draws perturb exactly what each
// scenario says, within the documented ranges, blind; and a fixed-seed run of the diagnosis over
// every scenario meets the physics benchmark's targets (docs/diagnosis.md "Physics benchmark" lists
// what fails and why). The truth is decided by the physics (and tested in test_physics_rig.cpp),
// never by what the diagnosis computes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "diagnose/physics_bench.hpp"

namespace acore {
namespace {

constexpr double kDeg = M_PI / 180;

size_t index_of(const std::string& label) {
  const auto& s = physics_scenarios();
  for (size_t k = 0; k < s.size(); ++k)
    if (s[k].label() == label) return k;
  ADD_FAILURE() << "no scenario " << label;
  return 0;
}

TEST(PhysicsBench, DrawsPerturbOnlyTheirScenarioWithinRange) {
  BenchOptions opt;
  opt.per_effect = 3;
  opt.seed = 5;
  const auto cases = draw_physics_cases(opt);
  ASSERT_EQ(cases.size(), 3 * physics_scenarios().size());
  for (const PhysicsCase& c : cases) {
    const PhysicsCase again = draw_physics_case(5, c.index, c.scenario);
    EXPECT_EQ(c.params, again.params);
    const PhysicsRig &n = c.sim_rig, &r = c.real_rig;
    const std::string& s = c.scenario.name;
    const int nch = n.sensor.channels();
    EXPECT_EQ(nch, c.scenario.sensor == "hall4" ? 4 : 2);
    EXPECT_LT(c.real_traj.speed_rps * c.real_traj.speed_end_rps, 0);  // through a reversal
    auto in = [&](double x, double lo, double hi) {
      EXPECT_GE(x, lo * (1 - 1e-12)) << c.scenario.label();
      EXPECT_LE(x, hi * (1 + 1e-12)) << c.scenario.label();
    };
    // What is not the scenario's stays nominal.
    if (s != "runout" && s != "runout_offaxis") EXPECT_EQ(r.runout_m, 0);
    if (s != "sensor_shift") EXPECT_EQ(r.sensor_shift_m, n.sensor_shift_m) << s;
    if (s != "air_gap") EXPECT_EQ(r.air_gap_m, n.air_gap_m);
    if (s != "stray_axial" && s != "stray_inplane") EXPECT_EQ(r.stray_T.norm(), 0);
    if (s != "adc") EXPECT_EQ(r.adc.bits, 0);
    if (s != "mux") EXPECT_TRUE(r.mux_order.empty());
    if (s != "encoder_zero") EXPECT_EQ(r.encoder_zero_rad, 0);
    if (s != "rc_filter" && s != "rc_mismatch") EXPECT_TRUE(r.rc_tau_s.empty());
    EXPECT_EQ(n.magnet.br_per_C, 0);  // the remanence is held except in the temperature scenario
    EXPECT_EQ(r.magnet.br_per_C, s == "temperature" ? -0.0012 : 0.0);
    for (const auto& e : r.sensor.elements)
      EXPECT_EQ(e.cubic, s == "nonlinearity" ? r.sensor.elements[0].cubic : 0.0);
    if (s == "nonlinearity") in(-r.sensor.elements[0].cubic, 0.02, 0.08);
    if (s == "runout") {
      in(r.runout_m, 0.3e-3, 0.6e-3);
      // The physics of the truth (zero_offset): a constant angle shift carrying >= 90 % of the
      // clean angle error's square.
      double shift = 0, rms = 0;
      for (const auto& [k, v] : c.params) {
        if (k == "angle_shift_deg") shift = v;
        if (k == "angle_error_rms_deg") rms = v;
      }
      EXPECT_GE(std::fabs(shift), 0.05);
      EXPECT_GE(shift * shift, 0.9 * rms * rms);
    }
    if (s == "runout_offaxis") {
      in(r.runout_m, 0.15e-3, 0.4e-3);
      in(n.sensor_shift_m.norm(), 0.3e-3, 0.5e-3);
    }
    if (s == "air_gap") in(r.air_gap_m - n.air_gap_m, 0.2e-3, 0.6e-3);
    if (s == "adc") in(r.adc.bits, 8, 10);
    if (s == "encoder_zero") in(std::fabs(r.encoder_zero_rad) / kDeg, 20, 180);
    if (s == "mux") {
      std::vector<int> o = r.mux_order;
      std::sort(o.begin(), o.end());
      for (int k = 0; k < nch; ++k) EXPECT_EQ(o[static_cast<size_t>(k)], k);
    }
    if (s == "rc_mismatch") {
      // Around the modelled filter: the mean is the nominal tau.
      double mean = 0;
      for (double t : r.rc_tau_s) mean += t / nch;
      EXPECT_NEAR(mean, n.rc_tau_s[0], 1e-12 * mean);
    }
  }
  // Blind: nothing in the recordings names the scenario.
  const BenchRecordings rec = make_physics_recordings(cases[3 * index_of("runout/tmr2")], 2000);
  for (const Recording* x : {&rec.sim, &rec.real, &rec.holdout})
    for (const auto& [k, v] : x->meta) EXPECT_EQ(v.find("runout"), std::string::npos) << k;
  EXPECT_TRUE(rec.sim.temp.empty());
  EXPECT_FALSE(rec.real.temp.empty());
}

TEST(PhysicsBench, FixedSeedSmallRunMeetsTheIssueTargets) {
  // Every scenario once (seed 7, 6000 samples; about 9 s of CPU). The targets: top-1 >= 90 %
  // with median holdout shrink >= 70 %; a constant angle shift (run-out of a magnet over a sensor
  // whose shift carries the error, a reference encoder's zero) named zero_offset; channels sampled
  // in a random slot order or through mismatched RC filters named channel_skew. Measured on this
  // run: 35 of 35, median shrink 100 %, lowest 71 % (docs/diagnosis.md "Physics benchmark"; 350
  // recordings: 99.7 %, 99.9 %). The margins: one wrong case, a median of 90 %, no case under 50 %.
  BenchOptions opt;
  opt.per_effect = 1;
  opt.seed = 7;
  opt.samples = 6000;
  opt.jobs = 1;
  const BenchSummary s = run_physics_bench(opt);
  ASSERT_EQ(s.cases.size(), physics_scenarios().size());
  int wrong = 0;
  for (const auto& r : s.cases) {
    wrong += !r.correct;
    EXPECT_FALSE(r.confident_wrong) << r.label;
    const std::string name = r.label.substr(0, r.label.find('/'));
    if (name == "runout" || name == "encoder_zero" || name == "mux" || name == "rc_mismatch")
      EXPECT_TRUE(r.correct) << r.label << ": expected " << r.expected << ", got " << r.top1;
    if (r.effect_case && r.correct) EXPECT_GE(r.shrink, 0.5) << r.label;
  }
  EXPECT_LE(wrong, 1);
  EXPECT_GE(s.top1_accuracy, 0.9);
  EXPECT_GE(s.median_shrink, 0.9);
  EXPECT_EQ(s.confident_wrong, 0);
  EXPECT_TRUE(s.met()) << (s.missed().empty() ? "" : s.missed().front());
  int total = 0;
  for (const auto& row : s.confusion)
    for (int v : row) total += v;
  EXPECT_EQ(total, static_cast<int>(s.cases.size()));
  EXPECT_EQ(s.rows.size(), physics_scenarios().size());
}

}  // namespace
}  // namespace acore
