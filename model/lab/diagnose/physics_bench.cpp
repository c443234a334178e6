// SPDX-License-Identifier: MIT
#include "diagnose/physics_bench.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/angle.hpp"
#include "core/errors.hpp"
#include "diagnose/diagnose.hpp"
#include "sim/effect_table.hpp"

namespace acore {

namespace {

constexpr double kDeg = kPi / 180.0;
constexpr double kDuration = 2.0;     // seconds per recording, as the effect bench
constexpr double kDriftSpanC = 40.0;  // drift coefficients are drawn as a change over this span
constexpr double kMm = 1e-3;
constexpr double kMt = 1e-3;

double top_speed(const Trajectory& t) {
  return std::max(std::fabs(t.speed_rps), std::fabs(t.speed_end_rps));
}

// The clean angle error of a rig's pairs over one turn at 25 degC (atan2 of c1 - c3, c2 - c4 or of
// sin, cos, minus theta): its mean and RMS, in degrees. The physics behind a truth, computed from
// the rig alone.
struct AngleSignature {
  double mean_deg = 0, rms_deg = 0;
};
AngleSignature angle_signature(const PhysicsRig& rig) {
  const DiametricCylinder magnet = make_magnet(rig.magnet);
  const int n = 180, nch = rig.sensor.channels();
  AngleSignature a;
  for (int k = 0; k < n; ++k) {
    const double th = 2 * kPi * k / n;
    double v[4] = {0, 0, 0, 0};
    for (int c = 0; c < nch; ++c) v[c] = rig_output(rig, magnet, c, th, 25);
    const double s = nch == 4 ? v[0] - v[2] : v[0], co = nch == 4 ? v[1] - v[3] : v[1];
    const double e = std::remainder(std::atan2(s, co) - th, 2 * kPi) / kDeg;
    a.mean_deg += e / n;
    a.rms_deg += e * e / n;
  }
  a.rms_deg = std::sqrt(a.rms_deg);
  return a;
}

// Element c moved along the ring by `deg` (hall4), or its sensing axis turned by `deg` (tmr2).
void misplace(SensingElement& e, double deg) {
  const double a = deg * kDeg, c = std::cos(a), s = std::sin(a);
  if (e.direction.z() != 0) {
    e.position = {c * e.position.x() - s * e.position.y(), s * e.position.x() + c * e.position.y(),
                  e.position.z()};
  } else {
    e.direction = {c * e.direction.x() - s * e.direction.y(),
                   s * e.direction.x() + c * e.direction.y(), 0};
  }
}

// The designer's rig: air gap 1..2 mm, Hall ring radius 0.8..1.2 mm, sensitivities set so that
// the nominal channels swing +-1, noise 0.05..0.2 % of that.
void draw_nominal(BenchDraw& d, PhysicsRig& n, const std::string& sensor) {
  n = PhysicsRig{};
  // The magnet's remanence is held constant except in the temperature scenario. Its reversible
  // fall (-0.12 %/K) scales every channel alike, which cancels in atan2 but for the angle noise,
  // growing by the same few per cent when hot: at the edge of what a gap measure detects, so
  // neither a clean second perturbation in every scenario nor a clean truth of its own.
  n.magnet.br_per_C = 0;
  n.air_gap_m = d.u(1.0, 2.0) * kMm;
  n.sensor = sensor == "hall4" ? hall_ring(d.u(0.8, 1.2) * kMm, 1.0) : inplane_pair(1.0);
  const double sigma = d.u(0.0005, 0.002);
  for (int ch = 0; ch < n.sensor.channels(); ++ch) {
    SensingElement& e = n.sensor.elements[static_cast<size_t>(ch)];
    e.sensitivity = 1.0 / rig_amplitude(n, ch);
    e.noise = sigma;
  }
}

// Applies the scenario's perturbation to the case's rigs (both start nominal) and records the
// drawn parameters.
void perturb(BenchDraw& d, PhysicsCase& c) {
  PhysicsRig& r = c.real_rig;
  const std::string& s = c.scenario.name;
  const int nch = r.sensor.channels();
  const double v = top_speed(c.real_traj);
  ParamList& p = c.params;
  if (s == "nominal") {
  } else if (s == "runout") {
    // The pairs turn by a constant angle, as sin 2 beta of the offset's direction from M (zero
    // along M's axes, where tmr2 only loses amplitude). hall4 also keeps a small 4th-order error,
    // and its shift comes from the cubic part of Bz(rho), whose sign changes with the air gap
    // (near 1.5 mm for this magnet, where only the 4th-order error is left). Redrawn until the
    // shift is >= 0.05 deg and carries >= 90 % of the clean angle error's square, so that the
    // physics says zero_offset; after 40 tries the nominal geometry too.
    AngleSignature a;
    for (int attempt = 1;; ++attempt) {
      r.runout_m = d.u(0.3, 0.6) * kMm;
      r.runout_angle_rad = d.u(0, 2 * kPi);
      a = angle_signature(r);
      if (std::fabs(a.mean_deg) >= 0.05 && a.mean_deg * a.mean_deg >= 0.9 * a.rms_deg * a.rms_deg)
        break;
      if (attempt % 40 == 0) {
        draw_nominal(d, c.sim_rig, c.scenario.sensor);
        r = c.sim_rig;
      }
    }
    p = {{"runout_mm", r.runout_m / kMm},
         {"runout_angle_deg", r.runout_angle_rad / kDeg},
         {"angle_shift_deg", a.mean_deg},
         {"angle_error_rms_deg", a.rms_deg}};
  } else if (s == "runout_offaxis") {
    // The designer's rig already has the package off axis (both sim and real).
    const double d0 = d.u(0.3, 0.5) * kMm, a0 = d.u(0, 2 * kPi);
    c.sim_rig.sensor_shift_m = r.sensor_shift_m = {d0 * std::cos(a0), d0 * std::sin(a0), 0};
    r.runout_m = d.u(0.15, 0.4) * kMm;
    r.runout_angle_rad = d.u(0, 2 * kPi);
    p = {{"sensor_shift_mm", d0 / kMm},
         {"sensor_shift_angle_deg", a0 / kDeg},
         {"runout_mm", r.runout_m / kMm},
         {"runout_angle_deg", r.runout_angle_rad / kDeg}};
  } else if (s == "sensor_shift") {
    // Along the package's x or y (a placement tolerance): the field map stays symmetric about the
    // displacement, so each pair keeps its phase and only their amplitudes differ.
    const double mm = nch == 4 ? d.u(0.4, 0.8) : d.u(0.2, 0.5);
    const double a = 90 * d.i(0, 3) * kDeg;
    r.sensor_shift_m = {mm * kMm * std::cos(a), mm * kMm * std::sin(a), 0};
    p = {{"shift_mm", mm}, {"direction_deg", a / kDeg}};
  } else if (s == "placement_c1" || s == "placement_c2") {
    const int ch = s == "placement_c1" ? 0 : 1;
    const double deg = d.sign() * (nch == 4 ? d.u(2, 6) : d.u(1, 4));
    misplace(r.sensor.elements[static_cast<size_t>(ch)], deg);
    p = {{nch == 4 ? "moved_on_ring_deg" : "axis_turned_deg", deg}};
  } else if (s == "plate_gain") {
    const int ch = d.i(0, nch - 1);
    const double g = d.sign() * d.u(0.02, 0.05);
    r.sensor.elements[static_cast<size_t>(ch)].sensitivity *= 1 + g;
    p = {{"channel", ch + 1}, {"gain_minus_1", g}};
  } else if (s == "plate_offset") {
    const int ch = d.i(0, nch - 1);
    const double o = d.sign() * d.u(0.01, 0.04);  // x the nominal amplitude (1)
    r.sensor.elements[static_cast<size_t>(ch)].offset += o;
    p = {{"channel", ch + 1}, {"offset", o}};
  } else if (s == "nonlinearity") {
    // The elements (or their amplifiers) compress: x - a x^3 with a = 2..8 %, the same on all.
    const double a3 = -d.u(0.02, 0.08);
    for (auto& e : r.sensor.elements) e.cubic = a3;
    p = {{"cubic", a3}};
  } else if (s == "air_gap") {
    // The magnet backs off (end play, wear): every channel smaller by 12..35 %. (Closer, the
    // channels grow and only the angle noise falls: nothing a gap measure can see.)
    const double mm = d.u(0.2, 0.6);
    r.air_gap_m += mm * kMm;
    p = {{"gap_change_mm", mm}};
  } else if (s == "stray_axial" || s == "stray_inplane") {
    const double mt = s == "stray_axial" ? d.u(2, 10) * d.sign() : d.u(1, 4);
    const double a = d.u(0, 2 * kPi);
    r.stray_T = s == "stray_axial"
                    ? Eigen::Vector3d(0, 0, mt * kMt)
                    : Eigen::Vector3d(mt * kMt * std::cos(a), mt * kMt * std::sin(a), 0);
    p = {{"stray_mT", mt}};
    if (s == "stray_inplane") p.push_back({"stray_angle_deg", a / kDeg});
  } else if (s == "rc_filter") {
    // The filter's lag at the top speed: 0.2..3 deg.
    const double tau = d.u(0.2, 3) / (360.0 * v);
    r.rc_tau_s.assign(static_cast<size_t>(nch), tau);
    p = {{"tau_s", tau}};
  } else if (s == "rc_mismatch") {
    // The designer models the nominal filter (lag 1..2 deg at the top speed); the real ones differ
    // by 10..30 % (component tolerance) around it, their mean staying the nominal.
    const double tau0 = d.u(1, 2) / (360.0 * v), spread = d.u(0.1, 0.3);
    std::vector<double> m(static_cast<size_t>(nch));
    for (auto& x : m) x = d.u(-1, 1);
    double mean = 0;
    for (double x : m) mean += x / nch;
    double peak = 0;
    for (auto& x : m) peak = std::max(peak, std::fabs(x -= mean));
    c.sim_rig.rc_tau_s.assign(static_cast<size_t>(nch), tau0);
    r.rc_tau_s.clear();
    p = {{"tau0_s", tau0}};
    for (int ch = 0; ch < nch; ++ch) {
      r.rc_tau_s.push_back(tau0 * (1 + spread * m[static_cast<size_t>(ch)] / peak));
      p.push_back({fmt::format("tau_c{}_s", ch + 1), r.rc_tau_s.back()});
    }
  } else if (s == "adc") {
    r.adc.bits = d.i(8, 10);
    r.adc.full_scale = d.u(1.1, 1.5);  // x the nominal amplitude
    p = {{"bits", r.adc.bits}, {"full_scale", r.adc.full_scale}};
  } else if (s == "mux") {
    // Any conversion order; the slot lasts 0.2..3 deg of turn at the top speed.
    r.mux_order.resize(static_cast<size_t>(nch));
    for (int ch = 0; ch < nch; ++ch) r.mux_order[static_cast<size_t>(ch)] = ch;
    for (int k = nch - 1; k > 0; --k)
      std::swap(r.mux_order[static_cast<size_t>(k)], r.mux_order[static_cast<size_t>(d.i(0, k))]);
    r.mux_slot_s = d.u(0.2, 3) / (360.0 * v);
    p = {{"slot_s", r.mux_slot_s}};
    for (int ch = 0; ch < nch; ++ch)
      p.push_back({fmt::format("slot_c{}", ch + 1), r.mux_order[static_cast<size_t>(ch)]});
  } else if (s == "encoder_zero") {
    r.encoder_zero_rad = d.sign() * d.u(20, 180) * kDeg;
    p = {{"encoder_zero_deg", r.encoder_zero_rad / kDeg}};
  } else if (s == "temperature") {
    // The magnet's remanence (NdFeB, -0.12 %/K), and the offsets and sensitivities of a random
    // subset of elements drift (1..5 % over 40 degC).
    r.magnet.br_per_C = -0.0012;
    p = {{"br_per_C", r.magnet.br_per_C}};
    std::vector<double> ko, kg;
    do {
      ko.assign(static_cast<size_t>(nch), 0.0);
      kg.assign(static_cast<size_t>(nch), 0.0);
      const auto sub = d.subset(nch);
      for (int ch = 0; ch < nch; ++ch) {
        if (!sub[static_cast<size_t>(ch)]) continue;
        const int what = d.i(0, 2);  // 0: offset, 1: sensitivity, 2: both
        if (what != 1) ko[static_cast<size_t>(ch)] = d.sign() * d.u(0.01, 0.05) / kDriftSpanC;
        if (what != 0) kg[static_cast<size_t>(ch)] = d.sign() * d.u(0.01, 0.05) / kDriftSpanC;
      }
      // Visible in what the estimator sees over 40 degC (1 % of the amplitude): an offset or gain
      // common to both channels of a pair cancels in its difference.
      auto o = [&](size_t ch) { return ko[ch] * kDriftSpanC; };
      auto g = [&](size_t ch) { return kg[ch] * kDriftSpanC; };
      const bool visible =
          nch == 2
              ? std::fabs(o(0)) >= 0.01 || std::fabs(o(1)) >= 0.01 || std::fabs(g(0) - g(1)) >= 0.01
              : std::fabs(o(0) - o(2)) >= 0.01 || std::fabs(o(1) - o(3)) >= 0.01 ||
                    std::fabs(0.5 * (g(0) + g(2)) - 0.5 * (g(1) + g(3))) >= 0.01;
      if (visible) break;
    } while (true);
    for (int ch = 0; ch < nch; ++ch) {
      SensingElement& e = r.sensor.elements[static_cast<size_t>(ch)];
      e.offset_per_C = ko[static_cast<size_t>(ch)];
      e.sensitivity_per_C = kg[static_cast<size_t>(ch)];
      if (e.offset_per_C != 0)
        p.push_back({fmt::format("offset_per_C_c{}", ch + 1), e.offset_per_C});
      if (e.sensitivity_per_C != 0)
        p.push_back({fmt::format("sensitivity_per_C_c{}", ch + 1), e.sensitivity_per_C});
    }
  } else {
    throw InputError("diagnose-bench --physics: unknown scenario '" + s + "'");
  }
}

}  // namespace

const std::vector<PhysicsScenario>& physics_scenarios() {
  static const std::vector<PhysicsScenario> k = [] {
    std::vector<PhysicsScenario> v;
    // The truths are the effect table's names (or the verdict no_gap).
    auto name = [](EffectId id) { return effect_name(id); };
    auto both = [&](const std::string& n, const std::string& truth, const std::string& why) {
      v.push_back({n, "hall4", truth, why});
      v.push_back({n, "tmr2", truth, why});
    };
    both("nominal", "no_gap", "the nominal rig: fresh noise, another trajectory and temperature");
    v.push_back({"runout", "hall4", name(EffectId::zero_offset),
                 "the ring moves on a circle off the magnet's axis: the linear part of Bz adds the "
                 "same offset to every plate, the cubic part turns the pairs by a constant angle "
                 "(and leaves a small 3rd spatial harmonic)"});
    v.push_back({"runout", "tmr2", name(EffectId::zero_offset),
                 "the sensor is a fixed point of the magnet's frame: the field turns rigidly with "
                 "the shaft, off M by a constant angle (and smaller)"});
    v.push_back(
        {"runout_offaxis", "tmr2", name(EffectId::eccentricity),
         "sensor off the axis (in sim too) plus run-out: the point the sensor sees moves "
         "once per turn in the magnet's frame: angle and amplitude modulated once per turn"});
    both("sensor_shift", name(EffectId::gain_mismatch),
         "package off axis along x or y: the field map stays symmetric about the shift, the two "
         "pairs keep their phases and differ in amplitude");
    both("placement_c1", name(EffectId::phase_error),
         "c1 moved on the ring (hall4) or the sin axis turned (tmr2): the sine pair's phase");
    both("placement_c2", name(EffectId::phase_error),
         "c2 moved on the ring (hall4) or the cos axis turned (tmr2): the cosine pair's phase");
    both("plate_gain", name(EffectId::gain_mismatch), "one element's sensitivity");
    both("nonlinearity", name(EffectId::harmonic),
         "x - a x^3 on every element: sin^3 = (3 sin - sin 3t) / 4, a 3rd harmonic seen alike "
         "from every element's position");
    both("plate_offset", name(EffectId::offset), "one element's offset");
    both("air_gap", name(EffectId::amplitude),
         "the magnet backs off: every element sees the field scaled alike (smaller), so the angle "
         "noise grows");
    both("stray_axial", "no_gap",
         "hall4: the same Bz on every plate cancels in c1 - c3; tmr2: in-plane elements do not "
         "see Bz");
    v.push_back({"stray_inplane", "hall4", "no_gap", "Hall plates measure Bz only"});
    v.push_back({"stray_inplane", "tmr2", name(EffectId::offset),
                 "a constant field adds a constant to sin, cos"});
    both("rc_filter", name(EffectId::common_delay), "one RC on every channel: a lag omega tau");
    both("rc_mismatch", name(EffectId::channel_skew),
         "RCs around the modelled one: each channel lags by its own tau");
    both("adc", name(EffectId::quantization), "an ADC of 8..10 bits");
    both("mux", name(EffectId::channel_skew),
         "one ADC converts the channels in turn, in any slot order");
    both("encoder_zero", name(EffectId::zero_offset), "the reference's zero is another angle");
    both("temperature", name(EffectId::drift),
         "the remanence and element offsets and sensitivities change with temperature");
    return v;
  }();
  return k;
}

PhysicsCase draw_physics_case(uint64_t seed, size_t index, const PhysicsScenario& s) {
  PhysicsCase c;
  c.index = index;
  c.scenario = s;
  c.seed = bench_mix(bench_mix(seed) ^ index);
  BenchDraw d(c.seed);
  draw_nominal(d, c.sim_rig, s.sensor);
  c.sim_traj.kind = "constant";
  c.sim_traj.turns = d.u(2, 5);
  c.sim_traj.theta0_rad = d.u(0, 2 * kPi);
  c.real_traj = draw_bench_ramp(d);
  c.hold_traj = draw_bench_ramp(d);
  draw_bench_temperature(d, c.real_temp);
  draw_bench_temperature(d, c.hold_temp);
  c.real_rig = c.sim_rig;
  perturb(d, c);
  return c;
}

std::vector<PhysicsCase> draw_physics_cases(const BenchOptions& opt) {
  if (opt.per_effect < 1) throw InputError("diagnose-bench: --per-effect must be >= 1");
  std::vector<PhysicsCase> cases;
  for (const PhysicsScenario& s : physics_scenarios())
    for (int k = 0; k < opt.per_effect; ++k)
      cases.push_back(draw_physics_case(opt.seed, cases.size(), s));
  return cases;
}

BenchRecordings make_physics_recordings(const PhysicsCase& c, size_t samples) {
  const double fs = static_cast<double>(samples) / kDuration;
  BenchRecordings out;
  Trajectory t = c.sim_traj;
  t.sample_rate_hz = fs;
  out.sim = simulate_physics(c.sim_rig, t, Temperature{}, samples, bench_mix(c.seed + 1));
  auto real_like = [&](const Trajectory& tr, const double temp[2], uint64_t seed) {
    Trajectory x = tr;
    x.sample_rate_hz = fs;
    return simulate_physics(c.real_rig, x, Temperature{true, temp[0], temp[1]}, samples, seed);
  };
  out.real = real_like(c.real_traj, c.real_temp, bench_mix(c.seed + 2));
  out.holdout = real_like(c.hold_traj, c.hold_temp, bench_mix(c.seed + 3));
  return out;
}

BenchCaseResult run_physics_case(const PhysicsCase& c, size_t samples) {
  const BenchRecordings rec = make_physics_recordings(c, samples);
  const auto t0 = std::chrono::steady_clock::now();
  const Diagnosis d = diagnose(rec.sim, rec.real, &rec.holdout);
  BenchCaseResult r =
      judge_diagnosis(d, c.scenario.truth,
                      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  r.drawn.index = c.index;
  r.drawn.truth = c.scenario.truth;
  r.drawn.channels = c.real_rig.sensor.channels();
  r.label = c.scenario.label();
  r.effect_case = c.scenario.truth != "no_gap";
  r.drawn_params = c.params;
  return r;
}

BenchSummary run_physics_bench(const BenchOptions& opt, const BenchTargets& targets) {
  if (opt.samples < 2000) throw InputError("diagnose-bench: --samples must be >= 2000");
  const std::vector<PhysicsCase> cases = select_cases(draw_physics_cases(opt), opt.only);
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<BenchCaseResult> results = run_bench_cases(
      cases.size(), opt.jobs, [&](size_t i) { return run_physics_case(cases[i], opt.samples); },
      opt.progress);
  std::vector<std::string> rows;
  for (const PhysicsScenario& s : physics_scenarios()) rows.push_back(s.label());
  return summarize_bench(
      std::move(results), rows, targets,
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}

}  // namespace acore
