// SPDX-License-Identifier: MIT
// The sensor simulator and its effect library: the paper's figures (docs/contracts.md, paper
// scenario), the Fourier content of the channels against the configured AF/BF, the noise model,
// every effect against its closed form, trajectories, two-channel sensors, and the scenario JSON
// round trip and errors.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/angle.hpp"
#include "core/errors.hpp"
#include "sim/simulator.hpp"
#include "support/paper_signals.hpp"

namespace acore {
namespace {

constexpr double kDeg = 180.0 / kPi;

struct Stats {
  double rms, max_abs, mean;
};

// Uncorrected angle error (deg): atan2((d13 - O13)/A13, (d24 - O24)/A24) - p theta_ref, wrapped to
// (-180, 180], O = mean, A = sqrt(2 mean((d - O)^2)).
std::vector<double> uncorrected_error(const Recording& r, int p = 1) {
  const size_t n = r.size();
  double o13 = 0, o24 = 0, v13 = 0, v24 = 0;
  for (size_t i = 0; i < n; ++i) o13 += r.d13(i) / n, o24 += r.d24(i) / n;
  for (size_t i = 0; i < n; ++i)
    v13 += std::pow(r.d13(i) - o13, 2) / n, v24 += std::pow(r.d24(i) - o24, 2) / n;
  const double a13 = std::sqrt(2 * v13), a24 = std::sqrt(2 * v24);
  std::vector<double> e(n);
  for (size_t i = 0; i < n; ++i) {
    double d = std::atan2((r.d13(i) - o13) / a13, (r.d24(i) - o24) / a24) - p * r.theta_ref[i];
    d = std::remainder(d, 2 * kPi);
    if (d <= -kPi) d += 2 * kPi;
    e[i] = d * kDeg;
  }
  return e;
}

Stats stats(const std::vector<double>& e) {
  Stats s{0, 0, 0};
  for (double x : e) s.rms += x * x, s.mean += x, s.max_abs = std::max(s.max_abs, std::fabs(x));
  s.rms = std::sqrt(s.rms / e.size());
  s.mean /= e.size();
  return s;
}

double max_diff(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double m = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) m = std::max(m, std::fabs(a[i] - b[i]));
  return m;
}

// Ideal channel c at electrical angle phi.
double ideal(int c, double phi) { return std::sin(phi + c * kPi / 2); }

TEST(Simulator, PaperScenarioUncorrectedFigures) {
  for (uint64_t seed : {1u, 2u, 12345u}) {
    const Recording r = simulate(builtin_scenario("paper"), 4096, seed);
    const Stats s = stats(uncorrected_error(r));
    std::printf("paper, N=4096, seed %llu: uncorrected RMS %.4f deg, max %.4f deg, mean %.4f deg\n",
                static_cast<unsigned long long>(seed), s.rms, s.max_abs, s.mean);
    EXPECT_NEAR(s.rms, 8.54, 0.02);
    EXPECT_NEAR(s.max_abs, 18.9, 0.02 + 0.05);  // the published figure has 3 digits: 18.85..18.95
    EXPECT_NEAR(s.mean, -6.94, 0.02);
  }
}

TEST(Simulator, PaperNoiselessMatchesTheIndependentTableImplementation) {
  const size_t n = 1000;
  const Recording a = simulate(builtin_scenario("paper-noiseless"), n, 3);
  const Recording b = test::paper_recording(n);
  ASSERT_EQ(a.channels, 4);
  for (size_t c = 0; c < 4; ++c) EXPECT_LT(max_diff(a.ch[c], b.ch[c]), 1e-12) << c;
  // The exact grid theta_k = 2 pi k / N, t_k = k / N.
  EXPECT_EQ(a.theta_ref, b.theta_ref);
  for (size_t k = 0; k < n; ++k) ASSERT_EQ(a.t[k], static_cast<double>(k) / n);
  EXPECT_FALSE(a.has_temp());
  EXPECT_EQ(a.meta.at("scenario"), "paper-noiseless");
  EXPECT_EQ(a.meta.at("seed"), "3");
  EXPECT_EQ(a.meta.at("p"), "1");
}

// DFT of a simulated channel over whole turns: the cosine/sine coefficients at each electrical
// order are the configured AF/BF plus the ideal term, the DC the offset.
TEST(Simulator, FourierContentMatchesConfiguredCoefficients) {
  Scenario s = builtin_scenario("paper-noiseless");
  s.p = 2;
  s.sensor[0].offset = 0.07;
  s.sensor[1].amplitude = 0.9;
  s.sensor[2].af.push_back(0.0);
  s.sensor[2].af.push_back(0.025);                   // order 7
  s.sensor[3].bf = {0, 0, 0, 0, 0, 0, 0, 0, -0.04};  // order 9 only
  const size_t n = 512;
  const Recording r = simulate(s, n, 1);
  for (int c = 0; c < 4; ++c) {
    const ChannelModel& m = s.sensor[static_cast<size_t>(c)];
    for (int k = 0; k <= 12; ++k) {
      double a = 0, b = 0;
      for (size_t i = 0; i < n; ++i) {
        const double phi = s.p * r.theta_ref[i];
        a += r.ch[static_cast<size_t>(c)][i] * std::cos(k * phi);
        b += r.ch[static_cast<size_t>(c)][i] * std::sin(k * phi);
      }
      a *= (k == 0 ? 1.0 : 2.0) / n;
      b *= 2.0 / n;
      double want_a = k == 0 ? m.offset : (k <= static_cast<int>(m.af.size()) ? m.af[k - 1] : 0.0);
      double want_b = k >= 1 && k <= static_cast<int>(m.bf.size()) ? m.bf[k - 1] : 0.0;
      if (k == 1) {
        // c1 = A sin, c2 = A cos, c3 = -A sin, c4 = -A cos (Eq. 2 with the c4 sign fixed).
        const double sign = c < 2 ? 1.0 : -1.0;
        (c % 2 == 0 ? want_b : want_a) += sign * m.amplitude;
      }
      EXPECT_NEAR(a, want_a, 1e-12) << "channel " << c + 1 << " cos order " << k;
      if (k > 0) EXPECT_NEAR(b, want_b, 1e-12) << "channel " << c + 1 << " sin order " << k;
    }
  }
}

TEST(Simulator, CommonNoiseCancelsInTheDifferences) {
  const size_t n = 20000;
  const Recording noisy = simulate(builtin_scenario("paper"), n, 9);
  const Recording clean = simulate(builtin_scenario("paper-noiseless"), n, 9);
  double var = 0, mean = 0;
  for (size_t i = 0; i < n; ++i) {
    EXPECT_NEAR(noisy.d13(i), clean.d13(i), 1e-12);
    EXPECT_NEAR(noisy.d24(i), clean.d24(i), 1e-12);
    const double d = noisy.ch[0][i] - clean.ch[0][i];
    // The same draw on every channel.
    ASSERT_NEAR(noisy.ch[3][i] - clean.ch[3][i], d, 1e-12);
    mean += d / n;
    var += d * d / n;
  }
  EXPECT_NEAR(mean, 0, 0.002);
  EXPECT_NEAR(std::sqrt(var), 0.05, 0.002);
  // Deterministic in the seed, different across seeds.
  EXPECT_EQ(simulate(builtin_scenario("paper"), 100, 9).ch[0],
            simulate(builtin_scenario("paper"), 100, 9).ch[0]);
  EXPECT_NE(simulate(builtin_scenario("paper"), 100, 9).ch[0],
            simulate(builtin_scenario("paper"), 100, 10).ch[0]);
}

TEST(Simulator, IndependentNoiseIsPerChannel) {
  const size_t n = 20000;
  const Recording noisy = simulate(builtin_scenario("paper-indep"), n, 4);
  const Recording clean = simulate(builtin_scenario("paper-noiseless"), n, 4);
  double v1 = 0, v3 = 0, cov = 0;
  for (size_t i = 0; i < n; ++i) {
    const double a = noisy.ch[0][i] - clean.ch[0][i], b = noisy.ch[2][i] - clean.ch[2][i];
    v1 += a * a / n, v3 += b * b / n, cov += a * b / n;
  }
  EXPECT_NEAR(std::sqrt(v1), 0.05, 0.002);
  EXPECT_NEAR(std::sqrt(v3), 0.05, 0.002);
  EXPECT_NEAR(cov / std::sqrt(v1 * v3), 0.0, 0.03);
}

TEST(Simulator, TwoChannelSensor) {
  const Scenario four = builtin_scenario("paper-noiseless");
  const Scenario two = with_channels(four, 2);
  const Recording r4 = simulate(four, 300, 1), r2 = simulate(two, 300, 1);
  EXPECT_EQ(r2.channels, 2);
  EXPECT_TRUE(r2.ch[2].empty());
  EXPECT_EQ(r2.ch[0], r4.ch[0]);  // sin = A1 sin + e1s
  EXPECT_EQ(r2.ch[1], r4.ch[1]);  // cos = A2 cos + e2s
  EXPECT_EQ(r2.meta.at("channels"), "2");
  // The TMR-like built-in: 3.5% gain mismatch, offsets, a small angle error.
  const Recording t = simulate(builtin_scenario("tmr"), 4096, 5);
  EXPECT_EQ(t.channels, 2);
  double ms = 0, mc = 0, ps = 0, pc = 0;
  for (size_t i = 0; i < t.size(); ++i) {
    ms += t.ch[0][i] / t.size(), mc += t.ch[1][i] / t.size();
    ps = std::max(ps, std::fabs(t.ch[0][i])), pc = std::max(pc, std::fabs(t.ch[1][i]));
  }
  EXPECT_NEAR(ms, 0.012, 0.001);
  EXPECT_NEAR(mc, -0.018, 0.001);
  const Stats e = stats(uncorrected_error(t));
  EXPECT_GT(e.rms, 0.05);
  EXPECT_LT(e.max_abs, 3.0);
}

// ---- Effects, each against its closed form on the ideal sensor ----

Scenario ideal_with(const std::string& effect, const ParamList& params, int channels = 4) {
  Scenario s = builtin_scenario("ideal");
  s.channels = channels;
  s.effects.push_back(make_effect(effect, params, channels));
  return s;
}

TEST(Effects, NamesParametersAndErrors) {
  EXPECT_EQ(effect_names().size(), 14u);
  for (const auto& e : effect_names()) {
    EXPECT_FALSE(effect_defaults(e, 4).empty()) << e;
    // Defaults are a no-op on the ideal sensor (quantization and saturation excepted).
    if (e == "quantization" || e == "saturation") continue;
    Scenario s = builtin_scenario("ideal");
    s.effects.push_back(make_effect(e, {}, 4));
    const Recording a = simulate(s, 64, 1), b = simulate(builtin_scenario("ideal"), 64, 1);
    for (size_t c = 0; c < 4; ++c) EXPECT_LT(max_diff(a.ch[c], b.ch[c]), 1e-15) << e;
  }
  const ParamList off2 = effect_defaults("offset", 2);
  ASSERT_EQ(off2.size(), 2u);
  EXPECT_EQ(off2[0].first, "offset_sin");
  EXPECT_EQ(off2[1].first, "offset_cos");
  EXPECT_EQ(effect_defaults("drift", 4)[4].first, "gain_per_C_c1");
  EXPECT_THROW(make_effect("wobble", {}, 4), InputError);
  EXPECT_THROW(make_effect("offset", {{"offset_c5", 1}}, 4), InputError);
  EXPECT_THROW(make_effect("quantization", {{"bits", 0}}, 4), InputError);
  EXPECT_THROW(make_effect("harmonic", {{"order", 2.5}}, 4), InputError);
  EXPECT_THROW(make_effect("saturation", {{"level", -1}}, 4), InputError);
  EXPECT_THROW(make_effect("offset", {{"offset_c1", 1}}, 4).param("gain_c1"), InputError);
  EXPECT_THROW(make_effect("amplitude", {{"scale", 0}}, 4), InputError);
  EXPECT_THROW(make_effect("eccentricity", {{"am_depth", 1}}, 4), InputError);
  EXPECT_THROW(make_effect("channel_skew", {{"tau_c1", 1e-4}}, 2), InputError);  // sin, cos
  EXPECT_TRUE(is_field_effect("zero_offset"));
  EXPECT_TRUE(is_field_effect("amplitude"));
  EXPECT_TRUE(is_field_effect("hysteresis"));
  EXPECT_FALSE(is_field_effect("offset"));
}

TEST(Effects, OffsetAndGainMismatch) {
  const Recording r = simulate(
      ideal_with(
          "offset",
          {{"offset_c1", 0.1}, {"offset_c2", -0.2}, {"offset_c3", 0.3}, {"offset_c4", 0.04}}),
      100, 1);
  const Recording g = simulate(
      ideal_with("gain_mismatch",
                 {{"gain_c1", 1.1}, {"gain_c2", 0.9}, {"gain_c3", 1.0}, {"gain_c4", 1.25}}),
      100, 1);
  const double o[4] = {0.1, -0.2, 0.3, 0.04}, k[4] = {1.1, 0.9, 1.0, 1.25};
  for (size_t i = 0; i < 100; ++i)
    for (int c = 0; c < 4; ++c) {
      EXPECT_NEAR(r.ch[static_cast<size_t>(c)][i], ideal(c, r.theta_ref[i]) + o[c], 1e-14);
      EXPECT_NEAR(g.ch[static_cast<size_t>(c)][i], k[c] * ideal(c, g.theta_ref[i]), 1e-14);
    }
}

TEST(Effects, PhaseErrorShiftsTheSinePairOnly) {
  const double d = 0.02;
  for (int channels : {4, 2}) {
    Scenario s = ideal_with("phase_error", {{"delta_rad", d}}, channels);
    s.p = 3;
    const Recording r = simulate(s, 200, 1);
    for (size_t i = 0; i < 200; ++i) {
      const double phi = 3 * r.theta_ref[i];
      EXPECT_NEAR(r.ch[0][i], std::sin(phi + d), 1e-14);
      EXPECT_NEAR(r.ch[1][i], std::cos(phi), 1e-14);
      if (channels == 4) {
        EXPECT_NEAR(r.ch[2][i], -std::sin(phi + d), 1e-14);
        EXPECT_NEAR(r.ch[3][i], -std::cos(phi), 1e-14);
      }
    }
  }
}

TEST(Effects, HarmonicSeenFromEachPosition) {
  const double a = 0.03, psi = 0.4;
  const Recording r = simulate(
      ideal_with("harmonic", {{"order", 3}, {"amplitude", a}, {"phase_rad", psi}}), 256, 1);
  for (size_t i = 0; i < 256; ++i)
    for (int c = 0; c < 4; ++c) {
      const double x = r.theta_ref[i] + c * kPi / 2;  // the field angle at the sensor's position
      EXPECT_NEAR(r.ch[static_cast<size_t>(c)][i], std::sin(x) + a * std::sin(3 * x + psi), 1e-14);
    }
  // Odd orders survive the difference (doubled), even orders cancel in c1 - c3.
  const Recording even = simulate(ideal_with("harmonic", {{"order", 2}, {"amplitude", a}}), 64, 1);
  for (size_t i = 0; i < 64; ++i) EXPECT_NEAR(even.d13(i), 2 * std::sin(even.theta_ref[i]), 1e-14);
}

TEST(Effects, Eccentricity) {
  const double eps = 0.01, phi0 = 0.7;
  Scenario s = ideal_with("eccentricity", {{"epsilon_rad", eps}, {"phi0_rad", phi0}});
  s.p = 2;
  const Recording r = simulate(s, 300, 1);
  for (size_t i = 0; i < 300; ++i) {
    const double th = r.theta_ref[i] + eps * std::sin(r.theta_ref[i] - phi0);
    for (int c = 0; c < 4; ++c)
      EXPECT_NEAR(r.ch[static_cast<size_t>(c)][i], ideal(c, 2 * th), 1e-14);
  }
  // The electrical angle of the differences is p * (theta + eps sin(theta - phi0)).
  for (size_t i = 0; i < 300; ++i) {
    const double e = std::remainder(std::atan2(r.d13(i), r.d24(i)) - 2 * r.theta_ref[i], 2 * kPi);
    EXPECT_NEAR(e, 2 * eps * std::sin(r.theta_ref[i] - phi0), 1e-12);
  }
}

// The magnitude part of eccentricity and the amplitude effect scale the field part only: a
// channel's electrical offset (C0) stays.
TEST(Effects, EccentricityModulatesTheMagnitudeToo) {
  const double eps = 0.01, phi0 = 0.7, m = 0.02, phim = -0.4, c0 = 0.1;
  Scenario s = ideal_with(
      "eccentricity",
      {{"epsilon_rad", eps}, {"phi0_rad", phi0}, {"am_depth", m}, {"am_phase_rad", phim}});
  s.p = 2;
  s.sensor[0].offset = c0;
  const Recording r = simulate(s, 300, 1);
  for (size_t i = 0; i < 300; ++i) {
    const double th = r.theta_ref[i], seen = th + eps * std::sin(th - phi0),
                 k = 1 + m * std::cos(th - phim);
    for (int c = 0; c < 4; ++c)
      EXPECT_NEAR(r.ch[static_cast<size_t>(c)][i], (c == 0 ? c0 : 0.0) + k * ideal(c, 2 * seen),
                  1e-14);
  }
}

TEST(Effects, AmplitudeAndZeroOffset) {
  const double k = 0.7, z = 0.03, c0 = -0.05;
  for (int channels : {4, 2}) {
    Scenario a = ideal_with("amplitude", {{"scale", k}}, channels);
    a.sensor[1].offset = c0;
    Scenario zs = ideal_with("zero_offset", {{"zero_rad", z}}, channels);
    zs.p = 3;  // the shift is mechanical: the electrical angle moves by p z
    const Recording ra = simulate(a, 200, 1), rz = simulate(zs, 200, 1);
    for (size_t i = 0; i < 200; ++i)
      for (int c = 0; c < channels; ++c) {
        EXPECT_NEAR(ra.ch[static_cast<size_t>(c)][i],
                    (c == 1 ? c0 : 0.0) + k * ideal(c, ra.theta_ref[i]), 1e-14);
        EXPECT_NEAR(rz.ch[static_cast<size_t>(c)][i], ideal(c, 3 * (rz.theta_ref[i] + z)), 1e-14);
      }
  }
  // Field scalings compose, in either order.
  Scenario both = ideal_with("amplitude", {{"scale", k}});
  both.effects.push_back(make_effect("eccentricity", {{"am_depth", 0.1}}, 4));
  Scenario swapped = both;
  std::swap(swapped.effects[0], swapped.effects[1]);
  const Recording b = simulate(both, 100, 1), w = simulate(swapped, 100, 1);
  for (size_t c = 0; c < 4; ++c) EXPECT_LT(max_diff(b.ch[c], w.ch[c]), 1e-14);
  for (size_t i = 0; i < 100; ++i)
    EXPECT_NEAR(b.ch[0][i], k * (1 + 0.1 * std::cos(b.theta_ref[i])) * std::sin(b.theta_ref[i]),
                1e-14);
}

// phase_error per channel: one plate moved (c2 alone), the cosine pair, and delta_rad as before;
// the pair and channel parameters add.
TEST(Effects, PhaseErrorOnEitherPairOrOneChannel) {
  const double d = 0.03, e = -0.01;
  const Recording r =
      simulate(ideal_with("phase_error", {{"delta_cos_rad", d}, {"phase_c2", e}}), 200, 1);
  for (size_t i = 0; i < 200; ++i) {
    const double phi = r.theta_ref[i];
    EXPECT_NEAR(r.ch[0][i], std::sin(phi), 1e-14);
    EXPECT_NEAR(r.ch[1][i], std::cos(phi + d + e), 1e-14);
    EXPECT_NEAR(r.ch[3][i], -std::cos(phi + d), 1e-14);
    // One plate moved by e: c2 - c4 is 2 cos(e/2) cos(phi + d + e/2) (half the shift, and smaller).
    EXPECT_NEAR(r.d24(i), 2 * std::cos(e / 2) * std::cos(phi + d + e / 2), 1e-14);
  }
  // delta_rad is the sine pair's shift, the same as phase_c1 = phase_c3.
  const Recording a = simulate(ideal_with("phase_error", {{"delta_rad", d}}), 100, 1);
  const Recording b =
      simulate(ideal_with("phase_error", {{"phase_c1", d}, {"phase_c3", d}}), 100, 1);
  for (size_t c = 0; c < 4; ++c) EXPECT_LT(max_diff(a.ch[c], b.ch[c]), 1e-15);
  const std::array<double, 4> sh =
      phase_error_shifts(make_effect("phase_error", {{"delta_rad", d}, {"phase_c4", e}}, 4), 4);
  EXPECT_EQ(sh, (std::array<double, 4>{d, 0, d, e}));
}

Scenario constant_speed(double speed_rps, double fs) {
  Scenario s = builtin_scenario("ideal");
  s.trajectory.kind = "constant";
  s.trajectory.speed_rps = speed_rps;
  s.trajectory.sample_rate_hz = fs;
  return s;
}

TEST(Effects, ChannelSkewAndCommonDelay) {
  // 5 rev/s: omega tau = 0.18 deg; 800 samples at 2 kHz = 2 whole turns (unbiased mean and
  // amplitude).
  const double tau = 1e-4, v = 5.0;
  const size_t n = 800;
  Scenario s = constant_speed(v, 2000);
  s.effects.push_back(make_effect("channel_skew", {{"tau_s", tau}}, 4));
  const Recording r = simulate(s, n, 1);
  for (size_t i = 0; i < n; ++i)
    for (int c = 0; c < 4; ++c) {
      const double th = 2 * kPi * v * (r.t[i] + c * tau);
      EXPECT_NEAR(r.ch[static_cast<size_t>(c)][i], ideal(c, th), 1e-12);
    }
  Scenario d = constant_speed(v, 2000);
  d.effects.push_back(make_effect("common_delay", {{"tau_s", tau}}, 4));
  const Recording q = simulate(d, n, 1);
  for (size_t i = 0; i < n; ++i)
    EXPECT_NEAR(q.ch[1][i], std::cos(2 * kPi * v * (q.t[i] - tau)), 1e-12);
  // The angle lags by omega tau.
  EXPECT_NEAR(stats(uncorrected_error(q)).mean, -360 * v * tau, 1e-6);
  // Faster rotation, larger skew error.
  Scenario fast = constant_speed(4 * v, 2000);
  fast.effects = s.effects;
  EXPECT_GT(stats(uncorrected_error(simulate(fast, n, 1))).rms,
            3 * stats(uncorrected_error(r)).rms);
}

// A multiplexed ADC in any slot order: tau_X per channel; tau_s (slots 0, tau, 2 tau, 3 tau in
// channel order) is the same as tau_c2 = tau, tau_c3 = 2 tau, tau_c4 = 3 tau.
TEST(Effects, ChannelSkewPerChannel) {
  const double tau = 1e-4, v = 5.0;
  const size_t n = 800;
  Scenario s = constant_speed(v, 2000);
  s.effects.push_back(
      make_effect("channel_skew", {{"tau_c1", 2 * tau}, {"tau_c3", 3 * tau}, {"tau_c4", tau}}, 4));
  const Recording r = simulate(s, n, 1);
  const double slot[4] = {2, 0, 3, 1};
  for (size_t i = 0; i < n; ++i)
    for (int c = 0; c < 4; ++c)
      EXPECT_NEAR(r.ch[static_cast<size_t>(c)][i], ideal(c, 2 * kPi * v * (r.t[i] + slot[c] * tau)),
                  1e-12);
  Scenario a = constant_speed(v, 2000), b = a;
  a.effects.push_back(make_effect("channel_skew", {{"tau_s", tau}}, 4));
  b.effects.push_back(
      make_effect("channel_skew", {{"tau_c2", tau}, {"tau_c3", 2 * tau}, {"tau_c4", 3 * tau}}, 4));
  const Recording ra = simulate(a, n, 1), rb = simulate(b, n, 1);
  for (size_t c = 0; c < 4; ++c) EXPECT_LT(max_diff(ra.ch[c], rb.ch[c]), 1e-15);
  // Two channels: sin, cos.
  Scenario two = constant_speed(v, 2000);
  two.channels = 2;
  two.effects.push_back(make_effect("channel_skew", {{"tau_sin", tau}}, 2));
  const Recording r2 = simulate(two, n, 1);
  for (size_t i = 0; i < n; ++i) {
    EXPECT_NEAR(r2.ch[0][i], std::sin(2 * kPi * v * (r2.t[i] + tau)), 1e-12);
    EXPECT_NEAR(r2.ch[1][i], std::cos(2 * kPi * v * r2.t[i]), 1e-12);
  }
}

// Scenario files written before the vocabulary was widened keep their meaning: eccentricity
// without magnitude modulation, channel_skew's tau_s, phase_error's delta_rad.
TEST(Effects, OldScenarioFilesKeepTheirMeaning) {
  const Scenario s = Scenario::from_json(nlohmann::json::parse(R"({"effects": [
      {"effect": "eccentricity", "epsilon_rad": 0.01, "phi0_rad": 0.3},
      {"effect": "channel_skew", "tau_s": 1e-4},
      {"effect": "phase_error", "delta_rad": 0.02}]})"));
  EXPECT_EQ(s.effects[0].param("am_depth"), 0.0);
  const std::array<double, 4> tau = channel_skew_offsets(s.effects[1], 4);
  for (size_t c = 0; c < 4; ++c) EXPECT_NEAR(tau[c], 1e-4 * c, 1e-18);
  EXPECT_EQ(phase_error_shifts(s.effects[2], 4), (std::array<double, 4>{0.02, 0, 0.02, 0}));
}

