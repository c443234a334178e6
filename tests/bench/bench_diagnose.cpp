// SPDX-License-Identifier: MIT
// The gap diagnosis of a 50,000-sample recording with a 50,000-sample holdout (issue 5: < 10 s on
// one core), on recordings of the blind self-benchmark (model/diagnose_bench.hpp):
//   build/tests/bench/bench_diagnose
// BM_Diagnose/<case>: one effect the diagnosis names (a single fit), and one outside the vocabulary
// (every effect fitted, then every pair tried on top of the best: the slowest path).
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "diagnose.hpp"
#include "diagnose_bench.hpp"

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

void BM_Diagnose_Drift4(benchmark::State& state) { run(state, "drift", 4, ""); }
void BM_Diagnose_Delay2(benchmark::State& state) { run(state, "common_delay", 2, ""); }
void BM_Diagnose_Glitch4(benchmark::State& state) { run(state, "outside", 4, "glitch"); }
BENCHMARK(BM_Diagnose_Drift4)->Unit(benchmark::kSecond)->Iterations(2);
BENCHMARK(BM_Diagnose_Delay2)->Unit(benchmark::kSecond)->Iterations(2);
BENCHMARK(BM_Diagnose_Glitch4)->Unit(benchmark::kSecond)->Iterations(2);

}  // namespace

BENCHMARK_MAIN();
