// SPDX-License-Identifier: MIT
#include "diagnose/diagnose.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

#include "core/errors.hpp"
#include "sim/effect_table.hpp"
#include "sim/effects.hpp"

namespace acore {

namespace {

constexpr size_t kMinSamples = 256;
constexpr double kSeedMin = 0.1;  // see the combination's start in diagnose()

int meta_periodicity(const Recording& r) {
  const auto it = r.meta.find("p");
  if (it == r.meta.end()) return 0;
  try {
    return std::max(1, std::stoi(it->second));
  } catch (const std::exception&) {
    return 0;
  }
}

void check_recording(const Recording& r, const std::string& what) {
  if (!r.has_theta())
    throw InputError(what + ": no theta_ref column (the gap needs the reference angle)");
  if (r.size() < kMinSamples)
    throw InputError(
        fmt::format("{}: {} samples, at least {} needed", what, r.size(), kMinSamples));
  // A sensor that is not connected (or a column of zeros) leaves nothing to compare or fit.
  bool varies = false;
  for (int c = 0; c < r.channels && !varies; ++c)
    for (double v : r.ch[c]) varies = varies || v != r.ch[c][0];
  if (!varies)
    throw InputError(fmt::format("{}: every channel ({}) is constant: no sensor signal to diagnose",
                                 what, r.channels == 4 ? "c1, c2, c3, c4" : "sin, cos"));
  // Wrapped or unwrapped: either way a turn must be covered, checked by 10-degree sectors.
  const int covered = turn_sectors_covered(r.theta_ref);
  if (covered < 36)
    throw InputError(
        fmt::format("{}: theta_ref covers only {} of the 36 ten-degree sectors of a turn; "
                    "at least one full turn is needed",
                    what, covered));
}

// Amplitude of the gap's mechanical orders 0..max by least squares (non-uniform angles allowed).
std::vector<std::pair<int, double>> gap_orders(const Recording& r, const std::vector<double>& g,
                                               int max_order) {
  const size_t n = r.size();
  Eigen::MatrixXd X(n, 2 * max_order + 1);
  for (size_t i = 0; i < n; ++i) {
    X(i, 0) = 1;
    for (int k = 1; k <= max_order; ++k) {
      X(i, 2 * k - 1) = std::cos(k * r.theta_ref[i]);
      X(i, 2 * k) = std::sin(k * r.theta_ref[i]);
    }
  }
  const Eigen::VectorXd y =
      Eigen::Map<const Eigen::VectorXd>(g.data(), static_cast<Eigen::Index>(n));
  const Eigen::VectorXd b = X.colPivHouseholderQr().solve(y);
  std::vector<std::pair<int, double>> out = {{0, std::fabs(b(0))}};
  for (int k = 1; k <= max_order; ++k) out.push_back({k, std::hypot(b(2 * k - 1), b(2 * k))});
  return out;
}

// First-order signal-domain causes of an angle-error order k (Kuntz: a signal harmonic n gives
// angle-error orders n +- p; offsets give p, amplitude/phase mismatch 2p).
std::vector<std::string> causes_of(int k, int p) {
  std::vector<std::string> c;
  const std::string& zero = effect_name(EffectId::zero_offset);
  const std::string& offset = effect_name(EffectId::offset);
  const std::string& ecc = effect_name(EffectId::eccentricity);
  if (k == 0) {
    c.push_back(zero + " (a constant angle shift)");
    c.push_back(fmt::format("{} or {} (at one speed, in one direction)",
                            effect_name(EffectId::common_delay),
                            effect_name(EffectId::hysteresis)));
    return c;
  }
  if (k == p) c.push_back(offset + " (signal order 0)");
  if (k == 2 * p) c.push_back("amplitude or phase mismatch (signal order p)");
  if (k == 1 && p != 1) c.push_back(ecc + " (mechanical order 1)");
  if (k == 1 && p == 1) c.push_back(ecc + " or " + offset);
  for (int n : {k - p, k + p})
    if (n >= 2) c.push_back(fmt::format("signal harmonic of order {}", n));
  return c;
}

const EffectSpec& spec_of(const RankedEffect& r) { return effect_spec(r.cand.effect); }

// `general` contains `special` as a case (equal gains are an amplitude, equal sampling times a
// common delay): when the special one is named, the general one explaining as much is no ambiguity.
bool generalizes(const std::string& general, const std::string& special) {
  const auto& s = effect_spec(general).special_case;
  return s && effect_name(*s) == special;
}

// The special case a general effect reduces to (empty: none).
std::string special_case(const std::string& general) {
  const auto& s = effect_spec(general).special_case;
  return s ? effect_name(*s) : "";
}

// The special case a general effect owes its lead over to the common mode of the channels alone
// (empty: none): amplitude for gain_mismatch.
std::string common_mode_special(const std::string& general) {
  return effect_spec(general).leads_on_common_mode ? special_case(general) : "";
}

// Order among effects the recording cannot tell apart at all (identical columns, e.g. a constant
// shift, a delay and hysteresis at one constant speed): fewer parameters first, then the constant
// shift, then the vocabulary's order.
int tie_rank(const RankedEffect& r) {
  const EffectSpec& s = spec_of(r);
  const int order = s.shift == EffectShift::constant ? -1 : static_cast<int>(s.id);
  return 100 * r.cand.k + order;
}

// The order in which a set of effects is applied to a prediction, as simulate() does (the effect
// table's set_order: angle shifts, then eccentricity, then amplitude, then the signal-domain
// effects in the order they were chosen).
int apply_rank(const std::string& e) { return effect_spec(e).set_order; }

// The model's prediction with a set of effects (all but `skip`) added in apply order; the white
// noise they add per channel in *extra.
Recording predict_set(const FitProblem& f, const std::vector<RankedEffect>& set, double* extra,
                      size_t skip = SIZE_MAX) {
  std::vector<size_t> order;
  for (size_t k = 0; k < set.size(); ++k)
    if (k != skip) order.push_back(k);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return apply_rank(set[a].cand.effect) < apply_rank(set[b].cand.effect);
  });
  Recording pred = f.predicted;
  *extra = 0;
  for (size_t k : order) {
    double e = 0;
    pred = predict_effect(f, pred, set[k].cand, &e);
    *extra = std::hypot(*extra, e);
  }
  return pred;
}

