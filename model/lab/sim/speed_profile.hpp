// SPDX-License-Identifier: MIT
// A speed that is not constant: a sinusoidal ripple and a random slow change around a nominal
// speed, as a drive turning a shaft without a reference encoder gives (docs/calibration.md,
// self-calibration). The speed is v(u) = v0 (1 + r sin(2 pi f u + a) + d g(u / U)), u the nominal
// turns elapsed (v0 t), U the nominal turns of the whole recording, g a random smooth function
// with |g| <= 1 and at most 1.5 cycles over the recording (three sines of 0.5, 1 and 1.5 cycles,
// amplitudes and phases drawn from `seed`). The angle is its integral, in closed form.
#pragma once
#include <cstdint>

namespace acore {

struct SpeedVariation {
  double ripple_pct = 0;       // r, percent of the nominal speed (peak)
  double ripple_cycles = 3.7;  // f, ripple cycles per nominal turn (not a whole number: a drive's
                               // ripple is not locked to the shaft, or no method could tell it
                               // from the sensor's error)
  double drift_pct = 0;        // d, percent of the nominal speed (peak of the slow change)
  uint64_t seed = 1;           // draws the slow change's shape and the ripple's phase
  bool active() const { return ripple_pct != 0 || drift_pct != 0; }
};

// The mechanical angle added to the nominal 2 pi u (rad) after u nominal turns of a recording of
// `total_turns` nominal turns: 2 pi times the integral of (v / v0 - 1) from 0 to u.
double speed_variation_angle(const SpeedVariation& sv, double u, double total_turns);

}  // namespace acore
