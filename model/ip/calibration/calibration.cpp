// SPDX-License-Identifier: MIT
#include "calibration/calibration.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "core/fixed_point.hpp"
#include "engine/float_model.hpp"
#include "stages/cordic.hpp"
#include "stages/fourier_correct.hpp"
#include "stages/region_select.hpp"

namespace acore {

namespace {

// Least squares of the float chain's remaining angle error against the Fourier basis in its angle.
std::vector<double> fit_fourier(const Recording& rec, const FloatCoefficients& fc,
                                const CalOptions& opt) {
  const int cols = 2 * opt.fourier_k + 1;
  const size_t n = rec.size();
  if (n < static_cast<size_t>(4 * cols))
    throw InputError(
        fmt::format("calibration: a {}-harmonic Fourier correction needs at least {} samples, the "
                    "recording has {}",
                    opt.fourier_k, 4 * cols, n));
  Eigen::MatrixXd basis(n, cols);
  Eigen::VectorXd err(n);
  for (size_t i = 0; i < n; ++i) {
    const double theta = float_estimate(rec.d13(i), rec.d24(i), fc).angle;
    basis(i, 0) = 1.0;
    for (int k = 1; k <= opt.fourier_k; ++k) {
      basis(i, 2 * k - 1) = std::cos(k * theta);
      basis(i, 2 * k) = std::sin(k * theta);
    }
    err(i) = std::remainder(theta - opt.periodicity * rec.theta_ref[i] - fc.zero_offset, 2 * M_PI);
  }
  const Eigen::VectorXd sol = basis.colPivHouseholderQr().solve(err);
  return std::vector<double>(sol.data(), sol.data() + cols);
}

}  // namespace

double zero_offset_estimate(const std::vector<double>& s13, const std::vector<double>& s24,
                            const std::vector<double>& theta_ref, int periodicity) {
  // Sum of unit vectors e^{i (atan2(s13, s24) - p theta)} = (s24 + i s13) e^{-i p theta} / |s|.
  double re = 0, im = 0;
  for (size_t i = 0; i < s13.size(); ++i) {
    const double r = std::hypot(s13[i], s24[i]);
    if (!(r > 0)) continue;  // the zero vector has no angle
    const double e = periodicity * theta_ref[i];
    const double c = std::cos(e), s = std::sin(e);
    re += (s24[i] * c + s13[i] * s) / r;
    im += (s13[i] * c - s24[i] * s) / r;
  }
  if (!(std::hypot(re, im) > 1e-9 * static_cast<double>(s13.size())))
    throw InputError(
        "calibration: the angle error against theta_ref has no mean direction (is theta_ref the "
        "sensor's angle?): cannot estimate the zero offset");
  return wrap_pi(std::atan2(im, re));
}

FloatCoefficients calibrate(const Recording& rec, const CalOptions& opt) {
  if (!rec.has_theta()) throw InputError("calibration needs a theta_ref column");
  const size_t n = rec.size();
  FloatCoefficients fc;
  fc.correction = opt.correction;
  fc.degree = opt.degree;
  fc.regions = opt.regions;
  fc.xcenter = opt.xcenter;
  const DatapathConfig shape = fc.shape();
  shape.validate();
  const int terms = shape.coef_per_curve();
  if (n < static_cast<size_t>(8 * terms * opt.regions))
    throw InputError(fmt::format("calibration needs at least {} samples, the recording has {}",
                                 8 * terms * opt.regions, n));
  // The fit must see the whole electrical turn: every 10-degree sector of p * theta_ref.
  const int covered = turn_sectors_covered(rec.theta_ref, opt.periodicity);
  if (covered < 36)
    throw InputError(
        fmt::format("calibration: theta_ref covers only {} of the 36 ten-degree sectors "
                    "of a turn; record at least one full turn",
                    covered));
  fc.poly.assign(static_cast<size_t>(opt.regions) * 2 * terms, 0.0);

  // Scaling: offset = mean, amplitude = sqrt(2/N sum (c - O)^2)  (Eq. 4).
  std::vector<double> d[2] = {std::vector<double>(n), std::vector<double>(n)};
  for (size_t i = 0; i < n; ++i) {
    d[0][i] = rec.d13(i);
    d[1][i] = rec.d24(i);
  }
  for (int c = 0; c < 2; ++c) {
    double sum = 0;
    for (double v : d[c]) sum += v;
    fc.offset[c] = opt.given_scaling ? opt.offset[c] : sum / n;
    double ss = 0;
    for (double v : d[c]) ss += (v - fc.offset[c]) * (v - fc.offset[c]);
    fc.amp[c] = opt.given_scaling ? opt.amp[c] : std::sqrt(2.0 * ss / n);
    if (!(fc.amp[c] > 0))
      throw InputError(fmt::format("calibration: curve {} has zero amplitude", c ? "c24" : "c13"));
  }

  // Domain selection and the design matrix per region.
  std::vector<std::vector<size_t>> members(opt.regions);
  std::vector<double> xs(n), ys(n), s13(n), s24(n);
  for (size_t i = 0; i < n; ++i) {
    s13[i] = (d[0][i] - fc.offset[0]) / fc.amp[0];
    s24[i] = (d[1][i] - fc.offset[1]) / fc.amp[1];
    const int r = select_region_real(s13[i], s24[i], opt.regions, &xs[i]);
    ys[i] = x_is_sine(r, opt.regions) ? s24[i] : s13[i];
    members[r].push_back(i);
  }
  // Zero offset, from the uncorrected scaled curves (docs/calibration.md "Zero offset": iterating
  // it once more after the fit moves it by 0.01 deg on the paper scenario and changes no figure).
  fc.zero_offset = opt.estimate_zero
                       ? zero_offset_estimate(s13, s24, rec.theta_ref, opt.periodicity)
                       : wrap_pi(opt.zero_offset);
  for (int r = 0; r < opt.regions && terms > 0; ++r) {
    const auto& m = members[r];
    if (m.size() < static_cast<size_t>(2 * terms))
      throw InputError(
          fmt::format("calibration: region {} has {} samples, at least {} needed (does the "
                      "recording cover a turn?)",
                      r, m.size(), 2 * terms));
    Eigen::MatrixXd V(m.size(), terms);
    Eigen::MatrixXd rhs(m.size(), 2);
    for (size_t k = 0; k < m.size(); ++k) {
      const size_t i = m[k];
      double basis[64];
      correction_basis(shape, xs[i], ys[i], basis);
      for (int j = 0; j < terms; ++j) V(k, j) = basis[j];
      const double e =
          opt.periodicity * rec.theta_ref[i] + fc.zero_offset;  // the aligned reference
      rhs(k, 0) = s13[i] - std::sin(e);  // Eq. 6: measured scaled curve minus the ideal one
      rhs(k, 1) = s24[i] - std::cos(e);
    }
    const Eigen::MatrixXd sol = V.colPivHouseholderQr().solve(rhs);
    for (int c = 0; c < 2; ++c)
      for (int j = 0; j < terms; ++j) fc.coef(r, c, j) = sol(j, c);
  }
  if (opt.fourier_k > 0) fc.fourier = fit_fourier(rec, fc, opt);
  return fc;
}

double choose_in_scale(const Recording& rec, int in_w) {
  double peak = 0;
  for (int c = 0; c < rec.channels; ++c)
    for (double v : rec.ch[c]) peak = std::max(peak, std::fabs(v));
  if (!(peak > 0) || !std::isfinite(peak))
    throw InputError("recording has no signal (all channels zero)");
  const double target = std::ldexp(1.0, in_w - 3);  // a quarter of full scale
  return std::ldexp(1.0, static_cast<int>(std::floor(std::log2(target / peak))));
}

CalOptions cal_options_for(const DatapathConfig& cfg, int periodicity) {
  CalOptions opt;
  opt.correction = cfg.correction;
  opt.degree = cfg.degree;
  opt.regions = cfg.regions;
  opt.xcenter = cfg.xcenter;
  opt.periodicity = periodicity;
  opt.fourier_k = cfg.fourier_k;
  return opt;
}

RegImage calibrate_image(const Recording& rec, const DatapathConfig& cfg, int periodicity,
                         FloatCoefficients* fc) {
  const FloatCoefficients c = calibrate(rec, cal_options_for(cfg, periodicity));
  if (fc) *fc = c;
  return quantize_auto_range(c, cfg, choose_in_scale(rec, cfg.in_w));
}

}  // namespace acore
