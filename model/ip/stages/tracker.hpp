// SPDX-License-Identifier: MIT
// The tracking observer after the estimator, bit for bit rtl/acore_track.v: a type-II loop on the
// angle error with shift gains, giving the tracked angle, the velocity, a signed turn count, loss
// of tracking and the angle extrapolated over COMP_LATENCY + LEAD samples.
//
// Scales: the loop state is the angle with FRAC_W fraction bits below the input LSB, P_W = ANGLE_W
// + FRAC_W bits a turn, extended by a TURN_W-bit signed turn count; the velocity is P_W-bit signed
// in 2^-P_W turns per sample. One accepted sample theta, bandwidth code k:
//   pred = phi + v;  e = wrap(theta 2^FRAC_W - pred)
//   phi  = pred + (e >> k);  v = v + (e >> (2k + 1))           (>> arithmetic: floor)
// ki = kp^2 / 2: damping 1/sqrt(2), natural frequency wn = 2^-(k+1/2) rad/sample at every code.
// The first sample loads phi = theta, v = 0, turns = 0.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "stages/board_regs.hpp"

namespace acore {

// The observer's build parameters (rtl/acore_track.v, same names); the defaults are the board's
// (rtl/acore_board.v: its turn count and LEAD as wide as their registers' fields).
struct TrackConfig {
  int angle_w = 16;                           // input/output angle width
  int frac_w = 25;                            // fraction bits below the input LSB
  int turn_w = board::kTrkPositionTurnsBits;  // turn counter width (signed): turn_w + angle_w +
                                              // frac_w <= 64
  int comp_latency = 0;                       // COMP_LATENCY: whole samples compensated
  int lead_w = board::kTrkLeadLeadBits;       // LEAD register width
  int lead_f = board::kTrkLeadLeadFrac;       // LEAD fraction bits

  int p_w() const { return angle_w + frac_w; }
  static constexpr int kMin = 2;                  // smallest bandwidth code
  int k_max() const { return (frac_w - 1) / 2; }  // largest bandwidth code
  // Throws InputError naming the parameter when the RTL's elaboration would stop.
  void validate() const;
};

// The observer's registers; the defaults are the board's reset values (TRK_BW, TRK_LEAD, TRK_LOT).
struct TrackRegs {
  int bw = static_cast<int>(board::kTrkBwReset);  // bandwidth code k (kMin..k_max())
  uint32_t lead = board::kTrkLeadReset;           // LEAD, unsigned, lead_f fraction bits (samples)
  // The loss-of-tracking threshold, input angle LSBs (< 2^(angle_w-1)).
  uint32_t lot_thr = board::kTrkLotReset;
  // Throws InputError naming the register and its range.
  void validate(const TrackConfig& c) const;
};

struct TrackOutput {
  uint32_t angle = 0;       // round(phi), ANGLE_W bits
  uint32_t angle_comp = 0;  // round(phi + v (COMP_LATENCY + LEAD)), ANGLE_W bits
  int64_t velocity = 0;     // 2^-P_W turns per sample
  int64_t turns = 0;        // signed turn count of `angle`
  bool lot = false;         // |e| > lot_thr for this sample
};

class Tracker {
 public:
  Tracker(const TrackConfig& c, const TrackRegs& r);  // validates both
  TrackOutput step(uint32_t theta);
  void reset() { started_ = false; }
  const TrackConfig& config() const { return c_; }
  const TrackRegs& regs() const { return r_; }

 private:
  TrackConfig c_;
  TrackRegs r_;
  bool started_ = false;
  uint64_t x_ = 0;  // {turns, phi}, modulo 2^(TURN_W + P_W)
  int64_t v_ = 0;
};

// The continuous-loop equivalents of a bandwidth code: wn = 2^-(k+1/2) rad/sample, damping
// 1/sqrt(2); the angle's -3 dB frequency is 2.058 wn (type-II loop, zeta = 1/sqrt(2)).
double track_wn(int k);
double track_bandwidth_hz(int k, double sample_rate);  // the angle's -3 dB frequency
// The code whose bandwidth is nearest to hz (in log frequency); throws InputError when hz is not
// positive or lies outside the codes' range by more than a factor of sqrt(2).
int track_code_for_bandwidth(double hz, double sample_rate, const TrackConfig& c);

// The observer over a whole stream of ANGLE_W-bit codes (one Tracker, from its first sample).
std::vector<TrackOutput> track_codes(const std::vector<uint32_t>& codes, const TrackConfig& c,
                                     const TrackRegs& r);

// Velocity in turns per sample of a velocity word.
double track_velocity_turns(int64_t v, const TrackConfig& c);

}  // namespace acore
