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
  // The mode's row: its name, and its legal degree (core/correction_modes.hpp).
  const CorrectionMode& mode = correction_mode(correction);
  if (degree < mode.degree_min || degree > mode.degree_max)
    throw InputError(fmt::format("--degree {}: not in {}..{} (the {} of {})", degree,
                                 mode.degree_min, mode.degree_max,
                                 *mode.degree_word() ? mode.degree_word() : "degree", mode.name));
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
  if (xcenter && regions != 8) throw InputError("--xcenter needs --regions 8");
  if (reference != "theta_ref" && reference != "none")
    throw InputError("--reference " + reference + ": not one of theta_ref, none");
  check_range("--selfcal-harmonics", selfcal_harmonics, 0, 64);
  check_range("--mult", mult, 0, 1);
  if (reference == "none" && zero_offset != "auto")
    throw InputError("--zero-offset: without a reference (--reference none) the zero is unknown");
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
  cfg.mult = a.mult;
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
  out.self = a.reference == "none";
  const FloatCoefficients fc =
      out.self ? self_calibrate(rec, opt, &out.selfcal, a.selfcal_harmonics) : calibrate(rec, opt);
  out.fc = fc;
  // The frame the fit is judged in: theta_ref when given (about the mean after a
  // self-calibration), else the self-calibration's own estimated reference.
  const std::vector<double>& ref = out.self && !rec.has_theta() ? out.selfcal.theta : rec.theta_ref;
  const double in_scale = a.in_scale > 0 ? a.in_scale : choose_in_scale(rec, cfg.in_w);
  out.image = a.coef_frac ? quantize(fc, cfg, in_scale) : quantize_auto_range(fc, cfg, in_scale);
  const RegImage& img = out.image;
  cfg = img.cfg;
  out.image.provenance.push_back("command=" + command);
  out.image.provenance.push_back(fmt::format("periodicity={}", opt.periodicity));
  if (out.self) out.image.provenance.push_back("zero_reference=none");

  // Fit quality on the calibration recording itself, both engines.
  auto judge = [&](const std::vector<double>& angle) {
    return error_stats(judged_error_deg(img, angle, ref, opt.periodicity));
  };
  const AngleSeries fixed = run_fixed(rec, img);
  out.fit_float = judge(run_float(rec, fc).angle);
  out.fit_fixed = judge(fixed.angle);
  out.fit_uncorrected = judge(fixed.uncorrected);
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
                {"mult", cfg.mult},
                {"zero_offset",
                 {{"rad", img.zero_offset},
                  {"deg", img.zero_offset * 180 / M_PI},
                  {"code", img.zero_offset_code()},
                  {"estimated", opt.estimate_zero}}},
                {"fit_error_deg",
                 {{"float", stats_json(out.fit_float)},
                  {"fixed", stats_json(out.fit_fixed)},
                  {"uncorrected", stats_json(out.fit_uncorrected)}}}};
  out.report["reference"] = out.self ? "none" : "theta_ref";
  if (out.self) {
    const SelfCalReport& rep = out.selfcal;
    out.report["zero_reference"] = "none";
    out.report["fit_error_deg"]["about_mean"] = true;
    out.report["fit_error_deg"]["against"] = rec.has_theta() ? "theta_ref" : "estimated_reference";
    out.report["self_calibration"] = {
        {"turns", rep.turns},
        {"uniform_time", rep.uniform_time},
        {"ellipse",
         {{"offset", {rep.ellipse.offset[0], rep.ellipse.offset[1]}},
          {"amplitude", {rep.ellipse.amp[0], rep.ellipse.amp[1]}},
          {"phase_deg", rep.ellipse.delta * 180 / M_PI}}},
        {"speed_profile",
         {{"kind", "legendre_polynomial_in_t"},
          {"order", rep.profile_order},
          {"max_separable_order", rep.max_separable_order},
          {"variation_pct", rep.speed_variation_pct}}},
        {"harmonics", rep.harmonics},
        {"residual_deg", rep.residual_deg},
        {"noise_deg", rep.noise_deg},
        {"error_rms_deg", rep.error_rms_deg},
        {"halves_disagree_deg",
         rep.consistency_deg >= 0 ? nlohmann::json(rep.consistency_deg) : nlohmann::json()},
        {"confidence", rep.confidence},
        {"assumptions", rep.assumptions}};
  }
  return out;
}

}  // namespace acore
