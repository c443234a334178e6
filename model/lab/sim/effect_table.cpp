// SPDX-License-Identifier: MIT
#include "sim/effect_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "core/angle.hpp"
#include "core/errors.hpp"

namespace acore {

namespace {

constexpr double kRefTempC = 25.0;  // drift reference temperature

// ---- What the apply functions share ----

// The channel's mean over an electrical turn: its electrical offset, which no field change scales.
double sensor_dc(const EffectContext& ctx, int c) {
  constexpr int kPoints = 64;  // exact for sensor harmonics below 64
  double s = 0;
  for (int k = 0; k < kPoints; ++k) s += ctx.sensor(c, 2 * kPi * k / kPoints);
  return s / kPoints;
}

// A field-domain change: channel c at sample i sees the electrical angle shifted by delta(c, i) and
// its field part multiplied by factor(c, i) (nullptr: 1). Adds the change of the sensor's field
// part to the channel and updates the context.
void change_field(Recording& rec, EffectContext& ctx, const std::string& effect,
                  const std::function<double(int, size_t)>& delta,
                  const std::function<double(int, size_t)>& factor = nullptr) {
  if (!ctx.sensor)
    throw InputError(
        fmt::format("effect '{}': needs the sensor model (field-domain effect)", effect));
  const size_t n = rec.size();
  for (int c = 0; c < rec.channels; ++c) {
    auto& ph = ctx.phase[static_cast<size_t>(c)];
    auto& g = ctx.field_gain[static_cast<size_t>(c)];
    auto& x = rec.ch[static_cast<size_t>(c)];
    if (ph.size() != n)
      throw InputError(
          fmt::format("effect '{}': context has {} phases for channel {}, the recording {} samples",
                      effect, ph.size(), c + 1, n));
    if (g.size() != n) g.assign(n, 1.0);
    const double dc = factor ? sensor_dc(ctx, c) : 0.0;
    for (size_t i = 0; i < n; ++i) {
      const double d = delta(c, i), f = factor ? factor(c, i) : 1.0;
      if (d == 0 && f == 1) continue;
      const double old_field = ctx.sensor(c, ph[i]) - dc;
      const double new_field = d == 0 ? old_field : ctx.sensor(c, ph[i] + d) - dc;
      x[i] += g[i] * (f * new_field - old_field);
      ph[i] += d;
      g[i] *= f;
    }
  }
}

void need_time(const Recording& rec, const EffectContext& ctx, const std::string& effect) {
  if (!rec.has_t())
    throw InputError(fmt::format("effect '{}': the recording has no 't' column", effect));
  if (!ctx.theta_at)
    throw InputError(fmt::format("effect '{}': needs the trajectory's angle at any time", effect));
}

std::vector<double>& chan(Recording& rec, int c) { return rec.ch[static_cast<size_t>(c)]; }
std::string cname(const Recording& rec, int c) { return effect_channel_name(rec.channels, c); }

[[noreturn]] void bad(const Effect& ef, const std::string& what) {
  throw InputError(fmt::format("effect '{}': {}", ef.effect, what));
}

// ---- Each effect: how it is applied, its value rules, its field factor ----

void apply_offset(const Effect& ef, Recording& rec, EffectContext&) {
  for (int c = 0; c < rec.channels; ++c) {
    const double o = ef.param("offset_" + cname(rec, c));
    for (auto& v : chan(rec, c)) v += o;
  }
}

void apply_gain_mismatch(const Effect& ef, Recording& rec, EffectContext&) {
  for (int c = 0; c < rec.channels; ++c) {
    const double g = ef.param("gain_" + cname(rec, c));
    for (auto& v : chan(rec, c)) v *= g;
  }
}

double amplitude_factor(const Effect& ef, double) { return ef.param("scale"); }

void apply_amplitude(const Effect& ef, Recording& rec, EffectContext& ctx) {
  const double k = amplitude_factor(ef, 0.0);
  change_field(
      rec, ctx, ef.effect, [](int, size_t) { return 0.0; }, [&](int, size_t) { return k; });
}

void check_amplitude(const Effect& ef) {
  if (ef.param("scale") <= 0) bad(ef, "parameter 'scale' must be > 0");
}

void apply_phase_error(const Effect& ef, Recording& rec, EffectContext& ctx) {
  const std::array<double, 4> d = phase_error_shifts(ef, rec.channels);
  change_field(rec, ctx, ef.effect, [&](int c, size_t) { return d[static_cast<size_t>(c)]; });
}

void apply_zero_offset(const Effect& ef, Recording& rec, EffectContext& ctx) {
  const double z = ctx.p * ef.param("zero_rad");
  change_field(rec, ctx, ef.effect, [&](int, size_t) { return z; });
}

void apply_harmonic(const Effect& ef, Recording& rec, EffectContext& ctx) {
  const size_t n = rec.size();
  const double order = ef.param("order"), a = ef.param("amplitude"), psi = ef.param("phase_rad");
  for (int c = 0; c < rec.channels; ++c) {
    const auto& ph = ctx.phase[static_cast<size_t>(c)];
    if (ph.size() != n)
      throw InputError("effect 'harmonic': the context has no phases for the recording");
    for (size_t i = 0; i < n; ++i)
      chan(rec, c)[i] += a * std::sin(order * (ph[i] + c * kPi / 2) + psi);
  }
}

void check_harmonic(const Effect& ef) {
  const double n = ef.param("order");
  if (n < 1 || n != std::floor(n) || n > 1000) bad(ef, "parameter 'order' must be an integer >= 1");
}

double eccentricity_factor(const Effect& ef, double theta) {
  return 1.0 + ef.param("am_depth") * std::cos(theta - ef.param("am_phase_rad"));
}

void apply_eccentricity(const Effect& ef, Recording& rec, EffectContext& ctx) {
  const double eps = ef.param("epsilon_rad"), phi0 = ef.param("phi0_rad");
  // Shift and factor from the channel's angle before this effect.
  auto theta = [&](int c, size_t i) { return ctx.phase[static_cast<size_t>(c)][i] / ctx.p; };
  change_field(
      rec, ctx, ef.effect,
      [&](int c, size_t i) { return ctx.p * eps * std::sin(theta(c, i) - phi0); },
      [&](int c, size_t i) { return eccentricity_factor(ef, theta(c, i)); });
}

void check_eccentricity(const Effect& ef) {
  if (std::fabs(ef.param("am_depth")) >= 1) bad(ef, "parameter 'am_depth' must be in (-1, 1)");
}

void apply_channel_skew(const Effect& ef, Recording& rec, EffectContext& ctx) {
  const std::array<double, 4> tau = channel_skew_offsets(ef, rec.channels);
  if (std::all_of(tau.begin(), tau.end(), [](double v) { return v == 0; })) return;
  need_time(rec, ctx, ef.effect);
  change_field(rec, ctx, ef.effect, [&](int c, size_t i) {
    const double tc = tau[static_cast<size_t>(c)];
    return tc == 0 ? 0.0 : ctx.p * (ctx.theta_at(rec.t[i] + tc) - ctx.theta_at(rec.t[i]));
  });
}

void apply_common_delay(const Effect& ef, Recording& rec, EffectContext& ctx) {
  const double tau = ef.param("tau_s");
  if (tau == 0) return;
  need_time(rec, ctx, ef.effect);
  // theta_at(t) is shared by every channel: evaluate once per sample.
  const size_t n = rec.size();
  std::vector<double> d(n);
  for (size_t i = 0; i < n; ++i)
    d[i] = ctx.p * (ctx.theta_at(rec.t[i] - tau) - ctx.theta_at(rec.t[i]));
  change_field(rec, ctx, ef.effect, [&](int, size_t i) { return d[i]; });
}

void apply_hysteresis(const Effect& ef, Recording& rec, EffectContext& ctx) {
  const double h = ef.param("h_rad");
  if (ctx.direction.size() != rec.size())
    throw InputError("effect 'hysteresis': the context has no rotation direction");
  change_field(rec, ctx, ef.effect,
               [&](int, size_t i) { return ctx.p * h * (ctx.direction[i] >= 0 ? 1.0 : -1.0); });
}

void apply_drift(const Effect& ef, Recording& rec, EffectContext&) {
  if (!rec.has_temp()) throw InputError("effect 'drift': the recording has no 'temp' column");
  for (int c = 0; c < rec.channels; ++c) {
    const double ko = ef.param("offset_per_C_" + cname(rec, c)),
                 kg = ef.param("gain_per_C_" + cname(rec, c));
    auto& x = chan(rec, c);
    for (size_t i = 0; i < rec.size(); ++i) {
      const double dt = rec.temp[i] - kRefTempC;
      x[i] = x[i] * (1.0 + kg * dt) + ko * dt;
    }
  }
}

void apply_quantization(const Effect& ef, Recording& rec, EffectContext&) {
  const double fs = ef.param("full_scale");
  const double step = 2.0 * fs / std::ldexp(1.0, static_cast<int>(ef.param("bits")));
  for (int c = 0; c < rec.channels; ++c)
    for (auto& v : chan(rec, c)) v = std::clamp(std::nearbyint(v / step) * step, -fs, fs - step);
}

void check_quantization(const Effect& ef) {
  const double b = ef.param("bits");
  if (b < 1 || b > 52 || b != std::floor(b))
    bad(ef, "parameter 'bits' must be an integer in 1..52");
  if (ef.param("full_scale") <= 0) bad(ef, "parameter 'full_scale' must be > 0");
}

void apply_saturation(const Effect& ef, Recording& rec, EffectContext&) {
  const double level = ef.param("level");
  for (int c = 0; c < rec.channels; ++c)
    for (auto& v : chan(rec, c)) v = std::clamp(v, -level, level);
}

void check_saturation(const Effect& ef) {
  if (ef.param("level") <= 0) bad(ef, "parameter 'level' must be > 0");
}

void apply_excess_noise(const Effect& ef, Recording& rec, EffectContext& ctx) {
  const double sigma = ef.param("sigma");
  if (sigma == 0) return;
  std::normal_distribution<double> g(0.0, sigma);
  for (size_t i = 0; i < rec.size(); ++i)
    for (int c = 0; c < rec.channels; ++c) chan(rec, c)[i] += g(ctx.rng);
}

void check_excess_noise(const Effect& ef) {
  if (ef.param("sigma") < 0) bad(ef, "parameter 'sigma' must be >= 0");
}

// ---- The rows ----

constexpr const char* kAsInContract = "as in the contract";
constexpr const char* kUnits = "sensor units";

// A row with its name and kind; the rest is set field by field below (unset: none, no, empty).
EffectSpec& row(std::array<EffectSpec, kEffectCount>& t, EffectId id, const char* name,
                const char* abbrev, EffectDomain domain) {
  EffectSpec& r = t[static_cast<size_t>(id)];
  r.id = id;
  r.name = name;
  r.abbrev = abbrev;
  r.domain = domain;
  r.set_order = domain == EffectDomain::field ? 0 : 3;
  r.status = kAsInContract;
  return r;
}

std::array<EffectSpec, kEffectCount> make_table() {
  using D = EffectDomain;
  using F = EffectFit;
  std::array<EffectSpec, kEffectCount> t{};
  {
    EffectSpec& r = row(t, EffectId::offset, "offset", "off", D::signal);
    r.params = {{"offset_", 0, kUnits, true, "added to channel X"}};
    r.apply = apply_offset;
    r.fit = F::linear;
    r.meaning = "extra DC offset on channels (not cancelled by the differences)";
  }
  {
    EffectSpec& r = row(t, EffectId::gain_mismatch, "gain_mismatch", "gain", D::signal);
    r.params = {{"gain_", 1, "factor", true,
                 "channel X, its offset included (an amplifier), times this factor"}};
    r.apply = apply_gain_mismatch;
    r.fit = F::linear;
    r.special_case = EffectId::amplitude;
    r.leads_on_common_mode = true;
    r.meaning = "channel amplitudes scaled";
    r.widened =
        "channel gains relative to each other (the whole channel: an amplifier); equal gains are "
        "`amplitude`, which the diagnosis names (fewer parameters)";
    r.status = "as in the contract, relative made explicit";
  }
  {
    EffectSpec& r = row(t, EffectId::phase_error, "phase_error", "phase", D::field);
    r.params = {{"delta_rad", 0, "rad, electrical", false,
                 "the sine pair (c1, c3 / sin) sees φ + delta_rad (orthogonality error)"},
                {"delta_cos_rad", 0, "rad, electrical", false,
                 "the cosine pair (c2, c4 / cos) sees φ + delta_cos_rad"},
                {"phase_", 0, "rad, electrical", true,
                 "channel X alone sees φ + phase_X (a misplaced plate); with two channels the "
                 "same as its pair's delta; the three add"}};
    r.apply = apply_phase_error;
    r.fit = F::field_linearized;
    r.fit_note =
        "to each group of channels it can move (either pair, one plate), the best kept; one plate "
        "only if it fits the pairs as well";
    r.meaning = "sine pair shifted in phase against the cosine pair (orthogonality error)";
    r.widened =
        "a phase shift of the sine pair (orthogonality error, as in the contract), of the cosine "
        "pair, or (four channels) of one plate: c2 moved by δ shifts c2 − c4 by δ/2 and scales it "
        "by cos(δ/2)";
    r.status = "widened: either pair, per channel";
  }
  {
    EffectSpec& r = row(t, EffectId::harmonic, "harmonic", "harm", D::signal);
    r.params = {{"order", 3, "", false, "n, an integer ≥ 1"},
                {"amplitude", 0, kUnits, false, "a, the harmonic's amplitude"},
                {"phase_rad", 0, "rad", false,
                 "ψ: channel X gets a·sin(n·(φ + position_X·π/2) + ψ), the same field harmonic "
                 "seen from each sensor's 90° position"}};
    r.apply = apply_harmonic;
    r.check = check_harmonic;
    r.fit = F::linear;
    r.fit_note =
        "orders 2..9 tried (odd ones on four channels: an even order cancels in the pairs), a "
        "common scale of the field part as a nuisance";
    r.meaning = "an extra spatial harmonic of order n seen by the sensors";
  }
  {
    EffectSpec& r = row(t, EffectId::eccentricity, "eccentricity", "ecc", D::field);
    r.params = {
        {"epsilon_rad", 0, "rad, mechanical", false,
         "every channel sees the mechanical angle θ + ε·sin(θ − φ0)"},
        {"phi0_rad", 0, "rad, mechanical", false, "φ0, the angle modulation's phase"},
        {"am_depth", 0, "", false, "m, |m| < 1: the field part times 1 + m·cos(θ − φm)"},
        {"am_phase_rad", 0, "rad, mechanical", false, "φm, the magnitude modulation's phase"}};
    r.apply = apply_eccentricity;
    r.check = check_eccentricity;
    r.field_factor = eccentricity_factor;
    r.fit = F::field_linearized;
    r.fit_note = "its magnitude modulation scales the model's field part";
    r.set_order = 1;  // after the angle shifts: a shift and a scaling
    r.meaning = "all channels see θ + ε·sin(θ − φ0) (shaft or magnet off centre)";
    r.widened =
        "once per turn: the angle θ + ε·sin(θ − φ0) **and** the field part × (1 + m·cos(θ − φm)) "
        "(shaft run-out, magnet or sensor off the axis)";
    r.status = "widened: magnitude modulation";
  }
  {
    EffectSpec& r = row(t, EffectId::channel_skew, "channel_skew", "skew", D::field);
    r.params = {{"tau_s", 0, "s", false,
                 "shorthand: the channel at position i is sampled at t + i·tau_s (c1..c4 in slots "
                 "0, τ, 2τ, 3τ); adds to tau_X"},
                {"tau_", 0, "s", true,
                 "channel X is sampled at t + tau_X: it sees the angle of that time"}};
    r.apply = apply_channel_skew;
    r.fit = F::field_linearized;
    r.fit_note = "one sampling time per channel";
    r.needs_time = true;
    r.needs_speed_change = true;
    r.special_case = EffectId::common_delay;
    r.meaning = "channels sampled at slightly different times: error grows with speed";
    r.widened =
        "each channel sampled at its own time t + τ_X: a multiplexed ADC in any slot order (the "
        "part common to all channels is a `common_delay` of −τ)";
    r.status = "widened: per channel, any order";
  }
  {
    EffectSpec& r = row(t, EffectId::common_delay, "common_delay", "delay", D::field);
    r.params = {{"tau_s", 0, "s", false, "all channels sampled at t − tau_s"}};
    r.apply = apply_common_delay;
    r.fit = F::field_linearized;
    r.needs_time = true;
    r.shift = EffectShift::at_one_speed;
    r.meaning = "all channels delayed by τ (filter latency): the angle lags by ω·τ";
  }
  {
    EffectSpec& r = row(t, EffectId::drift, "drift", "drift", D::signal);
    r.params = {{"offset_per_C_", 0, "sensor units/°C", true,
                 "channel X = x·(1 + gain_per_C_X·(T − 25 °C)) + offset_per_C_X·(T − 25 °C)"},
                {"gain_per_C_", 0, "1/°C", true, "(see offset_per_C_X)"}};
    r.apply = apply_drift;
    r.fit = F::linear;
    r.needs_temperature = true;
    r.meaning = "offsets and/or gains change with temperature";
  }
  {
    EffectSpec& r = row(t, EffectId::quantization, "quantization", "quant", D::signal);
    r.params = {{"bits", 12, "", false,
                 "an ADC of this many bits (an integer in 1..52): step = 2·full_scale/2^bits, "
                 "values rounded to the nearest step (ties to even)"},
                {"full_scale", 2, kUnits, false,
                 "its range [−full_scale, +full_scale): values clamped to [−full_scale, "
                 "full_scale − step]"}};
    r.apply = apply_quantization;
    r.check = check_quantization;
    r.fit = F::lattice;
    r.fit_note = "the step from the gaps between values, bits from the levels they span";
    r.meaning = "an ADC of B bits over a full-scale range";
  }
  {
    EffectSpec& r = row(t, EffectId::saturation, "saturation", "sat", D::signal);
    r.params = {{"level", 1, kUnits, false, "channels clipped to [−level, +level]"}};
    r.apply = apply_saturation;
    r.check = check_saturation;
    r.fit = F::level_search;
    r.meaning = "channels clipped at a level below their peak";
  }
  {
    EffectSpec& r = row(t, EffectId::excess_noise, "excess_noise", "noise", D::signal);
    r.params = {
        {"sigma", 0, kUnits, false, "independent Gaussian noise of this σ added to every channel"}};
    r.apply = apply_excess_noise;
    r.check = check_excess_noise;
    r.fit = F::noise_variance;
    r.fit_note = "rejected when the excess is correlated from one sample to the next";
    r.meaning = "more white noise than the simulation has";
  }
  {
    EffectSpec& r = row(t, EffectId::hysteresis, "hysteresis", "hyst", D::field);
    r.params = {{"h_rad", 0, "rad, mechanical", false,
                 "the angle shifted by +h_rad while rotating forward (dθ/dt ≥ 0), −h_rad "
                 "backward"}};
    r.apply = apply_hysteresis;
    r.fit = F::field_linearized;
    r.shift = EffectShift::at_one_speed;
    r.meaning = "an angle shift whose sign follows the direction of rotation";
  }
  {
    EffectSpec& r = row(t, EffectId::zero_offset, "zero_offset", "zero", D::field);
    r.params = {{"zero_rad", 0, "rad, mechanical", false, "every channel sees θ + zero_rad"}};
    r.apply = apply_zero_offset;
    r.fit = F::shift_search;
    r.shift = EffectShift::constant;
    r.meaning = "a constant angle shift, independent of speed and direction";
    r.widened =
        "a constant angle shift θ + z, independent of speed and direction (reference zero, magnet "
        "mounted turned); never fitted as delay or hysteresis when the recording has speed "
        "changes and a reversal";
    r.status = "added";
  }
  {
    EffectSpec& r = row(t, EffectId::amplitude, "amplitude", "ampl", D::field);
    r.params = {{"scale", 1, "factor", false,
                 "the field part of every channel times this (> 0): a weaker or stronger magnet, "
                 "another air gap"}};
    r.apply = apply_amplitude;
    r.check = check_amplitude;
    r.field_factor = amplitude_factor;
    r.fit = F::linear;
    r.fit_note = "on the model's field part (the channel less its constant Fourier term)";
    r.set_order = 2;  // after eccentricity: it scales the field parts that came before
    r.meaning = "the field part of every channel scaled together";
    r.widened = "the field part of every channel scaled together: magnet strength, air gap";
    r.status = "added";
  }
  for (size_t k = 0; k < t.size(); ++k)
    if (static_cast<size_t>(t[k].id) != k || t[k].name.empty() || !t[k].apply)
      throw std::logic_error(fmt::format("effect table: row {} is missing or out of order", k));
  return t;
}

}  // namespace

ParamList EffectSpec::defaults(int channels) const {
  if (channels != 2 && channels != 4)
    throw InputError(fmt::format("effect '{}': channels must be 2 or 4", name));
  ParamList p;
  for (const EffectParamSpec& s : params) {
    if (!s.per_channel) {
      p.push_back({s.name, s.no_op});
      continue;
    }
    for (int c = 0; c < channels; ++c)
      p.push_back({s.name + effect_channel_name(channels, c), s.no_op});
  }
  return p;
}

const std::array<EffectSpec, kEffectCount>& effect_table() {
  static const std::array<EffectSpec, kEffectCount> table = make_table();
  return table;
}

const EffectSpec& effect_spec(EffectId id) { return effect_table()[static_cast<size_t>(id)]; }

const EffectSpec* find_effect(const std::string& name) {
  for (const EffectSpec& s : effect_table())
    if (s.name == name) return &s;
  return nullptr;
}

const EffectSpec& effect_spec(const std::string& name) {
  if (const EffectSpec* s = find_effect(name)) return *s;
  std::string valid;
  for (const EffectSpec& s : effect_table()) valid += (valid.empty() ? "" : ", ") + s.name;
  throw InputError(fmt::format("unknown effect '{}' (valid: {})", name, valid));
}

std::string effect_fit_text(EffectFit fit) {
  switch (fit) {
    case EffectFit::linear:
      return "linear least squares";
    case EffectFit::field_linearized:
      return "linearized through the model's derivative, then applied exactly";
    case EffectFit::shift_search:
      return "started at the circular mean of the angle difference, refined by Gauss-Newton on "
             "the exact shift";
    case EffectFit::level_search:
      return "a search over the level";
    case EffectFit::noise_variance:
      return "its variance by maximum likelihood";
    case EffectFit::lattice:
      return "read from the values' lattice, not fitted";
  }
  return "";
}

}  // namespace acore
