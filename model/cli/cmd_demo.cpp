// SPDX-License-Identifier: MIT
// `anglecore demo`: the main job on the built-in paper scenario. Simulate a calibration and a
// validation recording (different seeds), calibrate, run the float, bit-accurate and RTL engines on
// the validation recording, print the paper's Table 3 beside ours, and write a report with plots.
// run_demo() is the sequence of named steps below; every engine runs through run_engine().
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <utility>

#include "calibration/calibration.hpp"
#include "cli_util.hpp"
#include "commands.hpp"
#include "core/errors.hpp"
#include "diagnose/noise_floor.hpp"
#include "engine/estimator.hpp"
#include "engine/float_model.hpp"
#include "engine/track_series.hpp"
#include "rtlsim/run_engine.hpp"
#include "sim/simulator.hpp"
#include "sweep/design_space.hpp"

namespace acore::cli {

namespace {

struct DemoArgs {
  std::string out = "out/demo", json;
  size_t samples = 4096;
  uint64_t seed_cal = 1, seed_val = 2;
  bool no_rtl = false, no_plots = false, no_sweep = false;
};

struct Row {
  std::string name;
  ErrorStats s;
};

std::string row_md(const std::string& name, double rms, double max, double mean,
                   const std::string& note = "") {
  return fmt::format("| {} | {:.2f} | {:.2f} | {:+.2f} | {} |\n", name, rms, max, mean, note);
}

// Calibrate on `cal`, run float and fixed on `val`, return the error series.
struct ChainRun {
  FloatCoefficients fc;
  RegImage img;
  AngleSeries fl, fx;
  std::vector<double> e_unc, e_raw, e_fl,
      e_fx;  // e_raw: uncorrected without the zero offset removed
};

ChainRun run_chain(const Recording& cal, const Recording& val, CalOptions opt, DatapathConfig cfg) {
  ChainRun r;
  r.fc = calibrate(cal, opt);
  const double in_scale = choose_in_scale(cal, cfg.in_w);
  // Higher degrees can need a wider coefficient range (COEF_F stepped down).
  r.img = quantize_auto_range(r.fc, cfg, in_scale);
  // The float row runs the calibration's own coefficients, not the image's dequantized ones.
  EngineOptions unquantized;
  unquantized.float_coefficients = r.fc;
  r.fl = run_engine(Engine::Float, val, r.img, unquantized).series;
  r.fx = run_engine(Engine::Fixed, val, r.img).series;
  r.e_unc = angle_error_deg(r.fx.uncorrected, val.theta_ref);
  r.e_raw = r.e_unc;
  for (double& e : r.e_raw) e = wrap_deg(e + r.fx.zero_offset * 180 / M_PI);
  r.e_fl = angle_error_deg(r.fl.angle, val.theta_ref);
  r.e_fx = angle_error_deg(r.fx.angle, val.theta_ref);
  return r;
}

double max_diff_deg(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0;
  for (size_t i = 0; i < a.size(); ++i)
    m = std::max(m, std::fabs(wrap_deg((a[i] - b[i]) * 180.0 / M_PI)));
  return m;
}

// What every step adds to: the report's Markdown and its JSON summary.
struct Report {
  std::ostringstream md;
  nlohmann::json js;
};

// The paper's point (cubic, 4 regions, 16 CORDIC iterations, 52 words) and Table 3's rows.
struct PaperPoint {
  Recording cal, val;
  ChainRun run;
  std::vector<Row> rows;
  std::vector<double> e_rtl;  // per sample, when the RTL ran
  bool rtl_ran = false;
  double fx_vs_fl = 0;  // bit-accurate vs float, max |difference|, degrees
};

void print_header(const DemoArgs& a) {
  std::cout << fmt::format(
      "AngleCore demo: paper scenario (docs/contracts.md), {} samples per "
      "recording, "
      "calibration seed {}, validation seed {}\n\n",
      a.samples, a.seed_cal, a.seed_val);
}

// Simulates the calibration and validation recordings, calibrates, writes both recordings and the
// register image, and runs the float and bit-accurate rows (and Eq. 6 as printed).
PaperPoint paper_point(const DemoArgs& a) {
  namespace fs = std::filesystem;
  PaperPoint p;
  const Scenario paper = builtin_scenario("paper");
  p.cal = simulate(paper, a.samples, a.seed_cal);
  p.val = simulate(paper, a.samples, a.seed_val);
  write_recording(p.cal, (fs::path(a.out) / "calibration.csv").string());
  write_recording(p.val, (fs::path(a.out) / "validation.csv").string());
  p.run = run_chain(p.cal, p.val, CalOptions{}, DatapathConfig{});
  p.run.img.provenance.push_back("command=" + command_line());
  p.run.img.provenance.push_back(
      fmt::format("calibration=paper scenario, {} samples, seed {}", a.samples, a.seed_cal));
  write_regimage(p.run.img, (fs::path(a.out) / "regs.hex").string());

  // "uncorrected" as the paper reports it: atan2 of the scaled curves against the reference; then
  // with the calibration's zero offset removed (docs/calibration.md "Zero offset").
  p.rows = {{"ours, uncorrected", error_stats(p.run.e_raw)},
            {"ours, zero offset removed only", error_stats(p.run.e_unc)},
            {"ours, corrected, float", error_stats(p.run.e_fl)},
            {"ours, corrected, bit-accurate", error_stats(p.run.e_fx)}};
  // The paper's Eq. 6 as printed: fitted against theta_ref itself (zero offset taken as 0), so the
  // polynomials absorb the constant shift (docs/calibration.md "Zero offset" says why the default
  // aligns first).
  CalOptions as_printed;
  as_printed.estimate_zero = false;
  const ChainRun printed = run_chain(p.cal, p.val, as_printed, DatapathConfig{});
  p.rows.push_back({"ours, bit-accurate, Eq. 6 as printed", error_stats(printed.e_fx)});
  return p;
}

// The RTL rows: the pipelined top and the serial core (226 clocks a sample) on the same image,
// each bit-exact to the same model.
void add_rtl_rows(PaperPoint& p) {
  const std::pair<Engine, const char*> engines[] = {
      {Engine::Rtl, "ours, corrected, RTL (Verilator)"},
      {Engine::RtlSerial, "ours, corrected, serial RTL"}};
  for (const auto& [engine, name] : engines) {
    AngleSeries s;
    try {
      s = run_engine(engine, p.val, p.run.img).series;
    } catch (const RtlNotBuilt& e) {
      throw RtlNotBuilt(std::string(e.what()) + "; or leave the RTL rows out: demo --no-rtl");
    }
    std::vector<double> err = angle_error_deg(s.angle, p.val.theta_ref);
    p.rows.push_back({name, error_stats(err)});
    if (engine == Engine::Rtl) p.e_rtl = std::move(err);
  }
  p.rtl_ran = true;
}

void print_table3(const PaperPoint& p) {
  std::cout
      << "Table 3, paper scenario, validation recording (error = estimate - reference, degrees)\n";
  std::cout << fmt::format("  {:<36} {:>7} {:>7} {:>7}\n", "", "RMS", "max|e|", "mean");
  std::cout << fmt::format("  {:<36} {:7.2f} {:7.2f} {:+7.2f}   (paper prints the opposite sign)\n",
                           "paper, without correction", 9.01, 16.7, 7.18);
  std::cout << fmt::format("  {:<36} {:7.2f} {:7.2f} {:+7.2f}\n", "paper, with correction", 0.76,
                           3.21, 0.00);
  for (const Row& r : p.rows)
    std::cout << fmt::format("  {:<36} {:7.3f} {:7.3f} {:+7.3f}\n", r.name, r.s.rms, r.s.max_abs,
                             r.s.mean);
  std::cout << fmt::format(
      "  bit-accurate vs float: max |difference| {:.4f} deg; register file {} words\n", p.fx_vs_fl,
      p.run.img.cfg.words());
  std::cout << fmt::format(
      "  zero offset (sensor - reference, estimated by the calibration): {:+.3f} deg\n\n",
      p.run.img.zero_offset * 180 / M_PI);
}

void report_table3(const DemoArgs& a, const PaperPoint& p, Report& rep) {
  std::ostringstream& md = rep.md;
  md << "# AngleCore demo report\n\n";
  md << fmt::format(
      "Paper scenario (docs/contracts.md), {} samples per recording; calibration "
      "seed {}, "
      "validation seed {}. Command: `{}`.\n\n",
      a.samples, a.seed_cal, a.seed_val, command_line());
  md << "## Table 3, reproduced and beaten (validation recording)\n\n";
  md << "Error = estimate − reference, wrapped to (−180°, 180°], in degrees.\n\n";
  md << "| chain | RMS | max abs | mean | note |\n|---|---|---|---|---|\n";
  md << row_md("paper, without correction", 9.01, 16.7, 7.18,
               "paper's sign convention is the opposite");
  md << row_md("paper, with correction (cubic, k=16)", 0.76, 3.21, 0.00, "");
  for (const Row& r : p.rows)
    md << row_md(r.name, r.s.rms, r.s.max_abs, r.s.mean,
                 r.name.find("RTL") != std::string::npos ? "same register image" : "");
  md << fmt::format(
      "\nBit-accurate vs float: max |difference| {:.4f}°. Register image: `regs.hex` ({} words: "
      "4 scaling + {} polynomial + {} CORDIC).\n\n",
      p.fx_vs_fl, p.run.img.cfg.words(), p.run.img.cfg.poly_words(), p.run.img.cfg.iterations);
  md << fmt::format(
      "Zero offset estimated by the calibration (circular mean of the uncorrected angle error, "
      "docs/calibration.md \"Zero offset\"): {:+.3f}°; the corrected rows are in the reference "
      "frame (the "
      "offset subtracted), \"uncorrected\" is the paper's (atan2 against the reference).\n\n",
      p.run.img.zero_offset * 180 / M_PI);
  md << "![error vs "
        "angle](error_vs_angle.png)\n\n![Lissajous](lissajous.png)\n\n![histogram](histogram.png)"
        "\n\n";
  for (const Row& r : p.rows) rep.js["table3"][r.name] = stats_json(r.s);
  rep.js["bit_accurate_vs_float_max_deg"] = p.fx_vs_fl;
  rep.js["words"] = p.run.img.cfg.words();
  rep.js["zero_offset_deg"] = p.run.img.zero_offset * 180 / M_PI;
}

// Plot data: per-sample curves and errors of the validation recording.
void write_validation_angles(const DemoArgs& a, const PaperPoint& p) {
  std::ofstream f(std::filesystem::path(a.out) / "validation_angles.csv");
  f << "theta_ref,s13,s24,y13,y24,err_uncorrected,err_float,err_fixed"
    << (p.rtl_ran ? ",err_rtl" : "") << "\n";
  const Recording& val = p.val;
  for (size_t i = 0; i < val.size(); ++i) {
    const FloatSample s = float_estimate(val.d13(i), val.d24(i), p.run.fc);
    f << fmt::format("{:.9f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f}", val.theta_ref[i],
                     s.s13, s.s24, s.y13, s.y24, p.run.e_unc[i], p.run.e_fl[i], p.run.e_fx[i]);
    if (p.rtl_ran) f << fmt::format(",{:.6f}", p.e_rtl[i]);
    f << "\n";
  }
}

// Independent per-channel noise: the corrected error against the Cramér-Rao floor.
void independent_noise(const DemoArgs& a, Report& rep) {
  const Recording icl = simulate(builtin_scenario("paper-indep"), a.samples, a.seed_cal);
  const Recording ival = simulate(builtin_scenario("paper-indep"), a.samples, a.seed_val);
  const Recording clean = simulate(builtin_scenario("paper-noiseless"), a.samples, a.seed_val);
  const double sigma_d = differential_noise_sigma(ival, clean);
  const double floor = crlb_rms_deg(clean, sigma_d);
  const ChainRun ir = run_chain(icl, ival, CalOptions{}, DatapathConfig{});
  const ErrorStats sf = error_stats(ir.e_fl), sx = error_stats(ir.e_fx);
  std::cout << fmt::format(
      "Independent per-channel noise (sigma 0.05 per channel, {:.4f} per difference):\n"
      "  Cramer-Rao floor {:.3f} deg RMS; corrected {:.3f} (float) {:.3f} (bit-accurate) deg "
      "RMS = {:.1f}% above the floor\n\n",
      sigma_d, floor, sf.rms, sx.rms, 100.0 * (sx.rms / floor - 1.0));
  rep.md << "## Independent per-channel noise\n\n";
  rep.md << fmt::format(
      "With independent noise σ = 0.05 on each channel (σ = {:.4f} on each difference) the "
      "Cramér–Rao floor, RMS over the turn of σ/|dv/dθ|, is **{:.3f}°**. Corrected error: "
      "{:.3f}° RMS (float), {:.3f}° RMS (bit-accurate), {:.1f}% above the floor; max "
      "{:.2f}°.\n\n",
      sigma_d, floor, sf.rms, sx.rms, 100.0 * (sx.rms / floor - 1.0), sx.max_abs);
  rep.js["independent_noise"] = {{"sigma_diff", sigma_d},
                                 {"crlb_rms_deg", floor},
                                 {"float", stats_json(sf)},
                                 {"fixed", stats_json(sx)}};
}

// Beyond the paper: degree and regions against register words (noise-free scenario).
void degree_regions(const DemoArgs& a, Report& rep) {
  // Without noise the seed changes nothing: the validation turn is shifted by a fraction of a
  // step so that it measures the correction at angles the calibration never saw.
  const Scenario clean = builtin_scenario("paper-noiseless");
  Scenario clean_val = clean;
  clean_val.trajectory.theta0_rad += 0.6180339887498949 * 2 * M_PI / static_cast<double>(a.samples);
  const Recording ccal = simulate(clean, a.samples, a.seed_cal),
                  cval = simulate(clean_val, a.samples, a.seed_val);
  std::cout << "Beyond the paper: accuracy against register words (noise-free paper scenario, "
               "validation)\n";
  std::cout << fmt::format("  {:>6} {:>7} {:>5} {:>10} {:>10} {:>10} {:>10} {:>6}\n", "degree",
                           "regions", "words", "float RMS", "float max", "fixed RMS", "fixed max",
                           "COEF_F");
  std::ostringstream& md = rep.md;
  md << "## Beyond the paper: degree and regions (noise-free paper scenario)\n\n";
  md << "| degree | regions | words | float RMS ° | float max ° | bit-accurate RMS ° | "
        "bit-accurate max ° | COEF_F |\n";
  md << "|---|---|---|---|---|---|---|---|\n";
  for (int regions : {4, 8})
    for (int degree = 3; degree <= 7; ++degree) {
      CalOptions o;
      o.degree = degree;
      o.regions = regions;
      const ChainRun r = run_chain(ccal, cval, o, DatapathConfig{});
      const ErrorStats sf = error_stats(r.e_fl), sx = error_stats(r.e_fx);
      std::cout << fmt::format(
          "  {:>6} {:>7} {:>5} {:>10.4f} {:>10.4f} {:>10.4f} {:>10.4f} {:>6}\n", degree, regions,
          r.img.cfg.words(), sf.rms, sf.max_abs, sx.rms, sx.max_abs, r.img.cfg.coef_f);
      md << fmt::format("| {} | {} | {} | {:.4f} | {:.4f} | {:.4f} | {:.4f} | {} |\n", degree,
                        regions, r.img.cfg.words(), sf.rms, sf.max_abs, sx.rms, sx.max_abs,
                        r.img.cfg.coef_f);
      rep.js["sweep"].push_back({{"degree", degree},
                                 {"regions", regions},
                                 {"words", r.img.cfg.words()},
                                 {"float", stats_json(sf)},
                                 {"fixed", stats_json(sx)},
                                 {"coef_f", r.img.cfg.coef_f}});
    }
  std::cout << "\n";
  md << "\n";
}

// The other correction modes at their best points (accuracy targets: <= 64 words RMS <= 0.10,
// max <= 0.35; <= 104 words RMS <= 0.01, max <= 0.07). Same path as `anglecore sweep`.
void correction_modes(const DemoArgs& a, Report& rep) {
  const std::vector<std::pair<std::string, std::string>> modes = {
      {"Fourier K=21 after the CORDIC, no polynomial", "CORRECTION=2 FOURIER_K=21"},
      {"2-D cubic, 4 regions", "CORRECTION=1 DEGREE=3"},
      {"2-D cubic, 4 regions, 18-bit input and angle",
       "CORRECTION=1 DEGREE=3 IN_W=18 REG_W=20 COEF_F=17 K=18 CORDIC_G=4 Z_W=22 ANGLE_W=18"},
      {"degree 7, 8 centred regions", "DEGREE=7 REGIONS=8 XCENTER=1"}};
  const auto sc = sweep_scenarios(a.samples, a.samples + 3);
  const std::vector<SweepScenario> paper_only(sc.begin(), sc.begin() + 1);
  std::cout << "Beyond the paper: correction modes (noise-free paper scenario, validation, "
               "bit-accurate)\n";
  std::ostringstream& md = rep.md;
  md << "## Beyond the paper: correction modes (noise-free paper scenario, bit-accurate)\n\n";
  md << "| mode | RTL parameters | words | RMS ° | max ° |\n|---|---|---|---|---|\n";
  for (size_t i = 0; i < modes.size(); ++i) {
    const SweepResult r = evaluate_point(i, modes[i].second, paper_only);
    if (!r.error.empty()) throw CheckFailed("demo: " + modes[i].second + ": " + r.error);
    const ErrorStats& e = r.accuracy.front().fixed;
    std::cout << fmt::format("  {:<46} {:>4} words  RMS {:.4f}  max {:.4f}\n", modes[i].first,
                             r.words, e.rms, e.max_abs);
    md << fmt::format("| {} | `{}` | {} | {:.4f} | {:.4f} |\n", modes[i].first, modes[i].second,
                      r.words, e.rms, e.max_abs);
    rep.js["modes"].push_back({{"mode", modes[i].first},
                               {"params", modes[i].second},
                               {"words", r.words},
                               {"fixed", stats_json(e)}});
  }
  std::cout
      << "  (the whole design space: scripts/design_space.sh, synth/reports/design_space.md)\n\n";
  md << "\nThe whole design space: `scripts/design_space.sh`, "
        "`synth/reports/design_space.md`.\n\n";
}

// The drive outputs: the tracking observer (stages/tracker.hpp, bit for bit rtl/acore_track.v)
// after the bit-accurate engine on the demo's register image, at a drive's sample rate. Two
// measurements, as scripts/track_measure.py makes them at more points:
//   velocity  3000 rpm with a 2 % speed ripple at 40 Hz: the observer's velocity against the
//             profile's own speed (closed form, TrajectoryModel) and against p theta_ref through
//             the same observer (the estimator's share, velocity_error_rpm); velocity.csv for the
//             plot.
//   noise     constant 3000 rpm, independent channel noise: the observer's velocity noise beside a
//             finite difference of the same angles whose -3 dB frequency equals the observer's
//             velocity bandwidth (equal_bandwidth_difference_span); velocity_noise.csv.
struct DriveSetting {
  double fs = 1e6;    // samples per second
  double rpm = 3000;  // mechanical speed
  double ripple = 0.02, ripple_hz = 40;
  size_t ripple_samples = 200000, noise_samples = 300000;
  size_t settle = 50000, noise_settle = 100000;    // samples left out while the loop settles
  double velocity_bw_hz = 200, noise_bw_hz = 900;  // the observer's bandwidth (nearest code)
  size_t plot_step = 50;                           // every plot_step-th sample into the CSV
};

Recording drive_recording(const char* scenario, const Trajectory& tr, size_t n, uint64_t seed) {
  Scenario sc = builtin_scenario(scenario);
  sc.trajectory = tr;
  return simulate(sc, n, seed);
}

void drive_outputs(const DemoArgs& a, const PaperPoint& p, Report& rep) {
  namespace fs = std::filesystem;
  const DriveSetting d;
  const RegImage& img = p.run.img;
  Trajectory rip;
  rip.kind = "ripple";
  rip.sample_rate_hz = d.fs;
  rip.speed_rps = d.rpm / 60;
  rip.ripple = d.ripple;
  rip.ripple_hz = d.ripple_hz;
  const Recording rec = drive_recording("paper", rip, d.ripple_samples, a.seed_val);
  const int per = recording_periodicity(rec, "drive recording");
  const AngleSeries s = run_engine(Engine::Fixed, rec, img).series;
  TrackSettings ts;
  ts.bandwidth_hz = d.velocity_bw_hz;
  const double rate = recording_sample_rate(rec);
  const TrackedSeries tr = track_series(s.angle, rate, per, img.cfg.angle_w, ts);
  const std::vector<double> dv = track_velocity_error_rpm(tr, rec.theta_ref, per);
  const TrajectoryModel model(rip, d.ripple_samples);
  std::vector<double> vs_profile;
  {
    std::ofstream f(fs::path(a.out) / "velocity.csv");
    f << "t_ms,velocity_rpm,reference_rpm,profile_rpm\n";
    for (size_t i = 0; i < rec.size(); ++i) {
      const double profile = model.speed_at(rec.t[i]) * 60;
      if (i >= d.settle) vs_profile.push_back(tr.rpm[i] - profile);
      if (i % d.plot_step == 0)
        f << fmt::format("{:.4f},{:.3f},{:.3f},{:.3f}\n", rec.t[i] * 1e3, tr.rpm[i],
                         tr.rpm[i] - dv[i], profile);
    }
  }
  const ErrorStats sv = error_stats(dv), sp = error_stats(vs_profile);

  Trajectory cst;
  cst.kind = "constant";
  cst.sample_rate_hz = d.fs;
  cst.speed_rps = d.rpm / 60;
  const Recording crec = drive_recording("paper-indep", cst, d.noise_samples, a.seed_val);
  const AngleSeries cs = run_engine(Engine::Fixed, crec, img).series;
  TrackSettings ns;
  ns.bandwidth_hz = d.noise_bw_hz;
  const double crate = recording_sample_rate(crec);
  const TrackedSeries ct = track_series(cs.angle, crate, per, img.cfg.angle_w, ns);
  const int span = equal_bandwidth_difference_span(ct.regs.bw);
  const std::vector<double> fd = finite_difference_rpm(cs.angle, span, crate, per);
  // Both over the same samples after settling (fd[i - span] is the difference ending at i).
  std::vector<double> ob(ct.rpm.begin() + d.noise_settle, ct.rpm.end()),
      fdv(fd.begin() + (d.noise_settle - span), fd.end());
  const ErrorStats so = error_stats(ob), sf = error_stats(fdv);
  const double sd_ob = std::sqrt(std::max(0.0, so.rms * so.rms - so.mean * so.mean)),
               sd_fd = std::sqrt(std::max(0.0, sf.rms * sf.rms - sf.mean * sf.mean));
  {
    std::ofstream f(fs::path(a.out) / "velocity_noise.csv");
    f << "t_ms,observer_rpm,finite_difference_rpm\n";
    for (size_t i = d.noise_settle; i < crec.size(); i += d.plot_step)
      f << fmt::format("{:.4f},{:.3f},{:.3f}\n", crec.t[i] * 1e3, ct.rpm[i], fd[i - span]);
  }
  const nlohmann::json vtrack = track_json(tr), ntrack = track_json(ct);
  std::cout << fmt::format(
      "Drive outputs (tracking observer after the bit-accurate engine, {:.0f} samples/s)\n"
      "  velocity, {:.0f} rpm with a {:.0f}% ripple at {:.0f} Hz, code {} = {:.0f} Hz: error vs "
      "the reference through the observer RMS {:.2f} max {:.2f} rpm; vs the profile's speed RMS "
      "{:.2f} max {:.2f} rpm\n"
      "  velocity noise at constant {:.0f} rpm (independent channel noise), code {} = {:.0f} Hz: "
      "observer {:.2f} rpm RMS, finite difference over {} samples (equal bandwidth) {:.2f} rpm "
      "RMS = {:.2f}x\n\n",
      d.fs, d.rpm, 100 * d.ripple, d.ripple_hz, tr.regs.bw, vtrack["bandwidth_hz"].get<double>(),
      sv.rms, sv.max_abs, sp.rms, sp.max_abs, d.rpm, ct.regs.bw,
      ntrack["bandwidth_hz"].get<double>(), sd_ob, span, sd_fd, sd_fd / sd_ob);
  rep.md << "## Drive outputs: velocity and its noise\n\n";
  rep.md << fmt::format(
      "The tracking observer (bit for bit `rtl/acore_track.v`) after the bit-accurate engine on "
      "this register image, at {:.0f} samples/s (`anglecore estimate --track-bandwidth HZ --out`; "
      "more points in docs/reports/track_measure.md).\n\n",
      d.fs);
  rep.md << "| measurement | observer | against | RMS rpm | max rpm | mean rpm |\n"
            "|---|---|---|---|---|---|\n";
  const std::string ripple_name =
      fmt::format("{:.0f} rpm, {:.0f}% ripple at {:.0f} Hz", d.rpm, 100 * d.ripple, d.ripple_hz);
  const std::string code =
      fmt::format("code {} ({:.0f} Hz)", tr.regs.bw, vtrack["bandwidth_hz"].get<double>());
  rep.md << fmt::format(
      "| {} | {} | p·theta_ref through the observer | {:.2f} | {:.2f} | {:+.3f} |\n", ripple_name,
      code, sv.rms, sv.max_abs, sv.mean);
  rep.md << fmt::format(
      "| {} | {} | the profile's speed (after {} ms) | {:.2f} | {:.2f} | {:+.3f} |\n\n",
      ripple_name, code, d.settle / d.fs * 1e3, sp.rms, sp.max_abs, sp.mean);
  rep.md << fmt::format(
      "Velocity noise at a constant {:.0f} rpm with independent channel noise (paper-indep): the "
      "observer at code {} ({:.0f} Hz) **{:.2f} rpm** RMS about the mean, a finite difference of "
      "the same angles over {} samples (the same −3 dB frequency as the observer's velocity) "
      "**{:.2f} rpm**: {:.2f}× the observer's.\n\n",
      d.rpm, ct.regs.bw, ntrack["bandwidth_hz"].get<double>(), sd_ob, span, sd_fd, sd_fd / sd_ob);
  rep.md << "![velocity](velocity.png)\n\n";
  rep.js["drive"] = {
      {"sample_rate_hz", d.fs},
      {"velocity",
       {{"profile",
         {{"kind", "ripple"}, {"rpm", d.rpm}, {"ripple", d.ripple}, {"ripple_hz", d.ripple_hz}}},
        {"samples", d.ripple_samples},
        {"track", vtrack},
        {"velocity_error_rpm", stats_json(sv)},
        {"vs_profile_rpm", stats_json(sp)},
        {"settle_samples", d.settle}}},
      {"noise",
       {{"rpm", d.rpm},
        {"scenario", "paper-indep"},
        {"samples", d.noise_samples},
        {"track", ntrack},
        {"observer_rms_rpm", sd_ob},
        {"finite_difference_span", span},
        {"finite_difference_rms_rpm", sd_fd},
        {"ratio", sd_fd / sd_ob},
        {"settle_samples", d.noise_settle}}}};
}

// Plots (Debian's matplotlib through /usr/bin/python3), then report.md and summary.json.
void write_report(const DemoArgs& a, Report& rep) {
  namespace fs = std::filesystem;
  std::string plot_note;
  if (!a.no_plots) {
    const fs::path script = fs::path(ACORE_SOURCE_DIR) / "scripts" / "plot_demo.py";
    const std::string cmd = fmt::format("/usr/bin/python3 '{}' '{}'", script.string(), a.out);
    if (std::system(cmd.c_str()) != 0)
      plot_note = "plots skipped: /usr/bin/python3 with matplotlib failed";
  } else {
    plot_note = "plots skipped (--no-plots)";
  }
  if (!plot_note.empty()) {
    std::cout << plot_note << "\n";
    rep.md << "_" << plot_note << "_\n";
  }
  {
    std::ofstream f(fs::path(a.out) / "report.md");
    f << rep.md.str();
  }
  write_json((fs::path(a.out) / "summary.json").string(), rep.js);
  write_json(a.json, rep.js);
  std::cout << fmt::format(
      "Report: {}/report.md (plots, regs.hex, calibration.csv, validation.csv)\n", a.out);
}

void run_demo(const DemoArgs& a) {
  std::filesystem::create_directories(a.out);
  Report rep;
  print_header(a);
  PaperPoint p = paper_point(a);
  if (!a.no_rtl) add_rtl_rows(p);
  p.fx_vs_fl = max_diff_deg(p.run.fx.angle, p.run.fl.angle);
  print_table3(p);
  report_table3(a, p, rep);
  write_validation_angles(a, p);
  independent_noise(a, rep);
  drive_outputs(a, p, rep);
  if (!a.no_sweep) {
    degree_regions(a, rep);
    correction_modes(a, rep);
  }
  write_report(a, rep);
}

}  // namespace

void add_demo(CLI::App& app) {
  auto args = std::make_shared<DemoArgs>();
  CLI::App* c = app.add_subcommand(
      "demo", "The main job on the built-in paper scenario, with a report in out/demo/");
  c->add_option("--out", args->out, "Output folder (default out/demo)");
  c->add_option("--samples", args->samples, "Samples per recording (one turn)")
      ->check(CLI::Range(256, 10000000));
  c->add_option("--seed-cal", args->seed_cal, "Seed of the calibration recording");
  c->add_option("--seed-val", args->seed_val, "Seed of the validation recording");
  c->add_flag("--no-rtl", args->no_rtl, "Skip the RTL (Verilator) row");
  c->add_flag("--no-plots", args->no_plots, "Skip the PNG plots");
  c->add_flag("--no-sweep", args->no_sweep, "Skip the degree/regions table");
  c->add_option("--json", args->json, "Write the summary as JSON ('-' for stdout)");
  c->callback([args] {
    if (args->seed_cal == args->seed_val) throw InputError("--seed-cal and --seed-val must differ");
    run_demo(*args);
  });
}

}  // namespace acore::cli
