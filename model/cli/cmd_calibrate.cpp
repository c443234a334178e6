// SPDX-License-Identifier: MIT
// `anglecore calibrate`: fit the coefficients on a calibration recording and write the register
// image.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "calibration/calibrate_options.hpp"
#include "cli_util.hpp"
#include "commands.hpp"
#include "core/correction_modes.hpp"
#include "core/errors.hpp"
#include "engine/estimator.hpp"

namespace acore::cli {

namespace {
struct CalibrateArgs {
  std::string in, out, json;
  CalibrateSpec spec;
  int iterations = 16, coef_f = 15;  // taken only when given (spec.iterations, spec.coef_frac)
};

void run_calibrate(const CalibrateArgs& a) {
  const Recording rec = read_recording(a.in);
  const CalibrateOutcome c = calibrate_recording(rec, a.spec, a.in, command_line());
  const RegImage& img = c.image;
  const DatapathConfig& cfg = img.cfg;
  write_regimage(img, a.out);
  std::cout << fmt::format("calibrated {} samples: {} words ({}), in_scale={}\n", rec.size(),
                           cfg.words(), cfg.describe(), img.in_scale);
  std::cout << fmt::format(
      "  zero offset {:+.4f} deg electrical (sensor angle - p theta_ref, {}), {}\n",
      img.zero_offset * 180 / M_PI,
      c.self ? "unknown without a reference: header zero_reference=none"
             : (c.options.estimate_zero ? "estimated" : "given"),
      cfg.zero_word ? fmt::format("in the ZERO word (address {}, code {})", cfg.addr_zero(),
                                  img.zero_position())
                    : "subtracted by `estimate` in software");
  std::cout << fmt::format(
      "  on the calibration recording ({}): uncorrected RMS {:.3f} deg, "
      "corrected RMS {:.3f} (float) {:.3f} (fixed) deg\n",
      !c.self ? "reference frame"
              : (rec.has_theta() ? "theta_ref, about the mean; not used by the fit"
                                 : "against the self-calibration's own reference, about the mean"),
      c.fit_uncorrected.rms, c.fit_float.rms, c.fit_fixed.rms);
  if (c.self) {
    const SelfCalReport& rep = c.selfcal;
    std::cout << fmt::format(
        "  self-calibration: {:.3f} turns, speed profile order {} (of {} separable), {} "
        "harmonics, residual {:.4f} deg (noise {:.4f}), speed variation {:.2f} %, confidence "
        "{:.2f}\n",
        rep.turns, rep.profile_order, rep.max_separable_order, rep.harmonics, rep.residual_deg,
        rep.noise_deg, rep.speed_variation_pct, rep.confidence);
    for (const auto& s : rep.assumptions) std::cout << "    assumed: " << s << "\n";
  }
  write_json(a.json, c.report);
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
  // The modes, their meanings and degree limits: the table's rows (core/correction_modes.hpp).
  std::vector<std::string> names;
  std::string modes_help, degree_help;
  int degree_lo = 1000, degree_hi = 0;
  for (const acore::CorrectionMode& m : acore::correction_modes()) {
    names.emplace_back(m.name);
    modes_help += fmt::format("{}{}: {}", modes_help.empty() ? "" : "; ", m.name, m.meaning);
    if (*m.degree_word())
      degree_help += fmt::format("{}{}: {} {}..{}", degree_help.empty() ? "" : "; ", m.name,
                                 m.degree_word(), m.degree_min, m.degree_max);
    degree_lo = std::min(degree_lo, m.degree_min);
    degree_hi = std::max(degree_hi, m.degree_max);
  }
  c->add_option("--correction", args->spec.correction, modes_help)->check(CLI::IsMember(names));
  c->add_option("--degree", args->spec.degree, "Polynomial degree (" + degree_help + ")")
      ->check(CLI::Range(degree_lo, degree_hi));
  c->add_option("--regions", args->spec.regions, "Correction regions (4 or 8)")
      ->check(CLI::IsMember({4, 8}));
  c->add_flag("--xcenter", args->spec.xcenter,
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
       "--angle-w", args->spec.angle_w,
       "Output angle width: 8..16 (K=16, Z_W=20, REG_W=18), 18 (K=18, Z_W=22, REG_W=20) or 20 "
       "(K=20, Z_W=24, REG_W=22); see docs/datapath.md, CORDIC widths")
      ->check(CLI::Range(8, 20));
  c->add_option("--in-w", args->spec.in_w,
                "Input code width IN_W (default 16; REG_W grows to IN_W + 2 if needed)")
      ->check(CLI::Range(8, 24));
  c->add_option("--in-scale", args->spec.in_scale,
                "Input codes per recording unit (default: automatic power of two)")
      ->check(CLI::PositiveNumber);
  c->add_option("--periodicity", args->spec.periodicity,
                "Electrical periods per turn (default: the recording's # p=)")
      ->check(CLI::Range(1, 64));
  c->add_option(
       "--fourier", args->spec.fourier,
       "Harmonics K of the angle-domain Fourier correction after the CORDIC (default 0: off); "
       "2K+1 more words; with --correction none it corrects the uncorrected angle")
      ->check(CLI::Range(0, 31));
  c->add_option("--fourier-iterations", args->spec.fourier_iterations,
                "Rotation-CORDIC stages per harmonic of the Fourier correction (<= --iterations)")
      ->check(CLI::Range(4, 24));
  c->add_option("--fourier-guard", args->spec.fourier_guard,
                "Guard fraction bits of the Fourier rotations")
      ->check(CLI::Range(0, 8));
  c->add_option(
      "--zero-offset", args->spec.zero_offset,
      "Zero offset (sensor angle - p theta_ref, electrical): 'auto' (default) estimates it as the "
      "circular mean of the uncorrected angle error and fits the correction against the aligned "
      "reference; a number of degrees takes it as given (0: fit against theta_ref itself)");
  c->add_flag(
      "--zero-word", args->spec.zero_word,
      "Store the zero offset in one more register word (RTL ZERO=1, after every other word): the "
      "hardware outputs angle - zero, in the reference frame. Without it the image header records "
      "the offset and `estimate` subtracts it in software");
  c->add_option("--mult", args->spec.mult,
                "Products of the datapath (RTL MULT): 0 adders and shifters, every partial product "
                "floored (default, the paper's minimum); 1 hardware multipliers, the full product "
                "floored once (DSP blocks). The image header records 1; docs/datapath.md")
      ->check(CLI::Range(0, 1));
  c->add_option(
       "--reference", args->spec.reference,
       "theta_ref (default: fit against the recording's reference angle) or none "
       "(self-calibration: the reference is estimated from the recording's own turns and times; "
       "theta_ref, if present, is ignored by the fit; the zero offset is unknown)")
      ->check(CLI::IsMember({"theta_ref", "none"}));
  c->add_option("--selfcal-harmonics", args->spec.selfcal_harmonics,
                "--reference none: harmonics of the error model (default 0: automatic, 16)")
      ->check(CLI::Range(0, 64));
  c->add_option("--json", args->json, "Write results as JSON ('-' for stdout)");
  c->callback([args, c] {
    if (c->count("--coef-frac") > 0) args->spec.coef_frac = args->coef_f;
    if (c->count("--iterations") > 0) args->spec.iterations = args->iterations;
    args->spec.validate();
    run_calibrate(*args);
  });
}

}  // namespace acore::cli
