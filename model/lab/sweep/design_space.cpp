// SPDX-License-Identifier: MIT
#include "sweep/design_space.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>

#include "calibration/calibration.hpp"
#include "core/errors.hpp"
#include "engine/estimator.hpp"
#include "sim/simulator.hpp"

namespace acore {

namespace {

// A uniform turn of n samples starting at theta0 (the scenario's own trajectory replaced).
Recording turn(Scenario s, size_t n, double theta0) {
  s.trajectory = Trajectory{};
  s.trajectory.kind = "turn";
  s.trajectory.theta0_rad = theta0;
  s.sigma_common = s.sigma_indep = 0;
  return simulate(s, n, 1);
}

SweepScenario make_scenario(const std::string& name, Scenario s, size_t cal_n, size_t val_n) {
  SweepScenario sc;
  sc.name = name;
  sc.description = s.description + " (noise removed)";
  sc.p = s.p;
  sc.cal = turn(s, cal_n, 0.0);
  // (sqrt(5) - 1) / 2 of a validation step: never a calibration angle.
  sc.val = turn(s, val_n, 0.6180339887498949 * 2 * M_PI / static_cast<double>(val_n));
  return sc;
}

nlohmann::json values_of(const nlohmann::json& v) {
  return v.is_array() ? v : nlohmann::json::array({v});
}

}  // namespace

std::vector<SweepScenario> sweep_scenarios(size_t cal_samples, size_t val_samples) {
  if (cal_samples < 1024 || val_samples < 256)
    throw InputError(
        fmt::format("sweep: need at least 1024 calibration and 256 validation samples (got {}, {})",
                    cal_samples, val_samples));
  return {make_scenario("paper-noiseless", builtin_scenario("paper-noiseless"), cal_samples,
                        val_samples),
          make_scenario("tmr-noiseless", builtin_scenario("tmr"), cal_samples, val_samples)};
}

std::vector<std::string> expand_grid(const nlohmann::json& grid) {
  if (!grid.is_array()) throw InputError("sweep grid: expected a JSON array of sub-grids");
  std::vector<std::string> points;
  std::set<std::string> seen;
  for (size_t g = 0; g < grid.size(); ++g) {
    const nlohmann::json& sub = grid[g];
    if (!sub.is_object())
      throw InputError(fmt::format("sweep grid: sub-grid {} is not an object", g));
    // The product's size first: a few kilobytes of JSON can describe more points than memory
    // holds, and a sweep of that many points would never end anyway.
    size_t product = 1;
    for (const auto& [name, val] : sub.items()) {
      const size_t n = values_of(val).size();
      if (n != 0 && product > kMaxGridPoints / n)
        throw InputError(
            fmt::format("sweep grid: sub-grid {} field {}: the sub-grid has more than {} points", g,
                        name, kMaxGridPoints));
      product *= std::max<size_t>(n, 1);
    }
    // Cartesian product, the last field varying fastest.
    std::vector<std::string> partial = {""};
    for (const auto& [name, val] : sub.items()) {
      const nlohmann::json vals = values_of(val);
      if (vals.empty())
        throw InputError(fmt::format("sweep grid: sub-grid {} field {}: no values", g, name));
      std::vector<std::string> next;
      for (const std::string& head : partial)
        for (const auto& v : vals) {
          if (!v.is_number_integer())
            throw InputError(fmt::format("sweep grid: sub-grid {} field {}: {} is not an integer",
                                         g, name, v.dump()));
          next.push_back(head + (head.empty() ? "" : " ") +
                         fmt::format("{}={}", name, v.get<long long>()));
        }
      partial = std::move(next);
    }
    for (const std::string& p : partial) {
      try {
        DatapathConfig{}.with_rtl_params(p).validate();
      } catch (const InputError& e) {
        throw InputError(fmt::format("sweep grid: sub-grid {} point '{}': {}", g, p, e.what()));
      }
      if (seen.insert(p).second) points.push_back(p);
    }
  }
  return points;
}

nlohmann::json default_sweep_grid() {
  return nlohmann::json::parse(R"([
    {"DEGREE": [1, 2, 3, 4, 5, 6, 7], "REGIONS": [4, 8]},
    {"DEGREE": [3], "K": [12, 14, 18, 20]},
    {"DEGREE": [5, 6, 7], "REGIONS": [8], "XCENTER": [1]},
    {"CORRECTION": [1], "DEGREE": [1, 2, 3], "REGIONS": [4, 8]},
    {"CORRECTION": [1], "DEGREE": [3], "IN_W": [18], "REG_W": [20], "COEF_F": [17], "K": [18],
     "CORDIC_G": [4], "Z_W": [22], "ANGLE_W": [18]},
    {"CORRECTION": [2]},
    {"CORRECTION": [2], "FOURIER_K": [13, 20, 21]},
    {"DEGREE": [1], "FOURIER_K": [13]},
    {"DEGREE": [3], "FOURIER_K": [8]},
    {"DEGREE": [3], "FOLD": [2, 4, 8]},
    {"DEGREE": [1], "FOLD": [8]},
    {"DEGREE": [5], "REGIONS": [8], "FOLD": [4, 8]},
    {"DEGREE": [7], "REGIONS": [8], "XCENTER": [1], "FOLD": [8]}
  ])");
}