// The factor the field scalings of a set (all but `skip`) that are applied after `effect` put on
// the angle change it causes, per sample (empty: none).
std::vector<double> later_field_scale(const FitProblem& f, const std::vector<RankedEffect>& set,
                                      const std::string& effect, size_t skip = SIZE_MAX) {
  std::vector<double> s;
  for (size_t k = 0; k < set.size(); ++k) {
    const EffectCandidate& c = set[k].cand;
    const EffectSpec& spec = effect_spec(c.effect);
    if (k == skip || apply_rank(c.effect) <= apply_rank(effect)) continue;
    if (!spec.field_factor) continue;
    if (s.empty()) s.assign(f.real->size(), 1.0);
    const Effect e{c.effect, c.params};
    for (size_t i = 0; i < s.size(); ++i) s[i] *= spec.field_factor(e, f.real->theta_ref[i]);
  }
  return s;
}

// Fits `effect` on top of the other effects of a set (all but `skip`), as it will act in the set.
EffectCandidate fit_in_set(const FitProblem& f, const std::vector<RankedEffect>& set,
                           const std::string& effect, size_t skip = SIZE_MAX) {
  double extra = 0;
  const Recording base = predict_set(f, set, &extra, skip);
  const std::vector<double> scale = later_field_scale(f, set, effect, skip);
  return fit_effect(f, base, effect, extra, scale.empty() ? nullptr : &scale);
}

