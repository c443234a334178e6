// SPDX-License-Identifier: MIT
// `anglecore estimate`: run one engine (float, fixed, rtl, rtl-serial) on a recording and report
// the error, in the reference frame: the image's zero offset is removed by its ZERO word (the
// engine's output already is in that frame) or, without the word, here in software.
#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>

#include "calibration/calibration.hpp"
#include "cli_util.hpp"
#include "commands.hpp"
#include "core/errors.hpp"
#include "engine/estimator.hpp"
#ifdef ACORE_WITH_RTL
#include "rtl_engine.hpp"
#endif

namespace acore::cli {

namespace {
struct EstimateArgs {
  std::string regs, in, engine = "fixed", out, json;
  int p = 0;
  int fold = 1;  // --engine rtl: the build with this FOLD (clocks per sample)
};

void write_angles(const std::string& path, const Recording& rec, const AngleSeries& s,
                  const std::vector<double>& err) {
  std::ofstream f(path);
  if (!f) throw InputError(path + ": cannot write angles");
  f << "index,angle_rad,uncorrected_rad,region,flags"
    << (rec.has_theta() ? ",theta_ref,error_deg" : "") << "\n";
  for (size_t i = 0; i < s.angle.size(); ++i) {
    f << fmt::format("{},{:.9f},{:.9f},{},{}", i, s.angle[i], s.uncorrected[i], s.region[i],
                     s.flags[i]);
    if (rec.has_theta()) f << fmt::format(",{:.9f},{:.6f}", rec.theta_ref[i], err[i]);
    f << "\n";
  }
  if (!f) throw InputError(path + ": write failed");
}

void run_estimate(const EstimateArgs& a) {
  const Engine engine = parse_engine(a.engine);
  if (a.fold != 1 && engine != Engine::Rtl) throw InputError("--fold applies to --engine rtl only");
  const RegImage img = read_regimage(a.regs);
  const Recording rec = read_recording(a.in);
  AngleSeries s;
  switch (engine) {
    case Engine::Float:
      s = run_float(rec, dequantize(img));
      break;
    case Engine::Fixed:
      s = run_fixed(rec, img);
      break;
    case Engine::Rtl:
    case Engine::RtlSerial:
#ifdef ACORE_WITH_RTL
    {
      const auto codes = to_codes(rec, img.in_scale, img.cfg.in_w);
      RtlRunOptions opt;
      opt.fold = a.fold;
      opt.top = engine == Engine::Rtl ? RtlTop::kPipelined : RtlTop::kSerial;
      const auto rows = run_rtl(img, codes, opt);
      s = series_from_fixed(rows, img);
      // The RTL has no uncorrected output: take it from the bit-accurate model (same front end).
      s.uncorrected = run_fixed(rec, img).uncorrected;
      break;
    }
#else
      throw InputError(std::string("--engine ") + engine_name(engine) +
                       ": this anglecore was built without the RTL (ACORE_WITH_RTL=OFF)");
#endif
  }
  nlohmann::json j = {{"engine", engine_name(engine)}, {"samples", rec.size()}};
  if (engine == Engine::Rtl) j["fold"] = a.fold;
  j["zero_offset"] = {{"rad", s.zero_offset},
                      {"deg", s.zero_offset * 180 / M_PI},
                      {"code", angle_code(s.zero_offset, img.cfg.angle_w)},
                      {"applied_by", s.zero_word ? "zero_word" : "software"}};
  std::cout << fmt::format("zero offset {:+.4f} deg electrical, removed by {}\n",
                           s.zero_offset * 180 / M_PI,
                           s.zero_word ? "the ZERO word" : "estimate (software)");
  std::vector<double> err;
  if (rec.has_theta()) {
    const int p = a.p ? a.p : recording_periodicity(rec, a.in);
    err = angle_error_deg(s.angle, rec.theta_ref, p);
    // A self-calibrated image does not know the reference's zero: judge the errors about their
    // mean (and say so).
    const bool about_mean = img.zero_reference_unknown();
    if (about_mean) err = about_mean_deg(err);
    const auto eu = angle_error_deg(s.uncorrected, rec.theta_ref, p);
    const ErrorStats st = error_stats(err);
    const ErrorStats su = error_stats(about_mean ? about_mean_deg(eu) : eu);
    j["about_mean"] = about_mean;
    if (about_mean)
      std::cout << "the image's zero is unknown (zero_reference=none, a self-calibration): "
                   "errors are about their mean\n";
    j["error_deg"] = stats_json(st);
    j["uncorrected_error_deg"] = stats_json(su);
    std::cout << fmt::format(
        "{} engine, {} samples: error RMS {:.4f} deg, max {:.4f} deg, mean {:+.4f} deg "
        "(uncorrected {:.3f} / {:.3f} / {:+.3f})\n",
        engine_name(engine), rec.size(), st.rms, st.max_abs, st.mean, su.rms, su.max_abs, su.mean);
  } else {
    std::cout << fmt::format("{} engine, {} samples (no theta_ref: no error computed)\n",
                             engine_name(engine), rec.size());
  }
  size_t flagged = 0;
  for (unsigned f : s.flags) flagged += f != 0;
  j["flagged_samples"] = flagged;
  if (!a.out.empty()) write_angles(a.out, rec, s, err);
  write_json(a.json, j);
}
}  // namespace

void add_estimate(CLI::App& app) {
  auto args = std::make_shared<EstimateArgs>();
  CLI::App* c =
      app.add_subcommand("estimate", "Run the estimator on a recording and report the angle error");
  c->add_option("--regs", args->regs, "Register image from `calibrate`")->required();
  c->add_option("--in", args->in, "Recording to estimate (CSV)")->required();
  c->add_option("--engine", args->engine,
                "float | fixed | rtl (pipelined top) | rtl-serial (serial core) (default fixed)");
  c->add_option(
       "--fold", args->fold,
       "--engine rtl: the build folded to this many clocks per sample (rtl/configs.txt; the "
       "register image does not depend on it; default 1)")
      ->check(CLI::IsMember({1, 2, 4, 8}));
  c->add_option(
      "--out", args->out,
      "Write per-sample angles (CSV): angle_rad and uncorrected_rad in the reference frame (the "
      "engine's electrical angle minus the image's zero offset, as error_deg compares them)");
  c->add_option("--periodicity", args->p,
                "Electrical periods per turn (default: the recording's # p=)")
      ->check(CLI::Range(1, 64));
  c->add_option("--json", args->json, "Write results as JSON ('-' for stdout)");
  c->callback([args] { run_estimate(*args); });
}

}  // namespace acore::cli
