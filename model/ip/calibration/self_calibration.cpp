// SPDX-License-Identifier: MIT
#include "calibration/self_calibration.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "core/angle.hpp"
#include "core/errors.hpp"

namespace acore {

namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr double kDeg = 180.0 / M_PI;

// Legendre polynomials P_0..P_m at x in [-1, 1] (three-term recurrence: well conditioned).
void legendre(double x, int m, double* out) {
  out[0] = 1;
  if (m >= 1) out[1] = x;
  for (int j = 2; j <= m; ++j) out[j] = ((2 * j - 1) * x * out[j - 1] - (j - 1) * out[j - 2]) / j;
}

// The joint model: psi(t) = sum_j a_j P_j(tau) + sum_k alpha_k cos(k phi) + beta_k sin(k phi), the
// harmonics at the current estimate phi of the true angle. Columns: profile first, then harmonics.
Eigen::MatrixXd design(const std::vector<double>& tau, const std::vector<double>& phi, int order,
                       int harmonics) {
  const size_t n = tau.size();
  Eigen::MatrixXd X(n, order + 1 + 2 * harmonics);
  std::vector<double> p(static_cast<size_t>(order) + 1);
  for (size_t i = 0; i < n; ++i) {
    legendre(tau[i], order, p.data());
    for (int j = 0; j <= order; ++j) X(i, j) = p[static_cast<size_t>(j)];
    for (int k = 1; k <= harmonics; ++k) {
      X(i, order + 2 * k - 1) = std::cos(k * phi[i]);
      X(i, order + 2 * k) = std::sin(k * phi[i]);
    }
  }
  return X;
}

struct JointFit {
  Eigen::VectorXd coef;
  std::vector<double> profile, error;  // the fitted speed profile and periodic error, rad
  double rss = 0;
};

JointFit solve_joint(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, int order) {
  JointFit f;
  f.coef = X.colPivHouseholderQr().solve(y);
  const Eigen::VectorXd prof = X.leftCols(order + 1) * f.coef.head(order + 1);
  const Eigen::VectorXd err = X.rightCols(X.cols() - order - 1) * f.coef.tail(X.cols() - order - 1);
  f.profile.assign(prof.data(), prof.data() + prof.size());
  f.error.assign(err.data(), err.data() + err.size());
  f.rss = (y - prof - err).squaredNorm();
  return f;
}

// How much of the first harmonic's columns the profile of `order` explains (R^2, the larger of
// cos and sin): near 1, the two cannot be told apart.
double profile_harmonic_overlap(const std::vector<double>& tau, const std::vector<double>& phi,
                                int order) {
  const Eigen::MatrixXd X = design(tau, phi, order, 1);
  const Eigen::MatrixXd P = X.leftCols(order + 1);
  const auto qr = P.colPivHouseholderQr();
  double worst = 0;
  for (int c = 0; c < 2; ++c) {
    const Eigen::VectorXd h = X.col(order + 1 + c);
    const Eigen::VectorXd r = h - P * qr.solve(h);
    const double centered = (h.array() - h.mean()).matrix().squaredNorm();
    worst = std::max(worst, 1.0 - r.squaredNorm() / std::max(centered, 1e-300));
  }
  return worst;
}

}  // namespace

double EllipseFit::angle(double d13, double d24) const {
  const double c = (d24 - offset[1]) / amp[1];
  const double s = ((d13 - offset[0]) / amp[0] - c * std::sin(delta)) / std::cos(delta);
  return std::atan2(s, c);
}

