// SPDX-License-Identifier: MIT
#include "sim/simulator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "core/angle.hpp"
#include "core/errors.hpp"
#include "core/json_input.hpp"
#include "sim/effect_table.hpp"

namespace acore {

namespace {

// The trajectory kinds (simulator.hpp, Trajectory), for the messages and the JSON check.
constexpr const char* kTrajectoryKinds = "turn, constant, ramp, reversal, step, ripple";
bool is_trajectory_kind(const std::string& k) {
  return k == "turn" || k == "constant" || k == "ramp" || k == "reversal" || k == "step" ||
         k == "ripple";
}
using nlohmann::json;

// ---- JSON reading with field names in every error ----

[[noreturn]] void field_error(const std::string& where, const std::string& field,
                              const std::string& what) {
  throw InputError(fmt::format("{}: field '{}': {}", where, field, what));
}

std::string type_name(const json& v) { return v.type_name(); }

void check_keys(const json& j, const std::vector<std::string>& allowed, const std::string& where,
                const std::string& prefix) {
  if (!j.is_object())
    field_error(where, prefix.empty() ? "(top level)" : prefix,
                "expected an object, got " + type_name(j));
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (std::find(allowed.begin(), allowed.end(), it.key()) == allowed.end()) {
      std::string list;
      for (size_t k = 0; k < allowed.size(); ++k) list += (k ? ", " : "") + allowed[k];
      field_error(where, prefix + it.key(), "unknown field (valid: " + list + ")");
    }
  }
}

double get_number(const json& j, const std::string& key, double dflt, const std::string& where,
                  const std::string& field) {
  if (!j.contains(key)) return dflt;
  const json& v = j.at(key);
  if (!v.is_number()) field_error(where, field, "expected a number, got " + type_name(v));
  const double d = v.get<double>();
  if (!std::isfinite(d)) field_error(where, field, "not finite");
  return d;
}

int get_int(const json& j, const std::string& key, int dflt, const std::string& where,
            const std::string& field) {
  const double d = get_number(j, key, dflt, where, field);
  if (d != std::floor(d) || std::fabs(d) > 1e9) field_error(where, field, "expected an integer");
  return static_cast<int>(d);
}

std::string get_string(const json& j, const std::string& key, const std::string& dflt,
                       const std::string& where, const std::string& field) {
  if (!j.contains(key)) return dflt;
  const json& v = j.at(key);
  if (!v.is_string()) field_error(where, field, "expected a string, got " + type_name(v));
  return v.get<std::string>();
}

std::vector<double> get_numbers(const json& j, const std::string& key, const std::string& where,
                                const std::string& field) {
  std::vector<double> out;
  if (!j.contains(key)) return out;
  const json& v = j.at(key);
  if (!v.is_array()) field_error(where, field, "expected an array of numbers, got " + type_name(v));
  for (size_t k = 0; k < v.size(); ++k) {
    if (!v[k].is_number()) field_error(where, fmt::format("{}[{}]", field, k), "expected a number");
    out.push_back(v[k].get<double>());
    if (!std::isfinite(out.back()))
      field_error(where, fmt::format("{}[{}]", field, k), "not finite");
  }
  return out;
}

// The paper's Table 2 (docs/contracts.md, paper scenario): AF = cosine, BF = sine coefficients,
// orders 1..5.
Scenario paper_base() {
  static const double AF[4][5] = {{.11, .20, .13, 0, .03},
                                  {.10, .19, .07, .09, .03},
                                  {.50, .10, .17, .04, 0},
                                  {.13, 0, .10, .01, .01}};
  static const double BF[4][5] = {{.10, .11, .13, .06, .03},
                                  {.10, .19, .13, .04, .04},
                                  {.13, .17, 0, .07, .01},
                                  {0, .13, .10, .03, .01}};
  Scenario s;
  for (size_t c = 0; c < 4; ++c) {
    s.sensor[c].af.assign(AF[c], AF[c] + 5);
    s.sensor[c].bf.assign(BF[c], BF[c] + 5);
  }
  return s;
}

// Per-channel effect parameter `prefix + X` renamed for another channel count.
ParamList remap_params(const Effect& e, int from, int to) {
  ParamList given;
  for (const auto& [k, v] : e.params) {
    bool per_channel = false;
    for (int c = 0; c < from; ++c) {
      const std::string suffix = effect_channel_name(from, c);
      if (k.size() > suffix.size() + 1 &&
          k.compare(k.size() - suffix.size(), suffix.size(), suffix) == 0 &&
          k[k.size() - suffix.size() - 1] == '_') {
        per_channel = true;
        const std::string prefix = k.substr(0, k.size() - suffix.size());
        if (to == 2 && c < 2) given.push_back({prefix + effect_channel_name(2, c), v});
        if (to == 4) {
          given.push_back({prefix + effect_channel_name(4, c), v});
          given.push_back({prefix + effect_channel_name(4, c + 2), v});
        }
      }
    }
    if (!per_channel) given.push_back({k, v});
  }
  return given;
}

}  // namespace

