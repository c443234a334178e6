// SPDX-License-Identifier: MIT
// Verilated RTL throughput (samples per wall second, one core, tracing off): the RTL engine alone
// (run_rtl: register load + stream), the RTL at random stalls, and RTL + bit-accurate model compare
// (what `anglecore cosim` does); the same for the serial core (226 clocks a sample, on the first
// 20000 samples); the engine at FOLD=2 as well. Run:
//   build/tb/bench_rtl_cosim --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include "calibration/calibration.hpp"
#include "engine/estimator.hpp"
#include "engine/fixed_model.hpp"
#include "rtlsim/rtl_engine.hpp"
#include "support/paper_signals.hpp"

namespace {

struct Setup {
  acore::RegImage img;
  std::vector<acore::ChannelCodes> in;
  Setup() {
    const acore::Recording cal = acore::test::paper_recording(4000, true);
    img = acore::quantize(acore::calibrate(cal, acore::CalOptions{}), acore::DatapathConfig{},
                          acore::choose_in_scale(cal, 16));
    in = acore::to_codes(acore::test::paper_recording(200000, true), img.in_scale, 16);
  }
};

const Setup& setup() {
  static const Setup s;
  return s;
}

// Args: stall percent (input gaps and output backpressure), FOLD of the pipelined top.
void BM_RtlEngine(benchmark::State& state) {
  const Setup& s = setup();
  acore::RtlRunOptions opt;
  opt.backpressure = opt.gaps = static_cast<double>(state.range(0)) / 100.0;
  opt.fold = static_cast<int>(state.range(1));
  for (auto _ : state) benchmark::DoNotOptimize(acore::run_rtl(s.img, s.in, opt));
  state.counters["samples/s"] = benchmark::Counter(
      static_cast<double>(s.in.size()) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RtlEngine)
    ->Args({0, 1})
    ->Args({30, 1})
    ->Args({0, 2})
    ->ArgNames({"stall%", "fold"})
    ->Unit(benchmark::kMillisecond);

void BM_CosimCompare(benchmark::State& state) {
  const Setup& s = setup();
  const acore::FixedModel model(s.img);
  size_t bad = 0;
  for (auto _ : state) {
    const auto rtl = acore::run_rtl(s.img, s.in, acore::RtlRunOptions{});
    for (size_t i = 0; i < s.in.size(); ++i) bad += !(rtl[i] == model.step(s.in[i]));
  }
  if (bad) state.SkipWithError("RTL and model differ");
  state.counters["samples/s"] = benchmark::Counter(
      static_cast<double>(s.in.size()) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_CosimCompare)->Unit(benchmark::kMillisecond);

acore::RtlRunOptions serial_options() {
  acore::RtlRunOptions opt;
  opt.top = acore::RtlTop::kSerial;
  return opt;
}

std::vector<acore::ChannelCodes> serial_inputs() {
  return {setup().in.begin(), setup().in.begin() + 20000};
}

void BM_RtlSerialEngine(benchmark::State& state) {
  const Setup& s = setup();
  const auto in = serial_inputs();
  for (auto _ : state) benchmark::DoNotOptimize(acore::run_rtl(s.img, in, serial_options()));
  state.counters["samples/s"] = benchmark::Counter(
      static_cast<double>(in.size()) * state.iterations(), benchmark::Counter::kIsRate);
  const int cycles = acore::rtl_build_for(acore::RtlTop::kSerial, s.img.cfg).plugin().cycles;
  state.counters["clocks/s"] = benchmark::Counter(
      static_cast<double>(in.size()) * cycles * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RtlSerialEngine)->Unit(benchmark::kMillisecond);

void BM_SerialCosimCompare(benchmark::State& state) {
  const Setup& s = setup();
  const auto in = serial_inputs();
  const acore::FixedModel model(s.img);
  size_t bad = 0;
  for (auto _ : state) {
    const auto rtl = acore::run_rtl(s.img, in, serial_options());
    for (size_t i = 0; i < in.size(); ++i) bad += !(rtl[i] == model.step(in[i]));
  }
  if (bad) state.SkipWithError("serial RTL and model differ");
  state.counters["samples/s"] = benchmark::Counter(
      static_cast<double>(in.size()) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SerialCosimCompare)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
