// SPDX-License-Identifier: MIT
// The tracking observer (stages/tracker.hpp) over an engine's whole angle series, as `anglecore
// estimate` reports it and the Python package's estimate() returns it: velocity in mechanical rpm,
// the turn count, the compensated angle and loss of tracking, with the observer's settings
// (bandwidth, lead, loss-of-tracking threshold) given as the command's options take them. One
// implementation for both, so that the command and the package agree bit for bit.
#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/error_stats.hpp"
#include "core/recording.hpp"
#include "stages/tracker.hpp"

namespace acore {

// The observer's settings as the command's options give them.
struct TrackSettings {
  double bandwidth_hz = 0;  // --track-bandwidth: the nearest code at the sample rate; 0: TRK_BW's
                            // reset code
  double lead = 0;          // --track-lead: samples the compensated angle looks ahead
  std::optional<uint32_t> lot_threshold;  // --track-lot: angle LSBs; none: TRK_LOT's reset value
};

// The observer's build parameters for an engine of angle width angle_w (the board's, with the
// fraction narrowed so that ANGLE_W + FRAC_W fits 48 bits).
TrackConfig track_config_for(int angle_w);

// The registers and COMP_LATENCY the settings give at `sample_rate` (samples per second; 0 when
// unknown: then a bandwidth cannot be asked for). Throws InputError naming the option.
TrackRegs track_regs_for(const TrackSettings& s, double sample_rate, TrackConfig& c);

// The mean sample rate of a recording's t column: (N - 1) / (t_last - t_first); 0 when there is no
// t or it does not increase.
double recording_sample_rate(const Recording& rec);
// The same of a t column given as an array of n times.
double sample_rate_of_times(const double* t, size_t n);

struct TrackedSeries {
  double sample_rate = 0;  // samples per second (0: unknown, no velocity_rpm)
  TrackConfig config;
  TrackRegs regs;
  std::vector<double> rpm;     // mechanical rpm (only when sample_rate > 0)
  std::vector<int64_t> turns;  // signed count of electrical turns, 0 at the first sample
  std::vector<double> comp;    // compensated angle, rad [0, 2 pi)
  std::vector<uint8_t> lot;    // 1: loss of tracking at this sample
  bool has_rate() const { return sample_rate > 0; }
};

// The observer over angles (rad, any range: wrapped to the angle_w-bit code), p electrical periods
// a turn (velocity in mechanical rpm).
TrackedSeries track_series(const std::vector<double>& angle_rad, double sample_rate, int p,
                           int angle_w, const TrackSettings& s);

// The velocity error (rpm) of `tracked` against the reference: p theta_ref through the same
// observer, so that the error is the estimator's, not the observer's lag. Needs a sample rate.
std::vector<double> track_velocity_error_rpm(const TrackedSeries& tracked,
                                             const std::vector<double>& theta_ref, int p);

// The observer's block of `estimate --json`: {code, bandwidth_hz, sample_rate_hz, lead_samples,
// lot_threshold, lot_samples} (only with a sample rate: the bandwidth is in Hz).
nlohmann::json track_json(const TrackedSeries& t);

// A finite difference of the angle over n samples whose -3 dB frequency equals the observer's
// velocity bandwidth wn = 2^-(k+1/2) rad/sample (bandwidth code k): the smallest n with
// |sin(wn (n+1)/2) / ((n+1) sin(wn/2))| <= 1/sqrt(2), the moving average of n + 1 samples'
// differences. The reference a drive would otherwise use for the velocity.
int equal_bandwidth_difference_span(int code);

// The velocity (mechanical rpm) of that finite difference: (angle[i] - angle[i-n]) wrapped, over n
// samples; the first n samples have none (the vector starts at sample n).
std::vector<double> finite_difference_rpm(const std::vector<double>& angle_rad, int n,
                                          double sample_rate, int p);

}  // namespace acore
