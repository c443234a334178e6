// SPDX-License-Identifier: MIT
// `anglecore calibrate`: fit the coefficients on a calibration recording and write the register
// image.
#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <memory>

#include "calibration/calibration.hpp"
#include "calibration/self_calibration.hpp"
#include "cli_util.hpp"
#include "commands.hpp"
#include "core/errors.hpp"
#include "engine/estimator.hpp"

namespace acore::cli {

namespace {
struct CalibrateArgs {
  std::string in, out, json, correction = "poly", zero_offset = "auto", reference = "theta_ref";
  int selfcal_harmonics = 0;
  int degree = 3, regions = 4, iterations = 16, coef_f = 15, angle_w = 16, in_w = 16, p = 0;
  int fourier = 0, fourier_iterations = DatapathConfig{}.fourier_iterations;
  int fourier_guard = DatapathConfig{}.fourier_guard;
  double in_scale = 0;
  bool coef_f_given = false, iterations_given = false, xcenter = false, zero_word = false;
};

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

void run_calibrate(const CalibrateArgs& a) {
  const Recording rec = read_recording(a.in);
  CalOptions opt;
  opt.correction = parse_correction(a.correction);
  opt.degree = a.degree;
  opt.regions = a.regions;
  opt.xcenter = a.xcenter ? 1 : 0;
  opt.periodicity = a.p ? a.p : recording_periodicity(rec, a.in);
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
  if (a.iterations_given) cfg.iterations = a.iterations;
  // A wider input needs wider offset words (REG_W >= IN_W + 2); the coefficients keep Q3.x.
  cfg.in_w = a.in_w;
  if (const int grow = cfg.in_w + 2 - cfg.reg_w; grow > 0) {
    cfg.reg_w += grow;
    cfg.coef_f += grow;
  }
  if (a.coef_f_given) {
    cfg.acc_guard += cfg.coef_f - a.coef_f;  // the accumulator keeps its fraction bits
    cfg.coef_f = a.coef_f;
    cfg.acc_int = std::max(cfg.acc_int, cfg.reg_w - cfg.coef_f + 1);
  }
  cfg.validate();
  const bool self = a.reference == "none";
  if (self && a.zero_offset != "auto")
    throw InputError("--zero-offset: without a reference (--reference none) the zero is unknown");
  SelfCalReport rep;
  const FloatCoefficients fc =
      self ? self_calibrate(rec, opt, &rep, a.selfcal_harmonics) : calibrate(rec, opt);
  // The frame the fit is judged in: theta_ref when given (about the mean after a
  // self-calibration), else the self-calibration's own estimated reference.
  Recording judged = rec;
  if (self && !rec.has_theta()) judged.theta_ref = rep.theta;
  const bool about_mean = self;
  const double in_scale = a.in_scale > 0 ? a.in_scale : choose_in_scale(rec, cfg.in_w);
  RegImage img =
      a.coef_f_given ? quantize(fc, cfg, in_scale) : quantize_auto_range(fc, cfg, in_scale);
  cfg = img.cfg;
  img.provenance.push_back("command=" + command_line());
  img.provenance.push_back(fmt::format("periodicity={}", opt.periodicity));
  if (self) img.provenance.push_back("zero_reference=none");
  write_regimage(img, a.out);

  // Fit quality on the calibration recording itself, both engines.
  auto judge = [&](const std::vector<double>& angle) {
    const auto e = angle_error_deg(angle, judged.theta_ref, opt.periodicity);
    return error_stats(about_mean ? about_mean_deg(e) : e);
  };
  const AngleSeries fixed = run_fixed(rec, img);
  const ErrorStats sf = judge(run_float(rec, fc).angle), sx = judge(fixed.angle),
                   su = judge(fixed.uncorrected);
  std::cout << fmt::format("calibrated {} samples: {} words ({}), in_scale={}\n", rec.size(),
                           cfg.words(), cfg.describe(), in_scale);
  std::cout << fmt::format(
      "  zero offset {:+.4f} deg electrical (sensor angle - p theta_ref, {}), {}\n",
      img.zero_offset * 180 / M_PI,
      self ? "unknown without a reference: header zero_reference=none"
           : (opt.estimate_zero ? "estimated" : "given"),
      cfg.zero_word ? fmt::format("in the ZERO word (address {}, code {})", cfg.addr_zero(),
                                  img.zero_position())
                    : "subtracted by `estimate` in software");
  std::cout << fmt::format(
      "  on the calibration recording ({}): uncorrected RMS {:.3f} deg, "
      "corrected RMS {:.3f} (float) {:.3f} (fixed) deg\n",
      !self ? "reference frame"
            : (rec.has_theta() ? "theta_ref, about the mean; not used by the fit"
                               : "against the self-calibration's own reference, about the mean"),
      su.rms, sf.rms, sx.rms);
  if (self) {
    std::cout << fmt::format(
        "  self-calibration: {:.3f} turns, speed profile order {} (of {} separable), {} "
        "harmonics, residual {:.4f} deg (noise {:.4f}), speed variation {:.2f} %, confidence "
        "{:.2f}\n",
        rep.turns, rep.profile_order, rep.max_separable_order, rep.harmonics, rep.residual_deg,
        rep.noise_deg, rep.speed_variation_pct, rep.confidence);
    for (const auto& s : rep.assumptions) std::cout << "    assumed: " << s << "\n";
  }
  nlohmann::json j = {
      {"samples", rec.size()},
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
       {{"float", stats_json(sf)}, {"fixed", stats_json(sx)}, {"uncorrected", stats_json(su)}}}};
  j["reference"] = self ? "none" : "theta_ref";
  if (self) {
    j["zero_reference"] = "none";
    j["fit_error_deg"]["about_mean"] = true;
    j["fit_error_deg"]["against"] = rec.has_theta() ? "theta_ref" : "estimated_reference";
    j["self_calibration"] = {
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
  write_json(a.json, j);
}
}  // namespace

void add_calibrate(CLI::App& app) {
  auto args = std::make_shared<CalibrateArgs>();
  CLI::App* c =
      app.add_subcommand("calibrate", "Fit and quantize the coefficients into a register image");
  c->add_option("--in", args->in,
                "Calibration recording (CSV with theta_ref; with --reference none: t or equally "
                "spaced samples)")
      ->required();
  c->add_option("--out", args->out, "Register image to write ($readmemh)")->required();
  c->add_option(
       "--correction", args->correction,
       "poly (1-D in x, the paper's), poly2d (2-D in x and the other curve), none (no correction)")
      ->check(CLI::IsMember({"poly", "poly2d", "none"}));
  c->add_option("--degree", args->degree,
                "Polynomial degree n (poly: 1..7; poly2d: total degree 1..3)")
      ->check(CLI::Range(1, 7));
  c->add_option("--regions", args->regions, "Correction regions (4 or 8)")
      ->check(CLI::IsMember({4, 8}));
  c->add_flag("--xcenter", args->xcenter,
              "8 regions: fit in u = 2 (x -+ 3/8), centred in its half region (keeps high-degree "
              "coefficients in range, so COEF_F stays 15)");
  c->add_option("--iterations", args->iterations,
                "CORDIC iterations k (default: the --angle-w preset's)")
      ->check(CLI::Range(4, 24));
  c->add_option("--coef-frac", args->coef_f,
                "Fraction bits of a polynomial coefficient (default 15, lowered "
                "automatically when a coefficient needs more range)")
      ->check(CLI::Range(1, 17));
  c->add_option(
       "--angle-w", args->angle_w,
       "Output angle width: 8..16 (K=16, Z_W=20, REG_W=18), 18 (K=18, Z_W=22, REG_W=20) or 20 "
       "(K=20, Z_W=24, REG_W=22); see docs/datapath.md, CORDIC widths")
      ->check(CLI::Range(8, 20));
  c->add_option("--in-w", args->in_w,
                "Input code width IN_W (default 16; REG_W grows to IN_W + 2 if needed)")
      ->check(CLI::Range(8, 24));
  c->add_option("--in-scale", args->in_scale,
                "Input codes per recording unit (default: automatic power of two)")
      ->check(CLI::PositiveNumber);
  c->add_option("--periodicity", args->p,
                "Electrical periods per turn (default: the recording's # p=)")
      ->check(CLI::Range(1, 64));
  c->add_option(
       "--fourier", args->fourier,
       "Harmonics K of the angle-domain Fourier correction after the CORDIC (default 0: off); "
       "2K+1 more words; with --correction none it corrects the uncorrected angle")
      ->check(CLI::Range(0, 31));
  c->add_option("--fourier-iterations", args->fourier_iterations,
                "Rotation-CORDIC stages per harmonic of the Fourier correction (<= --iterations)")
      ->check(CLI::Range(4, 24));
  c->add_option("--fourier-guard", args->fourier_guard,
                "Guard fraction bits of the Fourier rotations")
      ->check(CLI::Range(0, 8));
  c->add_option(
      "--zero-offset", args->zero_offset,
      "Zero offset (sensor angle - p theta_ref, electrical): 'auto' (default) estimates it as the "
      "circular mean of the uncorrected angle error and fits the correction against the aligned "
      "reference; a number of degrees takes it as given (0: fit against theta_ref itself)");
  c->add_flag(
      "--zero-word", args->zero_word,
      "Store the zero offset in one more register word (RTL ZERO=1, after every other word): the "
      "hardware outputs angle - zero, in the reference frame. Without it the image header records "
      "the offset and `estimate` subtracts it in software");
  c->add_option(
       "--reference", args->reference,
       "theta_ref (default: fit against the recording's reference angle) or none "
       "(self-calibration: the reference is estimated from the recording's own turns and times; "
       "theta_ref, if present, is ignored by the fit; the zero offset is unknown)")
      ->check(CLI::IsMember({"theta_ref", "none"}));
  c->add_option("--selfcal-harmonics", args->selfcal_harmonics,
                "--reference none: harmonics of the error model (default 0: automatic, 16)")
      ->check(CLI::Range(0, 64));
  c->add_option("--json", args->json, "Write results as JSON ('-' for stdout)");
  c->callback([args, c] {
    args->coef_f_given = c->count("--coef-frac") > 0;
    args->iterations_given = c->count("--iterations") > 0;
    if (args->correction == "poly2d" && args->degree > 3)
      throw InputError(
          fmt::format("--degree {}: poly2d takes a total degree of 1..3", args->degree));
    if (args->xcenter && args->regions != 8) throw InputError("--xcenter needs --regions 8");
    run_calibrate(*args);
  });
}

}  // namespace acore::cli
