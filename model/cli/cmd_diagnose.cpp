// SPDX-License-Identifier: MIT
// `anglecore diagnose`: sim-to-real gap diagnosis (model/lab/diagnose/diagnose.hpp), with an
// optional report.
#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "cli_util.hpp"
#include "commands.hpp"
#include "core/errors.hpp"
#include "diagnose/diagnose.hpp"

namespace acore::cli {

namespace {

struct DiagnoseArgs {
  std::string sim, real, holdout, json, report;
  int order = 12;
};

std::string combination_names(const Diagnosis& d) {
  std::string s;
  for (const auto& r : d.combination) s += (s.empty() ? "" : " + ") + r.cand.effect;
  return s;
}

std::string params_text(const EffectCandidate& c) {
  std::string s;
  for (const auto& [k, v] : c.params) s += fmt::format("{}{}={:.4g}", s.empty() ? "" : ", ", k, v);
  return s;
}

void print_summary(const Diagnosis& d) {
  std::cout << fmt::format(
      "gap on --real: {:.4f} deg (systematic {:.4f}, excess noise {:.4f}; noise level {:.4f} "
      "deg)\n",
      d.before.gap_deg, d.before.systematic_deg, d.before.excess_noise_deg, d.before.noise_deg);
  std::cout << fmt::format("where: stage '{}' ({}), depends on {}\n", d.where_stage,
                           d.where_channels.empty()
                               ? std::string("-")
                               : fmt::format("{}", fmt::join(d.where_channels, ", ")),
                           d.domain);
  for (size_t k = 0; k < std::min<size_t>(4, d.harmonics.size()); ++k)
    std::cout << fmt::format("  gap order {:2d}: {:.4f} deg  <- {}\n", d.harmonics[k].order,
                             d.harmonics[k].amplitude_deg, fmt::join(d.harmonics[k].causes, "; "));
  std::cout << fmt::format("verdict: {}\n", d.verdict);
  if (!d.note.empty()) std::cout << fmt::format("  note: {}\n", d.note);
  if (!d.ambiguous_with.empty())
    std::cout << fmt::format(
        "  ambiguous: the recording cannot tell {} from {} (record with speed changes and a "
        "reversal)\n",
        d.ranking.front().cand.effect, fmt::join(d.ambiguous_with, ", "));
  std::cout << fmt::format("  {:<14} {:>10} {:>10} {:>10}  {}\n", "effect", "dBIC", "explained",
                           "after deg", "parameters");
  for (size_t k = 0; k < std::min<size_t>(6, d.ranking.size()); ++k) {
    const auto& r = d.ranking[k];
    std::cout << fmt::format(
        "  {:<14} {:>10.1f} {:>9.1f}% {:>10.4f}  {}{}\n", r.cand.effect, r.cand.delta_bic,
        100 * r.explained, r.after_deg, params_text(r.cand),
        r.cand.rejected.empty() ? "" : "  [rejected: " + r.cand.rejected + "]");
  }
  if (!d.combination.empty())
    std::cout << fmt::format("combination: {} explains {:.1f}%, gap after {:.4f} deg\n",
                             combination_names(d), 100 * d.combination_explained,
                             d.combination_after_deg);
  std::cout << fmt::format(
      "after adding the {} to the simulation: gap {:.4f} -> {:.4f} deg on --real",
      d.verdict == "explained" ? "effect" : "(no) effect", d.before.gap_deg, d.after.gap_deg);
  if (d.hold_before)
    std::cout << fmt::format(", {:.4f} -> {:.4f} deg on --holdout (not fitted)",
                             d.hold_before->gap_deg, d.hold_after->gap_deg);
  std::cout << "\n";
}

void write_report(const Diagnosis& d, const Recording& real, const std::string& dir) {
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  {
    std::ofstream f(fs::path(dir) / "gap_series.csv");
    f << "theta_ref,t,temp,omega,g,g_systematic,g_after_systematic\n";
    const auto w = angular_velocity(real);
    for (size_t i = 0; i < real.size(); ++i)
      f << fmt::format("{:.9g},{:.9g},{:.6g},{:.9g},{:.6g},{:.6g},{:.6g}\n", real.theta_ref[i],
                       real.has_t() ? real.t[i] : static_cast<double>(i),
                       real.has_temp() ? real.temp[i] : 0.0, w[i], d.before.g[i],
                       d.before.g_systematic[i], d.after.g_systematic[i]);
  }
  {
    std::ofstream f(fs::path(dir) / "stages.csv");
    f << "stage,signal,rms_over_noise\n";
    for (const auto& s : d.stages)
      for (size_t k = 0; k < s.signals.size(); ++k)
        f << fmt::format("{},{},{:.6g}\n", s.stage, s.signals[k], s.ratio[k]);
  }
  const nlohmann::json j = d.to_json();
  write_json((fs::path(dir) / "diagnosis.json").string(), j);
  std::ofstream md(fs::path(dir) / "report.md");
  md << "# Sim-to-real gap diagnosis\n\n";
  md << fmt::format(
      "**Verdict: {}.** Gap on the real recording {:.4f}° (systematic {:.4f}°, excess noise "
      "{:.4f}°; the "
      "simulation's own noise gives {:.4f}° RMS of angle noise).\n\n",
      d.verdict, d.before.gap_deg, d.before.systematic_deg, d.before.excess_noise_deg,
      d.before.noise_deg);
  if (!d.note.empty()) md << fmt::format("Note: {}.\n\n", d.note);
  md << fmt::format(
      "After adding the best explanation to the simulation: {:.4f}° on the real recording",
      d.after.gap_deg);
  if (d.hold_before)
    md << fmt::format(", {:.4f}° → {:.4f}° on the holdout (never fitted)", d.hold_before->gap_deg,
                      d.hold_after->gap_deg);
  md << ".\n\n## Where\n\n";
  md << fmt::format("First stage beyond noise: **{}** ({}); the gap depends on **{}**.\n\n",
                    d.where_stage,
                    d.where_channels.empty() ? std::string("-")
                                             : fmt::format("{}", fmt::join(d.where_channels, ", ")),
                    d.domain);
  md << "| stage | signal | RMS difference / noise |\n|---|---|---|\n";
  for (const auto& s : d.stages)
    for (size_t k = 0; k < s.signals.size(); ++k)
      md << fmt::format("| {} | {} | {:.2f} |\n", s.stage, s.signals[k], s.ratio[k]);
  md << "\n| domain | adjusted R² of the gap |\n|---|---|\n";
  for (const auto& s : d.domains) md << fmt::format("| {} | {:.3f} |\n", s.domain, s.r2);
  md << "\n| gap order | amplitude ° | likely causes |\n|---|---|---|\n";
  for (const auto& h : d.harmonics)
    md << fmt::format("| {} | {:.4f} | {} |\n", h.order, h.amplitude_deg,
                      fmt::join(h.causes, "; "));
  md << "\n## Which\n\n| rank | effect | ΔBIC | explained | gap after ° | parameters "
        "|\n|---|---|---|---|---|---|\n";
  for (size_t k = 0; k < d.ranking.size(); ++k) {
    const auto& r = d.ranking[k];
    md << fmt::format("| {} | {} | {:.1f} | {:.1f}% | {:.4f} | {}{} |\n", k + 1, r.cand.effect,
                      r.cand.delta_bic, 100 * r.explained, r.after_deg, params_text(r.cand),
                      r.cand.rejected.empty() ? "" : " (rejected: " + r.cand.rejected + ")");
  }
  if (!d.combination.empty())
    md << fmt::format("\nBest combination: {}, explains {:.1f}%, gap after {:.4f}°.\n",
                      combination_names(d), 100 * d.combination_explained, d.combination_after_deg);
  md << "\n## Plots\n\n![gap vs angle](gap_vs_angle.png)\n\n![gap vs speed, temperature, "
        "direction](gap_domains.png)\n\n"
        "![stages](stages.png)\n\n![gap spectrum](gap_spectrum.png)\n";
  md.close();
  const fs::path script = fs::path(ACORE_SOURCE_DIR) / "scripts" / "plot_diagnosis.py";
  const std::string cmd = fmt::format("/usr/bin/python3 '{}' '{}'", script.string(), dir);
  if (std::system(cmd.c_str()) != 0)
    std::cerr << "anglecore: note: plots skipped (/usr/bin/python3 with matplotlib failed)\n";
  std::cout << fmt::format("report: {}/report.md\n", dir);
}

void run_diagnose(const DiagnoseArgs& a) {
  const Recording sim = read_recording(a.sim);
  const Recording real = read_recording(a.real);
  std::unique_ptr<Recording> hold;
  if (!a.holdout.empty()) hold = std::make_unique<Recording>(read_recording(a.holdout));
  DiagnoseOptions opt;
  opt.fourier_order = a.order;
  const Diagnosis d = diagnose(sim, real, hold.get(), opt);
  print_summary(d);
  write_json(a.json, d.to_json());
  if (!a.report.empty()) write_report(d, real, a.report);
}

}  // namespace

void add_diagnose(CLI::App& app) {
  auto args = std::make_shared<DiagnoseArgs>();
  CLI::App* c = app.add_subcommand(
      "diagnose", "Sim-to-real gap: where it lies, which effect causes it, how far it shrinks");
  c->add_option("--sim", args->sim,
                "Simulated recording: the designer's sensor model (any trajectory, >= one turn)")
      ->required();
  c->add_option("--real", args->real,
                "Real recording to explain (theta_ref required; t, temp used when present)")
      ->required();
  c->add_option("--holdout", args->holdout,
                "Another real recording, used only to check, never to fit");
  c->add_option("--order", args->order, "Harmonics of the sensor model fitted to --sim")
      ->check(CLI::Range(2, 40));
  c->add_option("--json", args->json, "Write results as JSON ('-' for stdout)");
  c->add_option("--report", args->report, "Write a Markdown report with plots into this folder");
  c->callback([args] { run_diagnose(*args); });
}

}  // namespace acore::cli