// ---- Scenario ----

double Scenario::channel_value(int c, double phi) const {
  const ChannelModel& m = sensor[static_cast<size_t>(c)];
  double ideal = 0;
  switch (c) {
    case 0:
      ideal = std::sin(phi);
      break;
    case 1:
      ideal = std::cos(phi);
      break;
    case 2:
      ideal = -std::sin(phi);
      break;
    default:
      ideal = -std::cos(phi);
      break;
  }
  double v = m.amplitude * ideal + m.offset;
  for (size_t k = 0; k < m.af.size(); ++k)
    v += m.af[k] * std::cos(static_cast<double>(k + 1) * phi);
  for (size_t k = 0; k < m.bf.size(); ++k)
    v += m.bf[k] * std::sin(static_cast<double>(k + 1) * phi);
  return v;
}

nlohmann::json Scenario::to_json() const {
  json j;
  j["name"] = name;
  j["description"] = description;
  j["channels"] = channels;
  j["p"] = p;
  json sens = json::array();
  for (int c = 0; c < channels; ++c) {
    const ChannelModel& m = sensor[static_cast<size_t>(c)];
    sens.push_back({{"amplitude", m.amplitude}, {"offset", m.offset}, {"AF", m.af}, {"BF", m.bf}});
  }
  j["sensor"] = sens;
  j["sigma_common"] = sigma_common;
  j["sigma_indep"] = sigma_indep;
  j["trajectory"] = {{"kind", trajectory.kind},
                     {"sample_rate_hz", trajectory.sample_rate_hz},
                     {"theta0_rad", trajectory.theta0_rad},
                     {"turns", trajectory.turns},
                     {"speed_rps", trajectory.speed_rps},
                     {"speed_end_rps", trajectory.speed_end_rps},
                     {"sweep_turns", trajectory.sweep_turns},
                     {"cycles", trajectory.cycles},
                     {"speed_ripple_pct", trajectory.speed.ripple_pct},
                     {"speed_ripple_cycles", trajectory.speed.ripple_cycles},
                     {"speed_drift_pct", trajectory.speed.drift_pct},
                     {"speed_seed", trajectory.speed.seed}};
  // The step and ripple fields only with their kinds (older dumps stay as they were).
  if (trajectory.kind == "step") j["trajectory"]["step_at_s"] = trajectory.step_at_s;
  if (trajectory.kind == "ripple") {
    j["trajectory"]["ripple"] = trajectory.ripple;
    j["trajectory"]["ripple_hz"] = trajectory.ripple_hz;
  }
  j["temperature"] = {{"enabled", temperature.enabled},
                      {"start_C", temperature.start_C},
                      {"end_C", temperature.end_C}};
  json eff = json::array();
  for (const Effect& e : effects) {
    json o;
    o["effect"] = e.effect;
    for (const auto& [k, v] : e.params) o[k] = v;
    eff.push_back(o);
  }
  j["effects"] = eff;
  return j;
}

