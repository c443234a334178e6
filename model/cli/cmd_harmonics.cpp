// SPDX-License-Identifier: MIT
// `anglecore harmonics`: Kuntz's predicted vs exact angle-error harmonics of a signal spec
// (model/lab/harmonics/harmonics.hpp, docs/contracts.md, command line), with an optional plot
// folder (scripts/plot_harmonics.py).
#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "cli_util.hpp"
#include "commands.hpp"
#include "core/angle.hpp"
#include "core/errors.hpp"
#include "harmonics/harmonic_attribution.hpp"
#include "harmonics/harmonics.hpp"

namespace acore::cli {

namespace {

constexpr double kDeg = kDegPerRad;

struct HarmonicsArgs {
  std::string spec, json, plot;
  int grid = 0;
  bool attribute = false;
};

std::string opt_deg(const std::optional<double>& v) {
  return v ? fmt::format("{:.4f} deg", *v * kDeg) : "n/a";
}

void print_table(const HarmonicAnalysis& a, std::ostream& os) {
  os << fmt::format(
      "p = {}, grid {} points/turn, sum sqrt(A^2+B^2) = {:.4f}, sum |A|+|B| = {:.4f}\n", a.spec.p,
      a.phi.size(), a.sum_amplitude, a.taylor_sum);
  os << fmt::format("max |error| {:.4f} deg (bound Eq. 29: {:.4f} deg, Eq. 30: {})\n",
                    a.max_error * kDeg, a.bound_geometric * kDeg,
                    opt_deg(a.bound_geometric_linear));
  os << fmt::format("residual first order {:.4f} deg (bound Eq. 32 k=1: {})\n",
                    a.residual_first * kDeg, opt_deg(a.bound_taylor_first));
  os << fmt::format("residual second order {:.5f} deg (bound Eq. 32 k=2: {})\n",
                    a.residual_second * kDeg, opt_deg(a.bound_taylor_second));
  for (const auto& n : a.notes) os << "note: " << n << "\n";
  os << fmt::format(
      "{:>5} {:>12} {:>12} {:>12}   (electrical error amplitude, deg; orders per turn)\n", "order",
      "exact", "first", "second");
  for (const auto& h : a.harmonics) {
    // Orders that none of the three reaches 1e-4 deg are left out of the table (not of the JSON).
    if (std::max({h.exact, h.first, h.second}) * kDeg < 1e-4) continue;
    os << fmt::format("{:>5} {:>12.5f} {:>12.5f} {:>12.5f}\n", h.order, h.exact * kDeg,
                      h.first * kDeg, h.second * kDeg);
  }
}

void write_plot(const HarmonicAnalysis& a, const std::string& dir, std::ostream& log) {
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  {
    std::ofstream f(fs::path(dir) / "harmonics_curve.csv");
    f << "phi_deg,exact_deg,first_deg,second_deg,residual_first_deg,residual_second_deg\n";
    for (size_t j = 0; j < a.phi.size(); ++j)
      f << fmt::format("{:.6f},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", a.phi[j] * kDeg,
                       a.exact[j] * kDeg, a.first[j] * kDeg, a.second[j] * kDeg,
                       (a.exact[j] - a.first[j]) * kDeg, (a.exact[j] - a.second[j]) * kDeg);
    if (!f) throw InputError(fmt::format("{}: cannot write harmonics_curve.csv", dir));
  }
  write_json((fs::path(dir) / "harmonics.json").string(), a.to_json());
  const fs::path script = fs::path(ACORE_SOURCE_DIR) / "scripts" / "plot_harmonics.py";
  if (std::system("/usr/bin/python3 -c 'import matplotlib, numpy' >/dev/null 2>&1") != 0) {
    log << fmt::format(
        "plot skipped: /usr/bin/python3 with matplotlib and numpy not found; data in {}\n", dir);
    return;
  }
  const std::string cmd = fmt::format("/usr/bin/python3 '{}' '{}'", script.string(), dir);
  if (std::system(cmd.c_str()) != 0)
    log << fmt::format("plot skipped: {} failed; data in {}\n", script.string(), dir);
  else
    log << fmt::format("plots: {}/harmonics_spectrum.png, {}/harmonics_error.png\n", dir, dir);
}

// The inverse map on the exact spectrum (attribute_exact): which signal imperfections could have
// made each order, the best three causes of each printed; the JSON is the library's.
nlohmann::json print_attribution(const HarmonicAnalysis& a, std::ostream& os) {
  const std::vector<OrderCauses> orders = attribute_exact(a);
  os << "attribution of the exact spectrum (orders >= 5% of the largest; best causes first):\n";
  for (const auto& o : orders) {
    os << fmt::format("  order {:>3} ({:.4f} deg):\n", o.order, o.amplitude_deg);
    for (size_t i = 0; i < o.causes.size() && i < 3; ++i) {
      const auto& c = o.causes[i];
      os << fmt::format("      {:>5.1f}% explained, consistency {:.2f}: {}\n", 100 * c.explained,
                        c.consistency, c.text);
    }
  }
  return attribution_json(orders);
}

void run_harmonics(const HarmonicsArgs& args) {
  const SignalSpec spec = load_signal_spec(args.spec);
  const HarmonicAnalysis a = analyze(spec, args.grid);
  // With `--json -` stdout carries only the JSON; the table goes to stderr.
  std::ostream& os = args.json == "-" ? std::cerr : std::cout;
  print_table(a, os);
  nlohmann::json j = a.to_json();
  if (args.attribute) j["attribution"] = print_attribution(a, os);
  write_json(args.json, j);
  if (!args.plot.empty()) write_plot(a, args.plot, os);
}

}  // namespace

void add_harmonics(CLI::App& app) {
  auto args = std::make_shared<HarmonicsArgs>();
  CLI::App* c = app.add_subcommand(
      "harmonics", "Predicted (Kuntz, first and second order) vs exact angle-error harmonics");
  c->add_option("--spec", args->spec,
                "Signal spec JSON: {p, A0, B0, Ap, Bp, delta_p, terms: [{n, A, theta, B, psi}]}, "
                "angles in rad")
      ->required();
  c->add_option("--json", args->json, "Write results as JSON ('-' for stdout)");
  c->add_option("--plot", args->plot,
                "Write curve/spectrum data and plots (Fig. 7 style) into this folder");
  c->add_option("--grid", args->grid,
                "Samples per turn for the exact error (default: automatic, >= 4096)")
      ->check(CLI::Range(64, 1 << 22));
  c->add_flag("--attribute", args->attribute,
              "Also name, for each significant order, the signal harmonics and Table 1 mismatches "
              "that can cause it");
  c->callback([args] { run_harmonics(*args); });
}

}  // namespace acore::cli
