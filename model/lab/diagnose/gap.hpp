// SPDX-License-Identifier: MIT
// The sim-to-real gap (docs/diagnosis.md "How it works"): the simulation is turned into a static
// sensor model (sensor_fit.hpp), the estimator is calibrated on that model, and real and model are
// compared sample by sample at the real recording's angles, stage by stage.
//
//   g_i   = wrap(e_real,i - e_model,i)       angle-error difference, degrees
//   g     = X beta + r                       least squares on the gap basis X: angle harmonics
//                                            1..16 times {1, speed, direction, temperature}
//   sys^2 = mean((X beta)^2) - (cols/N) mean(sigma_i^2)        the systematic part, noise removed
//   exc^2 = mean(r^2) - mean(sigma_i^2), kept only when 4 standard errors above 0 (extra noise)
//   gap   = sqrt(max(0, sys^2) + max(0, exc^2))
//   slow^2 = sum_b n_b mean_b(r)^2 / N - (B/N) mean(sigma_i^2),  B = 16 blocks of samples in order:
//            the part of r that changes slowly in time. No effect of the vocabulary makes it (they
//            are functions of angle, speed, direction and temperature, all in the basis); a slip
//            of the magnet or a dropout does.
// where sigma_i^2 is the angle-noise variance the simulation's own noise level causes at sample i,
// through the estimator itself (region switches included; Monte-Carlo, fixed seed). Fresh noise
// alone gives a gap near 0; the projection keeps the rare large errors of region switches (noise
// near a region boundary) from swamping a small systematic gap.
#pragma once
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "calibration/calibration.hpp"
#include "core/recording.hpp"
#include "diagnose/sensor_fit.hpp"

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
  double systematic_deg = 0;          // sqrt(max(0, sys^2))
  double excess_noise_deg = 0;        // sqrt(max(0, exc^2)) when significant
  double slow_deg = 0;               // sqrt(max(0, slow^2)): the excess that changes slowly in time
  std::vector<double> g_systematic;  // X beta: the smooth part of g, for plots
};

// The gap basis of one recording, factorized once (it depends on the samples only).
struct GapBasis {
  Eigen::MatrixXd X;
  Eigen::LDLT<Eigen::MatrixXd> gram;
};
GapBasis make_gap_basis(const Recording& rec);

// `predicted` is what the model (possibly with an effect added) says `rec` should be; same size.
// extra_sigma: white noise per channel that the prediction carries beyond the simulation's
// (the excess_noise effect); it raises the noise term instead of adding random numbers.
StageSeries compare(const GapModel& m, const Recording& rec, const Recording& predicted,
                    double extra_sigma = 0, const GapBasis* basis = nullptr);

// Where the recordings part: per stage, the RMS difference over its noise level (1 = noise only).
struct StageDivergence {
  std::string stage;                 // raw, prefilter, scaling, correction, angle
  std::vector<std::string> signals;  // e.g. c1..c4, d13/d24
  std::vector<double> ratio;         // RMS(real - model) / expected noise RMS, per signal
  bool diverges = false;
};
std::vector<StageDivergence> stage_divergence(const GapModel& m, const Recording& rec,
                                              const Recording& predicted, const StageSeries& s);

// What the gap g depends on: the R^2 of g regressed on each domain's basis (adjusted for size).
struct DomainScore {
  std::string domain;  // angle, time_temperature, speed, direction, signal_level
  double r2 = 0;
};
std::vector<DomainScore> gap_domains(const Recording& rec, const std::vector<double>& g,
                                     int periodicity);

// Signed angular velocity per sample (rad/s, or rad/sample when the recording has no t column).
std::vector<double> angular_velocity(const Recording& rec);

}  // namespace acore