EllipseFit fit_ellipse(const std::vector<double>& d13, const std::vector<double>& d24) {
  const size_t n = d13.size();
  if (n < 6) throw InputError("self-calibration: an ellipse fit needs at least 6 samples");
  // Normalized coordinates x = (d24 - mx) / sx, y = (d13 - my) / sy for conditioning.
  double mx = 0, my = 0;
  for (size_t i = 0; i < n; ++i) {
    mx += d24[i];
    my += d13[i];
  }
  mx /= n;
  my /= n;
  double sx = 0, sy = 0;
  for (size_t i = 0; i < n; ++i) {
    sx += (d24[i] - mx) * (d24[i] - mx);
    sy += (d13[i] - my) * (d13[i] - my);
  }
  sx = std::sqrt(sx / n);
  sy = std::sqrt(sy / n);
  if (!(sx > 0) || !(sy > 0))
    throw InputError("self-calibration: a channel pair is constant (no Lissajous figure)");
  // Halir and Flusser (1998): the quadratic part D1 and the linear part D2 of the design matrix.
  Eigen::MatrixXd D1(n, 3), D2(n, 3);
  for (size_t i = 0; i < n; ++i) {
    const double x = (d24[i] - mx) / sx, y = (d13[i] - my) / sy;
    D1.row(i) << x * x, x * y, y * y;
    D2.row(i) << x, y, 1;
  }
  const Eigen::Matrix3d S1 = D1.transpose() * D1, S2 = D1.transpose() * D2,
                        S3 = D2.transpose() * D2;
  const Eigen::Matrix3d T = -S3.ldlt().solve(S2.transpose());
  const Eigen::Matrix3d M0 = S1 + S2 * T;
  Eigen::Matrix3d M;
  M.row(0) = M0.row(2) / 2;
  M.row(1) = -M0.row(1);
  M.row(2) = M0.row(0) / 2;
  Eigen::EigenSolver<Eigen::Matrix3d> es(M);
  int pick = -1;
  double best = 0;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d v = es.eigenvectors().col(k).real();
    const double cond = 4 * v(0) * v(2) - v(1) * v(1);  // > 0: an ellipse
    if (cond > best) {
      best = cond;
      pick = k;
    }
  }
  if (pick < 0)
    throw InputError(
        "self-calibration: the channels do not trace an ellipse (is it a sensor pair?)");
  const Eigen::Vector3d a1 = es.eigenvectors().col(pick).real();
  const Eigen::Vector3d a2 = T * a1;
  const double a = a1(0), b = a1(1), c = a1(2), d = a2(0), e = a2(1), f = a2(2);
  // Centre: the gradient is zero.
  const double det = 4 * a * c - b * b;
  const double x0 = (b * e - 2 * c * d) / det, y0 = (b * d - 2 * a * e) / det;
  const double f0 = a * x0 * x0 + b * x0 * y0 + c * y0 * y0 + d * x0 + e * y0 + f;
  if (!(std::fabs(f0) > 0))
    throw InputError("self-calibration: degenerate ellipse fit (the points meet in one point)");
  // Centred quadratic form in recording units, scaled so that the right side is 1:
  // x^2 / A24^2 + y^2 / A13^2 - 2 x y sin(delta) / (A24 A13) = cos^2(delta).
  const double qa = a / (sx * sx) / -f0, qb = b / (sx * sy) / -f0, qc = c / (sy * sy) / -f0;
  if (!(qa > 0) || !(qc > 0))
    throw InputError(
        "self-calibration: the channels do not trace an ellipse (is it a sensor pair?)");
  EllipseFit el;
  const double sd = -qb / (2 * std::sqrt(qa * qc));
  el.delta = std::asin(std::clamp(sd, -0.999, 0.999));
  const double c2 = 1 - sd * sd;
  el.offset[0] = my + y0 * sy;
  el.offset[1] = mx + x0 * sx;
  el.amp[0] = 1 / std::sqrt(qc * c2);
  el.amp[1] = 1 / std::sqrt(qa * c2);
  return el;
}