TEST(Effects, DriftFollowsTemperature) {
  Scenario s = ideal_with("drift", {{"offset_per_C_c1", 1e-3}, {"gain_per_C_c2", -2e-3}});
  s.temperature = {true, 25, 65};
  const Recording r = simulate(s, 101, 1);
  ASSERT_TRUE(r.has_temp());
  EXPECT_DOUBLE_EQ(r.temp.front(), 25);
  EXPECT_DOUBLE_EQ(r.temp.back(), 65);
  for (size_t i = 0; i < 101; ++i) {
    const double dt = r.temp[i] - 25;
    EXPECT_NEAR(r.ch[0][i], std::sin(r.theta_ref[i]) + 1e-3 * dt, 1e-14);
    EXPECT_NEAR(r.ch[1][i], std::cos(r.theta_ref[i]) * (1 - 2e-3 * dt), 1e-14);
    EXPECT_NEAR(r.ch[2][i], -std::sin(r.theta_ref[i]), 1e-14);
  }
  // Drift forces the temp column even without an enabled profile (constant 25: no change).
  EXPECT_TRUE(simulate(ideal_with("drift", {{"offset_per_C_c1", 1}}), 10, 1).has_temp());
}

TEST(Effects, QuantizationAndSaturation) {
  const Recording q =
      simulate(ideal_with("quantization", {{"bits", 6}, {"full_scale", 2}}), 500, 1);
  const double step = 4.0 / 64;
  for (size_t i = 0; i < 500; ++i)
    for (int c = 0; c < 4; ++c) {
      const double v = q.ch[static_cast<size_t>(c)][i];
      EXPECT_NEAR(v / step, std::round(v / step), 1e-9);
      EXPECT_LE(std::fabs(v - ideal(c, q.theta_ref[i])), step / 2 + 1e-12);
    }
  // Full scale below the peak: the ADC range clips at -fs and fs - step.
  const Recording c =
      simulate(ideal_with("quantization", {{"bits", 4}, {"full_scale", 0.5}}), 400, 1);
  EXPECT_DOUBLE_EQ(*std::max_element(c.ch[0].begin(), c.ch[0].end()), 0.5 - 1.0 / 16);
  EXPECT_DOUBLE_EQ(*std::min_element(c.ch[0].begin(), c.ch[0].end()), -0.5);
  const Recording s = simulate(ideal_with("saturation", {{"level", 0.8}}), 400, 1);
  for (size_t i = 0; i < 400; ++i)
    EXPECT_DOUBLE_EQ(s.ch[1][i], std::clamp(std::cos(s.theta_ref[i]), -0.8, 0.8));
}