nlohmann::json quick_sweep_grid() {
  return nlohmann::json::parse(R"([
    {"DEGREE": [1, 3], "REGIONS": [4]},
    {"DEGREE": [5], "REGIONS": [8]}
  ])");
}

Shard parse_shard(const std::string& text) {
  Shard s;
  const auto slash = text.find('/');
  size_t a = 0, b = 0;
  try {
    if (slash == std::string::npos) throw std::invalid_argument("no slash");
    s.index = std::stoi(text.substr(0, slash), &a);
    s.count = std::stoi(text.substr(slash + 1), &b);
  } catch (const std::exception&) {
    a = b = 0;
  }
  if (a == 0 || b == 0 || a != slash || slash + 1 + b != text.size() || s.count < 1 ||
      s.index < 0 || s.index >= s.count)
    throw InputError(fmt::format("--shard '{}': expected i/N with 0 <= i < N", text));
  return s;
}

nlohmann::json SweepResult::to_json() const {
  nlohmann::json j = {{"index", index},
                      {"params", params},
                      {"final_params", final_params},
                      {"words", words},
                      {"seconds", seconds}};
  auto stats = [](const ErrorStats& s) {
    return nlohmann::json{{"rms", s.rms}, {"max_abs", s.max_abs}, {"mean", s.mean}};
  };
  for (const ScenarioAccuracy& a : accuracy)
    j["accuracy"][a.scenario] = {{"float", stats(a.floating)}, {"fixed", stats(a.fixed)}};
  if (!error.empty()) j["error"] = error;
  return j;
}

SweepResult evaluate_point(size_t index, const std::string& params,
                           const std::vector<SweepScenario>& scenarios) {
  const auto t0 = std::chrono::steady_clock::now();
  SweepResult r;
  r.index = index;
  r.params = params;
  const DatapathConfig cfg = DatapathConfig{}.with_rtl_params(params);
  try {
    // One hardware configuration for every scenario: the calibration may lower COEF_F for range,
    // so the image with the least coefficient fraction bits sets it and the others are
    // re-quantized.
    std::vector<FloatCoefficients> fcs(scenarios.size());
    std::vector<RegImage> imgs;
    for (size_t i = 0; i < scenarios.size(); ++i)
      imgs.push_back(calibrate_image(scenarios[i].cal, cfg, scenarios[i].p, &fcs[i]));
    DatapathConfig built = cfg;
    for (const RegImage& img : imgs)
      if (&img == &imgs.front() || img.cfg.coef_f < built.coef_f) built = img.cfg;
    // Likewise the Fourier words' fraction bits (lowered on their own for range).
    for (const RegImage& img : imgs)
      built.fourier_coef_f = std::min(built.fourier_coef_f, img.cfg.fourier_coef_f);
    r.words = built.words();
    for (const auto& [name, value] : built.rtl_params())
      r.final_params += fmt::format("{}{}={}", r.final_params.empty() ? "" : " ", name, value);
    for (size_t i = 0; i < scenarios.size(); ++i) {
      const SweepScenario& sc = scenarios[i];
      if (imgs[i].cfg != built)
        imgs[i] = quantize(fcs[i], built, choose_in_scale(sc.cal, built.in_w));
      ScenarioAccuracy a;
      a.scenario = sc.name;
      a.floating =
          error_stats(angle_error_deg(run_float(sc.val, fcs[i]).angle, sc.val.theta_ref, sc.p));
      a.fixed =
          error_stats(angle_error_deg(run_fixed(sc.val, imgs[i]).angle, sc.val.theta_ref, sc.p));
      r.accuracy.push_back(a);
    }
  } catch (const InputError& e) {
    r.error = e.what();
    r.accuracy.clear();
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace acore
