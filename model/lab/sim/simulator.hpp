// SPDX-License-Identifier: MIT
// The sensor simulator: the paper's channel model (Eq. 2 with the c4 sign fixed, docs/contracts.md,
// systematic error of Eq. 7), Gaussian noise, a trajectory, a temperature profile and a list of
// effects (effects.hpp).
//
// Four channels at electrical angle phi = p*theta (theta mechanical, rad):
//   c1 =  A1 sin(phi) + e1(phi)      c2 =  A2 cos(phi) + e2(phi)
//   c3 = -A3 sin(phi) + e3(phi)      c4 = -A4 cos(phi) + e4(phi)
//   e_c(phi) = C0_c + sum_k AF_c,k cos(k phi) + BF_c,k sin(k phi)          (k = 1..any order)
// plus noise: one Gaussian draw per sample common to all channels (sigma_common, cancels in c1-c3)
// and one per channel (sigma_indep). Two channels: sin = A1 sin(phi) + e1, cos = A2 cos(phi) + e2.
//
// simulate() builds the clean recording on the trajectory, applies the field-domain effects (list
// order), adds the noise, then applies the signal-domain effects (list order), so an ADC
// (quantization) or clipping (saturation) sees the noisy signal.
//
// Scenario JSON (every field optional, defaults as below; unknown fields are errors):
// {
//   "name": "custom", "description": "", "channels": 4, "p": 1,
//   "sensor": [{"amplitude": 1, "offset": 0, "AF": [..], "BF": [..]}, ... one per channel (2 or
//   4)], "sigma_common": 0, "sigma_indep": 0, "trajectory": {"kind": "turn", "sample_rate_hz": 0,
//   "theta0_rad": 0, "turns": 1, "speed_rps": 0,
//                  "speed_end_rps": 0, "sweep_turns": 1, "cycles": 1, "step_at_s": 0,
//                  "ripple": 0, "ripple_hz": 0},
//   "temperature": {"enabled": false, "start_C": 25, "end_C": 25},
//   "effects": [{"effect": "offset", "offset_c1": 0.01, ...}, ...]          (effects.hpp
//   parameters)
// }
#pragma once
#include <array>
#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "core/recording.hpp"
#include "sim/effects.hpp"
#include "sim/speed_profile.hpp"

