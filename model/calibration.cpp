// SPDX-License-Identifier: MIT
#include "calibration.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "cordic.hpp"
#include "errors.hpp"
#include "fixed_point.hpp"
#include "float_model.hpp"
#include "fourier_correct.hpp"
#include "region_select.hpp"

namespace acore {

namespace {

// Least squares of the float chain's remaining angle error against the Fourier basis in its angle.
std::vector<double> fit_fourier(const Recording& rec, const FloatCoefficients& fc, const CalOptions& opt) {
  const int cols = 2 * opt.fourier_k + 1;
  const size_t n = rec.size();
  if (n < static_cast<size_t>(4 * cols))
    throw InputError(fmt::format("calibration: a {}-harmonic Fourier correction needs at least {} samples, the "
                                 "recording has {}", opt.fourier_k, 4 * cols, n));
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

DatapathConfig FloatCoefficients::shape() const {
  DatapathConfig c;
  c.correction = correction;
  c.degree = degree;
  c.regions = regions;
  c.xcenter = xcenter;
  return c;
}

double correction_u(double x, int xcenter) {
  if (!xcenter) return x;
  return 2 * (x >= 0 ? x - 0.375 : x + 0.375);
}

double correction_v(double y_other) {
  return std::ldexp(y_other >= 0 ? y_other - 1 : y_other + 1, kVShift);
}

void correction_basis(const DatapathConfig& shape, double x, double y_other, double* out) {
  const double u = correction_u(x, shape.xcenter);
  if (shape.correction == kPoly) {
    double pw = 1;
    for (int j = 0; j <= shape.degree; ++j, pw *= u) out[j] = pw;
  } else if (shape.correction == kPoly2d) {
    const double v = correction_v(y_other);
    double ui = 1;
    for (int i = 0; i <= shape.degree; ++i, ui *= u) {
      double vj = 1;
      for (int j = 0; i + j <= shape.degree; ++j, vj *= v) out[shape.term2d(i, j)] = ui * vj;
    }
  }
}

double correction_poly(const FloatCoefficients& fc, int r, int c, double x, double y_other) {
  const double u = correction_u(x, fc.xcenter);
  const int d = fc.degree;
  if (fc.correction == kPoly) {
    double acc = fc.coef(r, c, d);
    for (int j = d - 1; j >= 0; --j) acc = acc * u + fc.coef(r, c, j);
    return acc;
  }
  if (fc.correction != kPoly2d) return 0.0;
  const DatapathConfig shape = fc.shape();
  const double v = correction_v(y_other);
  double acc = 0;
  for (int i = d; i >= 0; --i) {
    double q = fc.coef(r, c, shape.term2d(i, d - i));
    for (int j = d - i - 1; j >= 0; --j) q = q * v + fc.coef(r, c, shape.term2d(i, j));
    acc = i == d ? q : acc * u + q;
  }
  return acc;
}

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
    fc.offset[c] = sum / n;
    double ss = 0;
    for (double v : d[c]) ss += (v - fc.offset[c]) * (v - fc.offset[c]);
    fc.amp[c] = std::sqrt(2.0 * ss / n);
    if (!(fc.amp[c] > 0)) throw InputError(fmt::format("calibration: curve {} has zero amplitude", c ? "c24" : "c13"));
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
  // Zero offset, from the uncorrected scaled curves (README "Zero offset": iterating it once more
  // after the fit moves it by 0.01 deg on the paper scenario and changes no figure).
  fc.zero_offset = opt.estimate_zero
                       ? zero_offset_estimate(s13, s24, rec.theta_ref, opt.periodicity)
                       : wrap_pi(opt.zero_offset);
  for (int r = 0; r < opt.regions && terms > 0; ++r) {
    const auto& m = members[r];
    if (m.size() < static_cast<size_t>(2 * terms))
      throw InputError(fmt::format(
          "calibration: region {} has {} samples, at least {} needed (does the recording cover a turn?)",
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
  if (!(peak > 0) || !std::isfinite(peak)) throw InputError("recording has no signal (all channels zero)");
  const double target = std::ldexp(1.0, in_w - 3);  // a quarter of full scale
  return std::ldexp(1.0, static_cast<int>(std::floor(std::log2(target / peak))));
}

RegImage quantize(const FloatCoefficients& fc, DatapathConfig cfg, double in_scale) {
  cfg.correction = fc.correction;
  cfg.degree = fc.degree;
  cfg.regions = fc.regions;
  cfg.xcenter = fc.xcenter;
  cfg.fourier_k = fc.fourier_k();
  cfg.validate();
  RegImage img;
  img.cfg = cfg;
  img.in_scale = in_scale;
  img.zero_offset = wrap_pi(fc.zero_offset);
  img.words.assign(cfg.words(), 0);
  if (cfg.zero_word) img.set_unsigned(cfg.addr_zero(), img.zero_offset_code());
  for (int c = 0; c < 2; ++c) {
    const char* curve = c ? "c24" : "c13";
    // The offset and amplitude are in codes of the pre-filtered curve d (D_W bits).
    try {
      img.set_signed(cfg.addr_offset(c), std::llround(fc.offset[c] * in_scale));
    } catch (const InputError&) {
      throw InputError(fmt::format("offset of {} = {} does not fit the {}-bit register", curve,
                                   fc.offset[c], cfg.reg_w));
    }
    const double amp_codes = fc.amp[c] * in_scale;
    const double recip = std::ldexp(1.0, cfg.s_f + cfg.r_shift) / amp_codes;
    try {
      img.set_unsigned(cfg.addr_recip(c), std::llround(recip));
    } catch (const InputError&) {
      throw InputError(fmt::format(
          "amplitude of {} = {:.1f} codes is out of the reciprocal register's range (needs "
          "2^(S_F+R_SHIFT)/A < 2^REG_W, i.e. A > {:.0f} codes): raise in_scale or r_shift",
          curve, amp_codes, std::ldexp(1.0, cfg.s_f + cfg.r_shift - cfg.reg_w)));
    }
  }
  for (int r = 0; r < cfg.regions; ++r)
    for (int c = 0; c < 2; ++c)
      for (int j = 0; j < cfg.coef_per_curve(); ++j) {
        const double v = fc.coef(r, c, j);
        const long long q = std::llround(std::ldexp(v, cfg.coef_f));
        try {
          img.set_signed(cfg.addr_poly(r, c, j), q);
        } catch (const InputError&) {
          throw InputError(fmt::format(
              "polynomial coefficient region {} curve {} {}^{} = {:.4f} exceeds the Q{}.{} range: "
              "lower --coef-frac",
              r, c ? "c24" : "c13", cfg.correction == kPoly2d ? "term" : "x", j, v,
              cfg.reg_w - cfg.coef_f, cfg.coef_f));
        }
      }
  const auto table = cordic_atan_table(cfg.z_w, cfg.iterations);
  for (int i = 0; i < cfg.iterations; ++i) img.set_unsigned(cfg.addr_atan(i), table[i]);
  // Fourier words: turns with fourier_coef_f fraction bits; harmonics divided by the rotation gain.
  const double gain = fourier_gain(cfg);
  for (int j = 0; j < cfg.fourier_words(); ++j) {
    const double turns = fc.fourier[j] / (2 * M_PI) / (j == 0 ? 1.0 : gain);
    const long long q = std::llround(std::ldexp(turns, cfg.fourier_coef_f));
    const int w = j == 0 ? cfg.reg_w : cfg.fourier_word_w;  // a harmonic's word: its low W bits
    if (q > fx::smax(w) || q < fx::smin(w))
      throw InputError(fmt::format("fourier coefficient {} = {:.4f} deg exceeds the {}-bit range of "
                                   "fourier_coef_f={} (+-{:.4f} deg)", j, fc.fourier[j] * 180 / M_PI, w,
                                   cfg.fourier_coef_f, std::ldexp(360.0, w - 1 - cfg.fourier_coef_f) * (j ? gain : 1)));
    img.set_signed(cfg.addr_fourier(j), q);
  }
  return img;
}

RegImage quantize_auto_range(const FloatCoefficients& coef, DatapathConfig cfg, double in_scale) {
  for (;;) {
    try {
      return quantize(coef, cfg, in_scale);
    } catch (const InputError& e) {
      if (std::string(e.what()).find("fourier coefficient") != std::string::npos && cfg.fourier_coef_f >= cfg.reg_w) {
        --cfg.fourier_coef_f;
        continue;
      }
      if (cfg.coef_f <= 8 || std::string(e.what()).find("polynomial coefficient") == std::string::npos) throw;
      const int acc_f = cfg.acc_f();
      --cfg.coef_f;
      cfg.acc_guard = acc_f - cfg.coef_f;
      cfg.acc_int = std::max(cfg.acc_int, cfg.reg_w - cfg.coef_f + 1);
    }
  }
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

RegImage calibrate_image(const Recording& rec, const DatapathConfig& cfg, int periodicity, FloatCoefficients* fc) {
  const FloatCoefficients c = calibrate(rec, cal_options_for(cfg, periodicity));
  if (fc) *fc = c;
  return quantize_auto_range(c, cfg, choose_in_scale(rec, cfg.in_w));
}

FloatCoefficients dequantize(const RegImage& img) {
  const DatapathConfig& cfg = img.cfg;
  FloatCoefficients fc;
  fc.correction = cfg.correction;
  fc.degree = cfg.degree;
  fc.regions = cfg.regions;
  fc.xcenter = cfg.xcenter;
  fc.poly.assign(static_cast<size_t>(cfg.poly_words()), 0.0);
  for (int c = 0; c < 2; ++c) {
    fc.offset[c] = img.offset(c) / img.in_scale;
    if (img.recip(c) <= 0) throw InputError("register image: an amplitude reciprocal is zero");
    fc.amp[c] = std::ldexp(1.0, cfg.s_f + cfg.r_shift) / img.recip(c) / img.in_scale;
  }
  for (int r = 0; r < cfg.regions; ++r)
    for (int c = 0; c < 2; ++c)
      for (int j = 0; j < cfg.coef_per_curve(); ++j)
        fc.coef(r, c, j) = std::ldexp(static_cast<double>(img.poly(r, c, j)), -cfg.coef_f);
  const double gain = fourier_gain(cfg);
  for (int j = 0; j < cfg.fourier_words(); ++j)
    fc.fourier.push_back(2 * M_PI * (j == 0 ? 1.0 : gain) *
                         std::ldexp(static_cast<double>(img.fourier(j)), -cfg.fourier_coef_f));
  // With the ZERO word the chain subtracts the word's value (what the hardware holds).
  fc.zero_word = cfg.zero_word;
  fc.zero_offset = img.applied_zero_offset();
  return fc;
}

}  // namespace acore
