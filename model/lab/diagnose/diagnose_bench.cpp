// SPDX-License-Identifier: MIT
#include "diagnose/diagnose_bench.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <complex>
#include <exception>
#include <mutex>
#include <random>
#include <thread>

#include "core/angle.hpp"
#include "core/errors.hpp"
#include "diagnose/diagnose.hpp"
#include "sim/effect_table.hpp"

namespace acore {

namespace {

constexpr double kDeg = kPi / 180.0;
constexpr double kDuration = 2.0;  // seconds per recording: the sample rate is samples / kDuration
constexpr double kDriftSpanC = 40.0;  // drift coefficients are drawn as a change over this span
// amplitude: |scale - 1| drawn in this range (enough to move the calibrated correction,
// docs/diagnosis.md).
constexpr double kAmplitudeMin = 0.05, kAmplitudeMax = 0.30;
constexpr double kVisible =
    0.01;  // a four-channel draw must move c1 - c3 or c2 - c4 this much (x A)

const std::vector<std::string>& outside_kinds() {
  static const std::vector<std::string> k = {"glitch", "dropout", "modulation", "pickup"};
  return k;
}

uint64_t mix(uint64_t x) { return bench_mix(x); }
using Draw = BenchDraw;
Trajectory draw_ramp(Draw& d) { return draw_bench_ramp(d); }
void draw_temperature(Draw& d, double out[2]) { draw_bench_temperature(d, out); }

double top_speed(const Trajectory& t) {
  return std::max(std::fabs(t.speed_rps), std::fabs(t.speed_end_rps));
}

// The time of the ramp's reversal, in seconds.
double reversal_time(const Trajectory& t) {
  const double a = std::fabs(t.speed_rps), b = std::fabs(t.speed_end_rps);
  return kDuration * a / (a + b);
}

// Four channels: the effect on the pairs the estimator sees. gain(c) and offset(c) per channel.
template <class G, class O>
bool pairs_move(int channels, G&& gain, O&& offset) {
  if (channels == 2)
    return std::fabs(offset(0)) >= kVisible || std::fabs(offset(1)) >= kVisible ||
           std::fabs(gain(0) - gain(1)) >= kVisible;
  return std::fabs(offset(0) - offset(2)) >= kVisible ||
         std::fabs(offset(1) - offset(3)) >= kVisible ||
         std::fabs(0.5 * (gain(0) + gain(2)) - 0.5 * (gain(1) + gain(3))) >= kVisible;
}

// ---- Each effect's draw: the ranges of diagnose_bench.hpp, no-op parameters left out ----

ParamList draw_offset(Draw& d, const BenchCase& c) {
  const int nch = c.channels;
  auto name = [&](int ch) { return effect_channel_name(nch, ch); };
  ParamList p;
  std::vector<double> o(4, 0.0);
  do {
    const auto s = d.subset(nch);
    for (int ch = 0; ch < nch; ++ch) o[ch] = s[ch] ? d.sign() * d.u(0.01, 0.05) : 0.0;
  } while (!pairs_move(
      nch, [](int) { return 0.0; }, [&](int ch) { return o[ch]; }));
  for (int ch = 0; ch < nch; ++ch)
    if (o[ch] != 0) p.push_back({"offset_" + name(ch), o[ch]});
  return p;
}

ParamList draw_gain_mismatch(Draw& d, const BenchCase& c) {
  const int nch = c.channels;
  auto name = [&](int ch) { return effect_channel_name(nch, ch); };
  ParamList p;
  std::vector<double> g(4, 0.0);
  do {
    const auto s = d.subset(nch);
    for (int ch = 0; ch < nch; ++ch) g[ch] = s[ch] ? d.sign() * d.u(0.01, 0.05) : 0.0;
  } while (!pairs_move(
      nch, [&](int ch) { return g[ch]; }, [](int) { return 0.0; }));
  for (int ch = 0; ch < nch; ++ch)
    if (g[ch] != 0) p.push_back({"gain_" + name(ch), 1.0 + g[ch]});
  return p;
}

ParamList draw_phase_error(Draw& d, const BenchCase& c) {
  const int nch = c.channels;
  auto name = [&](int ch) { return effect_channel_name(nch, ch); };
  // The sine pair, the cosine pair or (four channels) one plate.
  const double delta = d.sign() * d.u(0.5, 5) * kDeg;
  const int target = d.i(0, nch == 4 ? 5 : 1);
  return {{target == 0   ? "delta_rad"
           : target == 1 ? "delta_cos_rad"
                         : "phase_" + name(target - 2),
           delta}};
}

ParamList draw_zero_offset(Draw& d, const BenchCase&) {
  return {{"zero_rad", d.sign() * d.u(0.2, 3) * kDeg}};
}

ParamList draw_amplitude(Draw& d, const BenchCase&) {
  return {{"scale", 1 + d.sign() * d.u(kAmplitudeMin, kAmplitudeMax)}};
}

ParamList draw_harmonic(Draw& d, const BenchCase& c) {
  const int nch = c.channels;
  const int order = nch == 4 ? 2 * d.i(1, 3) + 1 : d.i(2, 5);
  return {{"order", order}, {"amplitude", d.u(0.01, 0.05)}, {"phase_rad", d.u(-kPi, kPi)}};
}

ParamList draw_eccentricity(Draw& d, const BenchCase&) {
  // Magnitude modulation up to 1.5 eps, its phase within 90 degrees of phi0 (the other half-plane
  // is what an offset does to a two-channel sensor, see effects.hpp).
  const double eps = d.u(0.2, 2) * kDeg, phi0 = d.u(-kPi, kPi);
  return {{"epsilon_rad", eps},
          {"phi0_rad", phi0},
          {"am_depth", eps * d.u(0, 1.5)},
          {"am_phase_rad", std::remainder(phi0 + d.u(-kPi / 2, kPi / 2), 2 * kPi)}};
}

ParamList draw_channel_skew(Draw& d, const BenchCase& c) {
  const int nch = c.channels;
  auto name = [&](int ch) { return effect_channel_name(nch, ch); };
  ParamList p;
  // A multiplexed ADC: the channels in a random slot order, tau apart; 360 v tau degrees is the
  // angle between neighbouring slots at the top speed.
  const double tau = d.u(0.2, 3) / (360.0 * top_speed(c.real_traj));
  std::vector<int> slot(static_cast<size_t>(nch));
  for (int k = 0; k < nch; ++k) slot[static_cast<size_t>(k)] = k;
  for (int k = nch - 1; k > 0; --k)
    std::swap(slot[static_cast<size_t>(k)], slot[static_cast<size_t>(d.i(0, k))]);
  for (int ch = 0; ch < nch; ++ch)
    if (slot[static_cast<size_t>(ch)] != 0)
      p.push_back({"tau_" + name(ch), slot[static_cast<size_t>(ch)] * tau});
  return p;
}

ParamList draw_common_delay(Draw& d, const BenchCase& c) {
  // The angle the effect moves at the top speed: 360 v tau degrees.
  return {{"tau_s", d.u(0.2, 3) / (360.0 * top_speed(c.real_traj))}};
}

ParamList draw_drift(Draw& d, const BenchCase& c) {
  const int nch = c.channels;
  auto name = [&](int ch) { return effect_channel_name(nch, ch); };
  ParamList p;
  std::vector<double> ko(4, 0.0), kg(4, 0.0);
  do {
    const auto s = d.subset(nch);
    for (int ch = 0; ch < nch; ++ch) {
      ko[ch] = kg[ch] = 0;
      if (!s[ch]) continue;
      const int what = d.i(0, 2);  // 0: offset, 1: gain, 2: both
      if (what != 1) ko[ch] = d.sign() * d.u(0.01, 0.05) / kDriftSpanC;
      if (what != 0) kg[ch] = d.sign() * d.u(0.01, 0.05) / kDriftSpanC;
    }
  } while (!pairs_move(
      nch, [&](int ch) { return kg[ch] * kDriftSpanC; },
      [&](int ch) { return ko[ch] * kDriftSpanC; }));
  for (int ch = 0; ch < nch; ++ch) {
    if (ko[ch] != 0) p.push_back({"offset_per_C_" + name(ch), ko[ch]});
    if (kg[ch] != 0) p.push_back({"gain_per_C_" + name(ch), kg[ch]});
  }
  return p;
}

ParamList draw_quantization(Draw& d, const BenchCase& c) {
  return {{"bits", d.i(6, 10)}, {"full_scale", c.peak * d.u(1.05, 1.5)}};
}

ParamList draw_saturation(Draw& d, const BenchCase& c) {
  return {{"level", c.peak * d.u(0.80, 0.95)}};
}

ParamList draw_excess_noise(Draw& d, const BenchCase& c) {
  return {{"sigma", c.model.sigma_indep * d.u(2, 5)}};
}

ParamList draw_hysteresis(Draw& d, const BenchCase&) {
  return {{"h_rad", d.sign() * d.u(0.1, 1) * kDeg}};
}

ParamList draw_outside(Draw& d, const BenchCase& c) {
  const std::string& k = c.outside;
  if (k == "glitch") {
    // The magnet slips on the shaft by J at t0, away from the reversal (else it is hysteresis).
    const double tr = reversal_time(c.real_traj);
    double t0;
    do t0 = d.u(0.15, 0.85) * kDuration;
    while (std::fabs(t0 - tr) < 0.2 * kDuration);
    return {{"t0_s", t0}, {"jump_rad", d.sign() * d.u(1, 3) * kDeg}};
  }
  if (k == "dropout") {
    // One channel freezes at its last value three times, 20..40 ms each.
    ParamList p = {{"channel", d.i(0, c.channels - 1)}};
    for (int s = 0; s < 3; ++s) {
      p.push_back({fmt::format("start{}_s", s), d.u(0.05, 0.9) * kDuration});
      p.push_back({fmt::format("length{}_s", s), d.u(0.02, 0.04)});
    }
    return p;
  }
  if (k == "modulation") {
    // The sine pair's amplitude modulated at a frequency that has nothing to do with the angle.
    return {{"depth", d.u(0.02, 0.05)}, {"freq_hz", d.u(3, 15)}, {"phase_rad", d.u(-kPi, kPi)}};
  }
  if (k == "pickup") {
    // Mains pick-up on one channel.
    return {{"channel", d.i(0, c.channels - 1)},
            {"amplitude", d.u(0.01, 0.03)},
            {"freq_hz", 50},
            {"phase_rad", d.u(-kPi, kPi)}};
  }
  throw InputError("diagnose-bench: unknown outside effect '" + k + "'");
}

double param(const ParamList& p, const std::string& name) {
  for (const auto& [k, v] : p)
    if (k == name) return v;
  throw InputError("diagnose-bench: no parameter '" + name + "'");
}

void apply_outside(const BenchCase& c, Recording& r) {
  const ParamList& p = c.outside_params;
  const size_t n = r.size();
  if (c.outside == "glitch") {
    // The sensor sees theta + J from t0 on: the reference lags the sensor by J.
    const double t0 = param(p, "t0_s"), j = param(p, "jump_rad");
    for (size_t i = 0; i < n; ++i)
      if (r.t[i] >= t0) r.theta_ref[i] -= j;
  } else if (c.outside == "dropout") {
    auto& x = r.ch[static_cast<size_t>(param(p, "channel"))];
    for (int s = 0; s < 3; ++s) {
      const double t0 = param(p, fmt::format("start{}_s", s)),
                   t1 = t0 + param(p, fmt::format("length{}_s", s));
      double held = x[0];
      for (size_t i = 0; i < n; ++i) {
        if (r.t[i] < t0)
          held = x[i];
        else if (r.t[i] < t1)
          x[i] = held;
      }
    }
  } else if (c.outside == "modulation") {
    const double m = param(p, "depth"), f = param(p, "freq_hz"), ph = param(p, "phase_rad");
    for (int ch = 0; ch < r.channels; ch += 2)
      for (size_t i = 0; i < n; ++i) r.ch[ch][i] *= 1.0 + m * std::sin(2 * kPi * f * r.t[i] + ph);
  } else if (c.outside == "pickup") {
    auto& x = r.ch[static_cast<size_t>(param(p, "channel"))];
    const double a = param(p, "amplitude"), f = param(p, "freq_hz"), ph = param(p, "phase_rad");
    for (size_t i = 0; i < n; ++i) x[i] += a * std::sin(2 * kPi * f * r.t[i] + ph);
  }
}

double rel(double fitted, double truth) { return std::fabs(fitted - truth) / std::fabs(truth); }

// ---- Each effect's score: a correctly named effect's parameters (diagnose_bench.hpp) ----

struct Scoring {
  const BenchCase& c;
  const EffectCandidate& cand;
  std::vector<BenchParam>& out;

