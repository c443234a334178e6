// SPDX-License-Identifier: MIT
// Fitting the vocabulary's effects (diagnose/effect_fit.*) on recordings made here from the fitted
// sensor model plus a known change and Gaussian noise at the model's own level, so every figure has
// a closed form: the signals' noise from the channels' (sigma^2 +- 2 rho sigma sigma), the -2 log L
// of a known residual, the offsets and gains recovered within their standard error, a zero offset
// recovered in rad, the BIC favouring a real effect and rejecting a fitted noise, and the
// prediction rebuilding the change from the parameters alone; every effect of the table fitted in
// the simulator's parameters and predicted as the simulator applies it (a second implementation).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "diagnose/effect_fit.hpp"
#include "sim/effect_table.hpp"
#include "sim/effects.hpp"
#include "support/paper_signals.hpp"

namespace acore {
namespace {

constexpr double kSigma = 0.01;

const GapModel& model() {
  static const GapModel m = [] {
    Recording sim = test::paper_recording(4000);
    std::mt19937_64 rng(1);
    std::normal_distribution<double> g(0, kSigma);
    for (int c = 0; c < 4; ++c)
      for (double& v : sim.ch[c]) v += g(rng);
    return build_gap_model(sim, 1);
  }();
  return m;
}

// The model's channels at random angles (with t and temp), then `change`, then fresh noise.
Recording real(size_t n, uint64_t seed, const std::function<void(Recording&)>& change) {
  Recording r;
  r.channels = 4;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 2 * M_PI);
  for (size_t k = 0; k < n; ++k) {
    r.t.push_back(0.001 * k);
    r.theta_ref.push_back(u(rng));
    r.temp.push_back(25.0 + 10.0 * k / n);
  }
  r = model().sensor.resample(r);
  change(r);
  std::normal_distribution<double> g(0, kSigma);
  for (int c = 0; c < 4; ++c)
    for (double& v : r.ch[c]) v += g(rng);
  return r;
}

const auto unchanged = [](Recording&) {};

TEST(EffectFit, ProblemHoldsTheModelAtTheRealAnglesAndTheSignalsNoise) {
  const GapModel& m = model();
  const Recording r = real(1000, 2, unchanged);
  const FitProblem fp = make_fit_problem(m, r);
  const Recording pred = m.sensor.resample(r);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(fp.predicted.ch[c], pred.ch[c]);
  ASSERT_EQ(fp.dtemp.size(), r.size());
  EXPECT_DOUBLE_EQ(fp.dtemp.back(), r.temp.back() - 25);
  EXPECT_DOUBLE_EQ(fp.deriv[2][17], m.sensor.derivative(2, r.theta_ref[17]));
  // d13 = c1 - c3 carries sigma1^2 + sigma3^2 - 2 rho sigma1 sigma3, m13 = (c1 + c3)/2 a quarter of
  // the sum with + 2 rho: independent noise of 0.01 gives 0.0141 and 0.0071.
  const auto& s = m.sensor.noise_sigma;
  const auto& rho = m.sensor.noise_corr;
  ASSERT_EQ(fp.signal_sigma.size(), 4u);
  EXPECT_NEAR(fp.signal_sigma[0], std::sqrt(s[0] * s[0] + s[2] * s[2] - 2 * rho[0] * s[0] * s[2]),
              1e-15);
  EXPECT_NEAR(fp.signal_sigma[3],
              0.5 * std::sqrt(s[1] * s[1] + s[3] * s[3] + 2 * rho[1] * s[1] * s[3]), 1e-15);
  EXPECT_NEAR(fp.signal_sigma[0], kSigma * std::sqrt(2.0), 0.001);
  EXPECT_NEAR(fp.signal_sigma[2], kSigma / std::sqrt(2.0), 0.0005);
}

TEST(EffectFit, LikelihoodOfAKnownResidual) {
  const Recording r = real(800, 3, unchanged);
  const FitProblem fp = make_fit_problem(model(), r);
  EXPECT_EQ(neg2_log_likelihood(fp, r), 0.0);  // the recording predicts itself
  // c1 off by d: d13 off by d, m13 by d / 2; the other signals not at all.
  const double d = 0.003, n = static_cast<double>(r.size());
  Recording off = r;
  for (double& v : off.ch[0]) v -= d;
  const auto& sg = fp.signal_sigma;
  const double want = n * (d * d / (sg[0] * sg[0]) + d * d / 4 / (sg[2] * sg[2]));
  EXPECT_NEAR(neg2_log_likelihood(fp, off), want, 1e-9 * want);
  // With extra white noise e per channel: variances sigma^2 + w e^2 (w = 2 for a difference, 1/2
  // for a mean) and their log terms.
  const double e = 0.004;
  double with = 0;
  const double w[4] = {2, 2, 0.5, 0.5};
  for (int q = 0; q < 4; ++q) {
    const double v = sg[q] * sg[q] + w[q] * e * e;
    const double rss = q == 0 ? n * d * d : q == 2 ? n * d * d / 4 : 0.0;
    with += rss / v + n * std::log(v / (sg[q] * sg[q]));
  }
  EXPECT_NEAR(neg2_log_likelihood(fp, off, e), with, 1e-9 * with);
}

TEST(EffectFit, OffsetsAndGainsAreRecoveredWithinTheirStandardError) {
  const size_t n = 3000;
  const double o[4] = {0.02, -0.01, 0.0, 0.015};
  const Recording ro = real(n, 4, [&](Recording& r) {
    for (int c = 0; c < 4; ++c)
      for (double& v : r.ch[c]) v += o[c];
  });
  const FitProblem fo = make_fit_problem(model(), ro);
  const EffectCandidate co = fit_effect(fo, fo.predicted, "offset");
  EXPECT_EQ(co.k, 4);
  // Each offset is seen by a difference and a mean: standard error about sigma / sqrt(N).
  const double se = kSigma / std::sqrt(static_cast<double>(n));
  for (int c = 0; c < 4; ++c)
    EXPECT_NEAR(co.param("offset_c" + std::to_string(c + 1)), o[c], 5 * se) << c;
  EXPECT_LT(co.delta_bic, -1000);  // overwhelming evidence
  // The prediction from the parameters alone is the model plus the offsets.
  double extra = -1;
  const Recording po = predict_effect(fo, fo.predicted, co, &extra);
  EXPECT_EQ(extra, 0.0);
  for (int c = 0; c < 4; ++c)
    for (size_t i = 0; i < n; i += 97)
      EXPECT_DOUBLE_EQ(po.ch[c][i],
                       fo.predicted.ch[c][i] + co.param("offset_c" + std::to_string(c + 1)));
  // Gains: c2 2 % up, c3 1 % down.
  const Recording rg = real(n, 5, [](Recording& r) {
    for (double& v : r.ch[1]) v *= 1.02;
    for (double& v : r.ch[2]) v *= 0.99;
  });
  const FitProblem fg = make_fit_problem(model(), rg);
  const EffectCandidate cg = fit_effect(fg, fg.predicted, "gain_mismatch");
  // A gain is an offset per unit of the channel (amplitude about 1): the same standard error.
  EXPECT_NEAR(cg.param("gain_c1"), 1.0, 8 * se);
  EXPECT_NEAR(cg.param("gain_c2"), 1.02, 8 * se);
  EXPECT_NEAR(cg.param("gain_c3"), 0.99, 8 * se);
  EXPECT_LT(cg.delta_bic, -1000);
}

TEST(EffectFit, AZeroOffsetIsRecoveredInRadians) {
  // Every channel seen 0.01 rad further on (the model evaluated at theta + z).
  const double z = 0.01;
  const Recording r = real(3000, 6, [&](Recording& rec) {
    for (int c = 0; c < 4; ++c)
      for (size_t i = 0; i < rec.size(); ++i)
        rec.ch[c][i] = model().sensor.value(c, rec.theta_ref[i] + z);
  });
  const FitProblem fp = make_fit_problem(model(), r);
  const EffectCandidate c = fit_effect(fp, fp.predicted, "zero_offset");
  // Standard error: sigma_d / (|d d13/d theta| sqrt N) ~ 0.014 / (2 sqrt 3000) = 1.3e-4 rad.
  EXPECT_NEAR(c.param("zero_rad"), z, 5e-4);
  EXPECT_LT(c.delta_bic, -1000);
}

// Parameters that change something, for every effect of the table (none left out).
ParamList active(const std::string& e) {
  if (e == "offset") return {{"offset_c2", 0.03}};
  if (e == "gain_mismatch") return {{"gain_c3", 1.04}};
  if (e == "phase_error") return {{"delta_cos_rad", 0.02}, {"phase_c1", -0.01}};
  if (e == "harmonic") return {{"order", 5}, {"amplitude", 0.01}, {"phase_rad", 0.4}};
  if (e == "eccentricity")
    return {{"epsilon_rad", 0.01}, {"phi0_rad", 0.3}, {"am_depth", 0.02}, {"am_phase_rad", -1}};
  if (e == "channel_skew") return {{"tau_s", 1e-4}, {"tau_c3", -2e-4}};
  if (e == "common_delay") return {{"tau_s", 3e-4}};
  if (e == "drift") return {{"gain_per_C_c2", 1e-3}, {"offset_per_C_c4", -2e-4}};
  if (e == "quantization") return {{"bits", 8}, {"full_scale", 1.5}};
  if (e == "saturation") return {{"level", 0.9}};
  if (e == "excess_noise") return {{"sigma", 0.01}};
  if (e == "hysteresis") return {{"h_rad", 0.01}};
  if (e == "zero_offset") return {{"zero_rad", 0.05}};
  if (e == "amplitude") return {{"scale", 0.9}};
  ADD_FAILURE() << "no active parameters for the table's effect '" << e << "': add them here";
  return {};
}

TEST(EffectFit, EveryEffectIsPredictedAsTheSimulatorAppliesIt) {
  // One turn and a half at a constant speed, with a reversal at the end (hysteresis), t and temp.
  Recording r;
  r.channels = 4;
  const double w = 2 * M_PI * 3;  // rad/s
  for (int k = 0; k < 1200; ++k) {
    const double t = 0.5e-3 * k;
    r.t.push_back(t);
    r.theta_ref.push_back(k < 1000 ? w * t : w * (2 * 0.5 - t));
    r.temp.push_back(20 + 0.01 * k);
  }
  r = model().sensor.resample(r);
  const FitProblem fp = make_fit_problem(model(), r);
  auto theta_at = [&](double t) { return t <= 0.5 ? w * t : w * (1.0 - t); };
  for (const EffectSpec& s : effect_table()) {
    if (s.fit == EffectFit::lattice || s.fit == EffectFit::noise_variance) continue;  // random
    if (s.needs_time) continue;  // below, away from the reversal
    EffectCandidate cand;
    cand.effect = s.name;
    cand.params = make_effect(s.name, active(s.name), 4).params;
    const Recording pred = predict_effect(fp, fp.predicted, cand, nullptr);
    Recording sim = fp.predicted;
    EffectContext ctx = make_effect_context(
        sim, 1, [](int c, double phi) { return model().sensor.value(c, phi); }, theta_at, 1);
    apply_effect(make_effect(s.name, active(s.name), 4), sim, ctx);
    for (int c = 0; c < 4; ++c)
      for (size_t i = 0; i < r.size(); ++i) {
        if (i >= 998 && i <= 1002) continue;  // the turning point: a direction of its own
        ASSERT_NEAR(pred.ch[c][i], sim.ch[c][i], 1e-9) << s.name << " c" << c + 1 << " " << i;
      }
  }
  // Sampling times: the prediction's omega tau is the trajectory's angle change (a constant speed).
  for (const EffectSpec& s : effect_table()) {
    if (!s.needs_time) continue;
    EffectCandidate cand;
    cand.effect = s.name;
    cand.params = make_effect(s.name, active(s.name), 4).params;
    const Recording pred = predict_effect(fp, fp.predicted, cand, nullptr);
    Recording sim = fp.predicted;
    EffectContext ctx = make_effect_context(
        sim, 1, [](int c, double phi) { return model().sensor.value(c, phi); }, theta_at, 1);
    apply_effect(make_effect(s.name, active(s.name), 4), sim, ctx);
    for (int c = 0; c < 4; ++c)
      for (size_t i = 10; i < 990; ++i)
        ASSERT_NEAR(pred.ch[c][i], sim.ch[c][i], 1e-9) << s.name << " c" << c + 1 << " " << i;
  }
}

TEST(EffectFit, EveryEffectIsFittedInTheSimulatorsParameters) {
  const Recording r = real(2000, 8, unchanged);
  const FitProblem fp = make_fit_problem(model(), r);
  ASSERT_TRUE(speed_changes(fp));
  for (const std::string& e : effect_names()) {
    const EffectCandidate c = fit_effect(fp, fp.predicted, e);
    EXPECT_EQ(c.effect, e);
    if (!c.applicable) {
      // Only an ADC leaves a lattice to read; this recording has none.
      EXPECT_EQ(effect_spec(e).fit, EffectFit::lattice) << e;
      continue;
    }
    // Every parameter of the simulator's, so a fitted effect can go into a scenario's effects.
    ParamList sim;
    for (const auto& [name, value] : effect_defaults(e, 4)) {
      (void)value;
      sim.push_back({name, c.param(name)});
    }
    EXPECT_NO_THROW(make_effect(e, sim, 4)) << e;
    EXPECT_GT(c.k, 0) << e;
  }
}

TEST(EffectFit, NoiseAloneIsNoEvidenceAndNamesAreChecked) {
  const Recording r = real(3000, 7, unchanged);
  const FitProblem fp = make_fit_problem(model(), r);
  // Fitting 4 offsets to pure noise gains about chi^2_4 = 4 in -2 log L; the BIC charges 4 ln(4 N).
  const EffectCandidate c = fit_effect(fp, fp.predicted, "offset");
  const double penalty = 4 * std::log(4.0 * 3000);
  EXPECT_GT(c.delta_bic, penalty - 30);
  EXPECT_GT(c.delta_bic, 0);
  EXPECT_NEAR(c.bic - c.neg2logl, penalty, 1e-9);
  EXPECT_THROW(fit_effect(fp, fp.predicted, "unexplained"), InputError);
  EXPECT_THROW(fit_effect(fp, fp.predicted, "Offset"), InputError);
  EXPECT_EQ(fittable_effects(), effect_names());
  EXPECT_THROW((void)c.param("gain_c1"), std::out_of_range);
}

}  // namespace
}  // namespace acore