Scenario Scenario::from_json(const nlohmann::json& j, const std::string& where) {
  Scenario s;
  check_keys(j,
             {"name", "description", "channels", "p", "sensor", "sigma_common", "sigma_indep",
              "trajectory", "temperature", "effects"},
             where, "");
  s.name = get_string(j, "name", s.name, where, "name");
  s.description = get_string(j, "description", s.description, where, "description");
  s.channels = get_int(j, "channels", s.channels, where, "channels");
  if (s.channels != 2 && s.channels != 4) field_error(where, "channels", "must be 2 or 4");
  s.p = get_int(j, "p", s.p, where, "p");
  if (s.p < 1) field_error(where, "p", "must be an integer >= 1");
  if (j.contains("sensor")) {
    const json& a = j.at("sensor");
    if (!a.is_array() || (a.size() != static_cast<size_t>(s.channels) && a.size() != 4))
      field_error(where, "sensor",
                  fmt::format("expected an array of {} channel objects", s.channels));
    for (size_t c = 0; c < a.size(); ++c) {
      const std::string f = fmt::format("sensor[{}]", c);
      check_keys(a[c], {"amplitude", "offset", "AF", "BF"}, where, f + ".");
      ChannelModel& m = s.sensor[c];
      m.amplitude = get_number(a[c], "amplitude", 1.0, where, f + ".amplitude");
      m.offset = get_number(a[c], "offset", 0.0, where, f + ".offset");
      m.af = get_numbers(a[c], "AF", where, f + ".AF");
      m.bf = get_numbers(a[c], "BF", where, f + ".BF");
    }
  }
  s.sigma_common = get_number(j, "sigma_common", 0, where, "sigma_common");
  s.sigma_indep = get_number(j, "sigma_indep", 0, where, "sigma_indep");
  if (s.sigma_common < 0) field_error(where, "sigma_common", "must be >= 0");
  if (s.sigma_indep < 0) field_error(where, "sigma_indep", "must be >= 0");
  if (j.contains("trajectory")) {
    const json& t = j.at("trajectory");
    check_keys(t,
               {"kind", "sample_rate_hz", "theta0_rad", "turns", "speed_rps", "speed_end_rps",
                "sweep_turns", "cycles", "step_at_s", "ripple", "ripple_hz", "speed_ripple_pct",
                "speed_ripple_cycles", "speed_drift_pct", "speed_seed"},
               where, "trajectory.");
    Trajectory& tr = s.trajectory;
    tr.kind = get_string(t, "kind", tr.kind, where, "trajectory.kind");
    if (!is_trajectory_kind(tr.kind))
      field_error(where, "trajectory.kind", "'" + tr.kind + "' is not one of " + kTrajectoryKinds);
    tr.sample_rate_hz =
        get_number(t, "sample_rate_hz", tr.sample_rate_hz, where, "trajectory.sample_rate_hz");
    tr.theta0_rad = get_number(t, "theta0_rad", tr.theta0_rad, where, "trajectory.theta0_rad");
    tr.turns = get_number(t, "turns", tr.turns, where, "trajectory.turns");
    tr.speed_rps = get_number(t, "speed_rps", tr.speed_rps, where, "trajectory.speed_rps");
    tr.speed_end_rps =
        get_number(t, "speed_end_rps", tr.speed_end_rps, where, "trajectory.speed_end_rps");
    tr.sweep_turns = get_number(t, "sweep_turns", tr.sweep_turns, where, "trajectory.sweep_turns");
    tr.cycles = get_number(t, "cycles", tr.cycles, where, "trajectory.cycles");
    tr.step_at_s = get_number(t, "step_at_s", tr.step_at_s, where, "trajectory.step_at_s");
    tr.ripple = get_number(t, "ripple", tr.ripple, where, "trajectory.ripple");
    tr.ripple_hz = get_number(t, "ripple_hz", tr.ripple_hz, where, "trajectory.ripple_hz");
    if (tr.step_at_s < 0) field_error(where, "trajectory.step_at_s", "must be >= 0 (0: T / 2)");
    if (tr.kind == "ripple" && !(tr.ripple >= 0 && tr.ripple < 1))
      field_error(where, "trajectory.ripple", "must be in [0, 1)");
    if (tr.kind == "ripple" && !(tr.ripple_hz > 0))
      field_error(where, "trajectory.ripple_hz", "must be > 0");
    SpeedVariation& sv = tr.speed;
    sv.ripple_pct =
        get_number(t, "speed_ripple_pct", sv.ripple_pct, where, "trajectory.speed_ripple_pct");
    sv.ripple_cycles = get_number(t, "speed_ripple_cycles", sv.ripple_cycles, where,
                                  "trajectory.speed_ripple_cycles");
    sv.drift_pct =
        get_number(t, "speed_drift_pct", sv.drift_pct, where, "trajectory.speed_drift_pct");
    sv.seed = static_cast<uint64_t>(
        get_int(t, "speed_seed", static_cast<int>(sv.seed), where, "trajectory.speed_seed"));
    if (std::fabs(sv.ripple_pct) + std::fabs(sv.drift_pct) >= 100)
      field_error(where, "trajectory.speed_ripple_pct",
                  "ripple and slow change together must stay below 100 % (the shaft would stop)");
    if (tr.sample_rate_hz < 0)
      field_error(where, "trajectory.sample_rate_hz", "must be >= 0 (0: N per second)");
    if (tr.kind == "reversal" && tr.sweep_turns <= 0)
      field_error(where, "trajectory.sweep_turns", "must be > 0");
    if (tr.kind == "reversal" && tr.speed_rps == 0 && tr.cycles <= 0)
      field_error(where, "trajectory.cycles", "must be > 0");
    if (tr.kind == "reversal" && tr.speed_rps < 0)
      field_error(where, "trajectory.speed_rps", "must be >= 0");
  }
  if (j.contains("temperature")) {
    const json& t = j.at("temperature");
    check_keys(t, {"enabled", "start_C", "end_C"}, where, "temperature.");
    if (t.contains("enabled")) {
      if (!t.at("enabled").is_boolean())
        field_error(where, "temperature.enabled", "expected true or false");
      s.temperature.enabled = t.at("enabled").get<bool>();
    }
    s.temperature.start_C =
        get_number(t, "start_C", s.temperature.start_C, where, "temperature.start_C");
    s.temperature.end_C = get_number(t, "end_C", s.temperature.end_C, where, "temperature.end_C");
  }
  if (j.contains("effects")) {
    const json& a = j.at("effects");
    if (!a.is_array()) field_error(where, "effects", "expected an array of effect objects");
    for (size_t k = 0; k < a.size(); ++k) {
      const std::string f = fmt::format("effects[{}]", k);
      if (!a[k].is_object()) field_error(where, f, "expected an object");
      const std::string name = get_string(a[k], "effect", "", where, f + ".effect");
      if (name.empty()) field_error(where, f + ".effect", "missing (the effect's name)");
      ParamList given;
      for (auto it = a[k].begin(); it != a[k].end(); ++it) {
        if (it.key() == "effect") continue;
        given.push_back({it.key(), get_number(a[k], it.key(), 0, where, f + "." + it.key())});
      }
      try {
        s.effects.push_back(make_effect(name, given, s.channels));
      } catch (const InputError& e) {
        field_error(where, f, e.what());
      }
    }
  }
  return s;
}

