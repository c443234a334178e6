// SPDX-License-Identifier: MIT
// The sim-to-real gap (README "Gap diagnosis"): the simulation is turned into a static sensor model
// (sensor_fit.hpp), the estimator is calibrated on that model, and real and model are compared
// sample by sample at the real recording's angles, stage by stage.
//
//   g_i   = wrap(e_real,i - e_model,i)       angle-error difference, degrees
//   gap   = sqrt(max(0, mean(g^2) - mean(sigma_theta,i^2)))
// where sigma_theta,i = sigma_d / |dv/dtheta| at sample i is the angle noise the simulation's own
// noise level sigma_d causes (the Cramér–Rao term), so fresh noise alone gives a gap near 0.
#pragma once
#include <string>
#include <vector>

#include "calibration.hpp"
#include "recording.hpp"
#include "sensor_fit.hpp"

namespace acore {

struct GapModel {
  SensorFit sensor;       // the simulation as a static model
  FloatCoefficients est;  // the estimator calibrated on it
  int periodicity = 1;
};

// Fits the model to a simulated recording (any trajectory covering a turn).
GapModel build_gap_model(const Recording& sim, int periodicity, int fourier_order = 12);

// Everything computed on one recording against the model at the same angles.
struct StageSeries {
  std::vector<double> err_deg;        // estimator error of the recording, degrees
  std::vector<double> model_err_deg;  // estimator error of the model at the same angles
  std::vector<double> g;              // wrap(err - model_err), degrees
  std::vector<double> noise_var;      // sigma_theta^2 per sample, degrees^2
  double gap_deg = 0;                 // see above
  double raw_rms_deg = 0;             // RMS of g, noise included
  double noise_deg = 0;               // sqrt(mean(noise_var))
};

// `predicted` is what the model (possibly with an effect added) says `rec` should be; same size.
StageSeries compare(const GapModel& m, const Recording& rec, const Recording& predicted);

// Where the recordings part: per stage, the RMS difference over its noise level (1 = noise only).
struct StageDivergence {
  std::string stage;                 // raw, prefilter, scaling, correction, angle
  std::vector<std::string> signals;  // e.g. c1..c4, d13/d24
  std::vector<double> ratio;         // RMS(real - model) / expected noise RMS, per signal
  bool diverges = false;
};
std::vector<StageDivergence> stage_divergence(const GapModel& m, const Recording& rec, const Recording& predicted,
                                              const StageSeries& s);

// What the gap g depends on: the R^2 of g regressed on each domain's basis (adjusted for size).
struct DomainScore {
  std::string domain;  // angle, time_temperature, speed, direction, signal_level
  double r2 = 0;
};
std::vector<DomainScore> gap_domains(const Recording& rec, const std::vector<double>& g, int periodicity);

// Signed angular velocity per sample (rad/s, or rad/sample when the recording has no t column).
std::vector<double> angular_velocity(const Recording& rec);

}  // namespace acore
