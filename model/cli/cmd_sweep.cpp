// SPDX-License-Identifier: MIT
// `anglecore sweep`: the accuracy half of the design-space sweep
// (model/lab/sweep/design_space.hpp). Writes one JSON line per point to
// DIR/accuracy-<i>-of-<N>.jsonl as points finish (a shard of a batch job writes only its own file),
// and the grid to DIR/grid.json so the merge step (scripts/design_space_report.py) can check that
// every shard ran the same grid.
#include <fmt/format.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <thread>

#include "cli_util.hpp"
#include "commands.hpp"
#include "core/errors.hpp"
#include "core/json_input.hpp"
#include "sweep/design_space.hpp"

namespace acore::cli {

namespace {
struct SweepArgs {
  std::string grid, out = "out/sweep", shard = "0/1";
  int jobs = 1;
  size_t cal_samples = 8192, val_samples = 4099;
  bool quick = false, list = false;
};

void run_sweep(const SweepArgs& a) {
  const nlohmann::json grid = !a.grid.empty() ? read_json_file(a.grid, "sweep grid")
                              : a.quick       ? quick_sweep_grid()
                                              : default_sweep_grid();
  const std::vector<std::string> points = expand_grid(grid);
  const Shard shard = parse_shard(a.shard);
  std::vector<size_t> mine;
  for (size_t i = 0; i < points.size(); ++i)
    if (shard.takes(i)) mine.push_back(i);
  if (a.list) {
    for (size_t i : mine) std::cout << fmt::format("{} {}\n", i, points[i]);
    return;
  }
  namespace fs = std::filesystem;
  fs::create_directories(a.out);
  {
    std::ofstream g(fs::path(a.out) / "grid.json");
    g << nlohmann::json{{"grid", grid},
                        {"points", points.size()},
                        {"cal_samples", a.cal_samples},
                        {"val_samples", a.val_samples}}
             .dump(1)
      << "\n";
    if (!g) throw InputError(a.out + "/grid.json: write failed");
  }
  const fs::path out_path =
      fs::path(a.out) / fmt::format("accuracy-{}-of-{}.jsonl", shard.index, shard.count);
  std::ofstream out(out_path);
  if (!out) throw InputError(out_path.string() + ": cannot write");

  const std::vector<SweepScenario> scenarios = sweep_scenarios(a.cal_samples, a.val_samples);
  std::cerr << fmt::format("sweep: {} of {} points (shard {}), {} scenarios, {} job(s) -> {}\n",
                           mine.size(), points.size(), a.shard, scenarios.size(), a.jobs,
                           out_path.string());
  std::atomic<size_t> next{0};
  std::mutex mu;
  size_t done = 0, failed = 0;
  auto worker = [&]() {
    for (size_t k = next++; k < mine.size(); k = next++) {
      const SweepResult r = evaluate_point(mine[k], points[mine[k]], scenarios);
      std::lock_guard<std::mutex> lock(mu);
      out << r.to_json().dump() << "\n" << std::flush;
      ++done;
      failed += !r.error.empty();
      std::string what = r.error.empty() ? "" : "FAILED: " + r.error;
      for (const ScenarioAccuracy& s : r.accuracy)
        what += fmt::format("{} {:.4f}/{:.3f}  ", s.scenario, s.fixed.rms, s.fixed.max_abs);
      std::cerr << fmt::format("[{}/{}] #{} {} ({} words): {}({:.1f} s)\n", done, mine.size(),
                               r.index, r.params, r.words, what, r.seconds);
    }
  };
  std::vector<std::thread> pool;
  for (int j = 0; j < std::max(1, a.jobs); ++j) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  if (!out) throw InputError(out_path.string() + ": write failed");
  std::cerr << fmt::format(
      "sweep: {} points done, {} could not be calibrated (see their \"error\")\n", done, failed);
}
}  // namespace

void add_sweep(CLI::App& app) {
  auto args = std::make_shared<SweepArgs>();
  CLI::App* c = app.add_subcommand(
      "sweep",
      "Design-space sweep, accuracy half: calibrate and validate every configuration of a grid "
      "(scripts/design_space.sh adds synthesis, the table and the Pareto plots)");
  c->add_option("--grid", args->grid,
                "Grid JSON: an array of sub-grids {\"RTL_PARAM\": [values], ...}; the points are "
                "the union of "
                "their Cartesian products (default: the built-in grid, see docs/synthesis.md)");
  c->add_flag("--quick", args->quick, "A small built-in grid (smoke test)");
  c->add_option("--out", args->out, "Output directory (accuracy-<i>-of-<N>.jsonl, grid.json)")
      ->capture_default_str();
  c->add_option("--jobs,-j", args->jobs, "Points evaluated in parallel (threads)")
      ->capture_default_str()
      ->check(CLI::Range(1, 256));
  c->add_option("--shard", args->shard,
                "i/N: evaluate only the points whose index modulo N is i (batch jobs)")
      ->capture_default_str();
  c->add_option("--cal-samples", args->cal_samples, "Calibration samples per scenario")
      ->capture_default_str();
  c->add_option("--val-samples", args->val_samples, "Validation samples per scenario")
      ->capture_default_str();
  c->add_flag("--list", args->list, "Print this shard's points and exit");
  c->callback([args]() { run_sweep(*args); });
}

}  // namespace acore::cli
