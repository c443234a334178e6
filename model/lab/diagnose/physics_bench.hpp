// SPDX-License-Identifier: MIT
// The physics benchmark of the gap diagnosis (`anglecore diagnose-bench --physics`,
// docs/diagnosis.md "Physics benchmark"): recordings made by a magnet, sensing elements and an ADC
// chain (physics_rig.hpp), not by the transforms the diagnosis fits (effects.hpp).
//
// Each case is a rig of one sensor kind, hall4 (four Hall plates on a ring, c1..c4) or tmr2 (an
// in-plane sin/cos pair at the axis), with drawn nominal geometry (air gap, ring radius) and noise:
//   sim      the nominal rig at a constant speed, 25 degC, no temperature column
//   real     the rig with ONE physical perturbation (the scenario), a speed ramp through a
//            reversal, a temperature ramp (the magnet's remanence follows it), another noise seed
//   holdout  the same perturbation, another ramp, temperature ramp and seed
// The truth of a scenario is decided by the physics (physics_truth(); docs/diagnosis.md, the
// scenario table): what reaches the two differential pairs the estimator sees, named in the
// vocabulary of docs/contracts.md, effect vocabulary.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "diagnose/diagnose_bench.hpp"
#include "physics/physics_rig.hpp"

namespace acore {

// One scenario of the physics benchmark and the sensor kind it runs on.
struct PhysicsScenario {
  std::string name;    // e.g. "runout"
  std::string sensor;  // "hall4" or "tmr2"
  std::string truth;   // the vocabulary name the physics gives (or no_gap)
  std::string why;     // one line: what reaches the pairs
  std::string label() const { return name + "/" + sensor; }
};

// Every (scenario, sensor) of the benchmark, in report order.
const std::vector<PhysicsScenario>& physics_scenarios();

struct PhysicsCase {
  size_t index = 0;
  PhysicsScenario scenario;
  PhysicsRig sim_rig, real_rig;  // nominal; perturbed (real and holdout)
  Trajectory sim_traj, real_traj, hold_traj;
  double real_temp[2] = {25, 25}, hold_temp[2] = {25, 25};  // start, end degC
  ParamList params;   // the drawn perturbation, physical units (m, deg, T, s, bits)
  uint64_t seed = 0;  // noise seeds derive from it
};

// The case `index` of a run with `seed` (drawn from (seed, index) alone).
PhysicsCase draw_physics_case(uint64_t seed, size_t index, const PhysicsScenario& s);
// per_effect cases of every scenario, in physics_scenarios() order.
std::vector<PhysicsCase> draw_physics_cases(const BenchOptions& opt);
// sim, real and holdout of a case, `samples` each.
BenchRecordings make_physics_recordings(const PhysicsCase& c, size_t samples);
// Diagnoses one case blind and judges it against its truth.
BenchCaseResult run_physics_case(const PhysicsCase& c, size_t samples);
// Draws, diagnoses (on opt.jobs threads) and summarizes; rows are the scenario labels.
BenchSummary run_physics_bench(const BenchOptions& opt,
                               const BenchTargets& targets = BenchTargets{});

}  // namespace acore
