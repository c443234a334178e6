// SPDX-License-Identifier: MIT
#include "sim/effects.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace acore {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRefTempC = 25.0;  // drift reference temperature

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (size_t k = 0; k < v.size(); ++k) s += (k ? ", " : "") + v[k];
  return s;
}

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

}  // namespace

double Effect::param(const std::string& name) const {
  for (const auto& [k, v] : params)
    if (k == name) return v;
  std::vector<std::string> names;
  for (const auto& kv : params) names.push_back(kv.first);
  throw InputError(
      fmt::format("effect '{}': no parameter '{}' (has: {})", effect, name, join(names)));
}

const std::vector<std::string>& effect_names() {
  static const std::vector<std::string> names = {
      "offset",       "gain_mismatch", "phase_error", "harmonic",     "eccentricity",
      "channel_skew", "common_delay",  "drift",       "quantization", "saturation",
      "excess_noise", "hysteresis",    "zero_offset", "amplitude"};
  return names;
}

bool is_field_effect(const std::string& e) {
  return e == "phase_error" || e == "eccentricity" || e == "channel_skew" || e == "common_delay" ||
         e == "hysteresis" || e == "zero_offset" || e == "amplitude";
}

std::string effect_channel_name(int channels, int c) {
  if (channels == 2) return c == 0 ? "sin" : "cos";
  return fmt::format("c{}", c + 1);
}

ParamList effect_defaults(const std::string& e, int channels) {
  if (channels != 2 && channels != 4)
    throw InputError(fmt::format("effect '{}': channels must be 2 or 4", e));
  ParamList p;
  auto per_channel = [&](const std::string& prefix, double v) {
    for (int c = 0; c < channels; ++c) p.push_back({prefix + effect_channel_name(channels, c), v});
  };
  if (e == "offset") {
    per_channel("offset_", 0.0);
  } else if (e == "gain_mismatch") {
    per_channel("gain_", 1.0);
  } else if (e == "amplitude") {
    p = {{"scale", 1.0}};
  } else if (e == "phase_error") {
    p = {{"delta_rad", 0.0}, {"delta_cos_rad", 0.0}};
    per_channel("phase_", 0.0);
  } else if (e == "harmonic") {
    p = {{"order", 3.0}, {"amplitude", 0.0}, {"phase_rad", 0.0}};
  } else if (e == "eccentricity") {
    p = {{"epsilon_rad", 0.0}, {"phi0_rad", 0.0}, {"am_depth", 0.0}, {"am_phase_rad", 0.0}};
  } else if (e == "zero_offset") {
    p = {{"zero_rad", 0.0}};
  } else if (e == "channel_skew") {
    p = {{"tau_s", 0.0}};
    per_channel("tau_", 0.0);
  } else if (e == "common_delay") {
    p = {{"tau_s", 0.0}};
  } else if (e == "drift") {
    per_channel("offset_per_C_", 0.0);
    per_channel("gain_per_C_", 0.0);
  } else if (e == "quantization") {
    p = {{"bits", 12.0}, {"full_scale", 2.0}};
  } else if (e == "saturation") {
    p = {{"level", 1.0}};
  } else if (e == "excess_noise") {
    p = {{"sigma", 0.0}};
  } else if (e == "hysteresis") {
    p = {{"h_rad", 0.0}};
  } else {
    throw InputError(fmt::format("unknown effect '{}' (valid: {})", e, join(effect_names())));
  }
  return p;
}