SelfCalReport estimate_reference(const Recording& rec, const SelfCalOptions& opt) {
  const size_t n = rec.size();
  const int p = opt.periodicity;
  SelfCalReport rep;
  std::vector<double> d13(n), d24(n);
  for (size_t i = 0; i < n; ++i) {
    d13[i] = rec.d13(i);
    d24[i] = rec.d24(i);
  }
  if (n < 64)
    throw InputError(
        fmt::format("self-calibration needs at least 64 samples, the recording has {}", n));
  rep.ellipse = fit_ellipse(d13, d24);

  // Time base: t, or equally spaced samples.
  std::vector<double> t(n);
  rep.uniform_time = !rec.has_t();
  for (size_t i = 0; i < n; ++i) t[i] = rep.uniform_time ? static_cast<double>(i) : rec.t[i];
  for (size_t i = 1; i < n; ++i)
    if (!(t[i] > t[i - 1]))
      throw InputError(fmt::format(
          "self-calibration: column t does not increase at sample {} ({} after {}): it needs "
          "the sample times (or no t column: equally spaced samples)",
          i, t[i], t[i - 1]));
  std::vector<double> tau(n);
  for (size_t i = 0; i < n; ++i) tau[i] = 2 * (t[i] - t[0]) / (t[n - 1] - t[0]) - 1;

  // The ellipse-corrected angle, unwrapped, turned forward.
  std::vector<double> psi(n);
  psi[0] = rep.ellipse.angle(d13[0], d24[0]);
  for (size_t i = 1; i < n; ++i)
    psi[i] = psi[i - 1] + wrap_pi(rep.ellipse.angle(d13[i], d24[i]) - psi[i - 1]);
  const double sign = psi[n - 1] >= psi[0] ? 1.0 : -1.0;
  for (double& v : psi) v *= sign;
  const double span = psi[n - 1] - psi[0];
  rep.turns = (span + span / static_cast<double>(n - 1)) / kTwoPi;
  if (rep.turns < 0.999)
    throw InputError(fmt::format(
        "self-calibration refused: the recording covers {:.3f} electrical turns, at least one "
        "full turn is needed (the sensor's error is learnt from its repetition over a turn)",
        rep.turns));

  // Reversal or stop: the angle advanced over windows of 1/16 turn, against the median window.
  {
    const double step = span / static_cast<double>(n - 1);
    const size_t w = std::max<size_t>(2, static_cast<size_t>(kTwoPi / 16 / std::max(step, 1e-12)));
    std::vector<double> rate;
    std::vector<size_t> at;
    for (size_t i = 0; i + w < n; i += w) {
      rate.push_back((psi[i + w] - psi[i]) / (t[i + w] - t[i]));
      at.push_back(i);
    }
    std::vector<double> sorted = rate;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const double median = sorted[sorted.size() / 2];
    for (size_t k = 0; k < rate.size(); ++k) {
      if (rate[k] < 0.1 * median)
        throw InputError(fmt::format(
            "self-calibration refused: the shaft {} near sample {} (t = {:.6g}): the angle "
            "advances at {:.1f} % of the median speed over 1/16 turn; it needs one direction "
            "and no stop",
            rate[k] < 0 ? "turns back" : "stops", at[k], t[at[k]], 100 * rate[k] / median));
    }
  }

  // The error model's harmonics: at most a quarter of the samples per turn, 16 by default.
  const double per_turn = static_cast<double>(n) / rep.turns;
  const int K =
      opt.harmonics > 0 ? opt.harmonics : std::max(2, std::min(16, static_cast<int>(per_turn / 8)));
  rep.harmonics = K;
  // The separable profile orders: the first harmonic must stay mostly outside the profile's span.
  const int cap = opt.max_profile_order > 0
                      ? opt.max_profile_order
                      : std::min(40, static_cast<int>(std::floor(4 * rep.turns)) + 1);
  int max_order = 1;
  for (int m = 2; m <= cap; ++m) {
    if (profile_harmonic_overlap(tau, psi, m) > 0.9) break;
    max_order = m;
  }
  rep.max_separable_order = max_order;

  // Order by BIC on the first pass, then the fixed point in the angle at that order.
  const Eigen::VectorXd y = Eigen::Map<const Eigen::VectorXd>(psi.data(), static_cast<long>(n));
  const double nn = static_cast<double>(n);
  int order = 1;
  double best_bic = 0;
  for (int m = 1; m <= max_order; ++m) {
    const JointFit f = solve_joint(design(tau, psi, m, K), y, m);
    const double bic = nn * std::log(std::max(f.rss / nn, 1e-300)) + (m + 1 + 2 * K) * std::log(nn);
    if (m == 1 || bic < best_bic) {
      best_bic = bic;
      order = m;
    }
  }
  rep.profile_order = order;
  std::vector<double> phi = psi;
  JointFit fit;
  for (int pass = 0; pass < 3; ++pass) {
    fit = solve_joint(design(tau, phi, order, K), y, order);
    for (size_t i = 0; i < n; ++i) phi[i] = psi[i] - fit.error[i];
  }

  // Figures of merit.
  rep.residual_deg = std::sqrt(fit.rss / nn) * kDeg;
  double d2 = 0;
  for (size_t i = 1; i + 1 < n; ++i) {
    const double v = phi[i + 1] - 2 * phi[i] + phi[i - 1] -
                     (fit.profile[i + 1] - 2 * fit.profile[i] + fit.profile[i - 1]);
    d2 += v * v;
  }
  rep.noise_deg = std::sqrt(d2 / (6 * (nn - 2))) * kDeg;
  double e2 = 0;
  for (double v : fit.error) e2 += v * v;
  rep.error_rms_deg = std::sqrt(e2 / nn) * kDeg;
  {
    double vmin = 1e300, vmax = -1e300,
           vmean = (fit.profile[n - 1] - fit.profile[0]) / (t[n - 1] - t[0]);
    for (size_t i = 1; i < n; ++i) {
      const double v = (fit.profile[i] - fit.profile[i - 1]) / (t[i] - t[i - 1]);
      vmin = std::min(vmin, v);
      vmax = std::max(vmax, v);
    }
    rep.speed_variation_pct = 100 * (vmax - vmin) / vmean;
  }
  // Consistency: the periodic error fitted on each half of the recording (two turns or more).
  if (rep.turns >= 2) {
    const size_t h = n / 2;
    const std::vector<double> ta(tau.begin(), tau.begin() + h), tb(tau.begin() + h, tau.end());
    const std::vector<double> pa(phi.begin(), phi.begin() + h), pb(phi.begin() + h, phi.end());
    const int oh = std::max(1, order / 2);
    auto half = [&](const std::vector<double>& tt, const std::vector<double>& pp, size_t from) {
      std::vector<double> ts(tt.size());
      for (size_t i = 0; i < tt.size(); ++i)
        ts[i] = 2 * (tt[i] - tt.front()) / (tt.back() - tt.front()) - 1;
      const Eigen::VectorXd yy = y.segment(static_cast<long>(from), static_cast<long>(tt.size()));
      return solve_joint(design(ts, pp, oh, K), yy, oh).coef.tail(2 * K).eval();
    };
    const Eigen::VectorXd ca = half(ta, pa, 0), cb = half(tb, pb, h);
    rep.consistency_deg = (ca - cb).norm() / std::sqrt(2.0) * kDeg;
  }
  // Confidence: how much of the residual is noise, and how well the halves agree.
  const double unexplained =
      std::sqrt(std::max(0.0, rep.residual_deg * rep.residual_deg - rep.noise_deg * rep.noise_deg));
  double conf = 1.0 / (1.0 + unexplained / std::max(rep.error_rms_deg, 1e-9));
  if (rep.consistency_deg >= 0)
    conf *= 1.0 / (1.0 + rep.consistency_deg / std::max(rep.error_rms_deg, 1e-9));
  else
    conf *= 0.5;  // one turn: a variation within the turn cannot be told from the error
  rep.confidence = conf;

  rep.assumptions.push_back(
      fmt::format("the sensor's error is periodic in the electrical angle (harmonics 1..{})", K));
  rep.assumptions.push_back(fmt::format(
      "the speed follows a polynomial of order {} in time over the recording (BIC among orders "
      "1..{}, the highest the recording separates from the error)",
      order, max_order));
  if (rep.uniform_time)
    rep.assumptions.push_back("no t column: the samples are taken as equally spaced in time");
  if (rep.turns < 2)
    rep.assumptions.push_back(
        "less than two turns: a speed variation within the turn cannot be told from the "
        "sensor's error and is taken as constant speed (profile order 1..2)");
  rep.assumptions.push_back(
      "the zero offset is unknown: the reference's zero is arbitrary (zero_reference none)");

  // Refusal: a speed variation the profile cannot follow and the recording cannot separate.
  if (unexplained > 3 * std::max(rep.noise_deg, 0.01) && order == max_order &&
      (rep.consistency_deg < 0 || rep.consistency_deg > 0.5 * rep.error_rms_deg))
    throw InputError(fmt::format(
        "self-calibration refused: a speed variation it cannot separate from the sensor's error "
        "(the fit leaves {:.3f} deg RMS against a noise of {:.3f} deg at the highest separable "
        "speed-profile order {}{}); record more turns at a steadier speed",
        rep.residual_deg, rep.noise_deg, max_order,
        rep.consistency_deg >= 0
            ? fmt::format(", the two halves' errors differ by {:.3f} deg", rep.consistency_deg)
            : std::string()));

  rep.theta.resize(n);
  for (size_t i = 0; i < n; ++i) rep.theta[i] = sign * phi[i] / p;
  return rep;
}

FloatCoefficients self_calibrate(const Recording& rec, const CalOptions& opt, SelfCalReport* report,
                                 int harmonics) {
  SelfCalOptions so;
  so.periodicity = opt.periodicity;
  so.harmonics = harmonics;
  SelfCalReport rep = estimate_reference(rec, so);
  Recording r = rec;
  r.theta_ref = rep.theta;
  CalOptions o = opt;
  o.estimate_zero = true;
  o.given_scaling = true;
  for (int c = 0; c < 2; ++c) {
    o.offset[c] = rep.ellipse.offset[c];
    o.amp[c] = rep.ellipse.amp[c];
  }
  const FloatCoefficients fc = calibrate(r, o);
  if (report) *report = std::move(rep);
  return fc;
}

}  // namespace acore
