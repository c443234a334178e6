// SPDX-License-Identifier: MIT
// Sim-to-real gap diagnosis (docs/contracts.md, command line `diagnose`, 3.4 effects): where the
// gap lies, which unmodelled effect causes it, how far it shrinks once that effect is added to the
// simulation, checked on a holdout recording the fit never saw.
#pragma once
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "diagnose/effect_fit.hpp"
#include "diagnose/gap.hpp"

namespace acore {

struct DiagnoseOptions {
  int fourier_order = 12;        // harmonics of the static sensor model fitted to the simulation
  bool try_pairs = true;         // combinations of effects when one leaves a clear remainder
  double slow_share_max = 0.01;  // the most of gap^2 a named explanation may leave as a slow
                                 // change in time (gap.hpp): more is a slip, a dropout
  int max_combined = 3;          // effects in a combination at most (run-out: zero_offset,
                                 // eccentricity and amplitude together)
  double explained_min =
      0.9;  // the best effect (or pair) must explain this share of gap^2 to be named
};

struct RankedEffect {
  EffectCandidate cand;
  double explained = 0;  // 1 - gap_after^2 / gap_before^2 on the real recording
  double after_deg = 0;  // gap after adding the effect
};

struct GapHarmonic {
  int order;  // mechanical order of the gap g(theta)
  double amplitude_deg;
  std::vector<std::string> causes;  // likely signal-domain causes
};

struct Diagnosis {
  std::string verdict;  // "explained", "unexplained" or "no_gap"
  std::string note;     // why an explanation that explains enough was not named (empty: none)
  StageSeries before, after;
  std::optional<StageSeries> hold_before, hold_after;
  std::vector<StageDivergence> stages;
  std::string where_stage;
  std::vector<std::string> where_channels;
  std::vector<DomainScore> domains;
  std::string domain;
  std::vector<GapHarmonic> harmonics;
  std::vector<RankedEffect> ranking;  // best first: those that could be named (explain
                                      // explained_min, dBIC < -10), then by information criterion
  // The effects chosen one after the other (forward selection, then refitted together) when the
  // best single effect leaves a clear remainder; explained and after_deg of each are those of the
  // set up to it.
  std::vector<RankedEffect> combination;
  double combination_after_deg = 0, combination_explained = 0;
  // Other effects the recording cannot tell from the named one: they explain as much and their
  // information criterion is within 10 of it (e.g. zero_offset, common_delay and hysteresis on a
  // recording at one constant speed), an effect that merely generalizes the named one excepted
  // (gain_mismatch for amplitude, channel_skew for common_delay). Record with speed changes and a
  // reversal to separate them.
  std::vector<std::string> ambiguous_with;
  int periodicity = 1;
  // The named effects: the combination when one was named, else the best single effect; empty
  // unless the verdict is "explained".
  std::vector<std::string> named() const;
  nlohmann::json to_json() const;  // docs/contracts.md, command line fields and more
};

// Throws InputError for recordings that cannot be compared (channel sets differ, no theta_ref,
// too few samples, less than a turn).
Diagnosis diagnose(const Recording& sim, const Recording& real, const Recording* holdout,
                   const DiagnoseOptions& opt = DiagnoseOptions{});

}  // namespace acore