// ---- Trajectory ----

TrajectoryModel::TrajectoryModel(const Trajectory& tr, size_t samples) : tr_(tr), n_(samples) {
  if (samples == 0) throw InputError("simulate: the number of samples must be >= 1");
  fs_ = tr.sample_rate_hz > 0 ? tr.sample_rate_hz : static_cast<double>(samples);
  duration_ = static_cast<double>(samples) / fs_;
  if (tr.kind == "turn") {
    v0_ = v1_ = 1.0 / duration_;
  } else if (tr.kind == "constant") {
    v0_ = v1_ = tr.speed_rps != 0 ? tr.speed_rps : tr.turns / duration_;
  } else if (tr.kind == "ramp") {
    v0_ = tr.speed_rps;
    v1_ = tr.speed_end_rps;
    if (v0_ == 0 && v1_ == 0) v1_ = 2.0 * tr.turns / duration_;
  } else if (tr.kind == "reversal") {
    v0_ = v1_ = tr.speed_rps > 0 ? tr.speed_rps : 2.0 * tr.sweep_turns * tr.cycles / duration_;
    if (!(v0_ > 0)) throw InputError("simulate: a reversal trajectory needs a speed > 0");
  } else if (tr.kind == "step") {
    v0_ = tr.speed_rps;
    v1_ = tr.speed_end_rps;
  } else if (tr.kind == "ripple") {
    v0_ = v1_ = tr.speed_rps != 0 ? tr.speed_rps : tr.turns / duration_;
    if (!(tr.ripple >= 0 && tr.ripple < 1 && tr.ripple_hz > 0))
      throw InputError("simulate: a ripple trajectory needs 0 <= ripple < 1 and ripple_hz > 0");
  } else {
    throw InputError("simulate: unknown trajectory kind '" + tr.kind +
                     "' (valid: " + kTrajectoryKinds + ")");
  }
}

