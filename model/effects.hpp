// SPDX-License-Identifier: MIT
// The effect library (DESIGN 3.4): parametric transforms of a sensor recording, each named exactly as
// in the vocabulary, with named parameters (the same names the gap diagnosis fits, effect_fit.hpp).
//
// An effect is applied to a recording together with an EffectContext: what the sensor model and the
// trajectory say beyond the recorded columns. Two kinds:
//   angle-domain effects change the electrical angle a channel *sees* (phase_error, eccentricity,
//     channel_skew, common_delay, hysteresis). They update ctx.phase[c] and add the change of the clean
//     sensor output, sensor(c, new phase) - sensor(c, old phase), to the channel: whatever was added
//     to the channel before (offsets, noise) is kept. Gains applied before them do not scale that
//     change, so simulate() applies the angle-domain effects first (see simulator.hpp).
//   signal-domain effects act on the channel values (offset, gain_mismatch, harmonic, drift,
//     quantization, saturation, excess_noise).
//
// Parameters (channel suffix X = c1..c4, or sin, cos for two-channel recordings; "position" of a
// channel = its 90-degree slot: c1..c4 -> 0..3, sin, cos -> 0, 1):
//   offset         offset_X        added to channel X (sensor units); default 0
//   gain_mismatch  gain_X          channel X multiplied by this factor; default 1
//   phase_error    delta_rad       the sine channels (c1, c3 / sin) see the electrical angle p*theta +
//                                  delta (orthogonality error); the cosine channels unchanged; default 0
//   harmonic       order           n (integer >= 1) of an extra spatial harmonic of the field
//                  amplitude       a (sensor units); default 0
//                  phase_rad       psi; channel X gets a*sin(n*(phase_X + position_X*pi/2) + psi), i.e.
//                                  the same field harmonic seen from each sensor's 90-degree position
//   eccentricity   epsilon_rad     every channel sees the mechanical angle theta + eps*sin(theta - phi0)
//                  phi0_rad        (theta = the mechanical angle the channel sees before this effect)
//   channel_skew   tau_s           the channel at position i is sampled at t + i*tau: it sees the
//                                  trajectory's angle at that time (needs ctx.theta_at)
//   common_delay   tau_s           all channels sampled at t - tau: the angle lags by omega*tau
//   drift          offset_per_C_X  channel X = x*(1 + gain_per_C_X*(temp-25)) + offset_per_C_X*(temp-25);
//                  gain_per_C_X    needs the recording's temp column (degrees C)
//   quantization   bits            an ADC of `bits` bits over [-full_scale, +full_scale): step =
//                  full_scale      2*full_scale/2^bits, value rounded to the nearest step (ties to
//                                  even) and clamped to [-full_scale, full_scale - step]
//   saturation     level           channels clipped to [-level, +level]
//   excess_noise   sigma           independent Gaussian noise of this sigma added to every channel
//   hysteresis     h_rad           mechanical angle shift +h while rotating forward (d theta/dt >= 0),
//                                  -h backward (ctx.direction)
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "recording.hpp"

namespace acore {

// Named parameter values, in the effect's canonical order (same alias as effect_fit.hpp).
using ParamList = std::vector<std::pair<std::string, double>>;

struct Effect {
  std::string effect;  // DESIGN 3.4 name, e.g. "offset"
  ParamList params;    // every parameter of the effect, canonical order (see effect_defaults)

  // The value of a parameter; throws InputError naming the effect when absent.
  double param(const std::string& name) const;
};

// The simulated effects, in DESIGN 3.4 order ("unexplained" is a verdict, not an effect).
const std::vector<std::string>& effect_names();
// True for the angle-domain effects (see the top of this file).
bool is_angle_effect(const std::string& effect);
// Channel name used in parameter suffixes: "c1".."c4", or "sin", "cos" when channels == 2.
std::string effect_channel_name(int channels, int c);
// Every parameter of `effect` with its default (no-op where one exists), for 2 or 4 channels.
// Throws InputError listing the valid names for an unknown effect.
ParamList effect_defaults(const std::string& effect, int channels);
// An effect with `given` parameters over the defaults; throws InputError for an unknown effect, an
// unknown parameter (listing the valid ones), or an invalid value (bits < 1, level <= 0, ...).
Effect make_effect(const std::string& effect, const ParamList& given, int channels);

// What an effect needs beyond the recording's columns.
struct EffectContext {
  int p = 1;  // periodicity: electrical angle = p * mechanical angle
  // Clean output of channel c (0-based) at electrical angle phi (rad): needed by angle-domain effects.
  std::function<double(int c, double phi)> sensor;
  // Mechanical angle (rad, unwrapped) of the trajectory at any time t (s): channel_skew, common_delay.
  std::function<double(double t)> theta_at;
  // Electrical angle each channel currently sees, per sample (updated by angle-domain effects).
  std::array<std::vector<double>, 4> phase;
  // +1 rotating forward, -1 backward, per sample (hysteresis).
  std::vector<double> direction;
  // Random source for excess_noise.
  std::mt19937_64 rng{0};
};

// A context for an existing recording: phases p*theta_ref, direction from the sign of the
// theta_ref increments (the first sample takes the second's), rng seeded with `seed`. Needs theta_ref.
EffectContext make_effect_context(const Recording& rec, int p, std::function<double(int, double)> sensor,
                                  std::function<double(double)> theta_at, uint64_t seed);

// Applies one effect in place. Throws InputError when the recording or context lacks what the effect
// needs (temp for drift, t and theta_at for channel_skew/common_delay, sensor for angle effects).
void apply_effect(const Effect& e, Recording& rec, EffectContext& ctx);

}  // namespace acore
