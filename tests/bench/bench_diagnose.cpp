// SPDX-License-Identifier: MIT
// The gap diagnosis of a 50,000-sample recording with a 50,000-sample holdout (target: < 10 s on
// one core), on recordings of the blind self-benchmark (model/lab/diagnose/diagnose_bench.hpp):
//   build/tests/bench/bench_diagnose
// BM_Diagnose/<case>: one effect the diagnosis names (a single fit), one outside the vocabulary
// (every effect fitted, then every other tried on top of the best), and shaft run-out (zero offset,
// eccentricity and amplitude: a combination of three found by forward selection and refitted
// together, the slowest named path).
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "diagnose/diagnose.hpp"
#include "diagnose/diagnose_bench.hpp"
#include "sim/simulator.hpp"

namespace {

constexpr size_t kSamples = 50000;

void run(benchmark::State& state, const std::string& truth, int channels,
         const std::string& outside) {
  const acore::BenchCase c = acore::draw_bench_case(1, 0, truth, channels, outside);
  const acore::BenchRecordings r = acore::make_bench_recordings(c, kSamples);
  std::string verdict;
  for (auto _ : state) {
    const acore::Diagnosis d = acore::diagnose(r.sim, r.real, &r.holdout);
    verdict = d.verdict == "explained" ? d.ranking.front().cand.effect : d.verdict;
    benchmark::DoNotOptimize(d.after.gap_deg);
  }
  state.SetLabel(
      fmt::format("{} ch, truth {} -> {}", channels, outside.empty() ? truth : outside, verdict));
  state.counters["samples"] = static_cast<double>(kSamples);
}

// Run-out on the self-benchmark's first four-channel sensor model: three effects at once.
void BM_Diagnose_RunOut4(benchmark::State& state) {
  acore::BenchCase c = acore::draw_bench_case(1, 0, "none", 4);
  const double fs = static_cast<double>(kSamples) / 2.0;
  acore::Scenario s = c.model;
  s.trajectory.sample_rate_hz = fs;
  const acore::Recording sim = acore::simulate(s, kSamples, 1);
  acore::Scenario r = c.model;
  r.temperature = {true, c.real_temp[0], c.real_temp[1]};
  r.effects = {
      acore::make_effect("zero_offset", {{"zero_rad", 0.02}}, 4),
      acore::make_effect(
          "eccentricity",
          {{"epsilon_rad", 0.015}, {"phi0_rad", 0.5}, {"am_depth", 0.012}, {"am_phase_rad", 0.9}},
          4),
      acore::make_effect("amplitude", {{"scale", 0.8}}, 4)};
  r.trajectory = c.real_traj;
  r.trajectory.sample_rate_hz = fs;
  const acore::Recording real = acore::simulate(r, kSamples, 2);
  r.trajectory = c.hold_traj;
  r.trajectory.sample_rate_hz = fs;
  const acore::Recording hold = acore::simulate(r, kSamples, 3);
  std::string named;
  for (auto _ : state) {
    const acore::Diagnosis d = acore::diagnose(sim, real, &hold);
    named.clear();
    for (const auto& n : d.named()) named += (named.empty() ? "" : " + ") + n;
    benchmark::DoNotOptimize(d.after.gap_deg);
  }
  state.SetLabel(fmt::format("4 ch, run-out -> {}", named.empty() ? "(none named)" : named));
  state.counters["samples"] = static_cast<double>(kSamples);
}

void BM_Diagnose_Drift4(benchmark::State& state) { run(state, "drift", 4, ""); }
void BM_Diagnose_Delay2(benchmark::State& state) { run(state, "common_delay", 2, ""); }
void BM_Diagnose_Glitch4(benchmark::State& state) { run(state, "outside", 4, "glitch"); }
BENCHMARK(BM_Diagnose_Drift4)->Unit(benchmark::kSecond)->Iterations(2);
BENCHMARK(BM_Diagnose_Delay2)->Unit(benchmark::kSecond)->Iterations(2);
BENCHMARK(BM_Diagnose_Glitch4)->Unit(benchmark::kSecond)->Iterations(2);
BENCHMARK(BM_Diagnose_RunOut4)->Unit(benchmark::kSecond)->Iterations(2);

}  // namespace

BENCHMARK_MAIN();
