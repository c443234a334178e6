// SPDX-License-Identifier: MIT
#include "sim/effects.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "sim/effect_table.hpp"

namespace acore {

namespace {

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (size_t k = 0; k < v.size(); ++k) s += (k ? ", " : "") + v[k];
  return s;
}

// The channel count is checked before the name, as it always was.
void check_channels(const std::string& e, int channels) {
  if (channels != 2 && channels != 4)
    throw InputError(fmt::format("effect '{}': channels must be 2 or 4", e));
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
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const EffectSpec& s : effect_table()) v.push_back(s.name);
    return v;
  }();
  return names;
}

bool is_field_effect(const std::string& e) { return effect_spec(e).domain == EffectDomain::field; }

std::string effect_channel_name(int channels, int c) {
  if (channels == 2) return c == 0 ? "sin" : "cos";
  return fmt::format("c{}", c + 1);
}

ParamList effect_defaults(const std::string& e, int channels) {
  check_channels(e, channels);
  return effect_spec(e).defaults(channels);
}

Effect make_effect(const std::string& e, const ParamList& given, int channels) {
  check_channels(e, channels);
  const EffectSpec& spec = effect_spec(e);
  Effect out{e, spec.defaults(channels)};
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
  if (spec.check) spec.check(out);
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
  effect_spec(ef.effect).apply(ef, rec, ctx);
}

}  // namespace acore
