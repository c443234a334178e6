// SPDX-License-Identifier: MIT
// `anglecore estimate`: run one engine (float, fixed, rtl, rtl-serial) on a recording and report
// the error, in the reference frame: the image's zero offset is removed by its ZERO word (the
// engine's output already is in that frame) or, without the word, here in software.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>

#include "calibration/calibration.hpp"
#include "cli_util.hpp"
#include "commands.hpp"
#include "core/angle.hpp"
#include "core/error_stats.hpp"
#include "core/errors.hpp"
#include "engine/estimator.hpp"
#include "rtlsim/run_engine.hpp"
#include "stages/tracker.hpp"

namespace acore::cli {

namespace {
struct EstimateArgs {
  std::string regs, in, engine = "fixed", out, json;
  int p = 0;
  int fold = 1;                // --engine rtl: the build with this FOLD (clocks per sample)
  double track_bandwidth = 0;  // Hz; 0: the observer's default code
  double track_lead = 0;       // samples the compensated angle looks ahead
};

// The tracking observer (stages/tracker.hpp) over the estimated angles: velocity in mechanical rpm
// (needs the sample rate, from t), the turn count, the compensated angle.
struct Tracked {
  bool has_rate = false;
  double sample_rate = 0;      // samples per second (from t)
  int code = 0;                // bandwidth code used
  std::vector<double> rpm;     // mechanical rpm (with has_rate)
  std::vector<int64_t> turns;  // signed count of electrical turns, 0 at the first sample
  std::vector<double> comp;    // compensated angle, rad [0, 2 pi)
  std::vector<unsigned> lot;   // loss of tracking
};

// The mean sample rate of the recording's t column (0 when absent or not increasing).
double sample_rate_of(const Recording& rec) {
  if (!rec.has_t() || rec.size() < 2) return 0;
  const double span = rec.t.back() - rec.t.front();
  return span > 0 ? static_cast<double>(rec.size() - 1) / span : 0;
}

TrackConfig track_config(int angle_w) {
  TrackConfig c;
  c.angle_w = angle_w;
  c.frac_w = std::min(c.frac_w, 48 - angle_w);
  return c;
}

// --track-lead in samples as LATENCY (whole samples) + LEAD (lead_f fraction bits), rounded.
void set_lead(double lead, TrackConfig& c, TrackRegs& r) {
  if (!(lead >= 0 && lead <= 255 + 15.9375))
    throw InputError("--track-lead must be 0..270.9375 samples (is " + std::to_string(lead) + ")");
  const long q = std::lround(lead * (1 << c.lead_f));
  c.comp_latency = static_cast<int>(q >> c.lead_f);
  r.lead = static_cast<uint32_t>(q & ((1 << c.lead_f) - 1));
}

Tracked track_series(const std::vector<double>& angle, double fs, int p, int angle_w,
                     const EstimateArgs& a) {
  TrackConfig c = track_config(angle_w);
  TrackRegs r;
  if (a.track_bandwidth != 0) r.bw = track_code_for_bandwidth(a.track_bandwidth, fs, c);
  set_lead(a.track_lead, c, r);
  std::vector<uint32_t> codes(angle.size());
  for (size_t i = 0; i < angle.size(); ++i) codes[i] = angle_code(angle[i], angle_w);
  const auto out = track_codes(codes, c, r);
  Tracked t;
  t.has_rate = fs > 0;
  t.sample_rate = fs;
  t.code = r.bw;
  for (const auto& o : out) {
    if (t.has_rate) t.rpm.push_back(track_velocity_turns(o.velocity, c) * fs * 60 / p);
    t.turns.push_back(o.turns);
    t.comp.push_back(std::ldexp(static_cast<double>(o.angle_comp), -angle_w) * 2 * M_PI);
    t.lot.push_back(o.lot);
  }
  return t;
}

void write_angles(const std::string& path, const Recording& rec, const AngleSeries& s,
                  const std::vector<double>& err, const Tracked& tr) {
  std::ofstream f(path);
  if (!f) throw InputError(path + ": cannot write angles");
  f << "index,angle_rad,uncorrected_rad,region,flags"
    << (rec.has_theta() ? ",theta_ref,error_deg" : "") << ",turns,angle_comp_rad,lot"
    << (tr.has_rate ? ",velocity_rpm" : "") << "\n";
  for (size_t i = 0; i < s.angle.size(); ++i) {
    f << fmt::format("{},{:.9f},{:.9f},{},{}", i, s.angle[i], s.uncorrected[i], s.region[i],
                     s.flags[i]);
    if (rec.has_theta()) f << fmt::format(",{:.9f},{:.6f}", rec.theta_ref[i], err[i]);
    f << fmt::format(",{},{:.9f},{}", tr.turns[i], tr.comp[i], tr.lot[i]);
    if (tr.has_rate) f << fmt::format(",{:.6f}", tr.rpm[i]);
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
  const double fs = sample_rate_of(rec);
  if (a.track_bandwidth != 0 && !(fs > 0))
    throw InputError(a.in + ": --track-bandwidth needs the recording's t column (increasing)");
  const Tracked tr = track_series(s.angle, fs, p, img.cfg.angle_w, a);
  nlohmann::json extra = nlohmann::json::object();  // the fields beyond estimate_json's
  if (fs > 0) {
    const double bw = track_bandwidth_hz(tr.code, fs);
    std::cout << fmt::format(
        "tracking observer: code {} = {:.1f} Hz bandwidth at {:.6g} samples/s{}\n", tr.code, bw, fs,
        a.track_bandwidth > 0 ? fmt::format(" (nearest to {:.1f} Hz)", a.track_bandwidth) : "");
    extra["track"] = {{"code", tr.code}, {"bandwidth_hz", bw}, {"sample_rate_hz", fs}};
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
      // The reference angle (mechanical, unwrapped) as the electrical angle through the same
      // observer: the velocity error is the estimator's, not the observer's lag.
      std::vector<double> ref(rec.size());
      for (size_t i = 0; i < rec.size(); ++i) ref[i] = p * rec.theta_ref[i];
      const Tracked tref = track_series(ref, fs, p, img.cfg.angle_w, a);
      std::vector<double> dv(rec.size());
      for (size_t i = 0; i < rec.size(); ++i) dv[i] = tr.rpm[i] - tref.rpm[i];
      const ErrorStats sv = error_stats(dv);
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
      ->check(CLI::IsMember({1, 2, 4, 8}));
  c->add_option(
      "--out", args->out,
      "Write per-sample angles (CSV): angle_rad and uncorrected_rad in the reference frame (the "
      "engine's electrical angle minus the image's zero offset, as error_deg compares them)");
  c->add_option("--periodicity", args->p,
                "Electrical periods per turn (default: the recording's # p=)")
      ->check(CLI::Range(1, 64));
  c->add_option("--json", args->json, "Write results as JSON ('-' for stdout)");
  c->add_option("--track-bandwidth", args->track_bandwidth,
                "Tracking observer bandwidth, Hz at the recording's sample rate (from t): the "
                "nearest available setting is used and printed (default: code 6)");
  c->add_option("--track-lead", args->track_lead,
                "Samples the compensated angle (angle_comp_rad) looks ahead: LATENCY + LEAD, "
                "rounded to 1/16 sample (default 0)");
  c->callback([args] { run_estimate(*args); });
}

}  // namespace acore::cli
