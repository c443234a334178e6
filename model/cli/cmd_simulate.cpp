// SPDX-License-Identifier: MIT
// `anglecore simulate`: a sensor recording from a built-in scenario or a scenario JSON file
// (model/lab/sim/simulator.hpp, docs/contracts.md, command line), with a summary of the uncorrected
// angle error.
#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli_util.hpp"
#include "commands.hpp"
#include "core/angle.hpp"
#include "core/error_stats.hpp"
#include "core/errors.hpp"
#include "sim/effect_table.hpp"
#include "sim/simulator.hpp"

namespace acore::cli {

namespace {

struct SimulateArgs {
  std::string scenario, config, out, json, dump_config;
  size_t samples = 4096;
  uint64_t seed = 1;
  int channels = 0;  // 0: the scenario's own
  bool list = false, list_effects = false;
  // A speed profile replacing the scenario's trajectory (--profile; empty: the scenario's own).
  std::string profile;
  double speed_rpm = 0, speed_end_rpm = 0, sample_rate = 0, ripple = 0, ripple_hz = 0, step_at = 0,
         sweep_turns = 1;
  double turns = 0, speed_ripple = 0, speed_drift = 0;  // 0: the scenario's own trajectory
};

// The scenario's trajectory replaced by the speed profile of the command line (mechanical rpm).
Trajectory profile_trajectory(const SimulateArgs& a, const Trajectory& base) {
  Trajectory tr;
  tr.kind = a.profile;
  tr.theta0_rad = base.theta0_rad;
  tr.sample_rate_hz = a.sample_rate > 0 ? a.sample_rate : base.sample_rate_hz;
  tr.speed_rps = a.speed_rpm / 60;
  tr.speed_end_rps = a.speed_end_rpm / 60;
  tr.sweep_turns = a.sweep_turns;
  tr.step_at_s = a.step_at;
  tr.ripple = a.ripple;
  tr.ripple_hz = a.ripple_hz;
  const auto bad = [&](const std::string& what) {
    throw InputError("simulate --profile " + a.profile + ": " + what);
  };
  if (a.profile == "constant" || a.profile == "ramp" || a.profile == "step") {
    if (a.speed_rpm == 0 && a.speed_end_rpm == 0) bad("give --speed-rpm (and --speed-end-rpm)");
  } else if (a.profile == "reversal") {
    if (!(a.speed_rpm > 0)) bad("--speed-rpm must be > 0");
    if (!(a.sweep_turns > 0)) bad("--sweep-turns must be > 0");
  } else if (a.profile == "ripple") {
    if (a.speed_rpm == 0) bad("give --speed-rpm");
    if (!(a.ripple >= 0 && a.ripple < 1)) bad("--ripple must be in [0, 1) (0.02 = 2 %)");
    if (!(a.ripple_hz > 0)) bad("--ripple-hz must be > 0");
  } else {
    throw InputError("simulate: --profile '" + a.profile +
                     "' is not one of constant, ramp, step, reversal, ripple");
  }
  return tr;
}

// Uncorrected electrical angle error (deg): atan2 of the differential pair, each centred on its
// mean and scaled by its RMS amplitude, minus p * theta_ref, wrapped to (-180, 180].
std::vector<double> uncorrected_error_deg(const Recording& r, int p) {
  const size_t n = r.size();
  double m13 = 0, m24 = 0;
  for (size_t i = 0; i < n; ++i) {
    m13 += r.d13(i);
    m24 += r.d24(i);
  }
  m13 /= static_cast<double>(n);
  m24 /= static_cast<double>(n);
  double v13 = 0, v24 = 0;
  for (size_t i = 0; i < n; ++i) {
    v13 += (r.d13(i) - m13) * (r.d13(i) - m13);
    v24 += (r.d24(i) - m24) * (r.d24(i) - m24);
  }
  const double a13 = std::sqrt(2 * v13 / static_cast<double>(n)),
               a24 = std::sqrt(2 * v24 / static_cast<double>(n));
  std::vector<double> e(n);
  for (size_t i = 0; i < n; ++i) {
    const double est =
        std::atan2((r.d13(i) - m13) / (a13 > 0 ? a13 : 1), (r.d24(i) - m24) / (a24 > 0 ? a24 : 1));
    double d = std::remainder(est - p * r.theta_ref[i], 2 * kPi);
    if (d <= -kPi) d += 2 * kPi;
    e[i] = d * 180.0 / kPi;
  }
  return e;
}

// The effect table (model/lab/sim/effect_table.hpp): what a scenario's "effects" may hold, with
// every parameter's no-op default; --json adds what the diagnosis does with each (docs/diagnosis.md
// "Effect vocabulary" is generated from it by scripts/effect_vocabulary.py).
void list_effects(const SimulateArgs& a) {
  std::ostream& out = a.json == "-" ? std::cerr : std::cout;
  nlohmann::json effects = nlohmann::json::array();
  for (const EffectSpec& e : effect_table()) {
    const bool field = e.domain == EffectDomain::field;
    out << fmt::format("{:<14} {}-domain: {}\n", e.name, field ? "field" : "signal", e.meaning);
    nlohmann::json params = nlohmann::json::array();
    for (const EffectParamSpec& p : e.params) {
      const std::string name = p.per_channel ? p.name + "X" : p.name;
      out << fmt::format("  {:<15} {:<6} {:<18} {}\n", name, fmt::format("{:g}", p.no_op),
                         p.unit.empty() ? "-" : p.unit, p.what);
      params.push_back({{"name", name},
                        {"default", p.no_op},
                        {"unit", p.unit},
                        {"per_channel", p.per_channel},
                        {"what", p.what}});
    }
    effects.push_back({{"name", e.name},
                       {"domain", field ? "field" : "signal"},
                       {"meaning", e.meaning},
                       {"widened", e.widened},
                       {"status", e.status},
                       {"fit", effect_fit_text(e.fit)},
                       {"fit_note", e.fit_note},
                       {"params", params}});
  }
  out << "X: a channel, c1..c4 (four channels) or sin, cos (two)\n";
  if (!a.json.empty()) write_json(a.json, {{"effects", effects}});
}

void run_simulate(const SimulateArgs& a) {
  if (a.list_effects) {
    list_effects(a);
    return;
  }
  if (a.list) {
    nlohmann::json names = nlohmann::json::array();
    for (const auto& n : builtin_scenario_names()) {
      const Scenario s = builtin_scenario(n);
      std::cout << fmt::format("{:<16} {}\n", n, s.description);
      names.push_back({{"name", n}, {"description", s.description}, {"channels", s.channels}});
    }
    if (!a.json.empty()) write_json(a.json, {{"scenarios", names}});
    return;
  }
  if (a.scenario.empty() == a.config.empty())
    throw InputError(
        "simulate: give exactly one of --scenario NAME or --config FILE (--list shows the names)");
  if (a.out.empty() && a.dump_config.empty())
    throw InputError("simulate: --out FILE.csv is required");
  Scenario s = a.config.empty() ? builtin_scenario(a.scenario) : load_scenario(a.config);
  if (a.channels != 0) s = with_channels(s, a.channels);
  if (!a.profile.empty()) s.trajectory = profile_trajectory(a, s.trajectory);
  if (a.turns > 0) {
    s.trajectory.kind = "constant";
    s.trajectory.turns = a.turns;
    s.trajectory.speed_rps = 0;
  }
  if (a.speed_ripple > 0 || a.speed_drift > 0) {
    if (s.trajectory.kind != "turn" && s.trajectory.kind != "constant")
      throw InputError(
          "simulate: --speed-ripple/--speed-drift need a 'turn' or 'constant' "
          "trajectory, the scenario's is '" +
          s.trajectory.kind + "'");
    if (a.speed_ripple + a.speed_drift >= 100)
      throw InputError("simulate: --speed-ripple + --speed-drift must stay below 100 %");
    s.trajectory.speed.ripple_pct = a.speed_ripple;
    s.trajectory.speed.drift_pct = a.speed_drift;
    s.trajectory.speed.seed = a.seed;
  }
  if (!a.dump_config.empty()) write_json(a.dump_config, s.to_json());
  if (a.out.empty()) return;

  Recording rec = simulate(s, a.samples, a.seed);
  if (!a.config.empty()) rec.meta["config"] = a.config;
  rec.comments.push_back(
      fmt::format("anglecore simulate: {}", s.description.empty() ? s.name : s.description));
  const bool to_stdout = a.out == "-";
  if (to_stdout)
    std::cout << format_recording(rec);
  else
    write_recording(rec, a.out);

  const ErrorStats st = error_stats(uncorrected_error_deg(rec, s.p));
  std::ostream& log = to_stdout || a.json == "-" ? std::cerr : std::cout;
  log << fmt::format("simulated '{}': {} samples, {} channels, p = {}, seed {} -> {}\n", s.name,
                     rec.size(), rec.channels, s.p, a.seed, to_stdout ? "stdout" : a.out);
  log << fmt::format(
      "uncorrected electrical angle error: RMS {:.4f} deg, max |e| {:.4f} deg, mean {:.4f} deg\n",
      st.rms, st.max_abs, st.mean);
  if (!a.json.empty()) {
    nlohmann::json j = {{"scenario", s.name},
                        {"samples", rec.size()},
                        {"seed", a.seed},
                        {"channels", rec.channels},
                        {"p", s.p},
                        {"out", a.out},
                        {"uncorrected_error_deg", stats_json(st)},
                        {"config", s.to_json()}};
    write_json(a.json, j);
  }
}

}  // namespace

void add_simulate(CLI::App& app) {
  auto args = std::make_shared<SimulateArgs>();
  CLI::App* c = app.add_subcommand(
      "simulate",
      "Simulate a sensor recording (docs/contracts.md, recording file CSV) from a scenario");
  auto* sc = c->add_option("--scenario", args->scenario, "Built-in scenario (see --list)");
  auto* cf = c->add_option("--config", args->config,
                           "Scenario JSON file (model/lab/sim/simulator.hpp documents the fields)");
  sc->excludes(cf);
  c->add_option("--samples", args->samples, "Number of samples (default 4096)")
      ->check(CLI::Range(1, 100000000));
  c->add_option("--seed", args->seed, "Noise seed (std::mt19937_64, default 1)");
  c->add_option("--out", args->out, "Output recording CSV ('-' for stdout)");
  c->add_option("--channels", args->channels,
                "Override the channel count: 4 (c1..c4) or 2 (sin, cos)")
      ->check(CLI::IsMember({2, 4}));
  c->add_option("--turns", args->turns,
                "Turns at a constant nominal speed over the recording (a 'constant' trajectory; "
                "default: the scenario's, one turn)")
      ->check(CLI::PositiveNumber);
  c->add_option("--speed-ripple", args->speed_ripple,
                "Speed ripple, percent of the nominal speed (sinusoidal, 3.7 cycles per turn)")
      ->check(CLI::Range(0.0, 99.0));
  c->add_option("--speed-drift", args->speed_drift,
                "Random slow speed change, peak percent of the nominal speed (shape drawn from "
                "--seed)")
      ->check(CLI::Range(0.0, 99.0));
  c->add_flag("--list", args->list, "List the built-in scenarios and exit");
  c->add_flag("--list-effects", args->list_effects,
              "List the effects a scenario's \"effects\" may hold, with their parameters and "
              "no-op defaults, and exit");
  c->add_option("--json", args->json, "Write a summary as JSON ('-' for stdout)");
  c->add_option("--dump-config", args->dump_config,
                "Write the scenario as JSON (a starting point for --config)");
  c->add_option("--profile", args->profile,
                "Speed profile replacing the scenario's trajectory: constant, ramp (--speed-rpm to "
                "--speed-end-rpm), step (--speed-rpm, then --speed-end-rpm at --step-at), "
                "reversal (--speed-rpm, --sweep-turns), ripple (--speed-rpm, --ripple, "
                "--ripple-hz)");
  c->add_option("--speed-rpm", args->speed_rpm, "--profile: (start) speed, mechanical rpm");
  c->add_option("--speed-end-rpm", args->speed_end_rpm, "--profile ramp, step: end speed, rpm");
  c->add_option("--step-at", args->step_at, "--profile step: time of the step, s (0: T / 2)");
  c->add_option("--sweep-turns", args->sweep_turns,
                "--profile reversal: turns forward before turning back (default 1)");
  c->add_option("--ripple", args->ripple,
                "--profile ripple: relative speed ripple amplitude (0.02 = 2 %)");
  c->add_option("--ripple-hz", args->ripple_hz, "--profile ripple: ripple frequency, Hz");
  c->add_option("--sample-rate", args->sample_rate,
                "--profile: samples per second (default: the scenario's; 0 = N per second)")
      ->check(CLI::NonNegativeNumber);
  c->callback([args] { run_simulate(*args); });
}

}  // namespace acore::cli
