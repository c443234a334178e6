// SPDX-License-Identifier: MIT
// Saturation coverage of the co-sim: every run cosim_config makes (cosim::config_cases: the paper
// scenario, corner inputs, random images), for every configuration given, replayed through a copy
// of the bit-accurate model compiled with ACORE_SAT_COVERAGE. The model equals the RTL bit for bit
// on these runs (the co-sim asserts it), so the counts are the co-sim's. For every saturation
// point (each call of fx::saturate, by function, line and the width it saturates to) it counts the
// values below, inside and above the bound, and for the status window the magnitudes below LOS,
// inside and above DOS; then lists each side of a bound that no run reached.
//   sat_coverage [--samples N] [--out FILE.md] [--expect-unreached FILE] NAME=PARAMS...
// NAME=PARAMS: a registry line's name and its parameters, comma-separated (CMake passes every
// `sim` build of rtl/configs.txt). --expect-unreached: the points known not to be reached, one
// "function bound side" per line; exit 1 when the unreached list differs from it (a point newly
// left unreached, or one now reached whose entry is stale).
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/fixed_point.hpp"
#include "cosim/cosim_stimuli.hpp"
#include "engine/fixed_model.hpp"

namespace acore {
namespace {

struct Args {
  size_t samples = 30000;
  std::string out, expect;
  std::vector<std::pair<std::string, std::string>> configs;
};

Args parse_args(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string s = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw InputError(s + ": value missing");
      return argv[++i];
    };
    if (s == "--samples")
      a.samples = std::stoul(value());
    else if (s == "--out")
      a.out = value();
    else if (s == "--expect-unreached")
      a.expect = value();
    else if (s.find('=') != std::string::npos) {
      std::string params = s.substr(s.find('=') + 1);
      std::replace(params.begin(), params.end(), ',', ' ');
      a.configs.emplace_back(s.substr(0, s.find('=')), params);
    } else
      throw InputError("unknown argument '" + s + "'");
  }
  if (a.configs.empty()) throw InputError("no configuration given (NAME=PARAMS)");
  return a;
}

std::string short_file(const std::string& f) {
  const size_t at = f.find("model/ip/");
  return at == std::string::npos ? f : f.substr(at + 9);
}

int run(const Args& a) {
  fx::SatCount window;  // below = LOS, above = DOS
  size_t samples = 0;
  for (const auto& [name, params] : a.configs) {
    const DatapathConfig cfg = DatapathConfig{}.with_rtl_params(params);
    cfg.validate();
    for (const cosim::Case& c : cosim::config_cases(cfg, name, a.samples)) {
      const FixedModel m(c.img);
      const StatusWindow w = StatusWindow::defaults(cfg);
      for (const ChannelCodes& in : c.in) {
        const FixedSample s = m.step(in);
        ++(s.magnitude < w.mag_lo   ? window.below
           : s.magnitude > w.mag_hi ? window.above
                                    : window.inside);
      }
      samples += c.in.size();
    }
    std::fprintf(stderr, "sat_coverage: %s done\n", name.c_str());
  }
  std::ostringstream md;
  md << fmt::format(
      "Saturation points in the co-sim runs of {} configurations ({} samples): values below, "
      "inside and above each bound.\n\n",
      a.configs.size(), samples);
  md << "| point | function | bound | below | inside | above |\n|---|---|---|---:|---:|---:|\n";
  std::vector<std::string> unreached;
  auto row = [&](const std::string& point, const std::string& fn, const std::string& bound,
                 const fx::SatCount& c) {
    md << fmt::format("| {} | {} | {} | {} | {} | {} |\n", point, fn, bound, c.below, c.inside,
                      c.above);
    if (c.below == 0) unreached.push_back(fn + " " + bound + " below");
    if (c.above == 0) unreached.push_back(fn + " " + bound + " above");
    if (c.inside == 0) unreached.push_back(fn + " " + bound + " inside");
  };
  for (const auto& [site, c] : fx::sat_counts())
    row(fmt::format("{}:{}", short_file(std::get<1>(site)), std::get<2>(site)), std::get<0>(site),
        fmt::format("signed {} bits", std::get<3>(site)), c);
  row("engine/fixed_model.cpp", "status window", "LOS < 0.5, DOS > 1.5 x nominal", window);
  md << "\nNever reached: " << (unreached.empty() ? "none" : "") << "\n";
  for (const std::string& u : unreached) md << "- " << u << "\n";
  std::fputs(md.str().c_str(), stdout);
  if (!a.out.empty()) {
    std::ofstream f(a.out);
    f << md.str();
    if (!f) throw InputError(a.out + ": cannot write");
  }
  if (a.expect.empty()) return 0;
  std::ifstream f(a.expect);
  if (!f) throw InputError(a.expect + ": cannot open");
  std::set<std::string> want;
  for (std::string line; std::getline(f, line);)
    if (!line.empty() && line[0] != '#') want.insert(line);
  const std::set<std::string> got(unreached.begin(), unreached.end());
  int bad = 0;
  for (const std::string& u : got)
    if (!want.count(u)) std::printf("NEWLY UNREACHED: %s\n", u.c_str()), ++bad;
  for (const std::string& u : want)
    if (!got.count(u))
      std::printf("NOW REACHED (remove from %s): %s\n", a.expect.c_str(), u.c_str()), ++bad;
  return bad ? 1 : 0;
}

}  // namespace
}  // namespace acore

int main(int argc, char** argv) {
  try {
    return acore::run(acore::parse_args(argc, argv));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sat_coverage: %s\n", e.what());
    return 2;
  }
}
