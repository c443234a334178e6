// SPDX-License-Identifier: MIT
// The cost of the physics scenarios (model/lab/physics/physics_*.hpp): one field evaluation of the
// magnet, and the three recordings (sim, real, holdout) of a physics benchmark case at the default
// 20,000 samples each, beside what the diagnosis of that case costs (bench_diagnose):
//   build/tests/bench/bench_physics
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "diagnose/physics_bench.hpp"

namespace {

void BM_MagnetField(benchmark::State& state) {
  const acore::DiametricCylinder m(3e-3, 2.5e-3, 1.25, static_cast<int>(state.range(0)));
  Eigen::Vector3d p(1.1e-3, 0.2e-3, -3e-3), sum(0, 0, 0);
  for (auto _ : state) {
    sum += m.field(p);
    p.x() += 1e-9;
  }
  benchmark::DoNotOptimize(sum);
  state.SetLabel(fmt::format("{} quadrature angles", state.range(0)));
}
BENCHMARK(BM_MagnetField)->Arg(32)->Arg(96);

void recordings(benchmark::State& state, const std::string& label) {
  const auto& all = acore::physics_scenarios();
  const auto it = std::find_if(all.begin(), all.end(),
                               [&](const acore::PhysicsScenario& s) { return s.label() == label; });
  const acore::PhysicsCase c = acore::draw_physics_case(1, 0, *it);
  for (auto _ : state) {
    const acore::BenchRecordings r = acore::make_physics_recordings(c, 20000);
    benchmark::DoNotOptimize(r.real.ch[0].back());
  }
  state.SetLabel(label + ": sim + real + holdout, 20,000 samples each");
}
void BM_PhysicsRecordings_Hall4(benchmark::State& state) { recordings(state, "runout/hall4"); }
void BM_PhysicsRecordings_Tmr2(benchmark::State& state) { recordings(state, "runout/tmr2"); }
BENCHMARK(BM_PhysicsRecordings_Hall4)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PhysicsRecordings_Tmr2)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
