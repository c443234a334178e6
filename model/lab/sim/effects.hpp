// SPDX-License-Identifier: MIT
// The effect library (docs/contracts.md, effect vocabulary, meanings widened in docs/diagnosis.md
// "Effect vocabulary"): parametric transforms of a sensor recording, each named exactly as in the
// vocabulary, with named parameters (the same names the gap diagnosis fits and reports,
// effect_fit.hpp).
//
// An effect is applied to a recording together with an EffectContext: what the sensor model and the
// trajectory say beyond the recorded columns. Two kinds:
//   field-domain effects change what a channel *sees*: the electrical angle (phase_error,
//     eccentricity, channel_skew, common_delay, hysteresis, zero_offset) and the magnitude of the
//     field (amplitude, eccentricity). They update ctx.phase[c] and ctx.field_gain[c] and add the
//     change of the sensor's field part, g' (sensor(c, new phase) - dc_c) - g (sensor(c, old phase)
//     - dc_c), to the channel (dc_c = the channel's mean over a turn: its electrical offset, which
//     no field change scales); whatever was added to the channel before (offsets, noise) is kept.
//     The order of field-domain effects among themselves does not matter to first order (exactly,
//     for the scaling ones); gains applied before them do not scale their change, so simulate()
//     applies the field-domain effects first (see simulator.hpp).
//   signal-domain effects act on the channel values (offset, gain_mismatch, harmonic, drift,
//     quantization, saturation, excess_noise).
//
// Parameters (channel suffix X = c1..c4, or sin, cos for two-channel recordings; "position" of a
// channel = its 90-degree slot: c1..c4 -> 0..3, sin, cos -> 0, 1; theta = the mechanical angle the
// channel sees before the effect, phi = p theta the electrical one; every default is a no-op).
//
// offset         offset_X        added to channel X (sensor units); default 0
// gain_mismatch  gain_X          channel X (offset included: an amplifier) times this factor;
//                                default 1. The gains relative to each other: equal gains are
//                                `amplitude` (which the diagnosis names: fewer parameters)
// amplitude      scale           the field part of every channel times `scale` (> 0): a weaker or
//                                stronger magnet, another air gap; default 1
// phase_error    delta_rad       the sine pair (c1, c3 / sin) sees phi + delta (orthogonality
//                                error, as before); default 0
//                delta_cos_rad   the cosine pair (c2, c4 / cos) sees phi + delta_cos; default 0
//                phase_X         channel X alone sees phi + phase_X (a misplaced plate: c2 moved
//                                by d gives c2 - c4 a phase shift d/2 and the factor cos(d/2));
//                                with two channels the same as the pair's delta. The three add.
// harmonic       order           n (integer >= 1) of an extra spatial harmonic of the field
//                amplitude       a (sensor units); default 0
//                phase_rad       psi; channel X gets a*sin(n*(phase_X + position_X*pi/2) + psi),
//                                the same field harmonic seen from each sensor's 90-degree position
// eccentricity   epsilon_rad     every channel sees the mechanical angle
//                phi0_rad          theta + eps*sin(theta - phi0) (angle modulation, as before)
//                am_depth        and its field part is multiplied by 1 + m*cos(theta - phi_m)
//                am_phase_rad    (magnitude modulation); m = 0 by default: old files keep their
//                                meaning. A displacement d of the sensor in a rotating field
//                                changes it by J d (J its gradient): along B the magnitude, across
//                                it the angle. A 2-D potential field (J symmetric, traceless)
//                                gives m = eps, phi_m = phi0; an isotropic part of J (in-plane
//                                divergence) a fixed vector in the lab, m = eps, phi_m = phi0 + pi,
//                                i.e. an offset to a two-channel sensor. Geometry decides the mix,
//                                so all four are free (docs/diagnosis.md "Effect vocabulary").
// zero_offset    zero_rad        every channel sees the mechanical angle theta + zero: a constant
//                                angle shift (reference zero, magnet mounted turned), independent
//                                of speed and direction; default 0
// channel_skew   tau_X           channel X is sampled at t + tau_X (s): it sees the trajectory's
//                                angle at that time (a multiplexed ADC in any slot order; a part
//                                common to all channels is a common_delay of -tau)
//                tau_s           shorthand: the channel at position i is sampled at t + i*tau_s
//                                (c1..c4 in slots 0, tau, 2 tau, 3 tau); adds to tau_X
// common_delay   tau_s           all channels sampled at t - tau: the angle lags by omega*tau
// drift          offset_per_C_X  channel X = x*(1 + gain_per_C_X*(temp - 25))
//                gain_per_C_X                + offset_per_C_X*(temp - 25); needs a temp column (C)
// quantization   bits            an ADC of `bits` bits over [-full_scale, +full_scale): step =
//                full_scale      2*full_scale/2^bits, value rounded to the nearest step (ties to
//                                even) and clamped to [-full_scale, full_scale - step]
// saturation     level           channels clipped to [-level, +level]
// excess_noise   sigma           independent Gaussian noise of this sigma added to every channel
// hysteresis     h_rad           mechanical angle shift +h while rotating forward
//                                (d theta/dt >= 0), -h backward (ctx.direction)
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
  ParamList params;    // every parameter of the effect, canonical order (see effect_defaults)

  // The value of a parameter; throws InputError naming the effect when absent.
  double param(const std::string& name) const;
};

// The simulated effects: docs/contracts.md, effect vocabulary's twelve in its order, then the two
// added since (zero_offset, amplitude). "unexplained" is a verdict, not an effect.
const std::vector<std::string>& effect_names();
// True for the field-domain effects (see the top of this file).
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

// Applies one effect in place. Throws InputError when the recording or context lacks what the
// effect needs (temp for drift, t and theta_at for channel_skew/common_delay, sensor for field
// effects).
void apply_effect(const Effect& e, Recording& rec, EffectContext& ctx);

}  // namespace acore