TEST(Effects, ExcessNoise) {
  const size_t n = 20000;
  const Recording r = simulate(ideal_with("excess_noise", {{"sigma", 0.01}}), n, 3);
  double v = 0, m = 0, cov = 0;
  for (size_t i = 0; i < n; ++i) {
    const double a = r.ch[0][i] - std::sin(r.theta_ref[i]),
                 b = r.ch[2][i] + std::sin(r.theta_ref[i]);
    v += a * a / n, m += a / n, cov += a * b / n;
  }
  EXPECT_NEAR(std::sqrt(v), 0.01, 0.0004);
  EXPECT_NEAR(m, 0, 0.0004);
  EXPECT_NEAR(cov / v, 0, 0.03);  // independent per channel
}

TEST(Effects, HysteresisFollowsTheDirection) {
  const double h = 0.005;
  Scenario s = ideal_with("hysteresis", {{"h_rad", h}});
  s.trajectory.kind = "reversal";
  s.trajectory.sweep_turns = 1;
  s.trajectory.cycles = 2;
  const Recording r = simulate(s, 2000, 1);
  int fwd = 0, back = 0;
  for (size_t i = 0; i < 2000; ++i) {
    // Forward in the first half of each back-and-forth period (period 0.5 s over the 1 s
    // recording).
    const double u = std::fmod(r.t[i], 0.5);
    const double dir = u < 0.25 ? 1.0 : -1.0;
    (dir > 0 ? fwd : back)++;
    EXPECT_NEAR(r.ch[0][i], std::sin(r.theta_ref[i] + dir * h), 1e-12) << i;
    EXPECT_NEAR(r.ch[1][i], std::cos(r.theta_ref[i] + dir * h), 1e-12) << i;
  }
  EXPECT_EQ(fwd, 1000);
  EXPECT_EQ(back, 1000);
}