  const Effect& truth() const { return c.effect; }
  void add(const std::string& name, double t, double fitted) const {
    out.push_back({name, t, fitted, rel(fitted, t)});
  }
  // Whether the draw set this parameter (not left at its no-op default).
  bool drawn(const std::string& name) const {
    double given = 0.0;
    for (const auto& [k, v] : c.effect.params)
      if (k == name) given = v;
    for (const auto& [k, v] : effect_spec(c.effect.effect).defaults(c.channels))
      if (k == name) return given != v;
    return false;
  }
  // A vector of per-channel values, compared as a whole: |fitted - true| / |true|.
  void add_vector(const std::string& name, const std::array<double, 4>& t,
                  const std::array<double, 4>& f) const {
    double dt = 0, nt = 0, nf = 0;
    for (size_t k = 0; k < 4; ++k)
      dt += (f[k] - t[k]) * (f[k] - t[k]), nt += t[k] * t[k], nf += f[k] * f[k];
    out.push_back({name, std::sqrt(nt), std::sqrt(nf), std::sqrt(dt / nt)});
  }
  // The fitted per-channel quantities (phase_error, channel_skew) as the simulator reads them.
  Effect fitted() const { return make_effect(c.effect.effect, cand.params, c.channels); }
};

// Offsets, drift coefficients, a delay, sigma, h, z: each drawn parameter itself.
void score_drawn(const Scoring& s) {
  for (const auto& [k, v] : s.truth().params)
    if (s.drawn(k)) s.add(k, v, s.cand.param(k));
}

// Gains and the amplitude's scale: the mismatch, each drawn factor minus 1.
void score_factor_minus_one(const Scoring& s) {
  for (const auto& [k, v] : s.truth().params)
    if (s.drawn(k)) s.add(k + " - 1", v - 1, s.cand.param(k) - 1);
}

void score_phase_error(const Scoring& s) {
  s.add_vector("phase per channel", phase_error_shifts(s.truth(), s.c.channels),
               phase_error_shifts(s.fitted(), s.c.channels));
}

void score_channel_skew(const Scoring& s) {
  s.add_vector("time per channel", channel_skew_offsets(s.truth(), s.c.channels),
               channel_skew_offsets(s.fitted(), s.c.channels));
}

void score_harmonic(const Scoring& s) {
  const Effect& e = s.truth();
  const EffectCandidate& cand = s.cand;
  const std::complex<double> t = std::polar(e.param("amplitude"), e.param("phase_rad"));
  const std::complex<double> f = cand.param("order") == e.param("order")
                                     ? std::polar(cand.param("amplitude"), cand.param("phase_rad"))
                                     : std::complex<double>(0, 0);
  s.out.push_back({fmt::format("order {} a e^(i psi)", e.param("order")), std::abs(t), std::abs(f),
                   std::abs(f - t) / std::abs(t)});
}

// Angle and magnitude modulation together: the vector (eps e^(i phi0), m e^(i phi_m)).
void score_eccentricity(const Scoring& s) {
  const Effect& e = s.truth();
  const EffectCandidate& cand = s.cand;
  const std::complex<double> ta = std::polar(e.param("epsilon_rad"), e.param("phi0_rad")),
                             tm = std::polar(e.param("am_depth"), e.param("am_phase_rad"));
  const std::complex<double> fa = std::polar(cand.param("epsilon_rad"), cand.param("phi0_rad")),
                             fm = std::polar(cand.param("am_depth"), cand.param("am_phase_rad"));
  const double nt = std::hypot(std::abs(ta), std::abs(tm));
  s.out.push_back({"(eps e^(i phi0), m e^(i phi_m))", nt, std::hypot(std::abs(fa), std::abs(fm)),
                   std::hypot(std::abs(fa - ta), std::abs(fm - tm)) / nt});
}

void score_quantization(const Scoring& s) {
  const Effect& e = s.truth();
  s.add("step", 2 * e.param("full_scale") / std::ldexp(1.0, static_cast<int>(e.param("bits"))),
        s.cand.param("step"));
}

void score_saturation(const Scoring& s) {
  s.add("depth 1 - level/P", 1 - s.truth().param("level") / s.c.peak,
        1 - s.cand.param("level") / s.c.peak);
}

// ---- The bench table: one row per row of the effect table (effect_table.hpp), same order ----

struct BenchEffect {
  EffectId id;
  ParamList (*draw)(Draw&, const BenchCase&);
  void (*score)(const Scoring&);
};

const std::array<BenchEffect, kEffectCount> kBenchEffects = {{
    {EffectId::offset, draw_offset, score_drawn},
    {EffectId::gain_mismatch, draw_gain_mismatch, score_factor_minus_one},
    {EffectId::phase_error, draw_phase_error, score_phase_error},
    {EffectId::harmonic, draw_harmonic, score_harmonic},
    {EffectId::eccentricity, draw_eccentricity, score_eccentricity},
    {EffectId::channel_skew, draw_channel_skew, score_channel_skew},
    {EffectId::common_delay, draw_common_delay, score_drawn},
    {EffectId::drift, draw_drift, score_drawn},
    {EffectId::quantization, draw_quantization, score_quantization},
    {EffectId::saturation, draw_saturation, score_saturation},
    {EffectId::excess_noise, draw_excess_noise, score_drawn},
    {EffectId::hysteresis, draw_hysteresis, score_drawn},
    {EffectId::zero_offset, draw_zero_offset, score_drawn},
    {EffectId::amplitude, draw_amplitude, score_factor_minus_one},
}};

// The bench row of an effect name; throws InputError for an unknown one.
const BenchEffect& bench_effect(const std::string& e) {
  const EffectSpec* spec = find_effect(e);
  if (!spec) throw InputError("diagnose-bench: unknown effect '" + e + "'");
  const BenchEffect& b = kBenchEffects[static_cast<size_t>(spec->id)];
  if (b.id != spec->id)
    throw std::logic_error(
        "diagnose-bench: the bench table is not in the effect table's order at " + e);
  return b;
}

Effect draw_effect(Draw& d, const BenchCase& c) {
  return make_effect(c.truth, bench_effect(c.truth).draw(d, c), c.channels);
}

// The scored parameters of a correctly named effect (see the header).
std::vector<BenchParam> score(const BenchCase& c, const EffectCandidate& cand) {
  std::vector<BenchParam> out;
  bench_effect(c.effect.effect).score(Scoring{c, cand, out});
  return out;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  const size_t m = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + m, v.end());
  if (v.size() % 2) return v[m];
  return 0.5 * (v[m] + *std::max_element(v.begin(), v.begin() + m));
}

}  // namespace

