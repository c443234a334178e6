// SPDX-License-Identifier: MIT
// The effect table (sim/effect_table.*) against what its rows claim, checked by applying each
// effect: a field-domain row changes what the channels see (the context's phases or field gains)
// and a signal-domain row only the values; a row with a field factor scales the field part by
// exactly that factor; the needs (a t column, a temp column) are what the effect refuses without;
// the special cases are what their general effect reduces to (equal sampling times are a common
// delay, bit for bit); every per-channel parameter is named for every channel; the set order puts
// the angle shifts first and the signal domain last. The names against the contract: test_effects.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "sim/effect_table.hpp"
#include "sim/effects.hpp"

namespace acore {
namespace {

// A sensor without an electrical offset (so a common gain and a field scaling agree), p = 1.
double sensor_value(int c, double phi) {
  return std::sin(phi + c * M_PI / 2) + 0.02 * std::sin(3 * phi);
}
double theta_of(double t) { return 2 * std::sin(2 * M_PI * t) + 3 * t; }

Recording recording(int channels, bool with_t = true, bool with_temp = true) {
  Recording r;
  r.channels = channels;
  for (int k = 0; k < 300; ++k) {
    const double t = k / 300.0;
    if (with_t) r.t.push_back(t);
    r.theta_ref.push_back(theta_of(t));
    if (with_temp) r.temp.push_back(10 + 0.2 * k);
    for (int c = 0; c < channels; ++c) r.ch[c].push_back(sensor_value(c, theta_of(t)));
  }
  return r;
}

// Every effect with parameters that change something (the table's rows, none left out).
Effect active(const std::string& e, int channels) {
  const std::string x = effect_channel_name(channels, 1);
  if (e == "offset") return make_effect(e, {{"offset_" + x, 0.03}}, channels);
  if (e == "gain_mismatch") return make_effect(e, {{"gain_" + x, 1.04}}, channels);
  if (e == "phase_error") return make_effect(e, {{"delta_rad", 0.02}}, channels);
  if (e == "harmonic") return make_effect(e, {{"amplitude", 0.01}, {"phase_rad", 0.4}}, channels);
  if (e == "eccentricity")
    return make_effect(e, {{"epsilon_rad", 0.01}, {"phi0_rad", 0.3}, {"am_depth", 0.02}}, channels);
  if (e == "channel_skew") return make_effect(e, {{"tau_" + x, 2e-3}}, channels);
  if (e == "common_delay") return make_effect(e, {{"tau_s", 1e-3}}, channels);
  if (e == "drift") return make_effect(e, {{"gain_per_C_" + x, 1e-3}}, channels);
  if (e == "quantization") return make_effect(e, {{"bits", 8}, {"full_scale", 1.5}}, channels);
  if (e == "saturation") return make_effect(e, {{"level", 0.9}}, channels);
  if (e == "excess_noise") return make_effect(e, {{"sigma", 0.01}}, channels);
  if (e == "hysteresis") return make_effect(e, {{"h_rad", 0.01}}, channels);
  if (e == "zero_offset") return make_effect(e, {{"zero_rad", 0.05}}, channels);
  if (e == "amplitude") return make_effect(e, {{"scale", 0.9}}, channels);
  ADD_FAILURE() << "no active parameters for the table's effect '" << e << "': add them here";
  return make_effect(e, {}, channels);
}

EffectContext context(const Recording& r) {
  return make_effect_context(r, 1, sensor_value, theta_of, 3);
}

TEST(EffectTable, RowsAreInIdOrderWithUniqueNamesAndAbbreviations) {
  const auto& t = effect_table();
  ASSERT_EQ(t.size(), kEffectCount);
  std::set<std::string> names, abbrevs;
  for (size_t k = 0; k < t.size(); ++k) {
    EXPECT_EQ(static_cast<size_t>(t[k].id), k);
    EXPECT_EQ(t[k].name, effect_names()[k]);
    EXPECT_EQ(&effect_spec(t[k].name), &t[k]);
    EXPECT_EQ(effect_name(t[k].id), t[k].name);
    EXPECT_TRUE(names.insert(t[k].name).second) << t[k].name;
    EXPECT_TRUE(abbrevs.insert(t[k].abbrev).second) << t[k].abbrev;
    EXPECT_LE(t[k].abbrev.size(), 6u) << t[k].name;
    EXPECT_FALSE(t[k].meaning.empty()) << t[k].name;
    EXPECT_FALSE(t[k].status.empty()) << t[k].name;
    ASSERT_NE(t[k].apply, nullptr) << t[k].name;
  }
  EXPECT_EQ(find_effect("unexplained"), nullptr);  // a verdict
  try {
    (void)effect_spec("wobble");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("valid: offset, gain_mismatch"), std::string::npos);
  }
}

TEST(EffectTable, PerChannelParametersAreNamedForEveryChannel) {
  for (const EffectSpec& s : effect_table())
    for (int channels : {2, 4}) {
      const ParamList p = s.defaults(channels);
      size_t expected = 0;
      for (const EffectParamSpec& q : s.params) {
        EXPECT_FALSE(q.what.empty()) << s.name << " " << q.name;
        expected += q.per_channel ? static_cast<size_t>(channels) : 1;
        if (!q.per_channel) continue;
        for (int c = 0; c < channels; ++c) {
          const std::string name = q.name + effect_channel_name(channels, c);
          EXPECT_EQ(
              std::count_if(p.begin(), p.end(), [&](const auto& kv) { return kv.first == name; }),
              1)
              << name;
        }
      }
      EXPECT_EQ(p.size(), expected) << s.name;
    }
}

TEST(EffectTable, TheDomainIsWhatApplyingTheEffectChanges) {
  for (const EffectSpec& s : effect_table())
    for (int channels : {2, 4}) {
      Recording r = recording(channels);
      EffectContext ctx = context(r);
      const EffectContext before = ctx;
      const Recording values = r;
      s.apply(active(s.name, channels), r, ctx);
      bool seen = false, values_moved = false;
      for (int c = 0; c < channels; ++c) {
        seen =
            seen || ctx.phase[c] != before.phase[c] ||
            (!ctx.field_gain[c].empty() && ctx.field_gain[c] != std::vector<double>(r.size(), 1.0));
        values_moved = values_moved || r.ch[c] != values.ch[c];
      }
      EXPECT_TRUE(values_moved) << s.name << ": the active parameters change nothing";
      EXPECT_EQ(seen, s.domain == EffectDomain::field) << s.name << ", " << channels << " channels";
    }
}

TEST(EffectTable, AFieldFactorIsTheGainOnTheFieldPart) {
  for (const EffectSpec& s : effect_table()) {
    Recording r = recording(4);
    EffectContext ctx = context(r);
    const Effect e = active(s.name, 4);
    s.apply(e, r, ctx);
    for (int c = 0; c < 4; ++c) {
      const auto& g = ctx.field_gain[c];
      for (size_t i = 0; i < r.size(); i += 37) {
        const double gain = g.empty() ? 1.0 : g[i];
        // The factor at the angle the channel saw before the effect (the reference's here).
        const double want = s.field_factor ? s.field_factor(e, r.theta_ref[i]) : 1.0;
        EXPECT_DOUBLE_EQ(gain, want) << s.name << " c" << c + 1 << " sample " << i;
      }
    }
  }
}

TEST(EffectTable, AnEffectRefusesARecordingWithoutWhatItNeeds) {
  for (const EffectSpec& s : effect_table()) {
    Recording no_t = recording(4, false, true), no_temp = recording(4, true, false);
    EffectContext a = context(no_t), b = context(no_temp);
    if (s.needs_time)
      EXPECT_THROW(s.apply(active(s.name, 4), no_t, a), InputError) << s.name;
    else
      EXPECT_NO_THROW(s.apply(active(s.name, 4), no_t, a)) << s.name;
    if (s.needs_temperature)
      EXPECT_THROW(s.apply(active(s.name, 4), no_temp, b), InputError) << s.name;
    else
      EXPECT_NO_THROW(s.apply(active(s.name, 4), no_temp, b)) << s.name;
  }
}

TEST(EffectTable, SpecialCasesAreTheirGeneralEffectWithEqualParameters) {
  // Every channel sampled at t - tau is a common delay of tau, bit for bit.
  const EffectSpec& skew = effect_spec(EffectId::channel_skew);
  ASSERT_EQ(skew.special_case, EffectId::common_delay);
  Recording a = recording(4), b = recording(4);
  EffectContext ca = context(a), cb = context(b);
  ParamList taus;
  for (int c = 0; c < 4; ++c) taus.push_back({"tau_" + effect_channel_name(4, c), -1e-3});
  skew.apply(make_effect(skew.name, taus, 4), a, ca);
  effect_spec(EffectId::common_delay)
      .apply(make_effect("common_delay", {{"tau_s", 1e-3}}, 4), b, cb);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(a.ch[c], b.ch[c]);
  // Equal gains are an amplitude (the sensor here has no electrical offset).
  const EffectSpec& gain = effect_spec(EffectId::gain_mismatch);
  ASSERT_EQ(gain.special_case, EffectId::amplitude);
  EXPECT_TRUE(gain.leads_on_common_mode);
  Recording g = recording(2), m = recording(2);
  EffectContext cg = context(g), cm = context(m);
  gain.apply(make_effect(gain.name, {{"gain_sin", 0.9}, {"gain_cos", 0.9}}, 2), g, cg);
  effect_spec(EffectId::amplitude).apply(make_effect("amplitude", {{"scale", 0.9}}, 2), m, cm);
  for (int c = 0; c < 2; ++c)
    for (size_t i = 0; i < g.size(); ++i) EXPECT_NEAR(g.ch[c][i], m.ch[c][i], 1e-12);
  for (const EffectSpec& s : effect_table())
    if (s.special_case) EXPECT_NE(*s.special_case, s.id) << s.name;
}

TEST(EffectTable, SetOrderPutsAngleShiftsFirstThenScalingsThenTheSignalDomain) {
  for (const EffectSpec& s : effect_table()) {
    if (s.domain == EffectDomain::signal) EXPECT_EQ(s.set_order, 3) << s.name;
    if (s.domain == EffectDomain::field) EXPECT_LT(s.set_order, 3) << s.name;
    // A field scaling comes after the angle shifts it scales.
    if (s.field_factor) EXPECT_GT(s.set_order, 0) << s.name;
    if (s.domain == EffectDomain::field && !s.field_factor) EXPECT_EQ(s.set_order, 0) << s.name;
  }
}

}  // namespace
}  // namespace acore
