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

constexpr double kDeg = 180.0 / M_PI;

// Legendre polynomials P_0..P_m at x in [-1, 1] (three-term recurrence: well conditioned).
void legendre(double x, int m, double* out) {
  out[0] = 1;
  if (m >= 1) out[1] = x;
  for (int j = 2; j <= m; ++j) out[j] = ((2 * j - 1) * x * out[j - 1] - (j - 1) * out[j - 2]) / j;
}

// The joint model: psi(t) = sum_j a_j P_j(tau) + sum_f c_f cos(pi f (tau + 1)) + d_f sin(..)
// + sum_k alpha_k cos(k phi) + beta_k sin(k phi), the harmonics at the current estimate phi of the
// true angle; f: speed ripple tones in cycles over the recording. Columns: the profile (polynomial,
// tones) first, then the harmonics.
Eigen::MatrixXd design(const std::vector<double>& tau, const std::vector<double>& phi, int order,
                       int harmonics, const std::vector<double>& tones = {}) {
  const size_t n = tau.size();
  const int prof = order + 1 + 2 * static_cast<int>(tones.size());
  Eigen::MatrixXd X(n, prof + 2 * harmonics);
  std::vector<double> p(static_cast<size_t>(order) + 1);
  for (size_t i = 0; i < n; ++i) {
    legendre(tau[i], order, p.data());
    for (int j = 0; j <= order; ++j) X(i, j) = p[static_cast<size_t>(j)];
    for (size_t f = 0; f < tones.size(); ++f) {
      const double a = M_PI * tones[f] * (tau[i] + 1);
      X(i, order + 1 + 2 * static_cast<int>(f)) = std::cos(a);
      X(i, order + 2 + 2 * static_cast<int>(f)) = std::sin(a);
    }
    for (int k = 1; k <= harmonics; ++k) {
      X(i, prof + 2 * k - 2) = std::cos(k * phi[i]);
      X(i, prof + 2 * k - 1) = std::sin(k * phi[i]);
    }
  }
  return X;
}

// The strongest sinusoid of r(tau) between 0.5 and f_max cycles over the recording (periodogram
// on a grid of 0.25 cycles, refined to 0.01), and its power.
double strongest_tone(const std::vector<double>& tau, const Eigen::VectorXd& r, double f_max,
                      double* power) {
  auto pw = [&](double f) {
    double c = 0, s = 0;
    for (size_t i = 0; i < tau.size(); ++i) {
      const double a = M_PI * f * (tau[i] + 1);
      c += r(static_cast<long>(i)) * std::cos(a);
      s += r(static_cast<long>(i)) * std::sin(a);
    }
    return c * c + s * s;
  };
  double best_f = 0, best = -1;
  for (double f = 0.5; f <= f_max; f += 0.25)
    if (const double v = pw(f); v > best) {
      best = v;
      best_f = f;
    }
  const double centre = best_f;
  for (double f = centre - 0.25; f <= centre + 0.25; f += 0.01)
    if (const double v = pw(f); f > 0 && v > best) {
      best = v;
      best_f = f;
    }
  *power = best;
  return best_f;
}

struct JointFit {
  Eigen::VectorXd coef;
  std::vector<double> profile, error;  // the fitted speed profile and periodic error, rad
  double rss = 0;
};

// `order`: the profile's columns minus one (polynomial order + 2 per tone).
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

// ---- The steps of estimate_reference() ----

// The joint model's BIC at profile order m and K harmonics, on the first pass (harmonics at psi).
double joint_bic(const std::vector<double>& tau, const std::vector<double>& psi,
                 const Eigen::VectorXd& y, int m, int k) {
  const double nn = static_cast<double>(y.size());
  const JointFit f = solve_joint(design(tau, psi, m, k), y, m);
  return nn * std::log(std::max(f.rss / nn, 1e-300)) + (m + 1 + 2 * k) * std::log(nn);
}