TEST(Effects, ApplyToAnExistingRecording) {
  // The same transform outside simulate(): a context built from the recording itself.
  Recording r = test::paper_recording(360);
  const Recording before = r;
  const Scenario paper = builtin_scenario("paper-noiseless");
  EffectContext ctx = make_effect_context(
      r, 1, [&](int c, double phi) { return paper.channel_value(c, phi); }, nullptr, 1);
  apply_effect(make_effect("eccentricity", {{"epsilon_rad", 0.02}, {"phi0_rad", 0}}, 4), r, ctx);
  for (size_t i = 0; i < r.size(); ++i) {
    const double th = before.theta_ref[i] + 0.02 * std::sin(before.theta_ref[i]);
    EXPECT_NEAR(r.ch[2][i], paper.channel_value(2, th), 1e-12);
  }
  // Without t and a trajectory, a delay cannot be applied.
  EXPECT_THROW(apply_effect(make_effect("common_delay", {{"tau_s", 1e-3}}, 4), r, ctx), InputError);
  Recording no_temp = before;
  EXPECT_THROW(apply_effect(make_effect("drift", {{"offset_per_C_c1", 1e-3}}, 4), no_temp, ctx),
               InputError);
}

// ---- Trajectories ----

TEST(Trajectory, KindsAndSampleRate) {
  Scenario s = builtin_scenario("ideal");
  s.trajectory.kind = "constant";
  s.trajectory.turns = 3;
  s.trajectory.sample_rate_hz = 1000;
  Recording r = simulate(s, 3000, 1);
  EXPECT_DOUBLE_EQ(r.t[1], 1e-3);
  EXPECT_NEAR(r.theta_ref.back() + (r.theta_ref[1] - r.theta_ref[0]), 3 * 2 * kPi,
              1e-9);  // unwrapped
  s.trajectory.kind = "ramp";
  s.trajectory.turns = 2;
  r = simulate(s, 1000, 1);
  const double d_first = r.theta_ref[1] - r.theta_ref[0],
               d_last = r.theta_ref[999] - r.theta_ref[998];
  EXPECT_NEAR(d_first, 2 * kPi * (4.0 * 0.5e-3) * 1e-3, 1e-9);  // v(t) = 4 t rev/s from 0 to 4
  EXPECT_GT(d_last, 100 * d_first);
  EXPECT_NEAR(r.theta_ref[999], 2 * kPi * 2 * 0.999 * 0.999, 1e-9);
  s.trajectory.kind = "reversal";
  s.trajectory.sweep_turns = 0.5;
  s.trajectory.cycles = 1;
  r = simulate(s, 1000, 1);
  EXPECT_NEAR(*std::max_element(r.theta_ref.begin(), r.theta_ref.end()), kPi, 0.01);
  EXPECT_NEAR(r.theta_ref[999], 2 * kPi * 0.001, 1e-9);  // back near the start
}

