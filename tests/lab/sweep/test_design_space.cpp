// SPDX-License-Identifier: MIT
// The design-space sweep (sweep/design_space.*): grids expand to the union of their sub-grids'
// Cartesian products (counted here from the JSON), shards partition the points, the scenarios'
// validation angles are never calibration angles, and a point's figures equal the same
// calibration and measurement done by hand (calibrate, quantize at the configuration it reports,
// run_float/run_fixed, error_stats), with a failing calibration recorded instead of thrown.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "calibration/calibration.hpp"
#include "core/errors.hpp"
#include "engine/estimator.hpp"
#include "support/paper_signals.hpp"
#include "sweep/design_space.hpp"

namespace acore {
namespace {

TEST(DesignSpace, GridsAreUnionsOfCartesianProducts) {
  const auto pts = expand_grid(nlohmann::json::parse(
      R"([{"REGIONS": [4, 8], "DEGREE": [1, 3]}, {"DEGREE": 3, "REGIONS": 8}, {"K": [12]}])"));
  // Fields in name order, the last varying fastest; the repeated point once; a scalar is a value.
  EXPECT_EQ(pts, (std::vector<std::string>{"DEGREE=1 REGIONS=4", "DEGREE=1 REGIONS=8",
                                           "DEGREE=3 REGIONS=4", "DEGREE=3 REGIONS=8", "K=12"}));
  // The default and quick grids: as many points as their products (no sub-grids overlap), each a
  // legal configuration.
  for (const nlohmann::json& g : {default_sweep_grid(), quick_sweep_grid()}) {
    size_t count = 0;
    for (const auto& sub : g) {
      size_t prod = 1;
      for (const auto& [name, v] : sub.items()) prod *= v.is_array() ? v.size() : 1;
      count += prod;
    }
    const auto p = expand_grid(g);
    EXPECT_EQ(p.size(), count);
    EXPECT_EQ(std::set<std::string>(p.begin(), p.end()).size(), p.size());
    for (const std::string& s : p) EXPECT_NO_THROW(DatapathConfig{}.with_rtl_params(s).validate());
  }
  EXPECT_EQ(expand_grid(quick_sweep_grid()).size(), 3u);
}

void expect_grid_error(const char* json, const std::string& words) {
  try {
    expand_grid(nlohmann::json::parse(json));
    ADD_FAILURE() << "accepted " << json;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(DesignSpace, GridErrorsNameTheSubGridAndField) {
  expect_grid_error(R"({"DEGREE": [1]})", "JSON array");
  expect_grid_error(R"([{"DEGREE": [1]}, [3]])", "sub-grid 1");
  expect_grid_error(R"([{"DEGREE": []}])", "field DEGREE: no values");
  expect_grid_error(R"([{"DEGREE": [2.5]}])", "2.5 is not an integer");
  expect_grid_error(R"([{"DEGREE": ["3"]}])", "is not an integer");
  expect_grid_error(R"([{"DEGREE": [3]}, {"DEGREE": [9]}])", "sub-grid 1 point 'DEGREE=9'");
  expect_grid_error(R"([{"NOPE": [1]}])", "sub-grid 0 point 'NOPE=1'");
}

TEST(DesignSpace, ShardsPartitionThePoints) {
  for (int n : {1, 2, 3, 7}) {
    std::vector<int> taken(100, 0);
    for (int i = 0; i < n; ++i) {
      const Shard s = parse_shard(std::to_string(i) + "/" + std::to_string(n));
      EXPECT_EQ(s.index, i);
      EXPECT_EQ(s.count, n);
      for (size_t p = 0; p < taken.size(); ++p) taken[p] += s.takes(p);
    }
    for (int t : taken) EXPECT_EQ(t, 1) << n;
  }
  for (const char* bad : {"3/3", "-1/2", "1/0", "1/", "/2", "a/b", "1/2x", "1/2/3", "12", ""})
    EXPECT_THROW(parse_shard(bad), InputError) << bad;
}

TEST(DesignSpace, ValidationAnglesAreNeverCalibrationAngles) {
  const auto sc = sweep_scenarios(1024, 256);
  ASSERT_EQ(sc.size(), 2u);
  EXPECT_EQ(sc[0].name, "paper-noiseless");
  EXPECT_EQ(sc[1].name, "tmr-noiseless");
  for (const SweepScenario& s : sc) {
    ASSERT_EQ(s.cal.size(), 1024u);
    ASSERT_EQ(s.val.size(), 256u);
    // Calibration on k/1024 of a turn, validation on k/256 shifted by 0.618 of its own step, i.e.
    // 2.472 calibration steps: about half a calibration step from any calibration angle.
    const double cal_step = 2 * M_PI / 1024;
    double nearest = 1;
    for (double v : s.val.theta_ref) {
      const double r = std::remainder(v / cal_step, 1.0);
      nearest = std::min(nearest, std::fabs(r));
    }
    EXPECT_GT(nearest, 0.01) << s.name;
    // Noise-free: a second run draws the same recording.
    EXPECT_EQ(s.cal.ch[0], sweep_scenarios(1024, 256)[&s - &sc[0]].cal.ch[0]);
  }
  EXPECT_THROW(sweep_scenarios(1023, 256), InputError);
  EXPECT_THROW(sweep_scenarios(1024, 255), InputError);
}

TEST(DesignSpace, APointsFiguresAreItsCalibrationMeasuredByHand) {
  const auto sc = sweep_scenarios(1024, 256);
  const SweepResult r = evaluate_point(7, "DEGREE=3 REGIONS=4", sc);
  ASSERT_TRUE(r.error.empty()) << r.error;
  EXPECT_EQ(r.index, 7u);
  EXPECT_EQ(r.words, 52);  // the paper's map
  EXPECT_NE(r.final_params.find("DEGREE=3"), std::string::npos);
  ASSERT_EQ(r.accuracy.size(), 2u);
  // One hardware configuration serves every scenario: the one the point reports it built.
  const DatapathConfig built = DatapathConfig{}.with_rtl_params(r.final_params);
  EXPECT_EQ(built.words(), r.words);
  for (size_t i = 0; i < sc.size(); ++i) {
    const FloatCoefficients fc = calibrate(sc[i].cal, cal_options_for(built, sc[i].p));
    const RegImage img = quantize(fc, built, choose_in_scale(sc[i].cal, built.in_w));
    const ErrorStats fl =
        error_stats(angle_error_deg(run_float(sc[i].val, fc).angle, sc[i].val.theta_ref, sc[i].p));
    const ErrorStats fx =
        error_stats(angle_error_deg(run_fixed(sc[i].val, img).angle, sc[i].val.theta_ref, sc[i].p));
    EXPECT_EQ(r.accuracy[i].scenario, sc[i].name);
    EXPECT_EQ(r.accuracy[i].floating.rms, fl.rms);
    EXPECT_EQ(r.accuracy[i].fixed.rms, fx.rms);
    EXPECT_EQ(r.accuracy[i].fixed.max_abs, fx.max_abs);
    // The bit-accurate chain tracks the float one, both far below the uncorrected ~8.5 deg.
    EXPECT_LT(std::fabs(fx.rms - fl.rms), 0.02) << sc[i].name;
    EXPECT_LT(fl.rms, 1.0) << sc[i].name;
  }
  const nlohmann::json j = r.to_json();
  for (const char* f : {"index", "params", "final_params", "words", "seconds", "accuracy"})
    EXPECT_TRUE(j.contains(f)) << f;
  EXPECT_EQ(j["accuracy"]["paper-noiseless"]["fixed"]["rms"].get<double>(),
            r.accuracy[0].fixed.rms);
  EXPECT_FALSE(j.contains("error"));
}

TEST(DesignSpace, ACalibrationThatCannotFitIsRecordedNotThrown) {
  // 300 samples cannot fit 8 regions of degree-7 polynomials (8 samples per coefficient needed).
  SweepScenario s;
  s.name = "short";
  s.cal = test::paper_recording(300);
  s.val = test::paper_recording(256);
  const SweepResult r = evaluate_point(0, "DEGREE=7 REGIONS=8 XCENTER=1", {s});
  EXPECT_NE(r.error.find("at least"), std::string::npos) << r.error;
  EXPECT_TRUE(r.accuracy.empty());
  EXPECT_EQ(r.to_json()["error"], r.error);
}

}  // namespace
}  // namespace acore
