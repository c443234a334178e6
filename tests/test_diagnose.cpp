// SPDX-License-Identifier: MIT
// Gap diagnosis on recordings whose one unmodelled effect is built here by hand (not with the
// simulator's or the diagnosis's own transforms): the right effect must come first, its parameter
// recovered, and the holdout gap must shrink. A recording that differs only by fresh noise must
// show no gap.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include "diagnose.hpp"
#include "errors.hpp"
#include "paper_signals.hpp"

namespace acore {
namespace {

// A back-and-forth trajectory with varying speed and a temperature ramp; `shift` moves the angle
// each channel sees, `chan` edits the channel values (given the angle and temperature);
// independent noise sigma.
Recording make(size_t n, uint64_t seed, double sigma,
               const std::function<double(int, double, double, double)>& shift,
               const std::function<void(double*, double, double)>& chan) {
  Recording r;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0, 1);
  const double T = 2.0, phase = 0.37 * static_cast<double>(seed);
  for (size_t k = 0; k < n; ++k) {
    const double t = T * k / n;
    // Three turns forward, then back: theta = 6 pi (1 - cos(pi t / T)) / 2 ... mapped to a full cycle.
    const double u = 2 * M_PI * t / T;
    const double th = 3.5 * M_PI * (1 - std::cos(u)) + phase;
    const double w = 3.5 * M_PI * std::sin(u) * 2 * M_PI / T;
    const double temp = 20 + 40 * t / T;
    double c[4];
    for (int ch = 0; ch < 4; ++ch) {
      double v[4];
      test::paper_channels(th + shift(ch, th, w, temp), v);
      c[ch] = v[ch];
    }
    chan(c, th, temp);
    for (int ch = 0; ch < 4; ++ch) r.ch[ch].push_back(c[ch] + sigma * noise(rng));
    r.theta_ref.push_back(th);
    r.t.push_back(t);
    r.temp.push_back(temp);
  }
  return r;
}

const auto no_shift = [](int, double, double, double) { return 0.0; };
const auto no_chan = [](double*, double, double) {};

Recording sim() { return make(20000, 1, 0.01, no_shift, no_chan); }

TEST(Diagnose, FreshNoiseAloneShowsNoGap) {
  const Diagnosis d = diagnose(sim(), make(20000, 2, 0.01, no_shift, no_chan), nullptr);
  EXPECT_EQ(d.verdict, "no_gap") << d.to_json().dump(1);
  EXPECT_LT(d.before.gap_deg, 0.1 * d.before.noise_deg + 0.01);
}

struct Case {
  std::string effect;
  std::function<double(int, double, double, double)> shift;
  std::function<void(double*, double, double)> chan;
  std::string param;
  double value;
};

TEST(Diagnose, NamesTheHandMadeEffectAndShrinksTheHoldoutGap) {
  const std::vector<Case> cases = {
      {"offset", no_shift, [](double* c, double, double) { c[0] += 0.03; }, "offset_c1", 0.03},
      {"gain_mismatch", no_shift, [](double* c, double, double) { c[1] *= 1.04; }, "gain_c2", 1.04},
      {"phase_error",
       [](int ch, double, double, double) { return ch == 0 || ch == 2 ? 0.02 : 0.0; }, no_chan,
       "delta_rad", 0.02},
      {"eccentricity", [](int, double th, double, double) { return 0.01 * std::sin(th - 0.5); },
       no_chan, "epsilon_rad", 0.01},
      {"common_delay", [](int, double, double w, double) { return -w * 2e-4; }, no_chan, "tau_s",
       2e-4},
      {"channel_skew", [](int ch, double, double w, double) { return w * ch * 1e-4; }, no_chan,
       "tau_s", 1e-4},
      {"hysteresis", [](int, double, double w, double) { return w >= 0 ? 0.004 : -0.004; }, no_chan,
       "h_rad", 0.004},
      {"drift", no_shift, [](double* c, double, double temp) { c[0] += 0.001 * (temp - 25); },
       "offset_per_C_c1", 0.001},
      {"saturation", no_shift,
       [](double* c, double, double) {
         for (int k = 0; k < 4; ++k) c[k] = std::clamp(c[k], -1.2, 1.2);
       },
       "level", 1.2},
  };
  const Recording s = sim();
  for (const Case& c : cases) {
    const Recording real = make(20000, 3, 0.01, c.shift, c.chan);
    const Recording hold = make(20000, 4, 0.01, c.shift, c.chan);
    const Diagnosis d = diagnose(s, real, &hold);
    ASSERT_FALSE(d.ranking.empty());
    EXPECT_EQ(d.verdict, "explained") << c.effect;
    EXPECT_EQ(d.ranking.front().cand.effect, c.effect) << d.to_json().dump(1);
    EXPECT_TRUE(d.ambiguous_with.empty())
        << c.effect << ": " << d.to_json()["ambiguous_with"].dump();
    if (d.ranking.front().cand.effect == c.effect)
      EXPECT_NEAR(d.ranking.front().cand.param(c.param), c.value, 0.2 * std::fabs(c.value)) << c.effect;
    ASSERT_TRUE(d.hold_before.has_value());
    EXPECT_LT(d.hold_after->gap_deg, 0.3 * d.hold_before->gap_deg) << c.effect << " real " << d.before.gap_deg << " -> " << d.after.gap_deg;
  }
}

// A third field harmonic seen from each sensor's 90-degree position: written out per channel here,
// c1: +sin(3 th + psi), c2: sin(3 th + 270 deg + psi) = -cos(3 th + psi), c3: -sin(3 th + psi),
// c4: +cos(3 th + psi), so it survives the differences c1 - c3, c2 - c4.
TEST(Diagnose, RecoversAHandMadeThirdHarmonic) {
  const double a = 0.02, psi = 0.4;
  const auto harmonic = [&](double* c, double th, double) {
    const double s3 = std::sin(3 * th + psi), c3 = std::cos(3 * th + psi);
    c[0] += a * s3;
    c[1] -= a * c3;
    c[2] -= a * s3;
    c[3] += a * c3;
  };
  const Recording real = make(20000, 3, 0.01, no_shift, harmonic);
  const Recording hold = make(20000, 4, 0.01, no_shift, harmonic);
  const Diagnosis d = diagnose(sim(), real, &hold);
  ASSERT_FALSE(d.ranking.empty());
  EXPECT_EQ(d.verdict, "explained");
  ASSERT_EQ(d.ranking.front().cand.effect, "harmonic") << d.to_json().dump(1);
  const EffectCandidate& h = d.ranking.front().cand;
  EXPECT_EQ(h.param("order"), 3);
  EXPECT_NEAR(h.param("amplitude"), a, 0.05 * a);
  EXPECT_NEAR(std::remainder(h.param("phase_rad") - psi, 2 * M_PI), 0.0, 0.05);
  EXPECT_LT(d.hold_after->gap_deg, 0.1 * d.hold_before->gap_deg);
}

// An 8-bit ADC over [-2, 2) applied here after the noise (step 4/256): the values lie on its
// lattice.
TEST(Diagnose, RecoversAHandMadeAdcStep) {
  const double step = 4.0 / 256;
  auto adc = [&](Recording r) {
    for (int c = 0; c < 4; ++c)
      for (double& v : r.ch[c]) v = step * std::round(v / step);
    return r;
  };
  const Recording real = adc(make(20000, 3, 0.01, no_shift, no_chan));
  const Recording hold = adc(make(20000, 4, 0.01, no_shift, no_chan));
  const Diagnosis d = diagnose(sim(), real, &hold);
  ASSERT_FALSE(d.ranking.empty());
  EXPECT_EQ(d.verdict, "explained");
  ASSERT_EQ(d.ranking.front().cand.effect, "quantization") << d.to_json().dump(1);
  EXPECT_NEAR(d.ranking.front().cand.param("step"), step, 1e-9);
  // The quantization noise of a dithered ADC, step^2 / 12, is what the gap was made of.
  EXPECT_GT(d.before.excess_noise_deg, 0);
  EXPECT_LT(d.hold_after->gap_deg, 0.3 * d.hold_before->gap_deg);
}

// The same recording without the ADC: no lattice, so quantization must not even be a candidate.
TEST(Diagnose, NoLatticeNoQuantization) {
  const Diagnosis d = diagnose(sim(), make(20000, 5, 0.03, no_shift, no_chan), nullptr);
  for (const auto& r : d.ranking) EXPECT_NE(r.cand.effect, "quantization");
}

// Mains pick-up (50 Hz) on c1: more variance than the simulation's noise, but not white noise and
// no effect of the vocabulary: the excess-noise candidate must be rejected, the verdict
// unexplained.
TEST(Diagnose, InterferenceIsNotExcessNoise) {
  Recording real = make(20000, 6, 0.01, no_shift, no_chan);
  for (size_t k = 0; k < real.size(); ++k)
    real.ch[0][k] += 0.02 * std::sin(2 * M_PI * 50 * real.t[k]);
  const Diagnosis d = diagnose(sim(), real, nullptr);
  EXPECT_EQ(d.verdict, "unexplained") << d.to_json().dump(1);
  bool seen = false;
  for (const auto& r : d.ranking)
    if (r.cand.effect == "excess_noise") {
      seen = true;
      EXPECT_FALSE(r.cand.rejected.empty());
    }
  EXPECT_TRUE(seen);
}

TEST(Diagnose, ExcessNoiseIsNamedAndExplained) {
  const Diagnosis d = diagnose(sim(), make(20000, 5, 0.03, no_shift, no_chan), nullptr);
  ASSERT_FALSE(d.ranking.empty());
  EXPECT_EQ(d.ranking.front().cand.effect, "excess_noise") << d.to_json().dump(1);
  EXPECT_NEAR(d.ranking.front().cand.param("sigma"), std::sqrt(0.03 * 0.03 - 0.01 * 0.01), 0.003);
  EXPECT_TRUE(d.ranking.front().cand.rejected.empty());
}

// At one constant speed a common delay is a constant angle lag, which hysteresis (a lag whose sign
// follows the direction, here always forward) explains just as well: the diagnosis must say so.
TEST(Diagnose, ConstantSpeedCannotTellDelayFromHysteresis) {
  const double T = 2.0, turns = 6, tau = 3e-4;
  Recording real;
  std::mt19937_64 rng(8);
  std::normal_distribution<double> noise(0, 0.01);
  for (size_t k = 0; k < 20000; ++k) {
    const double t = T * k / 20000, th = 2 * M_PI * turns * t / T, w = 2 * M_PI * turns / T;
    double v[4];
    test::paper_channels(th - w * tau, v);
    for (int c = 0; c < 4; ++c) real.ch[c].push_back(v[c] + noise(rng));
    real.theta_ref.push_back(th);
    real.t.push_back(t);
  }
  const Diagnosis d = diagnose(sim(), real, nullptr);
  ASSERT_EQ(d.verdict, "explained") << d.to_json().dump(1);
  const std::string top = d.ranking.front().cand.effect;
  ASSERT_TRUE(top == "common_delay" || top == "hysteresis") << top;
  const std::string other = top == "common_delay" ? "hysteresis" : "common_delay";
  EXPECT_NE(std::find(d.ambiguous_with.begin(), d.ambiguous_with.end(), other),
            d.ambiguous_with.end())
      << d.to_json()["ambiguous_with"].dump();
}

TEST(Diagnose, BadInputIsRejected) {
  const Recording s = sim();
  Recording two = s;
  two.channels = 2;
  EXPECT_THROW(diagnose(s, two, nullptr), InputError);
  Recording few = s;
  for (auto* v : {&few.theta_ref, &few.t, &few.temp, &few.ch[0], &few.ch[1], &few.ch[2], &few.ch[3]}) v->resize(100);
  EXPECT_THROW(diagnose(s, few, nullptr), InputError);
  Recording noref = s;
  noref.theta_ref.clear();
  EXPECT_THROW(diagnose(s, noref, nullptr), InputError);
  Recording flat = s;  // a sensor not connected: every channel constant
  for (int c = 0; c < 4; ++c) std::fill(flat.ch[c].begin(), flat.ch[c].end(), 0.25);
  EXPECT_THROW(diagnose(s, flat, nullptr), InputError);
  Recording part = s;
  for (auto* v : {&part.theta_ref, &part.t, &part.temp, &part.ch[0], &part.ch[1], &part.ch[2], &part.ch[3]})
    v->resize(1000);  // the first 1000 samples turn less than 360 degrees
  EXPECT_THROW(diagnose(s, part, nullptr), InputError);
}

}  // namespace
}  // namespace acore