// ---- Scenario JSON ----

TEST(Scenario, JsonRoundTrip) {
  Scenario s = builtin_scenario("paper");
  s.p = 2;
  s.trajectory.kind = "reversal";
  s.trajectory.sample_rate_hz = 10000;
  s.temperature = {true, 20, 30};
  for (const auto& e : effect_names()) s.effects.push_back(make_effect(e, {}, 4));
  s.effects[0] = make_effect("offset", {{"offset_c3", 0.25}}, 4);
  const nlohmann::json j = s.to_json();
  const Scenario b = Scenario::from_json(nlohmann::json::parse(j.dump()));
  EXPECT_EQ(b.to_json(), j);
  EXPECT_EQ(b.effects.size(), 14u);
  EXPECT_DOUBLE_EQ(b.effects[0].param("offset_c3"), 0.25);
  const Recording ra = simulate(s, 200, 5), rb = simulate(b, 200, 5);
  for (size_t c = 0; c < 4; ++c) EXPECT_EQ(ra.ch[c], rb.ch[c]);
  // Every built-in survives the trip.
  for (const auto& n : builtin_scenario_names()) {
    const Scenario x = builtin_scenario(n);
    EXPECT_EQ(Scenario::from_json(x.to_json()).to_json(), x.to_json()) << n;
  }
}