// Backfitting: each effect of the set refitted on top of the others, twice, so the parameters are
// those of the set together rather than of the order in which the effects were found.
void refit_set(const FitProblem& f, std::vector<RankedEffect>& set) {
  if (set.size() < 2) return;
  for (int round = 0; round < 2; ++round)
    for (size_t k = 0; k < set.size(); ++k) {
      const EffectCandidate c = fit_in_set(f, set, set[k].cand.effect, k);
      if (c.applicable && c.rejected.empty()) set[k].cand = c;
    }
}

// 1 - after^2 / before^2: the share of gap^2 an explanation removes.
double explained_share(double after_deg, double before2) {
  return before2 > 0 ? 1.0 - after_deg * after_deg / before2 : 0.0;
}

// The gap once a candidate is added to `base` (which carries base_extra of white noise).
StageSeries gap_with(const FitProblem& f, const GapModel& m, const Recording& base,
                     const EffectCandidate& c, double base_extra,
                     const std::vector<double>* field_scale = nullptr) {
  double extra = 0;
  const Recording pred = predict_effect(f, base, c, &extra, field_scale);
  return compare(m, *f.real, pred, std::hypot(base_extra, extra), &f.basis);
}

// ---- The steps of diagnose() ----

void check_inputs(const Recording& sim, const Recording& real, const Recording* holdout) {
  check_recording(sim, "--sim");
  check_recording(real, "--real");
  if (holdout) check_recording(*holdout, "--holdout");
  if (sim.channels != real.channels || (holdout && holdout->channels != real.channels))
    throw InputError(fmt::format("channel sets differ: --sim has {} channels, --real {}{}",
                                 sim.channels, real.channels,
                                 holdout ? fmt::format(", --holdout {}", holdout->channels) : ""));
}

// Where: the first stage that diverges beyond noise, and the signals involved there.
void find_divergent_stage(Diagnosis& d) {
  d.where_stage = "none";
  for (const auto& st : d.stages)
    if (st.diverges) {
      d.where_stage = st.stage;
      const double top = *std::max_element(st.ratio.begin(), st.ratio.end());
      for (size_t k = 0; k < st.signals.size(); ++k)
        if (st.ratio[k] > 1.0 + 0.25 * (top - 1.0)) d.where_channels.push_back(st.signals[k]);
      break;
    }
}

// Angle unless another domain explains clearly more; "random" when nothing explains much.
std::string dominant_domain(const std::vector<DomainScore>& domains) {
  std::string domain = "random";
  double best = 0.2, angle_r2 = -1;
  for (const auto& s : domains)
    if (s.domain == "angle") angle_r2 = s.r2;
  if (angle_r2 > best) domain = "angle", best = angle_r2;
  for (const auto& s : domains)
    if (s.domain != "angle" && s.r2 > best + 0.1) domain = s.domain, best = s.r2;
  return domain;
}

// The gap's mechanical orders above a tenth of the largest, largest first, with their causes.
std::vector<GapHarmonic> gap_harmonics(const Recording& real, const std::vector<double>& g, int p) {
  std::vector<GapHarmonic> h;
  const auto orders = gap_orders(real, g, 12);
  double peak = 0;
  for (const auto& o : orders) peak = std::max(peak, o.second);
  for (const auto& [k, a] : orders)
    if (a > 0.1 * peak && a > 1e-4) h.push_back({k, a, causes_of(k, p)});
  std::sort(h.begin(), h.end(), [](const GapHarmonic& a, const GapHarmonic& b) {
    return a.amplitude_deg > b.amplitude_deg;
  });
  return h;
}

// Which: every effect of the vocabulary fitted to the model's prediction and scored by the gap it
// leaves (unranked; those the recording cannot show are left out).
std::vector<RankedEffect> fit_each_effect(const FitProblem& fp, const GapModel& m, double before2) {
  std::vector<RankedEffect> ranking;
  for (const std::string& e : fittable_effects()) {
    RankedEffect r;
    r.cand = fit_effect(fp, fp.predicted, e);
    if (!r.cand.applicable) continue;
    const StageSeries after = gap_with(fp, m, fp.predicted, r.cand, 0);
    r.after_deg = after.gap_deg;
    r.explained = explained_share(after.gap_deg, before2);
    ranking.push_back(r);
  }
  return ranking;
}