Effect make_effect(const std::string& e, const ParamList& given, int channels) {
  Effect out{e, effect_defaults(e, channels)};
  for (const auto& kv_given : given) {
    const std::string& k = kv_given.first;
    const double v = kv_given.second;
    auto it = std::find_if(out.params.begin(), out.params.end(),
                           [&](const auto& kv) { return kv.first == k; });
    if (it == out.params.end()) {
      std::vector<std::string> names;
      for (const auto& kv : out.params) names.push_back(kv.first);
      throw InputError(
          fmt::format("effect '{}': unknown parameter '{}' (valid for {} channels: {})", e, k,
                      channels, join(names)));
    }
    if (!std::isfinite(v))
      throw InputError(fmt::format("effect '{}': parameter '{}' is not finite", e, k));
    it->second = v;
  }
  auto bad = [&](const std::string& what) {
    throw InputError(fmt::format("effect '{}': {}", e, what));
  };
  if (e == "harmonic") {
    const double n = out.param("order");
    if (n < 1 || n != std::floor(n) || n > 1000) bad("parameter 'order' must be an integer >= 1");
  } else if (e == "quantization") {
    const double b = out.param("bits");
    if (b < 1 || b > 52 || b != std::floor(b)) bad("parameter 'bits' must be an integer in 1..52");
    if (out.param("full_scale") <= 0) bad("parameter 'full_scale' must be > 0");
  } else if (e == "saturation") {
    if (out.param("level") <= 0) bad("parameter 'level' must be > 0");
  } else if (e == "excess_noise") {
    if (out.param("sigma") < 0) bad("parameter 'sigma' must be >= 0");
  } else if (e == "amplitude") {
    if (out.param("scale") <= 0) bad("parameter 'scale' must be > 0");
  } else if (e == "eccentricity") {
    if (std::fabs(out.param("am_depth")) >= 1) bad("parameter 'am_depth' must be in (-1, 1)");
  }
  return out;
}

std::array<double, 4> phase_error_shifts(const Effect& e, int channels) {
  std::array<double, 4> s{};
  for (int c = 0; c < channels; ++c)
    s[static_cast<size_t>(c)] = e.param(c % 2 == 0 ? "delta_rad" : "delta_cos_rad") +
                                e.param("phase_" + effect_channel_name(channels, c));
  return s;
}

std::array<double, 4> channel_skew_offsets(const Effect& e, int channels) {
  std::array<double, 4> s{};
  for (int c = 0; c < channels; ++c)
    s[static_cast<size_t>(c)] =
        c * e.param("tau_s") + e.param("tau_" + effect_channel_name(channels, c));
  return s;
}

EffectContext make_effect_context(const Recording& rec, int p,
                                  std::function<double(int, double)> sensor,
                                  std::function<double(double)> theta_at, uint64_t seed) {
  if (!rec.has_theta()) throw InputError("effect context: the recording has no theta_ref column");
  EffectContext ctx;
  ctx.p = p;
  ctx.sensor = std::move(sensor);
  ctx.theta_at = std::move(theta_at);
  ctx.rng.seed(seed);
  const size_t n = rec.size();
  for (int c = 0; c < rec.channels; ++c) {
    auto& ph = ctx.phase[static_cast<size_t>(c)];
    ph.resize(n);
    for (size_t i = 0; i < n; ++i) ph[i] = p * rec.theta_ref[i];
  }
  ctx.direction.assign(n, 1.0);
  for (size_t i = 1; i < n; ++i)
    ctx.direction[i] = rec.theta_ref[i] >= rec.theta_ref[i - 1] ? 1.0 : -1.0;
  if (n > 1) ctx.direction[0] = ctx.direction[1];
  return ctx;
}

