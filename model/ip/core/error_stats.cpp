// SPDX-License-Identifier: MIT
#include "core/error_stats.hpp"

#include <cmath>

namespace acore {

double wrap_deg(double deg) {
  double w = std::fmod(deg, 360.0);
  if (w <= -180.0) w += 360.0;
  if (w > 180.0) w -= 360.0;
  return w;
}

std::vector<double> angle_error_deg(const std::vector<double>& est, const std::vector<double>& ref,
                                    int periodicity) {
  std::vector<double> e(est.size());
  for (size_t i = 0; i < est.size(); ++i)
    e[i] = wrap_deg((est[i] - periodicity * ref[i]) * 180.0 / M_PI);
  return e;
}

std::vector<double> about_mean_deg(const std::vector<double>& e) {
  double c = 0, s = 0;
  for (double v : e) {
    c += std::cos(v * M_PI / 180);
    s += std::sin(v * M_PI / 180);
  }
  const double mean = std::atan2(s, c) * 180 / M_PI;
  std::vector<double> out(e.size());
  for (size_t i = 0; i < e.size(); ++i) out[i] = wrap_deg(e[i] - mean);
  return out;
}

ErrorStats error_stats(const std::vector<double>& e) { return error_stats(e.data(), e.size()); }

ErrorStats error_stats(const double* e, size_t n) {
  ErrorStats s;
  if (n == 0) return s;
  double sum = 0, sq = 0;
  for (size_t i = 0; i < n; ++i) {
    const double v = e[i];
    sum += v;
    sq += v * v;
    s.max_abs = std::max(s.max_abs, std::fabs(v));
  }
  s.mean = sum / n;
  s.rms = std::sqrt(sq / n);
  return s;
}

nlohmann::json stats_json(const ErrorStats& s) {
  return {{"rms", s.rms}, {"max_abs", s.max_abs}, {"mean", s.mean}};
}

}  // namespace acore