// An effect that could be named: it explains explained_min of the angle gap with dBIC < -10.
bool carries(const RankedEffect& r, const DiagnoseOptions& opt) {
  return r.explained >= opt.explained_min && r.cand.delta_bic < -10;
}

// An effect whose parameters are read from the recording, not fitted to the residual (the ADC's
// lattice), and that explains enough to be named.
bool measured(const RankedEffect& r, const DiagnoseOptions& opt) {
  return spec_of(r).fit == EffectFit::lattice && r.explained >= opt.explained_min;
}

// Effects that could be named come first, then by information criterion. The likelihood also
// counts what atan2 never sees (a common scale of every channel, e.g. the fundamental's shrink
// under a compressing nonlinearity): an effect that fits that part best but leaves the angle gap
// (gain_mismatch with equal gains) must not outrank the one that carries the angle gap (the
// harmonic). Among those, quantization, when the values lie on a lattice (its step read from the
// data, not fitted to the residual), comes first: the lattice proves the ADC, and excess noise
// would only be fitting its rounding noise.
void sort_by_evidence(std::vector<RankedEffect>& ranking, const DiagnoseOptions& opt) {
  std::sort(ranking.begin(), ranking.end(), [&](const RankedEffect& a, const RankedEffect& b) {
    if (a.cand.rejected.empty() != b.cand.rejected.empty()) return a.cand.rejected.empty();
    if (carries(a, opt) != carries(b, opt)) return carries(a, opt);
    if (measured(a, opt) != measured(b, opt)) return measured(a, opt);
    return a.cand.delta_bic < b.cand.delta_bic;
  });
}

// Among effects tied with the first (identical likelihoods: the recording cannot tell them apart),
// the simplest first (tie_rank).
void simplest_of_ties_first(std::vector<RankedEffect>& ranking, const DiagnoseOptions& opt) {
  const RankedEffect& first = ranking.front();
  const double b0 = first.cand.delta_bic;
  size_t pick = 0;
  for (size_t k = 1; k < ranking.size(); ++k) {
    const RankedEffect& r = ranking[k];
    const bool tie = r.cand.rejected.empty() == first.cand.rejected.empty() &&
                     carries(r, opt) == carries(first, opt) &&
                     measured(r, opt) == measured(first, opt) &&
                     std::fabs(r.cand.delta_bic - b0) <= 1e-6 * std::fabs(b0) + 1e-6;
    if (tie && tie_rank(r) < tie_rank(ranking[pick])) pick = k;
  }
  std::rotate(ranking.begin(), ranking.begin() + static_cast<std::ptrdiff_t>(pick),
              ranking.begin() + static_cast<std::ptrdiff_t>(pick) + 1);
}

// gain_mismatch first owes its lead to what atan2 never sees when amplitude carries as much of the
// angle gap: a plate ring's common mode, e.g. the field a run-out adds to every plate alike. Name
// amplitude then; gain_mismatch stays in the ranking, and is no ambiguity (generalizes()). (Not
// channel_skew for common_delay: the skews' differences are seen by atan2, however little they add
// to the share.)
void common_mode_special_first(std::vector<RankedEffect>& ranking, const DiagnoseOptions& opt) {
  const std::string simple = common_mode_special(ranking.front().cand.effect);
  for (size_t k = 1; k < ranking.size() && !simple.empty(); ++k) {
    const RankedEffect& r = ranking[k];
    if (r.cand.effect == simple && r.cand.rejected.empty() && carries(r, opt) &&
        r.explained >= ranking.front().explained - 0.01) {
      std::rotate(ranking.begin(), ranking.begin() + static_cast<std::ptrdiff_t>(k),
                  ranking.begin() + static_cast<std::ptrdiff_t>(k) + 1);
      break;
    }
  }
}