void apply_effect(const Effect& ef, Recording& rec, EffectContext& ctx) {
  const std::string& e = ef.effect;
  const size_t n = rec.size();
  const int nch = rec.channels;
  auto chan = [&](int c) -> std::vector<double>& { return rec.ch[static_cast<size_t>(c)]; };
  auto cname = [&](int c) { return effect_channel_name(nch, c); };
  if (e == "offset") {
    for (int c = 0; c < nch; ++c) {
      const double o = ef.param("offset_" + cname(c));
      for (auto& v : chan(c)) v += o;
    }
  } else if (e == "gain_mismatch") {
    for (int c = 0; c < nch; ++c) {
      const double g = ef.param("gain_" + cname(c));
      for (auto& v : chan(c)) v *= g;
    }
  } else if (e == "amplitude") {
    const double k = ef.param("scale");
    change_field(
        rec, ctx, e, [](int, size_t) { return 0.0; }, [&](int, size_t) { return k; });
  } else if (e == "phase_error") {
    const std::array<double, 4> d = phase_error_shifts(ef, nch);
    change_field(rec, ctx, e, [&](int c, size_t) { return d[static_cast<size_t>(c)]; });
  } else if (e == "zero_offset") {
    const double z = ctx.p * ef.param("zero_rad");
    change_field(rec, ctx, e, [&](int, size_t) { return z; });
  } else if (e == "harmonic") {
    const double order = ef.param("order"), a = ef.param("amplitude"), psi = ef.param("phase_rad");
    for (int c = 0; c < nch; ++c) {
      const auto& ph = ctx.phase[static_cast<size_t>(c)];
      if (ph.size() != n)
        throw InputError("effect 'harmonic': the context has no phases for the recording");
      for (size_t i = 0; i < n; ++i)
        chan(c)[i] += a * std::sin(order * (ph[i] + c * kPi / 2) + psi);
    }
  } else if (e == "eccentricity") {
    const double eps = ef.param("epsilon_rad"), phi0 = ef.param("phi0_rad");
    const double m = ef.param("am_depth"), phim = ef.param("am_phase_rad");
    // Shift and factor from the channel's angle before this effect.
    auto theta = [&](int c, size_t i) { return ctx.phase[static_cast<size_t>(c)][i] / ctx.p; };
    change_field(
        rec, ctx, e, [&](int c, size_t i) { return ctx.p * eps * std::sin(theta(c, i) - phi0); },
        [&](int c, size_t i) { return 1.0 + m * std::cos(theta(c, i) - phim); });
  } else if (e == "channel_skew") {
    const std::array<double, 4> tau = channel_skew_offsets(ef, nch);
    if (std::all_of(tau.begin(), tau.end(), [](double v) { return v == 0; })) return;
    need_time(rec, ctx, e);
    change_field(rec, ctx, e, [&](int c, size_t i) {
      const double tc = tau[static_cast<size_t>(c)];
      return tc == 0 ? 0.0 : ctx.p * (ctx.theta_at(rec.t[i] + tc) - ctx.theta_at(rec.t[i]));
    });
  } else if (e == "common_delay") {
    const double tau = ef.param("tau_s");
    if (tau == 0) return;
    need_time(rec, ctx, e);
    // theta_at(t) is shared by every channel: evaluate once per sample.
    std::vector<double> d(n);
    for (size_t i = 0; i < n; ++i)
      d[i] = ctx.p * (ctx.theta_at(rec.t[i] - tau) - ctx.theta_at(rec.t[i]));
    change_field(rec, ctx, e, [&](int, size_t i) { return d[i]; });
  } else if (e == "hysteresis") {
    const double h = ef.param("h_rad");
    if (ctx.direction.size() != n)
      throw InputError("effect 'hysteresis': the context has no rotation direction");
    change_field(rec, ctx, e,
                 [&](int, size_t i) { return ctx.p * h * (ctx.direction[i] >= 0 ? 1.0 : -1.0); });
  } else if (e == "drift") {
    if (!rec.has_temp()) throw InputError("effect 'drift': the recording has no 'temp' column");
    for (int c = 0; c < nch; ++c) {
      const double ko = ef.param("offset_per_C_" + cname(c)),
                   kg = ef.param("gain_per_C_" + cname(c));
      auto& x = chan(c);
      for (size_t i = 0; i < n; ++i) {
        const double dt = rec.temp[i] - kRefTempC;
        x[i] = x[i] * (1.0 + kg * dt) + ko * dt;
      }
    }
  } else if (e == "quantization") {
    const double fs = ef.param("full_scale");
    const double step = 2.0 * fs / std::ldexp(1.0, static_cast<int>(ef.param("bits")));
    for (int c = 0; c < nch; ++c)
      for (auto& v : chan(c)) v = std::clamp(std::nearbyint(v / step) * step, -fs, fs - step);
  } else if (e == "saturation") {
    const double level = ef.param("level");
    for (int c = 0; c < nch; ++c)
      for (auto& v : chan(c)) v = std::clamp(v, -level, level);
  } else if (e == "excess_noise") {
    const double sigma = ef.param("sigma");
    if (sigma == 0) return;
    std::normal_distribution<double> g(0.0, sigma);
    for (size_t i = 0; i < n; ++i)
      for (int c = 0; c < nch; ++c) chan(c)[i] += g(ctx.rng);
  } else {
    throw InputError(fmt::format("unknown effect '{}' (valid: {})", e, join(effect_names())));
  }
}

}  // namespace acore
