// SPDX-License-Identifier: MIT
// The blind self-benchmark (model/lab/diagnose/diagnose_bench.hpp): its draws stay in the
// documented ranges and carry exactly one effect, and a fixed-seed small run (4 recordings per
// effect, 6000 samples) meets the issue's targets: top-1 >= 90 %, median holdout shrink >= 70 %,
// every scored parameter within 20 %, no confident wrong answer on recordings without an effect or
// with one outside the vocabulary. The truth is the drawn effect, never what the diagnosis
// computes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "diagnose/diagnose_bench.hpp"

namespace acore {
namespace {

constexpr double kDeg = M_PI / 180;

TEST(DiagnoseBench, DrawsAreReproducibleAndInTheirRanges) {
  for (const std::string& e : effect_names()) {
    for (size_t k = 0; k < 40; ++k) {
      const int ch = k % 2 ? 2 : 4;
      const BenchCase c = draw_bench_case(3, k, e, ch);
      const BenchCase again = draw_bench_case(3, k, e, ch);
      ASSERT_EQ(c.effect.params, again.effect.params) << e;
      ASSERT_EQ(c.effect.effect, e);
      const double v =
          std::max(std::fabs(c.real_traj.speed_rps), std::fabs(c.real_traj.speed_end_rps));
      // The ramp reverses: its end speeds have opposite signs.
      EXPECT_LT(c.real_traj.speed_rps * c.real_traj.speed_end_rps, 0);
      auto in = [&](double x, double lo, double hi) {
        EXPECT_GE(x, lo * (1 - 1e-12)) << e << " #" << k;
        EXPECT_LE(x, hi * (1 + 1e-12)) << e << " #" << k;
      };
      if (e == "harmonic") in(c.effect.param("amplitude"), 0.01, 0.05);
      if (e == "harmonic" && ch == 4) EXPECT_EQ(std::fmod(c.effect.param("order"), 2), 1);
      if (e == "eccentricity") {
        in(c.effect.param("epsilon_rad") / kDeg, 0.2, 2);
        in(c.effect.param("am_depth") / c.effect.param("epsilon_rad"), 0, 1.5);
        in(std::fabs(std::remainder(c.effect.param("am_phase_rad") - c.effect.param("phi0_rad"),
                                    2 * M_PI)),
           0, M_PI / 2);
      }
      if (e == "common_delay") in(360 * v * c.effect.param("tau_s"), 0.2, 3);
      if (e == "channel_skew") {
        // A slot order: the channels' times are 0, tau, 2 tau, ... in some order.
        EXPECT_EQ(c.effect.param("tau_s"), 0);
        std::array<double, 4> t = channel_skew_offsets(c.effect, ch);
        std::sort(t.begin(), t.begin() + ch);
        in(360 * v * t[1], 0.2, 3);
        for (int k = 1; k < ch; ++k) EXPECT_NEAR(t[k], k * t[1], 1e-12 * t[1]) << e << " #" << k;
        EXPECT_EQ(t[0], 0);
      }
      if (e == "phase_error") {
        // One group moves: the sine pair, the cosine pair, or one channel (four channels).
        int moved = 0;
        for (const auto& [name, value] : c.effect.params) {
          if (value == 0) continue;
          ++moved;
          in(std::fabs(value) / kDeg, 0.5, 5);
        }
        EXPECT_EQ(moved, 1) << e << " #" << k;
      }
      if (e == "zero_offset") in(std::fabs(c.effect.param("zero_rad")) / kDeg, 0.2, 3);
      if (e == "amplitude") in(std::fabs(c.effect.param("scale") - 1), 0.05, 0.3);
      if (e == "quantization") in(c.effect.param("bits"), 6, 10);
      if (e == "saturation") in(c.effect.param("level") / c.peak, 0.8, 0.95);
      if (e == "excess_noise") in(c.effect.param("sigma") / c.model.sigma_indep, 2, 5);
      if (e == "hysteresis") in(std::fabs(c.effect.param("h_rad")) / kDeg, 0.1, 1);
      if (e == "offset" && ch == 4) {
        const auto o = [&](const char* n) { return c.effect.param(n); };
        EXPECT_GE(std::max(std::fabs(o("offset_c1") - o("offset_c3")),
                           std::fabs(o("offset_c2") - o("offset_c4"))),
                  0.01);
      }
    }
  }
  EXPECT_TRUE(draw_bench_case(3, 0, "none", 4).effect.effect.empty());
  // Blind: nothing in the recordings names the effect.
  const BenchRecordings r = make_bench_recordings(draw_bench_case(3, 0, "offset", 4), 2000);
  for (const Recording* rec : {&r.sim, &r.real, &r.holdout}) {
    for (const auto& [k, v] : rec->meta)
      EXPECT_EQ(v.find("offset"), std::string::npos) << k << "=" << v;
    for (const auto& line : rec->comments)
      EXPECT_EQ(line.find("offset"), std::string::npos) << line;
  }
  EXPECT_EQ(draw_bench_case(3, 0, "outside", 2, "glitch").outside_params.size(), 2u);
}

TEST(DiagnoseBench, FixedSeedSmallRunMeetsTheTargets) {
  BenchOptions opt;
  opt.per_effect = 4;  // every outside kind once
  opt.seed = 7;
  opt.samples = 6000;
  const BenchSummary s = run_diagnose_bench(opt);
  const size_t groups = effect_names().size() + 2;  // the effects, none, outside
  ASSERT_EQ(s.cases.size(), groups * 4);
  EXPECT_GE(s.top1_accuracy, 0.9) << s.text();
  EXPECT_GE(s.median_shrink, 0.7) << s.text();
  EXPECT_GT(s.params_scored, effect_names().size() * 4 / 2);
  EXPECT_EQ(s.params_within, s.params_scored) << s.text();
  EXPECT_EQ(s.confident_wrong, 0) << s.text();
  EXPECT_TRUE(s.met()) << s.text();
  // The confusion matrix counts every case once.
  int total = 0;
  for (const auto& row : s.confusion)
    for (int v : row) total += v;
  EXPECT_EQ(total, static_cast<int>(groups * 4));
}

}  // namespace
}  // namespace acore
