// SPDX-License-Identifier: MIT
// The effect library (sim/effects.*) against the contract and closed forms: the names are the
// vocabulary of docs/contracts.md (read from the file) plus the two added since; every effect's
// defaults leave a recording bit for bit unchanged (where a no-op exists); the signal-domain
// effects are their formulas; the field-domain ones change the channel by the sensor's field part
// at the shifted angle and compose (zero offsets add, amplitudes multiply). The effects inside
// simulated scenarios are tested in test_simulator.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "sim/effects.hpp"

namespace acore {
namespace {

// The vocabulary table of docs/contracts.md: the backquoted names of its rows.
std::vector<std::string> contract_vocabulary() {
  std::ifstream in(std::string(ACORE_SOURCE_DIR) + "/docs/contracts.md");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string doc = ss.str();
  const size_t from = doc.find("## Effect vocabulary");
  const size_t to = doc.find("\n## ", from + 1);
  const std::string section = doc.substr(from, to - from);
  std::vector<std::string> names;
  const std::regex row(R"(\n\| `([a-z_]+)` \|)");
  for (auto it = std::sregex_iterator(section.begin(), section.end(), row);
       it != std::sregex_iterator(); ++it)
    names.push_back((*it)[1]);
  return names;
}

TEST(Effects, NamesAreTheContractsVocabularyThenTheAdditions) {
  std::vector<std::string> want = contract_vocabulary();
  ASSERT_EQ(want.size(), 13u) << "the contract's table";
  ASSERT_EQ(want.back(), "unexplained");  // a verdict, not an effect
  want.pop_back();
  want.push_back("zero_offset");
  want.push_back("amplitude");
  EXPECT_EQ(effect_names(), want);
  for (const std::string& e : effect_names()) {
    EXPECT_NO_THROW(effect_defaults(e, 4)) << e;
    EXPECT_NO_THROW(effect_defaults(e, 2)) << e;
  }
  EXPECT_THROW(effect_defaults("unexplained", 4), InputError);
  EXPECT_THROW(effect_defaults("offset", 3), InputError);
  EXPECT_EQ(effect_channel_name(4, 2), "c3");
  EXPECT_EQ(effect_channel_name(2, 1), "cos");
}

// A four- or two-channel recording on a back-and-forth trajectory with t and temp columns, the
// sensor c_k = dc_k + sin(phi + k pi/2) (two channels: sin, cos), p = 2.
struct Bench {
  Recording rec;
  EffectContext ctx;
};
double sensor_value(int c, double phi) { return 0.1 * (c + 1) + std::sin(phi + c * M_PI / 2); }
double theta_of(double t) { return 3 * std::sin(2 * M_PI * t); }
Bench bench(int channels, int p = 2) {
  Bench b;
  b.rec.channels = channels;
  for (int k = 0; k < 400; ++k) {
    const double t = k / 400.0;
    b.rec.t.push_back(t);
    b.rec.theta_ref.push_back(theta_of(t));
    b.rec.temp.push_back(20 + 0.1 * k);
    for (int c = 0; c < channels; ++c) b.rec.ch[c].push_back(sensor_value(c, p * theta_of(t)));
  }
  b.ctx = make_effect_context(b.rec, p, sensor_value, theta_of, 7);
  return b;
}

TEST(Effects, DefaultsAreNoOps) {
  for (int channels : {2, 4})
    for (const std::string& e : effect_names()) {
      if (e == "quantization" || e == "saturation") continue;  // no parameter value is a no-op
      Bench b = bench(channels);
      const Recording before = b.rec;
      apply_effect(make_effect(e, {}, channels), b.rec, b.ctx);
      for (int c = 0; c < channels; ++c) EXPECT_EQ(b.rec.ch[c], before.ch[c]) << e;
    }
}

TEST(Effects, SignalDomainEffectsAreTheirFormulas) {
  Bench b = bench(4);
  const Recording x = b.rec;
  Bench q = b;
  // drift: x (1 + g (T - 25)) + o (T - 25) per channel.
  apply_effect(make_effect("drift", {{"gain_per_C_c2", 0.01}, {"offset_per_C_c4", -0.002}}, 4),
               b.rec, b.ctx);
  for (size_t i = 0; i < x.size(); ++i) {
    const double dt = x.temp[i] - 25;
    EXPECT_DOUBLE_EQ(b.rec.ch[1][i], x.ch[1][i] * (1 + 0.01 * dt));
    EXPECT_DOUBLE_EQ(b.rec.ch[3][i], x.ch[3][i] - 0.002 * dt);
    EXPECT_EQ(b.rec.ch[0][i], x.ch[0][i]);
  }
  // quantization: 3 bits over +-1: step 1/4, codes -4..3, ties to even.
  apply_effect(make_effect("quantization", {{"bits", 3}, {"full_scale", 1}}, 4), q.rec, q.ctx);
  for (int c = 0; c < 4; ++c)
    for (size_t i = 0; i < x.size(); ++i) {
      const double code = std::min(3.0, std::max(-4.0, std::nearbyint(x.ch[c][i] * 4)));
      ASSERT_EQ(q.rec.ch[c][i], code / 4);
    }
  Bench t = bench(2);
  t.rec.ch[0] = {0.125, 0.375, -0.125, 5.0};  // ties and a clamp, on a 4-sample recording
  t.rec.ch[1] = {0, 0, 0, -5.0};
  t.rec.theta_ref.resize(4);
  t.rec.t.resize(4);
  t.rec.temp.resize(4);
  apply_effect(make_effect("quantization", {{"bits", 3}, {"full_scale", 1}}, 2), t.rec, t.ctx);
  EXPECT_EQ(t.rec.ch[0], (std::vector<double>{0.0, 0.5, 0.0, 0.75}));
  EXPECT_EQ(t.rec.ch[1][3], -1.0);
  // saturation clips both sides.
  Bench s = bench(2);
  const Recording x2 = s.rec;
  apply_effect(make_effect("saturation", {{"level", 0.5}}, 2), s.rec, s.ctx);
  for (int c = 0; c < 2; ++c)
    for (size_t i = 0; i < x2.size(); ++i)
      ASSERT_EQ(s.rec.ch[c][i], std::min(0.5, std::max(-0.5, x2.ch[c][i])));
  // excess_noise: seeded, zero mean, its sigma.
  Bench n1 = bench(4), n2 = bench(4);
  const Effect noise = make_effect("excess_noise", {{"sigma", 0.2}}, 4);
  apply_effect(noise, n1.rec, n1.ctx);
  apply_effect(noise, n2.rec, n2.ctx);
  EXPECT_EQ(n1.rec.ch[2], n2.rec.ch[2]);  // same context seed, same draws
  double sum = 0, ss = 0;
  for (int c = 0; c < 4; ++c)
    for (size_t i = 0; i < x.size(); ++i) {
      const double d = n1.rec.ch[c][i] - x.ch[c][i];
      sum += d;
      ss += d * d;
    }
  EXPECT_NEAR(sum / 1600, 0.0, 4 * 0.2 / 40);
  EXPECT_NEAR(std::sqrt(ss / 1600), 0.2, 0.2 * 4 / std::sqrt(2 * 1600.0));
}

TEST(Effects, FieldEffectsMoveTheSensorsFieldPart) {
  const int p = 2;
  // zero_offset z: every channel reads the sensor at phi + p z.
  Bench b = bench(4, p);
  apply_effect(make_effect("zero_offset", {{"zero_rad", 0.3}}, 4), b.rec, b.ctx);
  for (int c = 0; c < 4; ++c)
    for (size_t i = 0; i < b.rec.size(); ++i)
      ASSERT_NEAR(b.rec.ch[c][i], sensor_value(c, p * (b.rec.theta_ref[i] + 0.3)), 1e-12);
  // A second zero offset adds to the first.
  apply_effect(make_effect("zero_offset", {{"zero_rad", -0.1}}, 4), b.rec, b.ctx);
  for (size_t i = 0; i < b.rec.size(); ++i)
    ASSERT_NEAR(b.rec.ch[1][i], sensor_value(1, p * (b.rec.theta_ref[i] + 0.2)), 1e-12);
  // amplitude k scales the field part about the channel's mean (its dc 0.1 (c + 1)), and two
  // amplitudes multiply.
  Bench a = bench(4, p);
  apply_effect(make_effect("amplitude", {{"scale", 1.5}}, 4), a.rec, a.ctx);
  apply_effect(make_effect("amplitude", {{"scale", 0.8}}, 4), a.rec, a.ctx);
  for (int c = 0; c < 4; ++c)
    for (size_t i = 0; i < a.rec.size(); ++i) {
      const double phi = p * a.rec.theta_ref[i];
      ASSERT_NEAR(a.rec.ch[c][i], 0.1 * (c + 1) + 1.2 * std::sin(phi + c * M_PI / 2), 1e-12);
    }
  // Offsets added before a field effect are kept.
  Bench o = bench(2, p);
  apply_effect(make_effect("offset", {{"offset_cos", 0.05}}, 2), o.rec, o.ctx);
  apply_effect(make_effect("zero_offset", {{"zero_rad", 0.3}}, 2), o.rec, o.ctx);
  for (size_t i = 0; i < o.rec.size(); ++i)
    ASSERT_NEAR(o.rec.ch[1][i], 0.05 + sensor_value(1, p * (o.rec.theta_ref[i] + 0.3)), 1e-12);
}

TEST(Effects, HysteresisAndDelayFollowTheTrajectory) {
  const int p = 2;
  Bench h = bench(4, p);
  apply_effect(make_effect("hysteresis", {{"h_rad", 0.05}}, 4), h.rec, h.ctx);
  for (size_t i = 1; i < h.rec.size(); ++i) {
    const double dir = h.rec.theta_ref[i] >= h.rec.theta_ref[i - 1] ? 1 : -1;
    ASSERT_NEAR(h.rec.ch[0][i], sensor_value(0, p * (h.rec.theta_ref[i] + 0.05 * dir)), 1e-12) << i;
  }
  // common_delay tau: every channel sees theta(t - tau).
  Bench d = bench(4, p);
  apply_effect(make_effect("common_delay", {{"tau_s", 0.004}}, 4), d.rec, d.ctx);
  for (size_t i = 0; i < d.rec.size(); ++i)
    for (int c = 0; c < 4; ++c)
      ASSERT_NEAR(d.rec.ch[c][i], sensor_value(c, p * theta_of(d.rec.t[i] - 0.004)), 1e-12);
  // channel_skew: channel c at t + c tau_s + tau_X.
  Bench s = bench(4, p);
  const Effect skew = make_effect("channel_skew", {{"tau_s", 1e-3}, {"tau_c1", 5e-4}}, 4);
  const std::array<double, 4> off = channel_skew_offsets(skew, 4);
  EXPECT_EQ(off, (std::array<double, 4>{5e-4, 1e-3, 2 * 1e-3, 3 * 1e-3}));
  apply_effect(skew, s.rec, s.ctx);
  for (size_t i = 0; i < s.rec.size(); ++i)
    for (int c = 0; c < 4; ++c)
      ASSERT_NEAR(s.rec.ch[c][i], sensor_value(c, p * theta_of(s.rec.t[i] + off[c])), 1e-12);
  // phase_error: the sine pair by delta, the cosine pair by delta_cos, one plate by phase_X.
  const Effect ph = make_effect(
      "phase_error", {{"delta_rad", 0.1}, {"delta_cos_rad", -0.2}, {"phase_c3", 0.05}}, 4);
  EXPECT_EQ(phase_error_shifts(ph, 4), (std::array<double, 4>{0.1, -0.2, 0.1 + 0.05, -0.2}));
  const Effect ph2 = make_effect("phase_error", {{"delta_rad", 0.1}, {"phase_cos", 0.3}}, 2);
  EXPECT_EQ(phase_error_shifts(ph2, 2), (std::array<double, 4>{0.1, 0.3, 0, 0}));
}

TEST(Effects, WhatAnEffectNeedsIsCheckedByName) {
  Bench b = bench(4);
  Recording no_temp = b.rec;
  no_temp.temp.clear();
  EXPECT_THROW(apply_effect(make_effect("drift", {{"gain_per_C_c1", 0.01}}, 4), no_temp, b.ctx),
               InputError);
  Recording no_t = b.rec;
  no_t.t.clear();
  EXPECT_THROW(apply_effect(make_effect("common_delay", {{"tau_s", 1e-3}}, 4), no_t, b.ctx),
               InputError);
  EffectContext blind = b.ctx;
  blind.sensor = nullptr;
  Recording r = b.rec;
  EXPECT_THROW(apply_effect(make_effect("zero_offset", {{"zero_rad", 0.1}}, 4), r, blind),
               InputError);
  // Parameters: unknown names, values out of their range, non-finite values.
  EXPECT_THROW(make_effect("offset", {{"offset_sin", 1}}, 4), InputError);
  EXPECT_THROW(make_effect("harmonic", {{"order", 2.5}}, 4), InputError);
  EXPECT_THROW(make_effect("quantization", {{"bits", 0}}, 4), InputError);
  EXPECT_THROW(make_effect("saturation", {{"level", 0}}, 4), InputError);
  EXPECT_THROW(make_effect("eccentricity", {{"am_depth", 1}}, 4), InputError);
  EXPECT_THROW(make_effect("amplitude", {{"scale", NAN}}, 4), InputError);
  try {
    (void)make_effect("offset", {}, 4).param("gain_c1");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("offset_c1"), std::string::npos) << "lists what it has";
  }
  for (const std::string& e : effect_names())
    EXPECT_EQ(is_field_effect(e), e == "phase_error" || e == "eccentricity" ||
                                      e == "channel_skew" || e == "common_delay" ||
                                      e == "hysteresis" || e == "zero_offset" || e == "amplitude")
        << e;
}

}  // namespace
}  // namespace acore