uint64_t bench_mix(uint64_t x) {
  // splitmix64: a well-mixed seed per (run seed, case index).
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

std::vector<bool> BenchDraw::subset(int n) {
  std::vector<bool> s(static_cast<size_t>(n));
  do {
    for (int c = 0; c < n; ++c) s[static_cast<size_t>(c)] = coin();
  } while (std::none_of(s.begin(), s.end(), [](bool b) { return b; }));
  return s;
}

Trajectory draw_bench_ramp(BenchDraw& d) {
  Trajectory t;
  t.kind = "ramp";
  const double dir = d.sign();
  t.speed_rps = dir * d.u(3, 12);
  t.speed_end_rps = -dir * d.u(3, 12);
  t.theta0_rad = d.u(0, 2 * kPi);
  return t;
}

void draw_bench_temperature(BenchDraw& d, double out[2]) {
  const double a = d.u(0, 30), b = a + d.u(30, 60);
  const bool cooling = d.coin();
  out[0] = cooling ? b : a;
  out[1] = cooling ? a : b;
}

std::string expected_top1(const std::string& truth) {
  if (truth == "none") return "no_gap";
  if (truth == "outside") return "unexplained";
  return truth;
}

BenchCase draw_bench_case(uint64_t seed, size_t index, const std::string& truth, int channels,
                          const std::string& outside) {
  if (channels != 2 && channels != 4) throw InputError("diagnose-bench: channels must be 2 or 4");
  BenchCase c;
  c.index = index;
  c.truth = truth;
  c.outside = outside;
  c.channels = channels;
  c.seed = mix(mix(seed) ^ index);
  Draw d(c.seed);
  // The designer's model: a realistic imperfect sensor (amplitudes, offsets, harmonics 1..5,
  // noise).
  Scenario& m = c.model;
  m.name = "bench";
  m.channels = channels;
  m.p = 1;
  for (int ch = 0; ch < channels; ++ch) {
    ChannelModel& cm = m.sensor[static_cast<size_t>(ch)];
    cm.amplitude = d.u(0.97, 1.03);
    cm.offset = d.u(-0.01, 0.01);
    for (int k = 1; k <= 5; ++k) {
      const double a = k == 1 ? 0.005 : 0.01;
      cm.af.push_back(d.u(-a, a));
      cm.bf.push_back(d.u(-a, a));
    }
  }
  m.sigma_indep = d.u(0.0005, 0.002);
  m.sigma_common = channels == 4 ? d.u(0, 0.005) : 0.0;
  m.trajectory.kind = "constant";
  m.trajectory.turns = d.u(2, 5);
  m.trajectory.theta0_rad = d.u(0, 2 * kPi);
  for (int ch = 0; ch < channels; ++ch)
    for (int k = 0; k < 3600; ++k)
      c.peak = std::max(c.peak, std::fabs(m.channel_value(ch, 2 * kPi * k / 3600)));
  c.real_traj = draw_ramp(d);
  c.hold_traj = draw_ramp(d);
  draw_temperature(d, c.real_temp);
  draw_temperature(d, c.hold_temp);
  if (truth == "outside") {
    if (std::find(outside_kinds().begin(), outside_kinds().end(), outside) == outside_kinds().end())
      throw InputError("diagnose-bench: unknown outside effect '" + outside + "'");
    c.outside_params = draw_outside(d, c);
  } else if (truth != "none") {
    c.effect = draw_effect(d, c);
  }
  return c;
}

BenchRecordings make_bench_recordings(const BenchCase& c, size_t samples) {
  const double fs = static_cast<double>(samples) / kDuration;
  Scenario s = c.model;
  s.trajectory.sample_rate_hz = fs;
  BenchRecordings out;
  out.sim = simulate(s, samples, mix(c.seed + 1));
  auto real_like = [&](const Trajectory& tr, const double temp[2], uint64_t seed) {
    Scenario r = c.model;
    r.trajectory = tr;
    r.trajectory.sample_rate_hz = fs;
    r.temperature = {true, temp[0], temp[1]};
    if (!c.effect.effect.empty()) r.effects = {c.effect};
    Recording rec = simulate(r, samples, seed);
    if (c.truth == "outside") apply_outside(c, rec);
    rec.meta.erase("effects");  // blind: the recording does not name its effect
    return rec;
  };
  out.real = real_like(c.real_traj, c.real_temp, mix(c.seed + 2));
  out.holdout = real_like(c.hold_traj, c.hold_temp, mix(c.seed + 3));
  return out;
}

BenchCaseResult judge_diagnosis(const Diagnosis& d, const std::string& expected, double seconds) {
  BenchCaseResult r;
  r.expected = expected;
  r.seconds = seconds;
  r.verdict = d.verdict;
  // The named effect: the best single one, or the first of a named combination.
  r.top1 = d.verdict == "explained" && !d.named().empty() ? d.named().front() : d.verdict;
  r.correct = r.top1 == expected;
  if (expected == "no_gap") r.confident_wrong = d.verdict == "explained";
  if (expected == "unexplained")
    r.confident_wrong = d.verdict == "explained" || d.verdict == "no_gap";
  r.ambiguous_with = d.ambiguous_with;
  r.slow_veto = !d.note.empty();
  r.slow_share = d.before.gap_deg > 0 ? std::pow(d.before.slow_deg / d.before.gap_deg, 2) : 0.0;
  r.best_explained = d.combination.empty() ? 0.0 : d.combination_explained;
  for (const auto& e : d.ranking)
    if (e.cand.rejected.empty()) r.best_explained = std::max(r.best_explained, e.explained);
  r.real_before = d.before.gap_deg;
  r.real_after = d.after.gap_deg;
  r.hold_before = d.hold_before->gap_deg;
  r.hold_after = d.hold_after->gap_deg;
  r.shrink = r.hold_before > 0 ? 1.0 - r.hold_after / r.hold_before : 0.0;
  return r;
}

BenchCaseResult run_bench_case(const BenchCase& c, size_t samples) {
  const BenchRecordings rec = make_bench_recordings(c, samples);
  const auto t0 = std::chrono::steady_clock::now();
  const Diagnosis d = diagnose(rec.sim, rec.real, &rec.holdout);
  BenchCaseResult r =
      judge_diagnosis(d, expected_top1(c.truth),
                      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  r.drawn = c;
  r.label = c.truth;
  r.effect_case = !c.effect.effect.empty();
  r.drawn_params = c.effect.params;
  r.drawn_params.insert(r.drawn_params.end(), c.outside_params.begin(), c.outside_params.end());
  if (r.correct && r.effect_case)
    r.params =
        score(c, d.combination.empty() ? d.ranking.front().cand : d.combination.front().cand);
  return r;
}

std::vector<BenchCase> draw_bench_cases(const BenchOptions& opt) {
  if (opt.per_effect < 1) throw InputError("diagnose-bench: --per-effect must be >= 1");
  std::vector<BenchCase> cases;
  auto add = [&](const std::string& truth, int k, const std::string& outside = "") {
    cases.push_back(draw_bench_case(opt.seed, cases.size(), truth, k % 2 == 0 ? 4 : 2, outside));
  };
  for (const std::string& e : effect_names())
    for (int k = 0; k < opt.per_effect; ++k) add(e, k);
  for (int k = 0; k < opt.per_effect; ++k) add("none", k);
  const int kinds = static_cast<int>(outside_kinds().size());
  for (int k = 0; k < opt.per_effect; ++k) add("outside", k / kinds, outside_kinds()[k % kinds]);
  return cases;
}

std::vector<BenchCaseResult> run_bench_cases(
    size_t n, int jobs, const std::function<BenchCaseResult(size_t)>& run,
    const std::function<void(size_t done, size_t total, const BenchCaseResult&)>& progress) {
  if (jobs < 1) throw InputError("diagnose-bench: --jobs must be >= 1");
  std::vector<BenchCaseResult> out(n);
  std::atomic<size_t> next{0};
  std::mutex mu;
  size_t done = 0;
  std::exception_ptr failure;
  auto worker = [&] {
    for (;;) {
      const size_t i = next++;
      if (i >= n) return;
      try {
        BenchCaseResult r = run(i);
        std::lock_guard<std::mutex> lock(mu);
        out[i] = std::move(r);
        ++done;
        if (progress) progress(done, n, out[i]);
      } catch (...) {
        std::lock_guard<std::mutex> lock(mu);
        if (!failure) failure = std::current_exception();
        next = n;
        return;
      }
    }
  };
  std::vector<std::thread> pool;
  for (int j = 1; j < jobs; ++j) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  return out;
}

BenchSummary summarize_bench(std::vector<BenchCaseResult> cases, std::vector<std::string> rows,
                             const BenchTargets& targets, double seconds) {
  BenchSummary s;
  s.targets = targets;
  s.cases = std::move(cases);
  s.seconds = seconds;
  s.rows = std::move(rows);
  s.columns = effect_names();
  for (const auto& r : s.cases)
    if (r.expected != "no_gap" && r.expected != "unexplained" &&
        std::find(s.columns.begin(), s.columns.end(), r.expected) == s.columns.end())
      s.columns.push_back(r.expected);  // a truth the vocabulary does not have (yet)
  s.columns.push_back("no_gap");
  s.columns.push_back("unexplained");
  s.confusion.assign(s.rows.size(), std::vector<int>(s.columns.size(), 0));
  auto index_of = [](const std::vector<std::string>& v, const std::string& x) {
    const auto it = std::find(v.begin(), v.end(), x);
    if (it == v.end()) throw std::logic_error("diagnose-bench: no row or column '" + x + "'");
    return static_cast<size_t>(it - v.begin());
  };
  int correct = 0, correct_effects = 0, effect_cases = 0;
  std::vector<double> shrinks, errors;
  for (const auto& r : s.cases) {
    ++s.confusion[index_of(s.rows, r.label)][index_of(s.columns, r.top1)];
    correct += r.correct;
    s.confident_wrong += r.confident_wrong;
    s.ambiguous += !r.ambiguous_with.empty();
    if (r.expected == "unexplained")
      s.outside_best_explained = std::max(s.outside_best_explained, r.best_explained);
    s.slow_vetoed += r.slow_veto;
    if (r.effect_case) {
      ++effect_cases;
      correct_effects += r.correct;
      shrinks.push_back(r.shrink);
    }
    for (const auto& p : r.params) {
      errors.push_back(p.rel_error);
      ++s.params_scored;
      s.params_within += p.rel_error <= targets.param_rel_max;
    }
  }
  s.top1_accuracy =
      s.cases.empty() ? 0.0 : static_cast<double>(correct) / static_cast<double>(s.cases.size());
  s.top1_effects = effect_cases ? static_cast<double>(correct_effects) / effect_cases : 0.0;
  s.median_shrink = median(shrinks);
  s.min_shrink = shrinks.empty() ? 0.0 : *std::min_element(shrinks.begin(), shrinks.end());
  s.param_median = median(errors);
  s.param_max = errors.empty() ? 0.0 : *std::max_element(errors.begin(), errors.end());
  return s;
}

InputError only_out_of_range(size_t index, size_t cases) {
  return InputError(
      fmt::format("diagnose-bench: --only {}: the run has cases 0..{}", index, cases - 1));
}

BenchSummary run_diagnose_bench(const BenchOptions& opt, const BenchTargets& targets) {
  if (opt.jobs < 1) throw InputError("diagnose-bench: --jobs must be >= 1");
  if (opt.samples < 2000) throw InputError("diagnose-bench: --samples must be >= 2000");
  const std::vector<BenchCase> cases = select_cases(draw_bench_cases(opt), opt.only);
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<BenchCaseResult> results = run_bench_cases(
      cases.size(), opt.jobs, [&](size_t i) { return run_bench_case(cases[i], opt.samples); },
      opt.progress);
  std::vector<std::string> rows = effect_names();
  rows.push_back("none");
  rows.push_back("outside");
  return summarize_bench(
      std::move(results), rows, targets,
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}

std::vector<std::string> BenchSummary::missed() const {
  std::vector<std::string> m;
  if (top1_accuracy < targets.top1_min)
    m.push_back(fmt::format("top-1 correct in {:.1f} % of cases (target >= {:.0f} %)",
                            100 * top1_accuracy, 100 * targets.top1_min));
  if (median_shrink < targets.shrink_min)
    m.push_back(fmt::format("median holdout shrink {:.1f} % (target >= {:.0f} %)",
                            100 * median_shrink, 100 * targets.shrink_min));
  if (params_within < params_scored)
    m.push_back(fmt::format("{} of {} scored parameters off by more than {:.0f} % (worst {:.1f} %)",
                            params_scored - params_within, params_scored,
                            100 * targets.param_rel_max, 100 * param_max));
  if (confident_wrong > targets.confident_wrong_max)
    m.push_back(fmt::format("{} confident wrong answers on none/outside recordings (target <= {})",
                            confident_wrong, targets.confident_wrong_max));
  return m;
}

bool BenchSummary::met() const { return missed().empty(); }

namespace {
std::string short_name(const std::string& s) {
  if (const EffectSpec* e = find_effect(s)) return e->abbrev;
  static const std::vector<std::pair<std::string, std::string>> k = {
      {"no_gap", "nogap"}, {"unexplained", "unexpl"}, {"none", "none"}, {"outside", "outside"}};
  for (const auto& [a, b] : k)
    if (a == s) return b;
  return s;
}
}  // namespace

std::string BenchSummary::text() const {
  // Rows named after physics scenarios are wider than the vocabulary, and their truth differs.
  size_t w = 14;
  for (const auto& r : rows) w = std::max(w, r.size());
  auto expected_of = [&](const std::string& row) {
    for (const auto& r : cases)
      if (r.label == row) return r.expected;
    return expected_top1(row);
  };
  bool truth_column = false;
  for (const auto& row : rows) truth_column |= expected_of(row) != expected_top1(row);
  std::string t =
      fmt::format("confusion matrix (rows: {}, columns: top-1 verdict), {} recordings\n",
                  truth_column ? "case" : "truth", cases.size());
  t += fmt::format("{:>{}}", "", w);
  for (const auto& c : columns) t += fmt::format(" {:>6}", short_name(c));
  t += "\n";
  for (size_t r = 0; r < rows.size(); ++r) {
    t += fmt::format("{:>{}}", rows[r], w);
    for (size_t c = 0; c < columns.size(); ++c)
      t += confusion[r][c] ? fmt::format(" {:>6}", confusion[r][c]) : fmt::format(" {:>6}", ".");
    t += "\n";
  }
  t += fmt::format("\n{:>{}}{} {:>4} {:>7} {:>15} {:>7} {:>9} {:>9} {:>8}\n",
                   truth_column ? "case" : "truth", w,
                   truth_column ? fmt::format(" {:>14}", "truth") : "", "n", "top-1",
                   "gap deg (med)", "shrink", "par med", "par max", "params");
  for (const auto& row : rows) {
    int n = 0, ok = 0;
    bool effect = false;
    std::vector<double> sh, pe, gap;
    for (const auto& r : cases) {
      if (r.label != row) continue;
      ++n;
      ok += r.correct;
      effect |= r.effect_case;
      sh.push_back(r.shrink);
      gap.push_back(r.real_before);
      for (const auto& p : r.params) pe.push_back(p.rel_error);
    }
    t += fmt::format(
        "{:>{}}{} {:>4} {:>6.0f}% {:>15.3f} {:>7} {:>9} {:>9} {:>8}\n", row, w,
        truth_column ? fmt::format(" {:>14}", expected_of(row)) : "", n, n ? 100.0 * ok / n : 0.0,
        median(gap), effect ? fmt::format("{:.0f}%", 100 * median(sh)) : "-",
        pe.empty() ? "-" : fmt::format("{:.1f}%", 100 * median(pe)),
        pe.empty() ? "-" : fmt::format("{:.1f}%", 100 * *std::max_element(pe.begin(), pe.end())),
        pe.size());
  }
  t += fmt::format(
      "\ntop-1 correct: {:.1f} % of all {} recordings ({:.1f} % of the effect recordings)\n",
      100 * top1_accuracy, cases.size(), 100 * top1_effects);
  t += fmt::format(
      "median holdout shrink (1 - after/before) over the effect recordings: {:.1f} % (lowest "
      "{:.1f} %)\n",
      100 * median_shrink, 100 * min_shrink);
  t += fmt::format(
      "parameters (strong enough to matter): {} scored, {} within {:.0f} %, median error {:.2f} %, "
      "max {:.2f} %\n",
      params_scored, params_within, 100 * targets.param_rel_max, 100 * param_median,
      100 * param_max);
  t += fmt::format("confident wrong answers on none/outside recordings: {}\n", confident_wrong);
  t += fmt::format("named effects the diagnosis flagged as ambiguous: {}\n", ambiguous);
  t += fmt::format(
      "outside the vocabulary, the best effect or combination explained at most {:.1f} % of gap^2 "
      "(naming needs 90 %)\n",
      100 * outside_best_explained);
  t += fmt::format(
      "explanations refused because they left a slow change in time (more than {:.0f} % of gap^2): "
      "{}\n",
      100 * DiagnoseOptions{}.slow_share_max, slow_vetoed);
  double total = 0, worst = 0;
  for (const auto& r : cases) total += r.seconds, worst = std::max(worst, r.seconds);
  t += fmt::format(
      "diagnosis time per recording: mean {:.2f} s, max {:.2f} s (wall {:.1f} s in all)\n",
      cases.empty() ? 0.0 : total / cases.size(), worst, seconds);
  return t;
}

nlohmann::json BenchSummary::to_json() const {
  using nlohmann::json;
  json j;
  j["recordings"] = cases.size();
  j["rows"] = rows;
  j["columns"] = columns;
  j["confusion"] = confusion;
  j["top1_accuracy"] = top1_accuracy;
  j["top1_accuracy_effects"] = top1_effects;
  j["median_holdout_shrink"] = median_shrink;
  j["min_holdout_shrink"] = min_shrink;
  j["confident_wrong"] = confident_wrong;
  j["ambiguous"] = ambiguous;
  j["outside_best_explained"] = outside_best_explained;
  j["slow_vetoed"] = slow_vetoed;
  j["params"] = {{"scored", params_scored},
                 {"within", params_within},
                 {"median_rel_error", param_median},
                 {"max_rel_error", param_max}};
  j["targets"] = {{"top1_min", targets.top1_min},
                  {"shrink_min", targets.shrink_min},
                  {"param_rel_max", targets.param_rel_max},
                  {"confident_wrong_max", targets.confident_wrong_max}};
  j["met"] = met();
  j["missed"] = missed();
  j["seconds"] = seconds;
  json all = json::array();
  for (const auto& r : cases) {
    json c;
    c["index"] = r.drawn.index;
    c["truth"] = r.drawn.truth;
    if (r.label != r.drawn.truth) c["case"] = r.label;
    c["expected"] = r.expected;
    c["channels"] = r.drawn.channels;
    json p = json::object();
    for (const auto& [k, v] : r.drawn_params) p[k] = v;
    if (!r.drawn.outside.empty()) c["outside"] = r.drawn.outside;
    c["params"] = p;
    c["verdict"] = r.verdict;
    c["top1"] = r.top1;
    c["correct"] = r.correct;
    c["confident_wrong"] = r.confident_wrong;
    c["ambiguous_with"] = r.ambiguous_with;
    c["gap_deg"] = {{"before", r.real_before}, {"after", r.real_after}};
    c["holdout_deg"] = {{"before", r.hold_before}, {"after", r.hold_after}};
    c["shrink"] = r.shrink;
    c["best_explained"] = r.best_explained;
    c["slow_veto"] = r.slow_veto;
    c["slow_share"] = r.slow_share;
    json sc = json::array();
    for (const auto& q : r.params)
      sc.push_back(
          {{"name", q.name}, {"truth", q.truth}, {"fitted", q.fitted}, {"rel_error", q.rel_error}});
    c["recovery"] = sc;
    c["seconds"] = r.seconds;
    all.push_back(c);
  }
  j["cases"] = all;
  return j;
}

}  // namespace acore
