// SPDX-License-Identifier: MIT
// Angle-error statistics (docs/contracts.md, command line): error = estimate - reference, wrapped
// to (-180, 180] degrees.
#pragma once
#include <cstddef>
#include <nlohmann/json.hpp>
#include <vector>

namespace acore {

struct ErrorStats {
  double rms = 0, max_abs = 0, mean = 0;
};

// Wraps an angle difference in degrees to (-180, 180].
double wrap_deg(double deg);
// Per-sample error in degrees: est_rad - p * ref_rad, wrapped.
std::vector<double> angle_error_deg(const std::vector<double>& est_rad,
                                    const std::vector<double>& ref_rad, int periodicity = 1);
ErrorStats error_stats(const std::vector<double>& err_deg);
ErrorStats error_stats(const double* err_deg, size_t n);
// {"rms", "max_abs", "mean"}: the statistics as every JSON report writes them.
nlohmann::json stats_json(const ErrorStats& s);
// The errors about their circular mean, wrapped: what a calibration whose zero offset is unknown
// (a self-calibration, image header zero_reference=none) can be judged by.
std::vector<double> about_mean_deg(const std::vector<double>& err_deg);

}  // namespace acore