double trajectory_theta(const Trajectory& tr, double v0, double v1, double duration, double t) {
  // Constant speed ("turn" off its grid, "constant"), rounded as it always was.
  if (tr.kind != "ramp" && tr.kind != "reversal" && tr.kind != "step" && tr.kind != "ripple")
    return tr.theta0_rad + 2 * kPi * v0 * t;
  double turns = 0;
  if (tr.kind == "ramp") {
    turns = v0 * t + (v1 - v0) * t * t / (2 * duration);
  } else if (tr.kind == "reversal") {
    const double period = 2 * tr.sweep_turns / v0;
    const double u = t - period * std::floor(t / period);
    turns = u < period / 2 ? v0 * u : tr.sweep_turns - v0 * (u - period / 2);
  } else if (tr.kind == "step") {
    const double ts = tr.step_at_s > 0 ? tr.step_at_s : duration / 2;
    turns = t < ts ? v0 * t : v0 * ts + v1 * (t - ts);
  } else if (tr.kind == "ripple") {
    // The integral of v0 (1 + r sin(w t)): v0 (t + r (1 - cos(w t)) / w).
    const double w = 2 * kPi * tr.ripple_hz;
    turns = v0 * (t + tr.ripple * (1 - std::cos(w * t)) / w);
  }
  return tr.theta0_rad + 2 * kPi * turns;
}

double trajectory_speed(const Trajectory& tr, double v0, double v1, double duration, double t) {
  if (tr.kind == "ramp") return v0 + (v1 - v0) * t / duration;
  if (tr.kind == "reversal") {
    const double period = 2 * tr.sweep_turns / v0;
    const double u = t - period * std::floor(t / period);
    return u < period / 2 ? v0 : -v0;
  }
  if (tr.kind == "step") return t < (tr.step_at_s > 0 ? tr.step_at_s : duration / 2) ? v0 : v1;
  if (tr.kind == "ripple") return v0 * (1 + tr.ripple * std::sin(2 * kPi * tr.ripple_hz * t));
  return v0;
}

double TrajectoryModel::theta_at(double t) const {
  // The speed variation (a ripple and a slow change, "turn" and "constant" only) adds exactly 0
  // when it is off.
  return trajectory_theta(tr_, v0_, v1_, duration_, t) + varied(v0_ * t);
}

double TrajectoryModel::varied(double u) const {
  if (!tr_.speed.active() || (tr_.kind != "turn" && tr_.kind != "constant")) return 0.0;
  return speed_variation_angle(tr_.speed, u, v0_ * duration_);
}

double TrajectoryModel::theta_sample(size_t k) const {
  // The published figures use exactly this grid.
  if (tr_.kind == "turn")
    return tr_.theta0_rad + 2 * kPi * static_cast<double>(k) / static_cast<double>(n_) +
           varied(static_cast<double>(k) / static_cast<double>(n_));
  return theta_at(time(k));
}

double TrajectoryModel::speed_at(double t) const {
  return trajectory_speed(tr_, v0_, v1_, duration_, t);
}

double TrajectoryModel::direction_at(double t) const { return speed_at(t) >= 0 ? 1.0 : -1.0; }

// ---- Built-ins ----

std::vector<std::string> builtin_scenario_names() {
  return {"paper", "paper-indep", "paper-noiseless", "ideal", "tmr"};
}

Scenario builtin_scenario(const std::string& name) {
  Scenario s;
  if (name == "paper") {
    s = paper_base();
    s.description =
        "docs/contracts.md, paper scenario: Table 2 systematic error, common-mode Gaussian noise "
        "sigma 0.05";
    s.sigma_common = 0.05;
  } else if (name == "paper-indep") {
    s = paper_base();
    s.description =
        "docs/contracts.md, paper scenario with independent per-channel Gaussian noise sigma 0.05";
    s.sigma_indep = 0.05;
  } else if (name == "paper-noiseless") {
    s = paper_base();
    s.description = "docs/contracts.md, paper scenario systematic error without noise";
  } else if (name == "ideal") {
    s.description = "pure sine and cosine, no error, no noise";
  } else if (name == "tmr") {
    // A two-channel TMR-like bridge sensor.
    s.description =
        "two-channel TMR-like sensor: offsets, 3.5% gain mismatch, 0.3 deg orthogonality error, "
        "1.5% third harmonic, small noise";
    s.channels = 2;
    s.sensor[0].offset = 0.012;
    s.sensor[1].offset = -0.018;
    s.sensor[1].amplitude = 1.035;
    s.sigma_indep = 0.002;
    s.effects.push_back(
        make_effect(effect_name(EffectId::phase_error), {{"delta_rad", 0.3 * kPi / 180}}, 2));
    s.effects.push_back(make_effect(effect_name(EffectId::harmonic),
                                    {{"order", 3}, {"amplitude", 0.015}, {"phase_rad", 0}}, 2));
  } else {
    std::string list;
    for (const auto& n : builtin_scenario_names()) list += (list.empty() ? "" : ", ") + n;
    throw InputError(fmt::format("unknown scenario '{}' (valid: {})", name, list));
  }
  s.name = name;
  return s;
}

