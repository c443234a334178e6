// SPDX-License-Identifier: MIT
#include "diagnose/diagnose.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

#include "core/errors.hpp"
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
  if (k == 0) {
    c.push_back("zero_offset (a constant angle shift)");
    c.push_back("common_delay or hysteresis (at one speed, in one direction)");
    return c;
  }
  if (k == p) c.push_back("offset (signal order 0)");
  if (k == 2 * p) c.push_back("amplitude or phase mismatch (signal order p)");
  if (k == 1 && p != 1) c.push_back("eccentricity (mechanical order 1)");
  if (k == 1 && p == 1) c.push_back("eccentricity or offset");
  for (int n : {k - p, k + p})
    if (n >= 2) c.push_back(fmt::format("signal harmonic of order {}", n));
  return c;
}

// `general` contains `special` as a case (equal gains are an amplitude, equal sampling times a
// common delay): when the special one is named, the general one explaining as much is no ambiguity.
bool generalizes(const std::string& general, const std::string& special) {
  return (general == "gain_mismatch" && special == "amplitude") ||
         (general == "channel_skew" && special == "common_delay");
}

// Order among effects the recording cannot tell apart at all (identical columns, e.g. a constant
// shift, a delay and hysteresis at one constant speed): fewer parameters first, then the constant
// shift, then the vocabulary's order.
int tie_rank(const RankedEffect& r) {
  const auto& names = fittable_effects();
  const int order =
      r.cand.effect == "zero_offset"
          ? -1
          : static_cast<int>(std::find(names.begin(), names.end(), r.cand.effect) - names.begin());
  return 100 * r.cand.k + order;
}

// The order in which a set of effects is applied to a prediction, as simulate() does: angle shifts,
// then eccentricity (a shift and a scaling), then amplitude (it scales what came before), then the
// signal-domain effects in the order they were chosen.
int apply_rank(const std::string& e) {
  if (e == "eccentricity") return 1;
  if (e == "amplitude") return 2;
  return is_field_effect(e) ? 0 : 3;
}

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
    if (k == skip || apply_rank(c.effect) <= apply_rank(effect)) continue;
    if (c.effect != "amplitude" && c.effect != "eccentricity") continue;
    if (s.empty()) s.assign(f.real->size(), 1.0);
    for (size_t i = 0; i < s.size(); ++i)
      s[i] *=
          c.effect == "amplitude"
              ? c.param("scale")
              : 1 + c.param("am_depth") * std::cos(f.real->theta_ref[i] - c.param("am_phase_rad"));
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

// The special case a general effect reduces to (empty: none).
std::string special_case(const std::string& general) {
  if (general == "gain_mismatch") return "amplitude";
  if (general == "channel_skew") return "common_delay";
  return "";
}

