// SPDX-License-Identifier: MIT
// The bit-accurate chain against std::atan2 over the same 1 M samples, in one run:
//   build/tests/bench/bench_estimator
// After the table, one line gives each chain's samples per second as a multiple of std::atan2's,
// all measured in this run (the median of the repetitions when --benchmark_repetitions is given).
// BM_EstimateFixedBatch is the Python package's estimate path (scripts/bench_python.py).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "calibration/calibration.hpp"
#include "engine/estimator.hpp"
#include "engine/fixed_model.hpp"
#include "support/paper_signals.hpp"

namespace {

constexpr size_t kSamples = 1 << 20;

struct Fixture {
  acore::Recording rec = acore::test::paper_recording(kSamples);
  acore::RegImage img = acore::quantize(acore::calibrate(rec, acore::CalOptions{}),
                                        acore::DatapathConfig{}, acore::choose_in_scale(rec, 16));
  std::vector<acore::ChannelCodes> codes = acore::to_codes(rec, img.in_scale, 16);
};

const Fixture& fixture() {
  static const Fixture f;  // built once, outside the timed loops
  return f;
}

void BM_Atan2(benchmark::State& state) {
  const auto& f = fixture();
  std::vector<double> s(kSamples), c(kSamples);
  for (size_t i = 0; i < kSamples; ++i) {
    s[i] = f.rec.d13(i);
    c[i] = f.rec.d24(i);
  }
  for (auto _ : state) {
    double acc = 0;
    for (size_t i = 0; i < kSamples; ++i) acc += std::atan2(s[i], c[i]);
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kSamples));
}
BENCHMARK(BM_Atan2)->Unit(benchmark::kMillisecond);

void BM_FixedChain(benchmark::State& state) {
  const auto& f = fixture();
  const acore::FixedModel model(f.img);
  std::vector<acore::FixedOutput> out(kSamples);
  for (auto _ : state) {
    model.run_batch(f.codes.data(), f.codes.size(), out.data());
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kSamples));
}
BENCHMARK(BM_FixedChain)->Unit(benchmark::kMillisecond);

// What the Python package's estimate(engine="fixed", uncorrected=False) runs on numpy arrays, in
// C++: fresh output arrays, recording values to codes, the batch chain, angles in rad, the error
// against theta_ref and its statistics (scripts/bench_python.py compares the two in one run).
void BM_EstimateFixedBatch(benchmark::State& state) {
  const auto& f = fixture();
  acore::ChannelColumns in;
  in.channels = f.rec.channels;
  for (int c = 0; c < f.rec.channels; ++c) in.ch[c] = f.rec.ch[c].data();
  in.theta_ref = f.rec.theta_ref.data();
  in.n = kSamples;
  for (auto _ : state) {
    std::vector<double> angle(kSamples), err(kSamples);
    std::vector<uint8_t> flags(kSamples), region(kSamples);
    acore::run_fixed_batch(f.img, in, 1, {angle.data(), flags.data(), region.data(), err.data()});
    benchmark::DoNotOptimize(acore::error_stats(err).rms);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kSamples));
}
BENCHMARK(BM_EstimateFixedBatch)->Unit(benchmark::kMillisecond);

void BM_FixedChainPerSample(benchmark::State& state) {
  const auto& f = fixture();
  const acore::FixedModel model(f.img);
  for (auto _ : state) {
    uint64_t acc = 0;
    for (const auto& c : f.codes) acc += model.step(c).angle;
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kSamples));
}
BENCHMARK(BM_FixedChainPerSample)->Unit(benchmark::kMillisecond);

void BM_FloatChain(benchmark::State& state) {
  const auto& f = fixture();
  const acore::FloatCoefficients fc = acore::dequantize(f.img);
  for (auto _ : state) {
    auto s = acore::run_float(f.rec, fc);
    benchmark::DoNotOptimize(s.angle.data());
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kSamples));
}
BENCHMARK(BM_FloatChain)->Unit(benchmark::kMillisecond);

// The console table, and each benchmark's items per second kept for the ratio line.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  RatioReporter() : ConsoleReporter(isatty(fileno(stdout)) ? OO_Color : OO_None) {}
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      if (r.error_occurred) continue;
      const auto it = r.counters.find("items_per_second");
      if (it == r.counters.end()) continue;
      if (r.run_type == Run::RT_Aggregate && r.aggregate_name != "median") continue;
      rate_[r.run_name.function_name] = it->second.value;  // the median replaces single runs
    }
  }
  // "batch 1.63x, per sample 0.05x, float 0.15x std::atan2 (same run)"
  void print_ratios() const {
    const auto atan2 = rate_.find("BM_Atan2");
    if (atan2 == rate_.end() || atan2->second <= 0) return;
    std::string line;
    for (const auto& [name, label] : {std::pair<const char*, const char*>{"BM_FixedChain", "batch"},
                                      {"BM_FixedChainPerSample", "per sample"},
                                      {"BM_FloatChain", "float"}}) {
      const auto it = rate_.find(name);
      if (it == rate_.end()) continue;
      char b[64];
      std::snprintf(b, sizeof b, "%s%s %.2fx", line.empty() ? "" : ", ", label,
                    it->second / atan2->second);
      line += b;
    }
    std::printf("samples/s as a multiple of std::atan2's (%.1f M/s), this run: %s\n",
                atan2->second / 1e6, line.c_str());
  }

 private:
  std::map<std::string, double> rate_;
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_ratios();
  benchmark::Shutdown();
  return 0;
}