TEST(Scenario, WithChannelsRemapsPerChannelParameters) {
  Scenario s = builtin_scenario("ideal");
  s.effects.push_back(
      make_effect("offset", {{"offset_c1", 0.1}, {"offset_c2", 0.2}, {"offset_c3", 0.3}}, 4));
  s.effects.push_back(make_effect("drift", {{"gain_per_C_c2", 1e-3}}, 4));
  s.effects.push_back(make_effect("phase_error", {{"delta_rad", 0.01}, {"phase_c2", 0.02}}, 4));
  s.effects.push_back(make_effect("channel_skew", {{"tau_c2", 1e-4}}, 4));
  const Scenario two = with_channels(s, 2);
  EXPECT_EQ(two.channels, 2);
  ASSERT_EQ(two.effects[0].params.size(), 2u);
  EXPECT_DOUBLE_EQ(two.effects[0].param("offset_sin"), 0.1);
  EXPECT_DOUBLE_EQ(two.effects[0].param("offset_cos"), 0.2);
  EXPECT_DOUBLE_EQ(two.effects[1].param("gain_per_C_cos"), 1e-3);
  EXPECT_DOUBLE_EQ(two.effects[2].param("delta_rad"), 0.01);
  EXPECT_DOUBLE_EQ(two.effects[2].param("phase_cos"), 0.02);
  EXPECT_DOUBLE_EQ(two.effects[3].param("tau_cos"), 1e-4);
  const Scenario four = with_channels(two, 4);
  EXPECT_DOUBLE_EQ(four.effects[3].param("tau_c4"), 1e-4);
  EXPECT_DOUBLE_EQ(four.effects[0].param("offset_c3"), 0.1);
  EXPECT_DOUBLE_EQ(four.effects[0].param("offset_c4"), 0.2);
  EXPECT_THROW(with_channels(s, 3), InputError);
}

