// SPDX-License-Identifier: MIT
// The effect library (docs/contracts.md, effect vocabulary, meanings widened in docs/diagnosis.md
// "Effect vocabulary"): parametric transforms of a sensor recording, each named exactly as in the
// vocabulary, with named parameters (the same names the gap diagnosis fits and reports,
// effect_fit.hpp).
//
// An effect is applied to a recording together with an EffectContext: what the sensor model and the
// trajectory say beyond the recorded columns. Two kinds (each row of the effect table says which):
//   field-domain effects change what a channel *sees*: the electrical angle (a phase error, a
//     delay, ...) and the magnitude of the field (amplitude, eccentricity). They update
//     ctx.phase[c] and ctx.field_gain[c] and add the change of the sensor's field part, g'
//     (sensor(c, new phase) - dc_c) - g (sensor(c, old phase)
//     - dc_c), to the channel (dc_c = the channel's mean over a turn: its electrical offset, which
//     no field change scales); whatever was added to the channel before (offsets, noise) is kept.
//     The order of field-domain effects among themselves does not matter to first order (exactly,
//     for the scaling ones); gains applied before them do not scale their change, so simulate()
//     applies the field-domain effects first (see simulator.hpp).
//   signal-domain effects act on the channel values (an offset, a gain, an ADC, ...).
//
// Parameters: every effect's names, no-op defaults, units and meaning are rows of the effect table
// (effect_table.hpp; `anglecore simulate --list-effects`, docs/diagnosis.md "Effect vocabulary").
// A channel's suffix X is c1..c4, or sin, cos for two-channel recordings; its "position" is its
// 90-degree slot (c1..c4 -> 0..3, sin, cos -> 0, 1); theta is the mechanical angle the channel sees
// before the effect, phi = p theta the electrical one; every default is a no-op (quantization and
// saturation have none).
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "core/recording.hpp"

namespace acore {

// Named parameter values, in the effect's canonical order (same alias as effect_fit.hpp).
using ParamList = std::vector<std::pair<std::string, double>>;

struct Effect {
  std::string effect;  // docs/contracts.md, effect vocabulary name, e.g. "offset"
  ParamList params;    // every parameter of the effect, canonical order (its row's, effect_table)

  // The value of a parameter; throws InputError naming the effect when absent.
  double param(const std::string& name) const;
};

// The simulated effects, the names of the effect table's rows: docs/contracts.md, effect
// vocabulary's twelve in its order, then the two added since (zero_offset, amplitude).
// "unexplained" is a verdict, not an effect.
const std::vector<std::string>& effect_names();
// True for the field-domain effects (see the top of this file); throws InputError for an unknown
// name.
bool is_field_effect(const std::string& effect);
// Channel name used in parameter suffixes: "c1".."c4", or "sin", "cos" when channels == 2.
std::string effect_channel_name(int channels, int c);
// Every parameter of `effect` with its default (no-op where one exists), for 2 or 4 channels.
// Throws InputError listing the valid names for an unknown effect.
ParamList effect_defaults(const std::string& effect, int channels);
// An effect with `given` parameters over the defaults; throws InputError for an unknown effect, an
// unknown parameter (listing the valid ones), or an invalid value (bits < 1, level <= 0, ...).
Effect make_effect(const std::string& effect, const ParamList& given, int channels);

// phase_error: the electrical phase shift each channel sees (its pair's delta plus phase_X), rad.
std::array<double, 4> phase_error_shifts(const Effect& e, int channels);
// channel_skew: the time at which each channel is sampled, relative to t (position * tau_s +
// tau_X), s.
std::array<double, 4> channel_skew_offsets(const Effect& e, int channels);

// What an effect needs beyond the recording's columns.
struct EffectContext {
  int p = 1;  // periodicity: electrical angle = p * mechanical angle
  // Clean output of channel c (0-based) at electrical angle phi (rad): needed by field-domain
  // effects.
  std::function<double(int c, double phi)> sensor;
  // Mechanical angle (rad, unwrapped) of the trajectory at any time t (s): channel_skew,
  // common_delay.
  std::function<double(double t)> theta_at;
  // Electrical angle each channel currently sees, per sample (updated by field-domain effects).
  std::array<std::vector<double>, 4> phase;
  // Factor on each channel's field part, per sample (amplitude, eccentricity); empty means 1.
  std::array<std::vector<double>, 4> field_gain;
  // +1 rotating forward, -1 backward, per sample (hysteresis).
  std::vector<double> direction;
  // Random source for excess_noise.
  std::mt19937_64 rng{0};
};

// A context for an existing recording: phases p*theta_ref, direction from the sign of the
// theta_ref increments (the first sample takes the second's), rng seeded with `seed`. Needs
// theta_ref.
EffectContext make_effect_context(const Recording& rec, int p,
                                  std::function<double(int, double)> sensor,
                                  std::function<double(double)> theta_at, uint64_t seed);

// Applies one effect in place (its row's apply function). Throws InputError for an unknown effect
// and when the recording or context lacks what the effect needs (temp for drift, t and theta_at
// for channel_skew/common_delay, sensor for field effects).
void apply_effect(const Effect& e, Recording& rec, EffectContext& ctx);

}  // namespace acore