Scenario load_scenario(const std::string& json_path) {
  return Scenario::from_json(read_json_file(json_path, "scenario file"), json_path);
}

Scenario with_channels(const Scenario& s, int channels) {
  if (channels != 2 && channels != 4) throw InputError("channels must be 2 or 4");
  if (channels == s.channels) return s;
  Scenario out = s;
  out.channels = channels;
  if (channels == 4) {
    out.sensor[2] = s.sensor[0];
    out.sensor[3] = s.sensor[1];
  } else {
    out.sensor[2] = out.sensor[3] = ChannelModel{};
  }
  out.effects.clear();
  for (const Effect& e : s.effects)
    out.effects.push_back(make_effect(e.effect, remap_params(e, s.channels, channels), channels));
  return out;
}

// ---- Simulation ----

Recording simulate(const Scenario& s, size_t samples, uint64_t seed) {
  if (s.channels != 2 && s.channels != 4) throw InputError("simulate: channels must be 2 or 4");
  if (s.p < 1) throw InputError("simulate: p must be >= 1");
  const TrajectoryModel traj(s.trajectory, samples);
  const int nch = s.channels;
  Recording rec;
  rec.channels = nch;
  rec.t.resize(samples);
  rec.theta_ref.resize(samples);
  for (size_t k = 0; k < samples; ++k) {
    rec.t[k] = traj.time(k);
    rec.theta_ref[k] = traj.theta_sample(k);
  }
  bool needs_temp = false;
  for (const Effect& e : s.effects)
    needs_temp = needs_temp || effect_spec(e.effect).needs_temperature;
  if (s.temperature.enabled || needs_temp) {
    rec.temp.resize(samples);
    const double span = samples > 1 ? static_cast<double>(samples - 1) : 1.0;
    for (size_t k = 0; k < samples; ++k)
      rec.temp[k] = s.temperature.start_C +
                    (s.temperature.end_C - s.temperature.start_C) * static_cast<double>(k) / span;
  }

  EffectContext ctx;
  ctx.p = s.p;
  ctx.sensor = [&s](int c, double phi) { return s.channel_value(c, phi); };
  ctx.theta_at = [&traj](double t) { return traj.theta_at(t); };
  // The effects' noise draws come after the simulation's own, from an independent stream.
  ctx.rng.seed(seed ^ 0x9E3779B97F4A7C15ULL);
  ctx.direction.resize(samples);
  for (size_t k = 0; k < samples; ++k) ctx.direction[k] = traj.direction_at(rec.t[k]);
  for (int c = 0; c < nch; ++c) {
    auto& ph = ctx.phase[static_cast<size_t>(c)];
    auto& x = rec.ch[static_cast<size_t>(c)];
    ph.resize(samples);
    x.resize(samples);
    for (size_t k = 0; k < samples; ++k) {
      ph[k] = s.p * rec.theta_ref[k];
      x[k] = s.channel_value(c, ph[k]);
    }
  }
  for (const Effect& e : s.effects)
    if (is_field_effect(e.effect)) apply_effect(e, rec, ctx);

  // Noise: per sample, the common draw first, then one per channel.
  if (s.sigma_common > 0 || s.sigma_indep > 0) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> gc(0.0, s.sigma_common > 0 ? s.sigma_common : 1.0);
    std::normal_distribution<double> gi(0.0, s.sigma_indep > 0 ? s.sigma_indep : 1.0);
    for (size_t k = 0; k < samples; ++k) {
      const double common = s.sigma_common > 0 ? gc(rng) : 0.0;
      for (int c = 0; c < nch; ++c)
        rec.ch[static_cast<size_t>(c)][k] += common + (s.sigma_indep > 0 ? gi(rng) : 0.0);
    }
  }
  for (const Effect& e : s.effects)
    if (!is_field_effect(e.effect)) apply_effect(e, rec, ctx);

  rec.meta["scenario"] = s.name;
  rec.meta["seed"] = std::to_string(seed);
  rec.meta["p"] = std::to_string(s.p);
  rec.meta["channels"] = std::to_string(nch);
  rec.meta["samples"] = std::to_string(samples);
  rec.meta["trajectory"] = s.trajectory.kind;
  if (!s.effects.empty()) {
    std::string names;
    for (const Effect& e : s.effects) names += (names.empty() ? "" : ";") + e.effect;
    rec.meta["effects"] = names;
  }
  return rec;
}

}  // namespace acore
