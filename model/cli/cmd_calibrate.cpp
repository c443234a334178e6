// SPDX-License-Identifier: MIT
// `anglecore calibrate`: fit the coefficients on a calibration recording and write the register image.
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "calibration.hpp"
#include "cli_util.hpp"
#include "commands.hpp"
#include "errors.hpp"
#include "estimator.hpp"

namespace acore::cli {

namespace {
struct CalibrateArgs {
  std::string in, out, json;
  int degree = 3, regions = 4, iterations = 16, coef_f = 15, angle_w = 16, p = 0;
  int fourier = 0, fourier_iterations = DatapathConfig{}.fourier_iterations, fourier_guard = DatapathConfig{}.fourier_guard;
  double in_scale = 0;
  bool coef_f_given = false, fourier_only = false;
};

void run_calibrate(const CalibrateArgs& a) {
  const Recording rec = read_recording(a.in);
  CalOptions opt;
  opt.degree = a.degree;
  opt.regions = a.regions;
  opt.periodicity = a.p ? a.p : recording_periodicity(rec, a.in);
  opt.fourier_k = a.fourier;
  opt.fourier_only = a.fourier_only;
  if (a.fourier_only && a.fourier == 0) throw InputError("calibrate: --fourier-only needs --fourier K (K >= 1)");
  DatapathConfig cfg;
  cfg.fourier_k = a.fourier;
  cfg.fourier_iterations = a.fourier_iterations;
  cfg.fourier_guard = a.fourier_guard;
  cfg.degree = a.degree;
  cfg.regions = a.regions;
  cfg.iterations = a.iterations;
  cfg.coef_f = a.coef_f;
  cfg.angle_w = a.angle_w;
  cfg.z_w = std::max(cfg.z_w, a.angle_w + 4);
  cfg.validate();
  const FloatCoefficients fc = calibrate(rec, opt);
  const double in_scale = a.in_scale > 0 ? a.in_scale : choose_in_scale(rec, cfg.in_w);
  RegImage img = a.coef_f_given ? quantize(fc, cfg, in_scale) : quantize_auto_range(fc, cfg, in_scale);
  cfg = img.cfg;
  std::string fourier_args;
  if (a.fourier > 0)
    fourier_args = fmt::format(" --fourier {} --fourier-iterations {} --fourier-guard {}{}", a.fourier,
                               a.fourier_iterations, a.fourier_guard, a.fourier_only ? " --fourier-only" : "");
  img.provenance.push_back(fmt::format("command=anglecore calibrate --in {} --degree {} --regions {} "
                                       "--iterations {}{}", a.in, a.degree, a.regions, a.iterations, fourier_args));
  img.provenance.push_back(fmt::format("periodicity={}", opt.periodicity));
  write_regimage(img, a.out);

  // Fit quality on the calibration recording itself, both engines.
  const auto ef = angle_error_deg(run_float(rec, fc).angle, rec.theta_ref, opt.periodicity);
  const AngleSeries fixed = run_fixed(rec, img);
  const auto ex = angle_error_deg(fixed.angle, rec.theta_ref, opt.periodicity);
  const auto eu = angle_error_deg(fixed.uncorrected, rec.theta_ref, opt.periodicity);
  const ErrorStats sf = error_stats(ef), sx = error_stats(ex), su = error_stats(eu);
  std::cout << fmt::format("calibrated {} samples: {} words ({}), in_scale={}\n", rec.size(), cfg.words(),
                           cfg.describe(), in_scale);
  std::cout << fmt::format("  on the calibration recording: uncorrected RMS {:.3f} deg, corrected RMS "
                           "{:.3f} (float) {:.3f} (fixed) deg\n", su.rms, sf.rms, sx.rms);
  nlohmann::json j = {{"samples", rec.size()},      {"words", cfg.words()},
                      {"degree", cfg.degree},       {"regions", cfg.regions},
                      {"iterations", cfg.iterations}, {"in_scale", in_scale},
                      {"offset", {fc.offset[0], fc.offset[1]}}, {"amplitude", {fc.amp[0], fc.amp[1]}},
                      {"poly", fc.poly},
                      {"fourier_k", cfg.fourier_k},
                      {"fourier", fc.fourier},
                      {"fit_error_deg", {{"float", stats_json(sf)}, {"fixed", stats_json(sx)},
                                         {"uncorrected", stats_json(su)}}}};
  write_json(a.json, j);
}
}  // namespace

void add_calibrate(CLI::App& app) {
  auto args = std::make_shared<CalibrateArgs>();
  CLI::App* c = app.add_subcommand("calibrate", "Fit and quantize the coefficients into a register image");
  c->add_option("--in", args->in, "Calibration recording (CSV with theta_ref)")->required();
  c->add_option("--out", args->out, "Register image to write ($readmemh)")->required();
  c->add_option("--degree", args->degree, "Polynomial degree n")->check(CLI::Range(1, 7));
  c->add_option("--regions", args->regions, "Correction regions (4 or 8)")->check(CLI::IsMember({4, 8}));
  c->add_option("--iterations", args->iterations, "CORDIC iterations k")->check(CLI::Range(4, 24));
  c->add_option("--coef-frac", args->coef_f, "Fraction bits of a polynomial coefficient (default 15, lowered "
                                             "automatically when a coefficient needs more range)")
      ->check(CLI::Range(1, 17));
  c->add_option("--angle-w", args->angle_w, "Output angle width in bits")->check(CLI::Range(8, 20));
  c->add_option("--in-scale", args->in_scale, "Input codes per recording unit (default: automatic power of two)")
      ->check(CLI::PositiveNumber);
  c->add_option("--periodicity", args->p, "Electrical periods per turn (default: the recording's # p=)")
      ->check(CLI::Range(1, 64));
  c->add_option("--fourier", args->fourier, "Harmonics K of the angle-domain Fourier correction after the CORDIC "
                                            "(default 0: off); 2K+1 more words")
      ->check(CLI::Range(0, 31));
  c->add_option("--fourier-iterations", args->fourier_iterations,
                "Rotation-CORDIC stages per harmonic of the Fourier correction (<= --iterations)")
      ->check(CLI::Range(4, 24));
  c->add_option("--fourier-guard", args->fourier_guard, "Guard fraction bits of the Fourier rotations")
      ->check(CLI::Range(0, 8));
  c->add_flag("--fourier-only", args->fourier_only,
              "Fit no polynomial (its words stay zero: the curves pass unchanged) and only the Fourier correction");
  c->add_option("--json", args->json, "Write results as JSON ('-' for stdout)");
  c->callback([args, c] {
    args->coef_f_given = c->count("--coef-frac") > 0;
    run_calibrate(*args);
  });
}

}  // namespace acore::cli