std::string json_error(const std::string& text) {
  try {
    Scenario::from_json(nlohmann::json::parse(text), "cfg.json");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError for " << text;
  return "";
}

TEST(Scenario, ErrorsNameTheField) {
  EXPECT_NE(json_error(R"({"channels": 3})").find("cfg.json: field 'channels'"), std::string::npos);
  EXPECT_NE(json_error(R"({"trajectory": {"kind": 3}})").find("field 'trajectory.kind'"),
            std::string::npos);
  EXPECT_NE(json_error(R"({"trajectory": {"kind": "spin"}})").find("field 'trajectory.kind'"),
            std::string::npos);
  EXPECT_NE(json_error(R"({"trajectory": {"speed": 3}})").find("field 'trajectory.speed'"),
            std::string::npos);
  EXPECT_NE(json_error(R"({"sigma": 1})").find("field 'sigma': unknown field"), std::string::npos);
  EXPECT_NE(
      json_error(R"({"sensor": [{"AF": [1, "x"]}, {}, {}, {}]})").find("field 'sensor[0].AF[1]'"),
      std::string::npos);
  EXPECT_NE(json_error(R"({"effects": [{"effect": "offset", "offset_c9": 1}]})")
                .find("field 'effects[0]'"),
            std::string::npos);
  EXPECT_NE(json_error(R"({"effects": [{"effect": "offset", "offset_c9": 1}]})").find("offset_c9"),
            std::string::npos);
  EXPECT_NE(json_error(R"({"effects": [{"offset_c1": 1}]})").find("field 'effects[0].effect'"),
            std::string::npos);
  EXPECT_NE(json_error(R"({"sigma_indep": -1})").find("field 'sigma_indep'"), std::string::npos);
  try {
    builtin_scenario("nope");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("paper, paper-indep, paper-noiseless, ideal, tmr"),
              std::string::npos);
  }
  const std::string path = std::string(ACORE_BINARY_DIR) + "/test_simulator_bad.json";
  {
    std::ofstream f(path);
    f << "{\"p\": 0}";
  }
  try {
    load_scenario(path);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": field 'p'"), std::string::npos) << e.what();
  }
  {
    std::ofstream f(path);
    f << "{\"p\": ";
  }
  EXPECT_THROW(load_scenario(path), InputError);
  std::remove(path.c_str());
  EXPECT_THROW(simulate(builtin_scenario("paper"), 0, 1), InputError);
}

}  // namespace
}  // namespace acore
