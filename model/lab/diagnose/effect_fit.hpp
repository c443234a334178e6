// SPDX-License-Identifier: MIT
// Fitting the effects of the vocabulary (effects.hpp, docs/contracts.md, effect vocabulary widened)
// to the difference between a real recording and the static sensor model (gap.hpp), by maximum
// likelihood under the simulation's own noise level.
//
// The residual r = real - model is compared on "signals" whose noise is nearly independent:
// four-channel: d13 = c1 - c3, d24 = c2 - c4, m13 = (c1 + c3)/2, m24 = (c2 + c4)/2 (common-mode
// noise lives in m, so it cannot hide an effect on d); two-channel: sin, cos. Each signal s has the
// noise sigma_s the simulation shows. For a deterministic effect with parameters phi,
//   -2 log L = sum_s sum_i (r_s,i - J_s,i phi)^2 / sigma_s^2          (Gaussian, known sigma)
// linear (or linearized about no effect) in phi, so least squares with Eigen solves it. Effects
// that are not linear (quantization, saturation) are fitted by a search over their parameter;
// excess noise by its variance; a phase error once per group of channels it can move (either pair,
// one plate), the best kept. Field scalings (amplitude, eccentricity's magnitude modulation) act on
// the model's field part: the channel less its constant Fourier term. Each is scored by the
// Bayesian information criterion
//   BIC = -2 log L + k ln N,   compared to the model without any effect.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "diagnose/gap.hpp"

namespace acore {

using ParamList = std::vector<std::pair<std::string, double>>;

struct EffectCandidate {
  double param(const std::string& name) const;  // throws std::out_of_range when absent

  std::string effect;  // vocabulary name (effect_names())
  ParamList params;    // in the simulator's parametrization (model/lab/sim/effects.hpp)
  int k = 0;           // number of fitted parameters
  double neg2logl = 0;
  double bic = 0;
  double delta_bic = 0;    // bic - bic of "no effect": negative is evidence for the effect
  bool applicable = true;  // false: the recording cannot show the effect (no temp column for drift,
                           // values on no lattice for quantization); likelihoods are then infinite
  std::string
      rejected;  // non-empty: the recording contradicts the effect's own assumptions (excess
                 // noise that is not white); says how. Such an effect is never named.
};

// The residual problem: real and model channels at the real recording's samples.
struct FitProblem {
  const GapModel* model = nullptr;
  const Recording* real = nullptr;
  Recording predicted;                     // model channels at the real samples
  std::vector<double> omega;               // angular velocity, rad/s (or rad/sample without t)
  std::vector<double> dtemp;               // temp - 25 C (empty without temp)
  std::vector<std::vector<double>> deriv;  // d channel / d theta (mechanical), per channel
  std::vector<double> signal_sigma;        // noise per signal (see above)
  GapBasis basis;                          // for compare() on this recording
};

FitProblem make_fit_problem(const GapModel& m, const Recording& real);

// -2 log L of a candidate prediction of the real channels, whose noise is the simulation's plus
// white noise of extra_sigma on every channel (excess_noise, quantization), up to a constant.
double neg2_log_likelihood(const FitProblem& fp, const Recording& prediction,
                           double extra_sigma = 0);

// Fits one effect (a vocabulary name) on top of `base` (the model prediction, possibly already
// carrying other effects, whose extra white noise per channel is base_extra). field_scale (per
// sample, nullptr: 1): the factor that field scalings applied after this effect in a set
// (amplitude, eccentricity's magnitude modulation) put on the angle change it causes. Throws
// InputError for an unknown name.
EffectCandidate fit_effect(const FitProblem& fp, const Recording& base, const std::string& effect,
                           double base_extra = 0, const std::vector<double>* field_scale = nullptr);

// The prediction of `fp.real`'s channels with the effect added to `base` (the model prediction at
// the same samples, possibly carrying another effect), from the candidate's parameters alone: this
// is how a fitted effect is carried to a holdout recording without refitting. The white noise the
// effect adds per channel is returned in *extra_sigma: excess_noise (channels unchanged) and
// quantization (the ADC's mean output as channels, its added variance as noise); 0 for the others.
// field_scale: as for fit_effect, the factor on the angle change it causes.
Recording predict_effect(const FitProblem& fp, const Recording& base, const EffectCandidate& cand,
                         double* extra_sigma, const std::vector<double>* field_scale = nullptr);

// Whether the speed changes enough over the recording for a time to differ from an angle: a
// reversal (a twentieth of the samples each way), or a spread of the speed (5th to 95th
// percentile) of at least a fifth of its median magnitude. A drive at one constant speed with a
// little ripple does not: there a sampling time common to every channel is a zero offset, and one
// between channels a phase error (channel_skew is then not applicable).
bool speed_changes(const FitProblem& fp);

// The effect names fit_effect knows: effect_names() (without "unexplained").
const std::vector<std::string>& fittable_effects();

}  // namespace acore
