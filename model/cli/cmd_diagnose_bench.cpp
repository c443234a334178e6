// SPDX-License-Identifier: MIT
// `anglecore diagnose-bench`: the blind self-benchmark of the gap diagnosis
// (model/lab/diagnose/diagnose_bench.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli_util.hpp"
#include "commands.hpp"
#include "core/errors.hpp"
#include "diagnose/diagnose_bench.hpp"
#include "diagnose/physics_bench.hpp"

namespace acore::cli {

namespace {

struct BenchArgs {
  int per_effect = 10;
  uint64_t seed = 1;
  size_t samples = 20000;
  int jobs = 1;
  std::string json, save;
  std::vector<size_t> only;
  bool check = false, quiet = false, physics = false;
};

// The recordings of the selected cases, for `anglecore diagnose` by hand.
void save_cases(const BenchOptions& opt, bool physics, const std::string& dir) {
  std::filesystem::create_directories(dir);
  auto wanted = [&](size_t index) {
    return opt.only.empty() || std::find(opt.only.begin(), opt.only.end(), index) != opt.only.end();
  };
  auto save = [&](size_t index, const BenchRecordings& r) {
    const std::string stem = fmt::format("{}/case{:03d}_", dir, index);
    write_recording(r.sim, stem + "sim.csv");
    write_recording(r.real, stem + "real.csv");
    write_recording(r.holdout, stem + "holdout.csv");
  };
  if (physics) {
    for (const PhysicsCase& c : draw_physics_cases(opt))
      if (wanted(c.index)) save(c.index, make_physics_recordings(c, opt.samples));
  } else {
    for (const BenchCase& c : draw_bench_cases(opt))
      if (wanted(c.index)) save(c.index, make_bench_recordings(c, opt.samples));
  }
  std::cerr << fmt::format(
      "diagnose-bench: recordings written to {}/caseNNN_{{sim,real,holdout}}.csv\n", dir);
}

void run_bench(const BenchArgs& a) {
  BenchOptions opt;
  opt.per_effect = a.per_effect;
  opt.seed = a.seed;
  opt.samples = a.samples;
  opt.jobs = a.jobs;
  opt.only = a.only;
  if (!a.save.empty()) save_cases(opt, a.physics, a.save);
  if (!a.quiet)
    opt.progress = [physics = a.physics](size_t done, size_t total, const BenchCaseResult& r) {
      const std::string what = physics ? fmt::format("{} ({})", r.label, r.expected)
                               : r.drawn.truth == "outside" ? "outside:" + r.drawn.outside
                                                            : r.drawn.truth;
      std::cerr << fmt::format(
          "[{:>3}/{}] #{:<3} {:<14} {}ch -> {:<14} {}  gap {:.3f} deg, holdout {:.3f} -> {:.3f}  "
          "({:.1f} s)\n",
          done, total, r.drawn.index, what, r.drawn.channels, r.top1, r.correct ? "ok " : "BAD",
          r.real_before, r.hold_before, r.hold_after, r.seconds);
    };
  if (a.physics)
    std::cerr << fmt::format(
        "diagnose-bench --physics: {} recordings per scenario, {} scenarios, {} samples, seed {}, "
        "{} job(s)\n",
        a.per_effect, physics_scenarios().size(), a.samples, a.seed, a.jobs);
  else
    std::cerr << fmt::format(
        "diagnose-bench: {} recordings per effect, {} effects + none + outside, {} samples, seed "
        "{}, {} job(s)\n",
        a.per_effect, effect_names().size(), a.samples, a.seed, a.jobs);
  const BenchSummary s = a.physics ? run_physics_bench(opt) : run_diagnose_bench(opt);
  std::ostream& out = a.json == "-" ? std::cerr : std::cout;
  out << s.text();
  write_json(a.json, s.to_json());
  if (a.check) {
    const auto missed = s.missed();
    if (!missed.empty())
      throw CheckFailed(fmt::format("diagnose-bench targets missed: {}", fmt::join(missed, "; ")));
    out << "all targets met\n";
  }
}

}  // namespace

void add_diagnose_bench(CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* c = app.add_subcommand("diagnose-bench",
                                   "Blind self-benchmark of diagnose: random effects, confusion "
                                   "matrix, parameter recovery, shrink");
  c->add_option(
       "--per-effect", args->per_effect,
       "Recordings per effect (and as many with no effect and with one outside the vocabulary)")
      ->check(CLI::Range(1, 10000));
  c->add_option("--seed", args->seed, "Seed of every draw (default 1)");
  c->add_option("--samples", args->samples, "Samples per recording (default 20000)")
      ->check(CLI::Range(2000, 10000000));
  c->add_option("--jobs", args->jobs, "Worker threads (default 1)")->check(CLI::Range(1, 256));
  c->add_option("--json", args->json, "Write the summary and every case as JSON ('-' for stdout)");
  c->add_option("--only", args->only, "Run only these case indices (0-based, as printed)");
  c->add_option("--save", args->save,
                "Also write the recordings of the cases run into this folder");
  c->add_flag("--physics", args->physics,
              "Score the diagnosis on recordings of a magnet, Hall plates or an in-plane sensor "
              "and an ADC chain (physics scenarios) instead of the effect library");
  c->add_flag("--check", args->check,
              "Exit 1 when a target is missed (the targets of docs/diagnosis.md; with --physics "
              "top-1 and shrink)");
  c->add_flag("--quiet", args->quiet, "No per-recording progress on stderr");
  c->callback([args] { run_bench(*args); });
}

}  // namespace acore::cli