void rank_effects(std::vector<RankedEffect>& ranking, const DiagnoseOptions& opt) {
  sort_by_evidence(ranking, opt);
  if (ranking.empty()) return;
  simplest_of_ties_first(ranking, opt);
  common_mode_special_first(ranking, opt);
}

// Is there a gap at all? The systematic part must stand out of what noise leaves in the projection
// (cols/N of the noise variance, here required 3x over), or the excess noise must be significant.
bool gap_is_significant(const StageSeries& before, const FitProblem& fp) {
  const double n = static_cast<double>(fp.real->size());
  const double cols = static_cast<double>(fp.basis.X.cols());
  const double noise_in_projection = std::sqrt(cols / n) * before.noise_deg;
  return before.gap_deg > 1e-3 &&
         (before.systematic_deg > 3 * noise_in_projection || before.excess_noise_deg > 0);
}

std::string single_verdict(bool significant, const RankedEffect* top, const DiagnoseOptions& opt) {
  if (!significant) return "no_gap";
  if (top && top->cand.rejected.empty() && top->explained >= opt.explained_min &&
      top->cand.delta_bic < -10)
    return "explained";
  return "unexplained";
}

// The effects the recording cannot tell from the named one (`top`): as much explained, dBIC within
// 10, neither generalizing it nor rejected.
std::vector<std::string> ambiguous_effects(const std::vector<RankedEffect>& ranking,
                                           const RankedEffect& top, const DiagnoseOptions& opt) {
  std::vector<std::string> a;
  for (size_t k = 1; k < ranking.size(); ++k) {
    const RankedEffect& r = ranking[k];
    // A lattice settles quantization against excess noise (see the ranking).
    const bool settled =
        spec_of(top).fit == EffectFit::lattice && spec_of(r).fit == EffectFit::noise_variance;
    if (!settled && !generalizes(r.cand.effect, top.cand.effect) && r.cand.rejected.empty() &&
        r.explained >= opt.explained_min && r.cand.delta_bic < top.cand.delta_bic + 10)
      a.push_back(r.cand.effect);
  }
  return a;
}

// The combination starts from the best effect, or, when that carries almost nothing of the angle
// gap (less than kSeedMin), from the one that carries the most among those with evidence (dBIC <
// -10): the best by likelihood may owe it to what atan2 never sees (the common mode of a plate
// ring, e.g. a run-out's offset on every plate, or a ring off centre whose one-plate phase error
// fits the common mode and makes the angle gap worse). Chosen so, amplitude for gain_mismatch when
// it carries as much (see the ranking). nullptr: no effect at all.
const RankedEffect* combination_seed(const std::vector<RankedEffect>& ranking) {
  const RankedEffect* top = ranking.empty() ? nullptr : &ranking.front();
  const RankedEffect* seed = top;
  for (const auto& r : ranking)
    if (seed && top->explained < kSeedMin && r.cand.rejected.empty() && r.cand.delta_bic < -10 &&
        r.explained > seed->explained)
      seed = &r;
  for (const auto& r : ranking)
    if (seed && seed != top && r.cand.effect == common_mode_special(seed->cand.effect) &&
        r.cand.rejected.empty() && r.cand.delta_bic < -10 && r.explained >= seed->explained - 0.01)
      seed = &r;
  return seed;
}

// How a set of effects does together: share of gap^2 explained, gap after, BIC.
struct SetScore {
  double explained, after_deg, bic;
};

// The scoring of sets of effects on one recording.
struct SetScorer {
  const FitProblem& fp;
  const GapModel& m;
  double before2;

  SetScore operator()(const std::vector<RankedEffect>& set) const {
    const Recording& real = *fp.real;
    const double nsig = static_cast<double>(real.size()) * (real.channels == 4 ? 4 : 2);
    double extra = 0;
    const Recording pred = predict_set(fp, set, &extra);
    const StageSeries after = compare(m, real, pred, extra, &fp.basis);
    int k = 0;
    for (const auto& r : set) k += r.cand.k;
    return SetScore{explained_share(after.gap_deg, before2), after.gap_deg,
                    neg2_log_likelihood(fp, pred, extra) + k * std::log(nsig)};
  }
};