namespace acore {

// One channel's static model (see the top of this file).
struct ChannelModel {
  double amplitude = 1.0;  // A_c
  double offset = 0.0;     // C0_c, sensor units
  std::vector<double> af;  // AF_c,k for k = 1..af.size() (cosine coefficients)
  std::vector<double> bf;  // BF_c,k for k = 1..bf.size() (sine coefficients)
};

// How the shaft moves. N = number of samples, fs = sample rate, T = N / fs.
//   "turn"      one uniform turn: theta_k = theta0 + 2 pi k / N exactly (the paper's grid)
//   "constant"  constant speed: speed_rps, or `turns` turns over T when speed_rps == 0
//   "ramp"      speed rising linearly from speed_rps to speed_end_rps over T (both 0: from 0 to the
//               speed that covers `turns` turns over T)
//   "reversal"  back and forth: `sweep_turns` forward, the same back, at speed_rps (0: `cycles`
//               full back-and-forth cycles over T)
//   "step"      speed_rps until step_at_s (0: T / 2), then speed_end_rps (a velocity step)
//   "ripple"    speed_rps (1 + ripple sin(2 pi ripple_hz t)): a constant speed with a sinusoidal
//               speed ripple of relative amplitude `ripple` (0.02 = 2 %)
// theta(t) of every kind is trajectory_theta() below, a closed form (no integration).
struct Trajectory {
  std::string kind = "turn";
  double sample_rate_hz = 0;  // samples per second; 0 means N per second (t_k = k / N)
  double theta0_rad = 0;      // starting mechanical angle
  double turns = 1;           // constant, ramp: turns over the recording (see above)
  double speed_rps = 0;       // constant: speed; ramp: start speed; reversal: speed (rev/s)
  double speed_end_rps = 0;   // ramp: end speed (rev/s)
  double sweep_turns = 1;     // reversal: excursion before turning back (turns)
  double cycles = 1;          // reversal: back-and-forth cycles over the recording
  double step_at_s = 0;       // step: time of the speed step (s; 0 = half the recording)
  double ripple = 0;          // ripple: relative speed ripple amplitude (>= 0, < 1)
  double ripple_hz = 0;       // ripple: ripple frequency (Hz, > 0)
  // "turn" and "constant": a ripple and a slow change around the nominal speed (speed_profile.hpp);
  // JSON fields speed_ripple_pct, speed_ripple_cycles, speed_drift_pct, speed_seed.
  SpeedVariation speed;
};

// The mechanical angle (rad, unwrapped) at time t of a trajectory whose resolved speeds are v0, v1
// (rev/s; TrajectoryModel resolves them from the fields) over a recording of `duration` seconds.
double trajectory_theta(const Trajectory& tr, double v0, double v1, double duration, double t);
// Its speed (rev/s) at time t, the derivative of trajectory_theta.
double trajectory_speed(const Trajectory& tr, double v0, double v1, double duration, double t);

// Temperature column: linear from start_C (first sample) to end_C (last sample).
struct Temperature {
  bool enabled = false;  // write a temp column (forced on when the effects contain drift)
  double start_C = 25;
  double end_C = 25;
};

struct Scenario {
  std::string name = "custom";
  std::string description;
  int channels = 4;                    // 4 (c1..c4) or 2 (sin, cos)
  int p = 1;                           // periodicity: electrical angle = p * mechanical angle
  std::array<ChannelModel, 4> sensor;  // c1..c4 (or sin, cos in [0], [1])
  double sigma_common = 0;             // Gaussian noise common to all channels
  double sigma_indep = 0;              // Gaussian noise independent per channel
  Trajectory trajectory;
  Temperature temperature;
  std::vector<Effect> effects;  // applied in order within their domain (see the top of this file)

  // Clean output of channel c (0-based) at electrical angle phi, without noise or effects.
  double channel_value(int c, double phi) const;
  nlohmann::json to_json() const;
  // Throws InputError "WHERE: field 'a.b': what" for a missing/ill-typed/unknown field.
  static Scenario from_json(const nlohmann::json& j, const std::string& where = "scenario");
};

// The trajectory resolved for N samples: angle and direction at any time.
class TrajectoryModel {
 public:
  TrajectoryModel(const Trajectory& tr, size_t samples);
  double sample_rate() const { return fs_; }
  double time(size_t k) const { return static_cast<double>(k) / fs_; }
  double theta_at(double t) const;  // mechanical angle, rad, unwrapped
  double theta_sample(
      size_t k) const;  // the angle at sample k ("turn": exactly theta0 + 2 pi k / N)
  double direction_at(double t) const;  // +1 forward, -1 backward
  double speed_at(double t) const;      // rev/s, signed
  // The angle the speed variation adds after u nominal turns ("turn", "constant"; else 0).
  double varied(double u) const;

 private:
  Trajectory tr_;
  size_t n_;
  double fs_, duration_, v0_ = 0, v1_ = 0;
};

// Built-in scenarios: "paper", "paper-indep", "paper-noiseless", "ideal", "tmr".
std::vector<std::string> builtin_scenario_names();
// Throws InputError listing the valid names.
Scenario builtin_scenario(const std::string& name);
// Reads a scenario JSON file; errors name the file and the field.
Scenario load_scenario(const std::string& json_path);
// The scenario with another channel count: per-channel parameters of the sensor and the effects map
// c1 <-> sin, c2 <-> cos (c3, c4 dropped, or new ones mirroring sin, cos: c3 = -sin, c4 = -cos).
Scenario with_channels(const Scenario& s, int channels);

// Simulates `samples` samples (>= 1) with the noise seeded by `seed` (std::mt19937_64). Columns:
// t, theta_ref (unwrapped), c1..c4 or sin,cos, temp (when enabled or drift is used). Metadata:
// scenario, seed, p, channels, samples, trajectory.
Recording simulate(const Scenario& s, size_t samples, uint64_t seed);

}  // namespace acore
