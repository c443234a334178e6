// SPDX-License-Identifier: MIT
// The design-space sweep (accuracy half): every configuration of a grid is calibrated on one
// recording and measured on another it never saw, per scenario, in float and bit-accurate
// arithmetic, beside its register-file size. The hardware half (LUT4, Fmax) is measured by
// scripts/design_space_hw.py from the same points; scripts/design_space.sh runs both.
//
// A point is a string of RTL parameter overrides of rtl/acore_top.v, "DEGREE=5 REGIONS=8" (the same
// syntax as rtl/configs.txt). The calibration may lower COEF_F for range (quantize_auto_range), so
// each result also carries the configuration actually built (`final_params`).
#pragma once
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/datapath_config.hpp"
#include "core/error_stats.hpp"
#include "core/recording.hpp"

namespace acore {

struct SweepScenario {
  std::string name;
  std::string description;
  Recording cal;  // calibration recording
  Recording val;  // validation recording: other angles than cal
  int p = 1;
};

// The built-in scenarios, noise-free so that the figures measure the correction, not the noise:
//   paper-noiseless  the paper scenario's four-channel sensor;
//   tmr-noiseless    the two-channel TMR-like sensor of `simulate --scenario tmr` without its
//   noise.
// Calibration: cal_samples uniform angles over one turn; validation: val_samples uniform angles
// shifted by an irrational fraction of a step, so no validation angle is a calibration angle.
std::vector<SweepScenario> sweep_scenarios(size_t cal_samples, size_t val_samples);

// A grid is a JSON array of sub-grids; a sub-grid maps RTL parameter names to a value or an array
// of values; the points are the union of the sub-grids' Cartesian products, in order, without
// duplicates. Throws InputError naming the sub-grid and field that is not of that form, or a point
// whose configuration is invalid.
// A sub-grid of more than kMaxGridPoints points is refused before it is expanded.
constexpr size_t kMaxGridPoints = 100000;
std::vector<std::string> expand_grid(const nlohmann::json& grid);
// The grid `anglecore sweep` runs by default (docs/synthesis.md, "Design space").
nlohmann::json default_sweep_grid();
// A short grid for the test and a smoke run (--quick).
nlohmann::json quick_sweep_grid();

// "i/N": this shard takes the points whose index modulo N is i. Throws InputError otherwise.
struct Shard {
  int index = 0;
  int count = 1;
  bool takes(size_t point) const {
    return static_cast<int>(point % static_cast<size_t>(count)) == index;
  }
};
Shard parse_shard(const std::string& text);

struct ScenarioAccuracy {
  std::string scenario;
  ErrorStats floating;  // float model, degrees
  ErrorStats fixed;     // bit-accurate model (= RTL), degrees
};

struct SweepResult {
  size_t index = 0;
  std::string params;        // the grid point
  std::string final_params;  // every RTL parameter of the image actually built (after auto-range)
  int words = 0;             // register file words
  std::vector<ScenarioAccuracy> accuracy;
  double seconds = 0;  // wall time of this point
  std::string error;   // non-empty when the point could not be calibrated (then no accuracy)
  nlohmann::json to_json() const;
};

// Calibrates and measures one point on every scenario. Errors of the point itself (a calibration
// that cannot fit) are recorded in `error`, not thrown.
SweepResult evaluate_point(size_t index, const std::string& params,
                           const std::vector<SweepScenario>& scenarios);

}  // namespace acore
