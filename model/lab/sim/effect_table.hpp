// SPDX-License-Identifier: MIT
// The effect table: one row per effect of the vocabulary (docs/contracts.md, effect vocabulary;
// meanings widened in docs/diagnosis.md "Effect vocabulary"), the one place that knows an effect's
// name, its kind, its parameters (names, no-op defaults, units, per channel or not), how the
// simulator applies it, how the gap diagnosis fits it and what it means. Everything else reads the
// rows: the simulator's scenario reader and its error for an unknown effect (effects.hpp), the
// fits (model/lab/diagnose/effect_fit.cpp keeps one fitter per row, found by the row's id), the
// diagnosis's rules between effects (model/lab/diagnose/diagnose.cpp), the benchmarks' draws and
// scores, `anglecore simulate --list-effects`, and the vocabulary of docs/diagnosis.md (generated
// from that listing by scripts/effect_vocabulary.py, which also checks docs/contracts.md against
// the rows; CTest effect_vocabulary).
//
// Adding an effect: an id below, its row and apply function in effect_table.cpp, its fitter in
// effect_fit.cpp, its draw and score in diagnose_bench.cpp (docs/architecture.md, "How to add").
#pragma once
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "sim/effects.hpp"

namespace acore {

// The effects, in the vocabulary's order: the contract's twelve, then the two added since. The
// rows of effect_table() are in this order; "unexplained" is a verdict, not an effect.
enum class EffectId {
  offset,
  gain_mismatch,
  phase_error,
  harmonic,
  eccentricity,
  channel_skew,
  common_delay,
  drift,
  quantization,
  saturation,
  excess_noise,
  hysteresis,
  zero_offset,
  amplitude,
};
constexpr size_t kEffectCount = 14;

// Field-domain effects change what a channel sees (its electrical angle, the magnitude of its
// field); signal-domain effects act on the channel values (effects.hpp).
enum class EffectDomain { field, signal };

// How the gap diagnosis fits an effect (docs/diagnosis.md, "How it works", step 4).
enum class EffectFit {
  linear,            // linear least squares on columns of the residual
  field_linearized,  // linearized through the model's derivative, then applied exactly
  shift_search,      // started at a circular mean, refined by Gauss-Newton on the exact shift
  level_search,      // a search over one level (likelihood against the level)
  noise_variance,    // the variance of white noise on every channel, by maximum likelihood
  lattice,           // read from the recording (the values' lattice), not fitted
};

// What a recording of an angle shift looks like when the speed never changes.
enum class EffectShift {
  none,
  constant,     // a constant angle shift (the simplest name of what follows)
  at_one_speed  // a constant angle shift at one speed in one direction (a delay, hysteresis)
};

struct EffectParamSpec {
  std::string name;  // per channel: the prefix, the channel's name appended (offset_ + c1)
  double no_op = 0;  // the default: a no-op where one exists
  std::string unit;
  bool per_channel = false;
  std::string what;  // one line
};

struct EffectSpec {
  EffectId id{};
  std::string name;    // the vocabulary name, exact
  std::string abbrev;  // a column of the benchmarks' confusion matrix, at most 6 characters
  EffectDomain domain = EffectDomain::signal;
  std::vector<EffectParamSpec> params;  // the canonical order of Effect::params
  // Applies the effect to a recording in place (effects.hpp, apply_effect).
  void (*apply)(const Effect&, Recording&, EffectContext&) = nullptr;
  // The value rules beyond finiteness; throws InputError saying what is wrong. nullptr: none.
  void (*check)(const Effect&) = nullptr;
  // The factor the effect puts on every channel's field part at mechanical angle theta (amplitude,
  // eccentricity's magnitude modulation); nullptr: it scales no field.
  double (*field_factor)(const Effect&, double theta) = nullptr;
  EffectFit fit = EffectFit::linear;
  std::string fit_note;  // what the fit does beyond its kind (empty: nothing)
  // Where a set of effects applies it in the diagnosis's prediction, lowest first, as simulate()
  // does: angle shifts 0, eccentricity 1 (a shift and a scaling), amplitude 2 (it scales what came
  // before), the signal domain 3.
  int set_order = 3;
  bool needs_time = false;          // the t column and the trajectory's angle at any time
  bool needs_temperature = false;   // the temp column (simulate() writes one for it)
  bool needs_speed_change = false;  // told from simpler effects only when the speed changes
  EffectShift shift = EffectShift::none;
  // The simpler effect this one generalizes (equal gains are an amplitude, equal sampling times a
  // common delay): no ambiguity when that one is named, and named instead when a set prefers it.
  std::optional<EffectId> special_case;
  // This effect can lead the ranking on the channels' common mode alone, which atan2 never sees
  // (gain_mismatch on a plate ring): its special case is named when it carries as much of the
  // angle gap.
  bool leads_on_common_mode = false;
  std::string meaning;  // the one line of docs/contracts.md, effect vocabulary (verbatim)
  std::string widened;  // what it means now (docs/diagnosis.md); empty: as in the contract
  std::string status;   // "as in the contract", "widened: ...", "added"

  // Every parameter with its no-op default, for 2 or 4 channels; throws InputError otherwise.
  ParamList defaults(int channels) const;
};

// The rows, in EffectId order.
const std::array<EffectSpec, kEffectCount>& effect_table();
const EffectSpec& effect_spec(EffectId id);
// The row of a vocabulary name; nullptr when there is none.
const EffectSpec* find_effect(const std::string& name);
// The row of a vocabulary name; throws InputError listing the valid names for an unknown one.
const EffectSpec& effect_spec(const std::string& name);
inline const std::string& effect_name(EffectId id) { return effect_spec(id).name; }

// A short text for each fit kind (for the listing and the docs).
std::string effect_fit_text(EffectFit fit);

}  // namespace acore