// The sample times: t, or equally spaced samples without a t column; refused when t does not
// increase.
std::vector<double> sample_times(const Recording& rec, bool uniform) {
  const size_t n = rec.size();
  std::vector<double> t(n);
  for (size_t i = 0; i < n; ++i) t[i] = uniform ? static_cast<double>(i) : rec.t[i];
  for (size_t i = 1; i < n; ++i)
    if (!(t[i] > t[i - 1]))
      throw InputError(fmt::format(
          "self-calibration: column t does not increase at sample {} ({} after {}): it needs "
          "the sample times (or no t column: equally spaced samples)",
          i, t[i], t[i - 1]));
  return t;
}

// The times mapped onto [-1, 1] (the Legendre polynomials' interval).
std::vector<double> normalized_times(const std::vector<double>& t) {
  const size_t n = t.size();
  std::vector<double> tau(n);
  for (size_t i = 0; i < n; ++i) tau[i] = 2 * (t[i] - t[0]) / (t[n - 1] - t[0]) - 1;
  return tau;
}

// The ellipse-corrected angle, unwrapped, turned forward (*sign: -1 when it turned backward).
std::vector<double> forward_angle(const EllipseFit& el, const std::vector<double>& d13,
                                  const std::vector<double>& d24, double* sign) {
  const size_t n = d13.size();
  std::vector<double> psi(n);
  psi[0] = el.angle(d13[0], d24[0]);
  for (size_t i = 1; i < n; ++i)
    psi[i] = psi[i - 1] + wrap_pi(el.angle(d13[i], d24[i]) - psi[i - 1]);
  *sign = psi[n - 1] >= psi[0] ? 1.0 : -1.0;
  for (double& v : psi) v *= *sign;
  return psi;
}

// Electrical turns covered (one sample step counted at each end); refused below one.
double turns_covered(const std::vector<double>& psi) {
  const size_t n = psi.size();
  const double span = psi[n - 1] - psi[0];
  const double turns = (span + span / static_cast<double>(n - 1)) / kTwoPi;
  if (turns < 0.999)
    throw InputError(fmt::format(
        "self-calibration refused: the recording covers {:.3f} electrical turns, at least one "
        "full turn is needed (the sensor's error is learnt from its repetition over a turn)",
        turns));
  return turns;
}