// Whether `e` or an effect it generalizes or that generalizes it is in the set already.
bool in_set(const std::vector<RankedEffect>& set, const std::string& e) {
  return std::any_of(set.begin(), set.end(), [&](const RankedEffect& c) {
    return c.cand.effect == e || generalizes(c.cand.effect, e) || generalizes(e, c.cand.effect);
  });
}

// One step of the forward selection: every effect not in `chosen` fitted on top of it (with the
// set's later field scalings on its angle change, as it will act in the set), and the one that
// explains the most kept, if its dBIC on top of the set is < -10 and it adds at least 10 % of
// gap^2, or at least 2 % and half of what is left. At one speed a delay or hysteresis is a
// constant angle: the zero offset explaining as much is the simpler name, whichever was tried
// first.
std::optional<RankedEffect> best_addition(const SetScorer& score,
                                          const std::vector<RankedEffect>& chosen,
                                          const SetScore& cur, bool one_speed) {
  const FitProblem& fp = score.fp;
  double extra = 0;
  const Recording base = predict_set(fp, chosen, &extra);
  std::optional<RankedEffect> pick;
  for (const std::string& e : fittable_effects()) {
    if (in_set(chosen, e)) continue;
    const std::vector<double> scale = later_field_scale(fp, chosen, e);
    const std::vector<double>* sp = scale.empty() ? nullptr : &scale;
    RankedEffect r;
    r.cand = fit_effect(fp, base, e, extra, sp);
    if (!r.cand.applicable || !r.cand.rejected.empty() || r.cand.delta_bic > -10) continue;
    const StageSeries after = gap_with(fp, score.m, base, r.cand, extra, sp);
    r.explained = explained_share(after.gap_deg, score.before2);
    r.after_deg = after.gap_deg;
    const double gain = r.explained - cur.explained;
    const bool enough =
        gain >= 0.1 || (gain >= 0.02 && 1 - r.explained <= 0.5 * (1 - cur.explained));
    auto shift_like = [](const RankedEffect& x) {
      return spec_of(x).shift == EffectShift::at_one_speed;
    };
    auto constant_shift = [](const RankedEffect& x) {
      return spec_of(x).shift == EffectShift::constant;
    };
    bool better = !pick || r.explained > pick->explained;
    if (pick && one_speed && constant_shift(r) && shift_like(*pick))
      better = r.explained >= pick->explained - 0.01;
    if (pick && one_speed && constant_shift(*pick) && shift_like(r))
      better = r.explained > pick->explained + 0.01;
    if (enough && better) pick = r;
  }
  return pick;
}

// A general effect in the set replaced by its special case when the set's BIC prefers it.
void prefer_special_cases(const SetScorer& score, std::vector<RankedEffect>& chosen,
                          SetScore& cur) {
  for (size_t k = 0; k < chosen.size(); ++k) {
    const std::string simple = special_case(chosen[k].cand.effect);
    if (simple.empty()) continue;
    std::vector<RankedEffect> alt = chosen;
    alt[k].cand = fit_in_set(score.fp, alt, simple, k);
    if (!alt[k].cand.applicable) continue;
    refit_set(score.fp, alt);
    const SetScore a = score(alt);
    if (a.bic < cur.bic) chosen = alt, cur = a;
  }
}

