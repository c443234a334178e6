// SPDX-License-Identifier: MIT
// `anglecore estimate`: run one engine (float, fixed, rtl, rtl-serial) on a recording and report
// the error, in the reference frame: the image's zero offset is removed by its ZERO word (the
// engine's output already is in that frame) or, without the word, here in software.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <memory>

#include "calibration/calibration.hpp"
#include "cli_util.hpp"
#include "commands.hpp"
#include "core/angle.hpp"
#include "core/datapath_config.hpp"
#include "core/error_stats.hpp"
#include "core/errors.hpp"
#include "engine/estimator.hpp"
#include "engine/track_series.hpp"
#include "rtlsim/run_engine.hpp"

namespace acore::cli {

namespace {
struct EstimateArgs {
  std::string regs, in, engine = "fixed", out, json;
  int p = 0;
  int fold = 1;            // --engine rtl: the build with this FOLD (clocks per sample)
  TrackSettings track;     // --track-bandwidth, --track-lead, --track-lot
  int64_t track_lot = -1;  // --track-lot as given (-1: TRK_LOT's reset value)
};

void write_angles(const std::string& path, const Recording& rec, const AngleSeries& s,
                  const std::vector<double>& err, const TrackedSeries& tr) {
  std::ofstream f(path);
  if (!f) throw InputError(path + ": cannot write angles");
  f << "index,angle_rad,uncorrected_rad,region,flags"
    << (rec.has_theta() ? ",theta_ref,error_deg" : "") << ",turns,angle_comp_rad,lot"
    << (tr.has_rate() ? ",velocity_rpm" : "") << "\n";
  for (size_t i = 0; i < s.angle.size(); ++i) {
    f << fmt::format("{},{:.9f},{:.9f},{},{}", i, s.angle[i], s.uncorrected[i], s.region[i],
                     s.flags[i]);
    if (rec.has_theta()) f << fmt::format(",{:.9f},{:.6f}", rec.theta_ref[i], err[i]);
    f << fmt::format(",{},{:.9f},{}", tr.turns[i], tr.comp[i], tr.lot[i]);
    if (tr.has_rate()) f << fmt::format(",{:.6f}", tr.rpm[i]);
    f << "\n";
  }
  if (!f) throw InputError(path + ": write failed");
}

void run_estimate(const EstimateArgs& a) {
  const Engine engine = parse_engine(a.engine);
  EngineOptions opt;
  opt.fold = a.fold;
  check_engine_options(engine, opt);
  const RegImage img = read_regimage(a.regs);
  const Recording rec = read_recording(a.in);
  const AngleSeries s = run_engine(engine, rec, img, opt).series;
  std::cout << fmt::format("zero offset {:+.4f} deg electrical, removed by {}\n",
                           s.zero_offset * 180 / M_PI,
                           s.zero_word ? "the ZERO word" : "estimate (software)");
  std::vector<double> err;
  const int p = rec.has_theta() || rec.has_t() ? (a.p ? a.p : recording_periodicity(rec, a.in)) : 1;
  const double fs = recording_sample_rate(rec);
  TrackSettings ts = a.track;
  if (a.track_lot >= 0)
    ts.lot_threshold = static_cast<uint32_t>(std::min<int64_t>(a.track_lot, UINT32_MAX));
  TrackedSeries tr;
  try {
    tr = track_series(s.angle, fs, p, img.cfg.angle_w, ts);
  } catch (const InputError& e) {
    // The observer's settings are the command's options; a bandwidth needs the recording's t.
    if (a.track.bandwidth_hz != 0 && !(fs > 0)) throw InputError(a.in + ": " + e.what());
    throw;
  }
  nlohmann::json extra = nlohmann::json::object();  // the fields beyond estimate_json's
  if (fs > 0) {
    extra["track"] = track_json(tr);
    std::cout << fmt::format(
        "tracking observer: code {} = {:.1f} Hz bandwidth at {:.6g} samples/s{}\n", tr.regs.bw,
        extra["track"]["bandwidth_hz"].get<double>(), fs,
        a.track.bandwidth_hz > 0 ? fmt::format(" (nearest to {:.1f} Hz)", a.track.bandwidth_hz)
                                 : "");
  }
  ErrorStats st, su;
  if (rec.has_theta()) {
    err = judged_error_deg(img, s.angle, rec.theta_ref, p);
    st = error_stats(err);
    su = error_stats(judged_error_deg(img, s.uncorrected, rec.theta_ref, p));
    // A self-calibrated image does not know the reference's zero: the errors are about their
    // mean (say so).
    if (img.zero_reference_unknown())
      std::cout << "the image's zero is unknown (zero_reference=none, a self-calibration): "
                   "errors are about their mean\n";
    std::cout << fmt::format(
        "{} engine, {} samples: error RMS {:.4f} deg, max {:.4f} deg, mean {:+.4f} deg "
        "(uncorrected {:.3f} / {:.3f} / {:+.3f})\n",
        engine_name(engine), rec.size(), st.rms, st.max_abs, st.mean, su.rms, su.max_abs, su.mean);
    if (fs > 0) {
      // The velocity error is the estimator's, not the observer's lag: the reference through the
      // same observer (track_velocity_error_rpm).
      const ErrorStats sv = error_stats(track_velocity_error_rpm(tr, rec.theta_ref, p));
      extra["velocity_error_rpm"] = stats_json(sv);
      std::cout << fmt::format("velocity error RMS {:.4f} rpm, max {:.4f} rpm, mean {:+.4f} rpm\n",
                               sv.rms, sv.max_abs, sv.mean);
    }
  } else {
    std::cout << fmt::format("{} engine, {} samples (no theta_ref: no error computed)\n",
                             engine_name(engine), rec.size());
  }
  size_t flagged = 0;
  for (unsigned f : s.flags) flagged += f != 0;
  nlohmann::json j =
      estimate_json(engine, rec.size(), a.fold, img, s.zero_offset, s.zero_word,
                    rec.has_theta() ? &st : nullptr, rec.has_theta() ? &su : nullptr, flagged);
  j.update(extra);
  if (!a.out.empty()) write_angles(a.out, rec, s, err, tr);
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
      ->check(CLI::IsMember(acore::fold_values()));
  c->add_option(
      "--out", args->out,
      "Write per-sample angles (CSV): angle_rad and uncorrected_rad in the reference frame (the "
      "engine's electrical angle minus the image's zero offset, as error_deg compares them)");
  c->add_option("--periodicity", args->p,
                "Electrical periods per turn (default: the recording's # p=)")
      ->check(CLI::Range(1, 64));
  c->add_option("--json", args->json, "Write results as JSON ('-' for stdout)");
  c->add_option("--track-bandwidth", args->track.bandwidth_hz,
                "Tracking observer bandwidth, Hz at the recording's sample rate (from t): the "
                "nearest available setting is used and printed (default: code 6)");
  c->add_option("--track-lead", args->track.lead,
                "Samples the compensated angle (angle_comp_rad) looks ahead: LATENCY + LEAD, "
                "rounded to 1/16 sample (default 0)");
  c->add_option(
       "--track-lot", args->track_lot,
       "Loss-of-tracking threshold, angle LSBs (the TRK_LOT register): the lot column is 1 "
       "where |angle - prediction| exceeds it (default: 4096, 1/16 turn at 16 bits)")
      ->check(CLI::NonNegativeNumber);
  c->callback([args] { run_estimate(*args); });
}

}  // namespace acore::cli
