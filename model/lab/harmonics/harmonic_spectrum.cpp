// SPDX-License-Identifier: MIT
// Least-squares per-order spectrum of an angle-error series; see harmonic_spectrum.hpp.
#include "harmonics/harmonic_spectrum.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <cmath>

#include "core/errors.hpp"

namespace acore {

namespace {
constexpr double kHalfPi = 1.57079632679489661923;
}

std::vector<OrderAmplitude> error_spectrum(const std::vector<double>& theta,
                                           const std::vector<double>& err_deg, int max_order) {
  if (theta.size() != err_deg.size())
    throw InputError(
        fmt::format("error spectrum: {} angles but {} errors", theta.size(), err_deg.size()));
  if (max_order < 0) throw InputError("error spectrum: max_order must be >= 0");
  const int m = 2 * max_order + 1;
  if (theta.size() < static_cast<size_t>(m + 1))
    throw InputError(
        fmt::format("error spectrum: {} samples cannot resolve order {} (need at least {})",
                    theta.size(), max_order, m + 1));
  // Normal equations, accumulated so that long recordings need no N x m matrix.
  Eigen::MatrixXd ata = Eigen::MatrixXd::Zero(m, m);
  Eigen::VectorXd aty = Eigen::VectorXd::Zero(m);
  Eigen::VectorXd row(m);
  for (size_t i = 0; i < theta.size(); ++i) {
    if (!std::isfinite(theta[i]) || !std::isfinite(err_deg[i]))
      throw InputError(fmt::format("error spectrum: sample {} is not finite", i));
    row(0) = 1;
    for (int k = 1; k <= max_order; ++k) {
      row(2 * k - 1) = std::cos(k * theta[i]);
      row(2 * k) = std::sin(k * theta[i]);
    }
    ata.selfadjointView<Eigen::Lower>().rankUpdate(row);
    aty += row * err_deg[i];
  }
  ata = ata.selfadjointView<Eigen::Lower>();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(ata, Eigen::EigenvaluesOnly);
  const double lmin = eig.eigenvalues().minCoeff(), lmax = eig.eigenvalues().maxCoeff();
  if (!(lmin > 1e-10 * lmax))
    throw InputError(
        fmt::format("error spectrum: the reference angles do not cover the turn well enough to "
                    "separate orders up to {} "
                    "(condition {:.3g}); use fewer orders or more of the turn",
                    max_order, lmax / std::max(lmin, 1e-300)));
  const Eigen::VectorXd c = ata.ldlt().solve(aty);
  std::vector<OrderAmplitude> out(max_order + 1);
  out[0] = {0, std::fabs(c(0)), c(0) >= 0 ? kHalfPi : -kHalfPi, c(0), 0};
  for (int k = 1; k <= max_order; ++k) {
    const double a = c(2 * k - 1), b = c(2 * k);
    // a cos + b sin = H sin(k theta + phase) with H cos(phase) = b, H sin(phase) = a.
    out[k] = {k, std::hypot(a, b), std::atan2(a, b), a, b};
  }
  return out;
}

double spectrum_residual_rms(const std::vector<double>& theta, const std::vector<double>& err_deg,
                             const std::vector<OrderAmplitude>& spectrum) {
  if (theta.size() != err_deg.size() || theta.empty())
    throw InputError("error spectrum: residual needs equal, non-empty angle and error series");
  double s = 0;
  for (size_t i = 0; i < theta.size(); ++i) {
    double f = 0;
    for (const auto& o : spectrum)
      f += o.cos_deg * std::cos(o.order * theta[i]) + o.sin_deg * std::sin(o.order * theta[i]);
    s += (err_deg[i] - f) * (err_deg[i] - f);
  }
  return std::sqrt(s / theta.size());
}

}  // namespace acore