// Reversal or stop: the angle advanced over windows of 1/16 turn, against the median window.
void refuse_reversal_or_stop(const std::vector<double>& psi, const std::vector<double>& t) {
  const size_t n = psi.size();
  const double span = psi[n - 1] - psi[0];
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

// The highest speed-profile order the recording separates from the error: the first harmonic
// must stay mostly outside the profile's span.
int separable_profile_order(const std::vector<double>& tau, const std::vector<double>& psi,
                            double turns, const SelfCalOptions& opt) {
  const int cap = opt.max_profile_order > 0
                      ? opt.max_profile_order
                      : (turns < 2 ? 1 : std::min(40, static_cast<int>(std::floor(4 * turns)) + 1));
  int max_order = 1;
  for (int m = 2; m <= cap; ++m) {
    if (profile_harmonic_overlap(tau, psi, m) > 0.99) break;
    max_order = m;
  }
  return max_order;
}

// The error model's harmonics K (at most an eighth of the samples per turn) by BIC at the richest
// profile; `given` > 0 is taken as it is.
int choose_harmonics(const std::vector<double>& tau, const std::vector<double>& psi,
                     const Eigen::VectorXd& y, int max_order, double turns, int given) {
  const double per_turn = static_cast<double>(psi.size()) / turns;
  const int kmax = std::max(2, std::min(64, static_cast<int>(per_turn / 8)));
  int K = given;
  if (K <= 0) {
    double best = 0;
    for (int k = 4; k <= kmax || k == 4; k *= 2) {
      const int kk = std::min(k, kmax);
      const double b = joint_bic(tau, psi, y, max_order, kk);
      if (K == 0 || b < best) {
        best = b;
        K = kk;
      }
      if (kk == kmax) break;
    }
  }
  return K;
}

// The speed profile's order at K harmonics, by BIC among 1..max_order.
int choose_profile_order(const std::vector<double>& tau, const std::vector<double>& psi,
                         const Eigen::VectorXd& y, int max_order, int K) {
  int order = 1;
  double best_bic = 0;
  for (int m = 1; m <= max_order; ++m) {
    const double b = joint_bic(tau, psi, y, m, K);
    if (m == 1 || b < best_bic) {
      best_bic = b;
      order = m;
    }
  }
  return order;
}

// Speed ripple: tones in the residual that the polynomial cannot follow, kept while BIC gains (at
// most three; two or more turns, or a tone cannot be told from a harmonic).
std::vector<double> find_ripple_tones(const std::vector<double>& tau,
                                      const std::vector<double>& psi, const Eigen::VectorXd& y,
                                      int order, int K, double turns) {
  std::vector<double> tones;
  if (turns < 2) return tones;
  const size_t n = psi.size();
  const double nn = static_cast<double>(n);
  JointFit f = solve_joint(design(tau, psi, order, K), y, order);
  double cur = nn * std::log(std::max(f.rss / nn, 1e-300)) + (order + 1 + 2 * K) * std::log(nn);
  for (int t = 0; t < 3; ++t) {
    const Eigen::Map<const Eigen::VectorXd> prof(f.profile.data(), static_cast<long>(n));
    const Eigen::Map<const Eigen::VectorXd> err(f.error.data(), static_cast<long>(n));
    const Eigen::VectorXd r = y - prof - err;
    double power = 0;
    const double fr = strongest_tone(tau, r, (K + 1) * turns, &power);
    std::vector<double> trial = tones;
    trial.push_back(fr);
    const int cols = order + 2 * static_cast<int>(trial.size());
    const JointFit g = solve_joint(design(tau, psi, order, K, trial), y, cols);
    const double b =
        nn * std::log(std::max(g.rss / nn, 1e-300)) + (cols + 1 + 2 * K + 1) * std::log(nn);
    if (!(b < cur - 10)) break;
    cur = b;
    tones = trial;
    f = g;
  }
  return tones;
}

// The joint fit with the harmonics evaluated at the corrected angle phi = psi - e(.), repeated
// three times (a fixed point); phi returned in *phi.
JointFit fit_reference(const std::vector<double>& tau, const std::vector<double>& psi,
                       const Eigen::VectorXd& y, int order, int K, const std::vector<double>& tones,
                       std::vector<double>* phi) {
  const int prof_cols = order + 2 * static_cast<int>(tones.size());
  *phi = psi;
  JointFit fit;
  for (int pass = 0; pass < 3; ++pass) {
    fit = solve_joint(design(tau, *phi, order, K, tones), y, prof_cols);
    for (size_t i = 0; i < psi.size(); ++i) (*phi)[i] = psi[i] - fit.error[i];
  }
  return fit;
}

// Residual, noise (from second differences), the periodic error's RMS and the speed's variation.
void figures_of_merit(const JointFit& fit, const std::vector<double>& phi,
                      const std::vector<double>& t, SelfCalReport& rep) {
  const size_t n = phi.size();
  const double nn = static_cast<double>(n);
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
  double vmin = 1e300, vmax = -1e300,
         vmean = (fit.profile[n - 1] - fit.profile[0]) / (t[n - 1] - t[0]);
  for (size_t i = 1; i < n; ++i) {
    const double v = (fit.profile[i] - fit.profile[i - 1]) / (t[i] - t[i - 1]);
    vmin = std::min(vmin, v);
    vmax = std::max(vmax, v);
  }
  rep.speed_variation_pct = 100 * (vmax - vmin) / vmean;
}

// Consistency: the periodic error fitted again on each half of the recording alone, the speed
// profile of the whole fit held (two turns or more): an error that is the sensor's repeats, a
// speed variation the profile missed does not. The RMS difference of the halves' errors, degrees.
double half_consistency(const std::vector<double>& psi, const std::vector<double>& phi,
                        const JointFit& fit, int K) {
  const size_t n = psi.size();
  const size_t h = n / 2;
  auto half = [&](size_t from, size_t count) {
    Eigen::MatrixXd X(count, 2 * K);
    Eigen::VectorXd yy(count);
    for (size_t i = 0; i < count; ++i) {
      const size_t j = from + i;
      for (int k = 1; k <= K; ++k) {
        X(i, 2 * k - 2) = std::cos(k * phi[j]);
        X(i, 2 * k - 1) = std::sin(k * phi[j]);
      }
      yy(i) = psi[j] - fit.profile[j];
    }
    // The constant is the profile's: remove each half's mean first.
    return X.colPivHouseholderQr().solve((yy.array() - yy.mean()).matrix()).eval();
  };
  const Eigen::VectorXd ca = half(0, h), cb = half(h, n - h);
  return (ca - cb).norm() / std::sqrt(2.0) * kDeg;
}

// Confidence: how much of the residual is noise, and how well the halves agree.
double confidence(const SelfCalReport& rep) {
  const double unexplained =
      std::sqrt(std::max(0.0, rep.residual_deg * rep.residual_deg - rep.noise_deg * rep.noise_deg));
  double conf = 1.0 / (1.0 + unexplained / std::max(rep.error_rms_deg, 1e-9));
  if (rep.consistency_deg >= 0)
    conf *= 1.0 / (1.0 + rep.consistency_deg / std::max(rep.error_rms_deg, 1e-9));
  else
    conf *= 0.5;  // one turn: a variation within the turn cannot be told from the error
  return conf;
}

// What the reference rests on, one sentence each.
std::vector<std::string> assumptions(const SelfCalReport& rep) {
  std::vector<std::string> a;
  a.push_back(fmt::format(
      "the sensor's error is periodic in the electrical angle (harmonics 1..{})", rep.harmonics));
  a.push_back(fmt::format(
      "the speed follows a polynomial of order {} in time over the recording (BIC among orders "
      "1..{}, the highest the recording separates from the error)",
      rep.profile_order, rep.max_separable_order));
  if (!rep.ripple_tones.empty()) {
    std::string list;
    for (double f : rep.ripple_tones)
      list += fmt::format("{}{:.2f}", list.empty() ? "" : ", ", f / rep.turns);
    a.push_back(fmt::format("plus a speed ripple of {} cycles per turn (sinusoids in time)", list));
  }
  if (rep.uniform_time) a.push_back("no t column: the samples are taken as equally spaced in time");
  if (rep.turns < 2)
    a.push_back(
        "less than two turns: a speed variation within the turn cannot be told from the "
        "sensor's error: the speed is taken as constant (profile order 1), which one turn cannot "
        "verify (a parabola in time is as well a sum of the angle's harmonics over one turn)");
  a.push_back(
      "the zero offset is unknown: the reference's zero is arbitrary (zero_reference none)");
  return a;
}

// Refusal: a speed variation the profile cannot follow and the recording cannot separate. The
// halves' errors must agree to a quarter of the error, beyond what the noise explains (each half's
// 2K coefficients carry the noise over n / 2 samples).
void refuse_inconsistent_halves(const SelfCalReport& rep, size_t n) {
  const double nn = static_cast<double>(n);
  const double noise_spread = 10 * rep.noise_deg * std::sqrt(4.0 * rep.harmonics / nn);
  if (rep.consistency_deg >= 0 && rep.consistency_deg > 0.25 * rep.error_rms_deg + noise_spread)
    throw InputError(fmt::format(
        "self-calibration refused: a speed variation it cannot separate from the sensor's error "
        "(the fit leaves {:.3f} deg RMS against a noise of {:.3f} deg, speed-profile order {} "
        "of {} separable{}); record more turns at a steadier speed",
        rep.residual_deg, rep.noise_deg, rep.profile_order, rep.max_separable_order,
        rep.consistency_deg >= 0
            ? fmt::format(", the two halves' errors differ by {:.3f} deg", rep.consistency_deg)
            : std::string()));
}

// A sensor's angle error comes with a distortion of its Lissajous figure of the same order (a
// harmonic of the field or of a channel moves the radius as much as the angle); a speed variation
// moves the angle along an undistorted figure. A periodic error far beyond what the figure's
// distortion allows is a speed variation taken for error: refused. Sets rep.radius_rms.
void refuse_error_beyond_distortion(const std::vector<double>& d13, const std::vector<double>& d24,
                                    SelfCalReport& rep) {
  const size_t n = d13.size();
  double dev = 0;
  for (size_t i = 0; i < n; ++i) {
    const double c = (d24[i] - rep.ellipse.offset[1]) / rep.ellipse.amp[1];
    const double s =
        ((d13[i] - rep.ellipse.offset[0]) / rep.ellipse.amp[0] - c * std::sin(rep.ellipse.delta)) /
        std::cos(rep.ellipse.delta);
    dev += (std::hypot(s, c) - 1) * (std::hypot(s, c) - 1);
  }
  rep.radius_rms = std::sqrt(dev / static_cast<double>(n));
  const double allowed = (5 * rep.radius_rms + 0.035) * kDeg;
  if (rep.error_rms_deg > allowed)
    throw InputError(fmt::format(
        "self-calibration refused: a speed variation it cannot separate from the sensor's "
        "error: the periodic error it would take ({:.2f} deg RMS) is far more than the "
        "Lissajous figure's distortion allows (its radius deviates by {:.2f} % RMS: at most "
        "{:.2f} deg); record more turns at a steadier speed",
        rep.error_rms_deg, 100 * rep.radius_rms, allowed));
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
  // The points must lie near the ellipse: the corrected radius about 1 (RMS deviation < 0.3).
  double dev = 0;
  for (size_t i = 0; i < n; ++i) {
    const double c = (d24[i] - el.offset[1]) / el.amp[1];
    const double s = ((d13[i] - el.offset[0]) / el.amp[0] - c * sd) / std::sqrt(c2);
    dev += (std::hypot(s, c) - 1) * (std::hypot(s, c) - 1);
  }
  if (!(std::sqrt(dev / n) < 0.3))
    throw InputError(fmt::format(
        "self-calibration: the channels do not trace an ellipse (radius deviates by {:.2f} RMS "
        "from the fitted one; is it a sensor pair?)",
        std::sqrt(dev / n)));
  return el;
}

SelfCalReport estimate_reference(const Recording& rec, const SelfCalOptions& opt) {
  const size_t n = rec.size();
  SelfCalReport rep;
  std::vector<double> d13(n), d24(n);
  for (size_t i = 0; i < n; ++i) {
    d13[i] = rec.d13(i);
    d24[i] = rec.d24(i);
  }
  if (n < 64)
    throw InputError(
        fmt::format("self-calibration needs at least 64 samples, the recording has {}", n));
  // 1. The Lissajous ellipse; 2. the corrected angle over time, refused unless it turns forward
  // over a turn at least.
  rep.ellipse = fit_ellipse(d13, d24);
  rep.uniform_time = !rec.has_t();
  const std::vector<double> t = sample_times(rec, rep.uniform_time);
  const std::vector<double> tau = normalized_times(t);
  double sign = 1;
  const std::vector<double> psi = forward_angle(rep.ellipse, d13, d24, &sign);
  rep.turns = turns_covered(psi);
  refuse_reversal_or_stop(psi, t);
  // 3. The joint model's size (profile order, harmonics, ripple tones), then the reference.
  const Eigen::VectorXd y = Eigen::Map<const Eigen::VectorXd>(psi.data(), static_cast<long>(n));
  rep.max_separable_order = separable_profile_order(tau, psi, rep.turns, opt);
  rep.harmonics = choose_harmonics(tau, psi, y, rep.max_separable_order, rep.turns, opt.harmonics);
  rep.profile_order = choose_profile_order(tau, psi, y, rep.max_separable_order, rep.harmonics);
  rep.ripple_tones = find_ripple_tones(tau, psi, y, rep.profile_order, rep.harmonics, rep.turns);
  std::vector<double> phi;
  const JointFit fit =
      fit_reference(tau, psi, y, rep.profile_order, rep.harmonics, rep.ripple_tones, &phi);
  // How well it held, what it assumed, and the refusals that need the fit.
  figures_of_merit(fit, phi, t, rep);
  if (rep.turns >= 2) rep.consistency_deg = half_consistency(psi, phi, fit, rep.harmonics);
  rep.confidence = confidence(rep);
  rep.assumptions = assumptions(rep);
  refuse_inconsistent_halves(rep, n);
  refuse_error_beyond_distortion(d13, d24, rep);

  rep.theta.resize(n);
  for (size_t i = 0; i < n; ++i) rep.theta[i] = sign * phi[i] / opt.periodicity;
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
