// SPDX-License-Identifier: MIT
#include "diagnose/sensor_fit.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace acore {

// cos(h e), sin(h e) for h = 1..order by rotation (one sincos instead of `order`): the error grows
// about linearly with h, a few ulp at order 40.
double SensorFit::value(int c, double theta) const {
  const auto& k = coef[c];
  const double e = periodicity * theta, c1 = std::cos(e), s1 = std::sin(e);
  double v = k[0], ch = 1, sh = 0;
  for (int h = 1; h <= order; ++h) {
    const double cn = ch * c1 - sh * s1;
    sh = sh * c1 + ch * s1;
    ch = cn;
    v += k[2 * h - 1] * ch + k[2 * h] * sh;
  }
  return v;
}

double SensorFit::derivative(int c, double theta) const {
  const auto& k = coef[c];
  const double e = periodicity * theta, c1 = std::cos(e), s1 = std::sin(e);
  double v = 0, ch = 1, sh = 0;
  for (int h = 1; h <= order; ++h) {
    const double cn = ch * c1 - sh * s1;
    sh = sh * c1 + ch * s1;
    ch = cn;
    v += h * periodicity * (-k[2 * h - 1] * sh + k[2 * h] * ch);
  }
  return v;
}

Recording SensorFit::resample(const Recording& like) const {
  Recording r;
  r.channels = channels;
  r.theta_ref = like.theta_ref;
  r.t = like.t;
  r.temp = like.temp;
  r.meta = like.meta;
  for (int c = 0; c < channels; ++c) {
    r.ch[c].resize(like.theta_ref.size());
    for (size_t i = 0; i < like.theta_ref.size(); ++i) r.ch[c][i] = value(c, like.theta_ref[i]);
  }
  return r;
}

double SensorFit::diff_noise_sigma() const {
  if (channels == 2)
    return std::sqrt(0.5 * (noise_sigma[0] * noise_sigma[0] + noise_sigma[1] * noise_sigma[1]));
  // var(c1 - c3) = s1^2 + s3^2 - 2 rho s1 s3
  const double v13 = noise_sigma[0] * noise_sigma[0] + noise_sigma[2] * noise_sigma[2] -
                     2 * noise_corr[0] * noise_sigma[0] * noise_sigma[2];
  const double v24 = noise_sigma[1] * noise_sigma[1] + noise_sigma[3] * noise_sigma[3] -
                     2 * noise_corr[1] * noise_sigma[1] * noise_sigma[3];
  return std::sqrt(std::max(0.0, 0.5 * (v13 + v24)));
}

SensorFit fit_sensor(const Recording& rec, int order, int periodicity) {
  if (!rec.has_theta()) throw InputError("sensor model: the recording has no theta_ref column");
  const size_t n = rec.size();
  const int terms = 2 * order + 1;
  if (n < static_cast<size_t>(4 * terms))
    throw InputError(fmt::format("sensor model: {} samples, at least {} needed", n, 4 * terms));
  const int covered = turn_sectors_covered(rec.theta_ref, periodicity);
  if (covered < 36)
    throw InputError(
        fmt::format("the recording covers only {} of the 36 ten-degree sectors of a turn: "
                    "at least one full turn is needed",
                    covered));
  Eigen::MatrixXd V(n, terms);
  for (size_t i = 0; i < n; ++i) {
    const double e = periodicity * rec.theta_ref[i];
    V(i, 0) = 1;
    for (int h = 1; h <= order; ++h) {
      V(i, 2 * h - 1) = std::cos(h * e);
      V(i, 2 * h) = std::sin(h * e);
    }
  }
  Eigen::MatrixXd Y(n, rec.channels);
  for (int c = 0; c < rec.channels; ++c)
    for (size_t i = 0; i < n; ++i) Y(i, c) = rec.ch[c][i];
  const Eigen::MatrixXd sol = V.colPivHouseholderQr().solve(Y);
  const Eigen::MatrixXd res = Y - V * sol;
  SensorFit f;
  f.channels = rec.channels;
  f.periodicity = periodicity;
  f.order = order;
  const double dof = std::max<double>(1.0, static_cast<double>(n) - terms);
  for (int c = 0; c < rec.channels; ++c) {
    f.coef.emplace_back(sol.col(c).data(), sol.col(c).data() + terms);
    f.noise_sigma.push_back(std::sqrt(res.col(c).squaredNorm() / dof));
  }
  if (rec.channels == 4) {
    for (int pair = 0; pair < 2; ++pair) {
      const double a = res.col(pair).norm(), b = res.col(pair + 2).norm();
      f.noise_corr.push_back(a > 0 && b > 0 ? res.col(pair).dot(res.col(pair + 2)) / (a * b) : 0.0);
    }
  }
  return f;
}

}  // namespace acore