// More effects when the first leaves a clear remainder (forward selection from `seed`, at most
// max_combined, each refitted together with those before: backfitting), general effects replaced
// by their special cases where the set's BIC prefers. Sets d.combination (each effect's explained
// and after_deg those of the set up to it) when more than one effect was chosen; the set is named
// when it reaches explained_min.
void combine_effects(Diagnosis& d, const SetScorer& score, const RankedEffect& seed,
                     const DiagnoseOptions& opt) {
  const bool one_speed = !speed_changes(score.fp);
  std::vector<RankedEffect> chosen = {seed};
  SetScore cur{seed.explained, seed.after_deg, 0};
  while (static_cast<int>(chosen.size()) < opt.max_combined) {
    const std::optional<RankedEffect> pick = best_addition(score, chosen, cur, one_speed);
    if (!pick) break;
    chosen.push_back(*pick);
    refit_set(score.fp, chosen);
    cur = score(chosen);
  }
  if (chosen.size() < 2) return;
  cur = score(chosen);
  prefer_special_cases(score, chosen, cur);
  for (size_t k = 0; k < chosen.size(); ++k) {
    const SetScore p = score(std::vector<RankedEffect>(chosen.begin(), chosen.begin() + k + 1));
    chosen[k].explained = p.explained;
    chosen[k].after_deg = p.after_deg;
  }
  d.combination = chosen;
  d.combination_after_deg = cur.after_deg;
  d.combination_explained = cur.explained;
  if (d.verdict == "unexplained" && cur.explained >= opt.explained_min) d.verdict = "explained";
}

// How far it shrinks: the chosen effect(s) added to the simulation, on the recording of `f`.
StageSeries gap_with_chosen(const Diagnosis& d, const FitProblem& f, const GapModel& gm) {
  double extra = 0;
  Recording pred = f.predicted;
  if (d.verdict == "explained")
    pred = predict_set(
        f, d.combination.empty() ? std::vector<RankedEffect>{d.ranking.front()} : d.combination,
        &extra);
  return compare(gm, *f.real, pred, extra, &f.basis);
}

// Every effect of the vocabulary is a function of angle, speed, direction and temperature: an
// explanation that leaves a slow change in time (gap.hpp: a slip of the magnet, a dropout) has not
// found the cause, however much of gap^2 it explains. Refuses it (verdict unexplained, with a
// note) and recomputes the gap after.
void refuse_slow_change(Diagnosis& d, const FitProblem& fp, const GapModel& m, double before2,
                        const DiagnoseOptions& opt) {
  const double slow_share = before2 > 0 ? d.after.slow_deg * d.after.slow_deg / before2 : 0.0;
  if (!(d.verdict == "explained" && slow_share > opt.slow_share_max)) return;
  d.note = fmt::format(
      "the gap changes in time in a way no effect of the vocabulary does: after the best "
      "explanation "
      "{:.1f} % of gap^2 is left as a slow change over time (at most {:.0f} % allowed)",
      100 * slow_share, 100 * opt.slow_share_max);
  d.verdict = "unexplained";
  d.ambiguous_with.clear();
  d.after = gap_with_chosen(d, fp, m);
}

}  // namespace

std::vector<std::string> Diagnosis::named() const {
  std::vector<std::string> n;
  if (verdict != "explained") return n;
  if (!combination.empty()) {
    for (const auto& r : combination) n.push_back(r.cand.effect);
  } else if (!ranking.empty()) {
    n.push_back(ranking.front().cand.effect);
  }
  return n;
}

