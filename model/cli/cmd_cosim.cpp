// SPDX-License-Identifier: MIT
// `anglecore cosim`: the Verilated RTL against the bit-accurate model, sample by sample
// (docs/contracts.md, command line).
// --engine rtl (default) runs the pipelined top, rtl-serial the serial core; exit 1 on any
// mismatch, 2 when the build's run-time module is not built (the message names the command).
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "cli_util.hpp"
#include "commands.hpp"
#include "core/datapath_config.hpp"
#include "core/errors.hpp"
#include "engine/estimator.hpp"
#include "engine/fixed_model.hpp"
#include "rtlsim/run_engine.hpp"

namespace acore::cli {

namespace {
struct CosimArgs {
  std::string regs, in, json, trace, engine = "rtl";
  double backpressure = 0.0;
  uint64_t seed = 1;
  int fold = 1;  // --engine rtl: the build with this FOLD (clocks per sample)
};

nlohmann::json sample_json(const FixedSample& s) {
  return {{"angle", s.angle},
          {"region", s.region},
          {"flags", {{"ovf", s.ovf}, {"los", s.los}, {"dos", s.dos}}},
          {"magnitude", s.magnitude}};
}

void run_cosim(const CosimArgs& a) {
  const Engine engine = parse_engine(a.engine);
  if (!is_rtl(engine))
    throw InputError("--engine: '" + a.engine + "' is not an RTL engine (rtl, rtl-serial)");
  EngineOptions opt;
  opt.trace = a.trace;
  opt.seed = a.seed;
  opt.backpressure = a.backpressure;
  opt.gaps = a.backpressure;
  opt.fold = a.fold;
  check_engine_options(engine, opt);
  const RegImage img = read_regimage(a.regs);
  const Recording rec = read_recording(a.in);
  const std::vector<FixedSample> rtl = run_engine(engine, rec, img, opt).rows;
  const std::vector<FixedSample> model = run_engine(Engine::Fixed, rec, img).rows;
  size_t bad = 0;
  nlohmann::json first = nullptr;
  for (size_t i = 0; i < model.size(); ++i) {
    if (i < rtl.size() && rtl[i] == model[i]) continue;
    if (bad++ == 0)
      first = {{"index", i},
               {"rtl", i < rtl.size() ? sample_json(rtl[i]) : nullptr},
               {"model", sample_json(model[i])}};
  }
  const nlohmann::json j = {{"samples", model.size()},
                            {"mismatches", bad},
                            {"first_mismatch", first},
                            {"engine", engine_name(engine)},
                            {"fold", a.fold}};
  std::cout << fmt::format(
      "cosim: {} samples, {} mismatches ({} vs bit-accurate model{})\n", model.size(), bad,
      engine == Engine::Rtl
          ? (a.fold > 1 ? fmt::format("RTL folded to {} clocks a sample", a.fold) : "RTL")
          : "serial RTL",
      a.backpressure > 0 ? fmt::format(", backpressure/gaps {}", a.backpressure) : "");
  if (!a.trace.empty()) std::cout << "waveform: " << a.trace << "\n";
  write_json(a.json, j);
  if (bad)
    throw CheckFailed(fmt::format("{} of {} samples differ; first at index {}", bad, model.size(),
                                  first["index"].get<size_t>()));
}
}  // namespace

void add_cosim(CLI::App& app) {
  auto args = std::make_shared<CosimArgs>();
  CLI::App* c =
      app.add_subcommand("cosim", "RTL (Verilated) vs bit-accurate model, sample by sample");
  c->add_option("--regs", args->regs, "Register image ($readmemh, from `calibrate`)")->required();
  c->add_option("--in", args->in, "Recording (CSV)")->required();
  c->add_option("--json", args->json, "Write results as JSON ('-' for stdout)");
  c->add_option("--engine", args->engine,
                "rtl (pipelined top, default) | rtl-serial (serial core, rtl/acore_serial_top.v)");
  c->add_option(
       "--fold", args->fold,
       "--engine rtl: the build folded to this many clocks per sample (rtl/configs.txt; the "
       "register image does not depend on it; default 1)")
      ->check(CLI::IsMember(acore::fold_values()));
  c->add_option("--trace", args->trace, "Write an FST waveform of the RTL run");
  c->add_option("--backpressure", args->backpressure,
                "Probability of a stalled output and of an input gap per clock (default 0)")
      ->check(CLI::Range(0.0, 0.95));
  c->add_option("--seed", args->seed, "Seed of the random stalls (default 1)");
  c->callback([args] { run_cosim(*args); });
}

}  // namespace acore::cli
