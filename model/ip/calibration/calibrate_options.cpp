// SPDX-License-Identifier: MIT
#include "calibration/calibrate_options.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "engine/estimator.hpp"

namespace acore {

namespace {

void check_range(const char* option, long long v, long long lo, long long hi) {
  if (v < lo || v > hi) throw InputError(fmt::format("{} {}: not in {}..{}", option, v, lo, hi));
}

// --zero-offset: "auto" (estimate) or an electrical angle in degrees.
void parse_zero_offset(const std::string& v, CalOptions* opt) {
  if (v == "auto") return;
  size_t used = 0;
  double deg = 0;
  try {
    deg = std::stod(v, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != v.size() || !std::isfinite(deg))
    throw InputError("--zero-offset: '" + v + "' is neither 'auto' nor an angle in degrees");
  opt->estimate_zero = false;
  opt->zero_offset = deg * M_PI / 180;
}

}  // namespace

void CalibrateSpec::validate() const {
  parse_correction(correction);
  check_range("--degree", degree, 1, 7);
  if (regions != 4 && regions != 8)
    throw InputError(fmt::format("--regions {}: not one of 4, 8", regions));
  if (iterations) check_range("--iterations", *iterations, 4, 24);
  if (coef_frac) check_range("--coef-frac", *coef_frac, 1, 17);
  check_range("--angle-w", angle_w, 8, 20);
  check_range("--in-w", in_w, 8, 24);
  if (!(in_scale >= 0) || !std::isfinite(in_scale))
    throw InputError(fmt::format("--in-scale {}: not a positive number", in_scale));
  if (periodicity != 0) check_range("--periodicity", periodicity, 1, 64);
  check_range("--fourier", fourier, 0, 31);
  check_range("--fourier-iterations", fourier_iterations, 4, 24);
  check_range("--fourier-guard", fourier_guard, 0, 8);
  if (correction == "poly2d" && degree > 3)
    throw InputError(fmt::format("--degree {}: poly2d takes a total degree of 1..3", degree));
  if (xcenter && regions != 8) throw InputError("--xcenter needs --regions 8");
}

CalibrateOutcome calibrate_recording(const Recording& rec, const CalibrateSpec& a,
                                     const std::string& what, const std::string& command) {
  a.validate();
  CalibrateOutcome out;
  CalOptions& opt = out.options;
  opt.correction = parse_correction(a.correction);
  opt.degree = a.degree;
  opt.regions = a.regions;
  opt.xcenter = a.xcenter ? 1 : 0;
  opt.periodicity = a.periodicity ? a.periodicity : recording_periodicity(rec, what);
  opt.fourier_k = a.fourier;
  parse_zero_offset(a.zero_offset, &opt);
  DatapathConfig cfg = cordic_width_preset(a.angle_w);
  cfg.correction = opt.correction;
  cfg.fourier_k = a.fourier;
  cfg.fourier_iterations = a.fourier_iterations;
  cfg.fourier_guard = a.fourier_guard;
  cfg.degree = a.degree;
  cfg.regions = a.regions;
  cfg.xcenter = opt.xcenter;
  cfg.zero_word = a.zero_word ? 1 : 0;
  if (a.iterations) cfg.iterations = *a.iterations;
  // A wider input needs wider offset words (REG_W >= IN_W + 2); the coefficients keep Q3.x.
  cfg.in_w = a.in_w;
  if (const int grow = cfg.in_w + 2 - cfg.reg_w; grow > 0) {
    cfg.reg_w += grow;
    cfg.coef_f += grow;
  }
  if (a.coef_frac) {
    cfg.acc_guard += cfg.coef_f - *a.coef_frac;  // the accumulator keeps its fraction bits
    cfg.coef_f = *a.coef_frac;
    cfg.acc_int = std::max(cfg.acc_int, cfg.reg_w - cfg.coef_f + 1);
  }
  cfg.validate();
  const FloatCoefficients fc = calibrate(rec, opt);
  out.fc = fc;
  const double in_scale = a.in_scale > 0 ? a.in_scale : choose_in_scale(rec, cfg.in_w);
  out.image = a.coef_frac ? quantize(fc, cfg, in_scale) : quantize_auto_range(fc, cfg, in_scale);
  const RegImage& img = out.image;
  cfg = img.cfg;
  out.image.provenance.push_back("command=" + command);
  out.image.provenance.push_back(fmt::format("periodicity={}", opt.periodicity));

  // Fit quality on the calibration recording itself, both engines.
  const auto ef = angle_error_deg(run_float(rec, fc).angle, rec.theta_ref, opt.periodicity);
  const AngleSeries fixed = run_fixed(rec, img);
  const auto ex = angle_error_deg(fixed.angle, rec.theta_ref, opt.periodicity);
  const auto eu = angle_error_deg(fixed.uncorrected, rec.theta_ref, opt.periodicity);
  out.fit_float = error_stats(ef);
  out.fit_fixed = error_stats(ex);
  out.fit_uncorrected = error_stats(eu);
  out.report = {{"samples", rec.size()},
                {"words", cfg.words()},
                {"correction", correction_name(cfg.correction)},
                {"xcenter", cfg.xcenter},
                {"angle_w", cfg.angle_w},
                {"reg_w", cfg.reg_w},
                {"degree", cfg.degree},
                {"regions", cfg.regions},
                {"iterations", cfg.iterations},
                {"in_scale", in_scale},
                {"offset", {fc.offset[0], fc.offset[1]}},
                {"amplitude", {fc.amp[0], fc.amp[1]}},
                {"poly", fc.poly},
                {"fourier_k", cfg.fourier_k},
                {"fourier", fc.fourier},
                {"zero_word", cfg.zero_word},
                {"zero_offset",
                 {{"rad", img.zero_offset},
                  {"deg", img.zero_offset * 180 / M_PI},
                  {"code", img.zero_offset_code()},
                  {"estimated", opt.estimate_zero}}},
                {"fit_error_deg",
                 {{"float", stats_json(out.fit_float)},
                  {"fixed", stats_json(out.fit_fixed)},
                  {"uncorrected", stats_json(out.fit_uncorrected)}}}};
  return out;
}

}  // namespace acore