// The special case a general effect owes its lead over to the common mode of the channels alone
// (empty: none): amplitude for gain_mismatch.
std::string common_mode_special(const std::string& general) {
  return general == "gain_mismatch" ? "amplitude" : "";
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
  check_recording(sim, "--sim");
  check_recording(real, "--real");
  if (holdout) check_recording(*holdout, "--holdout");
  if (sim.channels != real.channels || (holdout && holdout->channels != real.channels))
    throw InputError(fmt::format("channel sets differ: --sim has {} channels, --real {}{}",
                                 sim.channels, real.channels,
                                 holdout ? fmt::format(", --holdout {}", holdout->channels) : ""));
  Diagnosis d;
  d.periodicity = std::max({1, meta_periodicity(sim), meta_periodicity(real)});
  const GapModel m = build_gap_model(sim, d.periodicity, opt.fourier_order);
  const FitProblem fp = make_fit_problem(m, real);
  d.before = compare(m, real, fp.predicted, 0, &fp.basis);

  // Where: the first stage that diverges beyond noise, and the signals involved there.
  d.stages = stage_divergence(m, real, fp.predicted, d.before);
  d.where_stage = "none";
  for (const auto& st : d.stages)
    if (st.diverges) {
      d.where_stage = st.stage;
      const double top = *std::max_element(st.ratio.begin(), st.ratio.end());
      for (size_t k = 0; k < st.signals.size(); ++k)
        if (st.ratio[k] > 1.0 + 0.25 * (top - 1.0)) d.where_channels.push_back(st.signals[k]);
      break;
    }
  d.domains = gap_domains(real, d.before.g, d.periodicity);
  // Angle unless another domain explains clearly more; "random" when nothing explains much.
  d.domain = "random";
  double best = 0.2, angle_r2 = -1;
  for (const auto& s : d.domains)
    if (s.domain == "angle") angle_r2 = s.r2;
  if (angle_r2 > best) d.domain = "angle", best = angle_r2;
  for (const auto& s : d.domains)
    if (s.domain != "angle" && s.r2 > best + 0.1) d.domain = s.domain, best = s.r2;
  {
    const auto orders = gap_orders(real, d.before.g, 12);
    double peak = 0;
    for (const auto& o : orders) peak = std::max(peak, o.second);
    for (const auto& [k, a] : orders)
      if (a > 0.1 * peak && a > 1e-4) d.harmonics.push_back({k, a, causes_of(k, d.periodicity)});
    std::sort(d.harmonics.begin(), d.harmonics.end(),
              [](const GapHarmonic& a, const GapHarmonic& b) {
                return a.amplitude_deg > b.amplitude_deg;
              });
  }

  // Which: every effect fitted and scored.
  const double before2 = d.before.gap_deg * d.before.gap_deg;
  auto evaluate = [&](const Recording& base, const EffectCandidate& c, const Recording& rec,
                      const GapModel& gm, const FitProblem& f, double extra0) {
    double extra = 0;
    const Recording pred = predict_effect(f, base, c, &extra);
    (void)rec;
    return compare(gm, *f.real, pred, std::hypot(extra, extra0), &f.basis);
  };
  for (const std::string& e : fittable_effects()) {
    RankedEffect r;
    r.cand = fit_effect(fp, fp.predicted, e);
    if (!r.cand.applicable) continue;
    const StageSeries after = evaluate(fp.predicted, r.cand, real, m, fp, 0);
    r.after_deg = after.gap_deg;
    r.explained = before2 > 0 ? 1.0 - after.gap_deg * after.gap_deg / before2 : 0.0;
    d.ranking.push_back(r);
  }
  // Effects that could be named (they explain explained_min of the angle gap, dBIC < -10) come
  // first, then by information criterion. The likelihood also counts what atan2 never sees (a
  // common scale of every channel, e.g. the fundamental's shrink under a compressing nonlinearity):
  // an effect that fits that part best but leaves the angle gap (gain_mismatch with equal gains)
  // must not outrank the one that carries the angle gap (the harmonic). Among those, quantization,
  // when the values lie on a lattice (its step read from the data, not fitted to the residual),
  // comes first: the lattice proves the ADC, and excess noise would only be fitting its rounding
  // noise.
  auto carries = [&](const RankedEffect& r) {
    return r.explained >= opt.explained_min && r.cand.delta_bic < -10;
  };
  auto measured = [&](const RankedEffect& r) {
    return r.cand.effect == "quantization" && r.explained >= opt.explained_min;
  };
  std::sort(d.ranking.begin(), d.ranking.end(), [&](const RankedEffect& a, const RankedEffect& b) {
    if (a.cand.rejected.empty() != b.cand.rejected.empty()) return a.cand.rejected.empty();
    if (carries(a) != carries(b)) return carries(a);
    if (measured(a) != measured(b)) return measured(a);
    return a.cand.delta_bic < b.cand.delta_bic;
  });
  if (!d.ranking.empty()) {
    const double b0 = d.ranking.front().cand.delta_bic;
    size_t pick = 0;
    for (size_t k = 1; k < d.ranking.size(); ++k) {
      const RankedEffect& r = d.ranking[k];
      const bool tie = r.cand.rejected.empty() == d.ranking.front().cand.rejected.empty() &&
                       carries(r) == carries(d.ranking.front()) &&
                       measured(r) == measured(d.ranking.front()) &&
                       std::fabs(r.cand.delta_bic - b0) <= 1e-6 * std::fabs(b0) + 1e-6;
      if (tie && tie_rank(r) < tie_rank(d.ranking[pick])) pick = k;
    }
    std::rotate(d.ranking.begin(), d.ranking.begin() + static_cast<std::ptrdiff_t>(pick),
                d.ranking.begin() + static_cast<std::ptrdiff_t>(pick) + 1);
    // gain_mismatch first owes its lead to what atan2 never sees when amplitude carries as much of
    // the angle gap: a plate ring's common mode, e.g. the field a run-out adds to every plate
    // alike. Name amplitude then; gain_mismatch stays in the ranking, and is no ambiguity
    // (generalizes()). (Not channel_skew for common_delay: the skews' differences are seen by
    // atan2, however little they add to the share.)
    const std::string simple = common_mode_special(d.ranking.front().cand.effect);
    for (size_t k = 1; k < d.ranking.size() && !simple.empty(); ++k) {
      const RankedEffect& r = d.ranking[k];
      if (r.cand.effect == simple && r.cand.rejected.empty() && carries(r) &&
          r.explained >= d.ranking.front().explained - 0.01) {
        std::rotate(d.ranking.begin(), d.ranking.begin() + static_cast<std::ptrdiff_t>(k),
                    d.ranking.begin() + static_cast<std::ptrdiff_t>(k) + 1);
        break;
      }
    }
  }

  // Is there a gap at all? mean(g^2) against the noise term, with its sampling spread.
  // Is there a gap at all? The systematic part must stand out of what noise leaves in the
  // projection (cols/N of the noise variance, here required 3x over), or the excess noise must be
  // significant.
  const double n = static_cast<double>(real.size());
  const double cols = static_cast<double>(fp.basis.X.cols());
  const double noise_in_projection = std::sqrt(cols / n) * d.before.noise_deg;
  const bool significant =
      d.before.gap_deg > 1e-3 &&
      (d.before.systematic_deg > 3 * noise_in_projection || d.before.excess_noise_deg > 0);
  const RankedEffect* top = d.ranking.empty() ? nullptr : &d.ranking.front();
  if (!significant) {
    d.verdict = "no_gap";
  } else if (top && top->cand.rejected.empty() && top->explained >= opt.explained_min &&
             top->cand.delta_bic < -10) {
    d.verdict = "explained";
  } else {
    d.verdict = "unexplained";
  }

  if (d.verdict == "explained")
    for (size_t k = 1; k < d.ranking.size(); ++k) {
      const RankedEffect& r = d.ranking[k];
      // A lattice settles quantization against excess noise (see the ranking above).
      const bool settled = top->cand.effect == "quantization" && r.cand.effect == "excess_noise";
      if (!settled && !generalizes(r.cand.effect, top->cand.effect) && r.cand.rejected.empty() &&
          r.explained >= opt.explained_min && r.cand.delta_bic < top->cand.delta_bic + 10)
        d.ambiguous_with.push_back(r.cand.effect);
    }

  // More effects when the first leaves a clear remainder (forward selection, at most max_combined):
  // each step fits every other effect on top of those chosen and keeps the one that explains the
  // most of the gap, if its dBIC on top of them is < -10 and it explains at least 10 % more of
  // gap^2, or at least 2 % more and half of what is left; the set is then refitted together
  // (backfitting). A general effect in the set is replaced by its special case when the set's BIC
  // prefers it. The set is named when it reaches explained_min.
  // The set starts from the best effect, or, when that carries almost nothing of the angle gap
  // (less than kSeedMin), from the one that carries the most among those with evidence (dBIC <
  // -10): the best by likelihood may owe it to what atan2 never sees (the common mode of a plate
  // ring, e.g. a run-out's offset on every plate, or a ring off centre whose one-plate phase error
  // fits the common mode and makes the angle gap worse).
  const RankedEffect* seed = top;
  for (const auto& r : d.ranking)
    if (seed && top->explained < kSeedMin && r.cand.rejected.empty() && r.cand.delta_bic < -10 &&
        r.explained > seed->explained)
      seed = &r;
  // Chosen so, amplitude for gain_mismatch when it carries as much (see the ranking above).
  for (const auto& r : d.ranking)
    if (seed && seed != top && r.cand.effect == common_mode_special(seed->cand.effect) &&
        r.cand.rejected.empty() && r.cand.delta_bic < -10 && r.explained >= seed->explained - 0.01)
      seed = &r;
  if (significant && opt.try_pairs && seed && seed->cand.rejected.empty() &&
      seed->explained < 0.9 && seed->cand.delta_bic < -10) {
    const double nsig = static_cast<double>(real.size()) * (real.channels == 4 ? 4 : 2);
    struct SetScore {
      double explained, after_deg, bic;
    };
    auto score = [&](const std::vector<RankedEffect>& set) {
      double extra = 0;
      const Recording pred = predict_set(fp, set, &extra);
      const StageSeries after = compare(m, real, pred, extra, &fp.basis);
      int k = 0;
      for (const auto& r : set) k += r.cand.k;
      return SetScore{before2 > 0 ? 1.0 - after.gap_deg * after.gap_deg / before2 : 0.0,
                      after.gap_deg, neg2_log_likelihood(fp, pred, extra) + k * std::log(nsig)};
    };
    auto in_set = [](const std::vector<RankedEffect>& set, const std::string& e) {
      return std::any_of(set.begin(), set.end(), [&](const RankedEffect& c) {
        return c.cand.effect == e || generalizes(c.cand.effect, e) || generalizes(e, c.cand.effect);
      });
    };
    const bool one_speed = !speed_changes(fp);
    std::vector<RankedEffect> chosen = {*seed};
    SetScore cur{seed->explained, seed->after_deg, 0};
    while (static_cast<int>(chosen.size()) < opt.max_combined) {
      // The chosen set's prediction, once per step; each candidate is fitted and tried on top of it
      // (with the set's later field scalings on its angle change, as it will act in the set).
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
        double e2 = 0;
        const Recording pred = predict_effect(fp, base, r.cand, &e2, sp);
        const StageSeries after = compare(m, real, pred, std::hypot(extra, e2), &fp.basis);
        const SetScore t{before2 > 0 ? 1.0 - after.gap_deg * after.gap_deg / before2 : 0.0,
                         after.gap_deg, 0};
        r.explained = t.explained;
        r.after_deg = t.after_deg;
        const double gain = t.explained - cur.explained;
        const bool enough =
            gain >= 0.1 || (gain >= 0.02 && 1 - t.explained <= 0.5 * (1 - cur.explained));
        // At one speed a delay or hysteresis is a constant angle: the zero offset explaining as
        // much is the simpler name, whichever was tried first.
        auto shift_like = [](const RankedEffect& x) {
          return x.cand.effect == "common_delay" || x.cand.effect == "hysteresis";
        };
        bool better = !pick || r.explained > pick->explained;
        if (pick && one_speed && r.cand.effect == "zero_offset" && shift_like(*pick))
          better = r.explained >= pick->explained - 0.01;
        if (pick && one_speed && pick->cand.effect == "zero_offset" && shift_like(r))
          better = r.explained > pick->explained + 0.01;
        if (enough && better) pick = r;
      }
      if (!pick) break;
      chosen.push_back(*pick);
      refit_set(fp, chosen);
      cur = score(chosen);
    }
    if (chosen.size() > 1) {
      cur = score(chosen);
      for (size_t k = 0; k < chosen.size(); ++k) {
        const std::string simple = special_case(chosen[k].cand.effect);
        if (simple.empty()) continue;
        std::vector<RankedEffect> alt = chosen;
        alt[k].cand = fit_in_set(fp, alt, simple, k);
        if (!alt[k].cand.applicable) continue;
        refit_set(fp, alt);
        const SetScore a = score(alt);
        if (a.bic < cur.bic) chosen = alt, cur = a;
      }
      // Each effect's explained and after_deg: those of the set up to it.
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
  }

  // How far it shrinks: the chosen effect(s) added to the simulation, on real and holdout.
  auto apply_chosen = [&](const FitProblem& f, const GapModel& gm) {
    double extra = 0;
    Recording pred = f.predicted;
    if (d.verdict == "explained")
      pred = predict_set(f, d.combination.empty() ? std::vector<RankedEffect>{*top} : d.combination,
                         &extra);
    return compare(gm, *f.real, pred, extra, &f.basis);
  };
  d.after = apply_chosen(fp, m);
  // Every effect of the vocabulary is a function of angle, speed, direction and temperature: an
  // explanation that leaves a slow change in time (gap.hpp: a slip of the magnet, a dropout) has
  // not found the cause, however much of gap^2 it explains.
  const double slow_share = before2 > 0 ? d.after.slow_deg * d.after.slow_deg / before2 : 0.0;
  if (d.verdict == "explained" && slow_share > opt.slow_share_max) {
    d.note = fmt::format(
        "the gap changes in time in a way no effect of the vocabulary does: after the best "
        "explanation "
        "{:.1f} % of gap^2 is left as a slow change over time (at most {:.0f} % allowed)",
        100 * slow_share, 100 * opt.slow_share_max);
    d.verdict = "unexplained";
    d.ambiguous_with.clear();
    d.after = apply_chosen(fp, m);
  }
  if (holdout) {
    const FitProblem fh = make_fit_problem(m, *holdout);
    d.hold_before = compare(m, *holdout, fh.predicted, 0, &fh.basis);
    d.hold_after = apply_chosen(fh, m);
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