Diagnosis diagnose(const Recording& sim, const Recording& real, const Recording* holdout,
                   const DiagnoseOptions& opt) {
  check_inputs(sim, real, holdout);
  Diagnosis d;
  d.periodicity = std::max({1, meta_periodicity(sim), meta_periodicity(real)});
  const GapModel m = build_gap_model(sim, d.periodicity, opt.fourier_order);
  const FitProblem fp = make_fit_problem(m, real);
  d.before = compare(m, real, fp.predicted, 0, &fp.basis);
  const double before2 = d.before.gap_deg * d.before.gap_deg;

  d.stages = stage_divergence(m, real, fp.predicted, d.before);
  find_divergent_stage(d);
  d.domains = gap_domains(real, d.before.g, d.periodicity);
  d.domain = dominant_domain(d.domains);
  d.harmonics = gap_harmonics(real, d.before.g, d.periodicity);

  d.ranking = fit_each_effect(fp, m, before2);
  rank_effects(d.ranking, opt);
  const bool significant = gap_is_significant(d.before, fp);
  const RankedEffect* top = d.ranking.empty() ? nullptr : &d.ranking.front();
  d.verdict = single_verdict(significant, top, opt);
  if (d.verdict == "explained") d.ambiguous_with = ambiguous_effects(d.ranking, *top, opt);

  const RankedEffect* seed = combination_seed(d.ranking);
  if (significant && opt.try_pairs && seed && seed->cand.rejected.empty() &&
      seed->explained < 0.9 && seed->cand.delta_bic < -10)
    combine_effects(d, SetScorer{fp, m, before2}, *seed, opt);

  d.after = gap_with_chosen(d, fp, m);
  refuse_slow_change(d, fp, m, before2, opt);
  if (holdout) {
    const FitProblem fh = make_fit_problem(m, *holdout);
    d.hold_before = compare(m, *holdout, fh.predicted, 0, &fh.basis);
    d.hold_after = gap_with_chosen(d, fh, m);
  }
  return d;
}

nlohmann::json Diagnosis::to_json() const {
  using nlohmann::json;
  auto params_json = [](const EffectCandidate& c) {
    json p = json::object();
    for (const auto& [k, v] : c.params) p[k] = v;
    return p;
  };
  json j;
  j["verdict"] = verdict;
  j["periodicity"] = periodicity;
  j["gap"] = {{"before_deg", before.gap_deg},       {"after_deg", after.gap_deg},
              {"noise_deg", before.noise_deg},      {"raw_rms_before_deg", before.raw_rms_deg},
              {"slow_before_deg", before.slow_deg}, {"slow_after_deg", after.slow_deg}};
  if (!note.empty()) j["note"] = note;
  if (hold_before)
    j["holdout"] = {{"before_deg", hold_before->gap_deg}, {"after_deg", hold_after->gap_deg}};
  else
    j["holdout"] = nullptr;
  json harm = json::array();
  for (const auto& h : harmonics)
    harm.push_back({{"order", h.order}, {"amplitude_deg", h.amplitude_deg}, {"causes", h.causes}});
  json dom = json::object();
  for (const auto& s : domains) dom[s.domain] = s.r2;
  json st = json::array();
  for (const auto& s : stages) {
    json r = json::object();
    for (size_t k = 0; k < s.signals.size(); ++k) r[s.signals[k]] = s.ratio[k];
    st.push_back({{"stage", s.stage}, {"diverges", s.diverges}, {"rms_over_noise", r}});
  }
  j["where"] = {{"stage", where_stage},    {"domain", domain}, {"channels", where_channels},
                {"angle_harmonics", harm}, {"domain_r2", dom}, {"stages", st}};
  json rank = json::array();
  if (verdict != "explained")
    rank.push_back({{"effect", "unexplained"},
                    {"params", json::object()},
                    {"explained", 0.0},
                    {"after_deg", before.gap_deg}});
  for (const auto& r : ranking) {
    json e = {{"effect", r.cand.effect},       {"params", params_json(r.cand)},
              {"explained", r.explained},      {"after_deg", r.after_deg},
              {"delta_bic", r.cand.delta_bic}, {"k", r.cand.k}};
    if (!r.cand.rejected.empty()) e["rejected"] = r.cand.rejected;
    rank.push_back(e);
  }
  j["ranking"] = rank;
  j["ambiguous_with"] = ambiguous_with;
  j["named"] = named();
  if (!combination.empty()) {
    json c = json::array();
    for (const auto& r : combination)
      c.push_back(
          {{"effect", r.cand.effect}, {"params", params_json(r.cand)}, {"explained", r.explained}});
    j["combination"] = {
        {"effects", c}, {"explained", combination_explained}, {"after_deg", combination_after_deg}};
  }
  return j;
}

}  // namespace acore
