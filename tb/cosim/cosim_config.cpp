// SPDX-License-Identifier: MIT
// Co-sim of one build of the registry (rtl/configs.txt; a configuration of the pipelined top or
// of the serial core) against the bit-accurate model:
//   cosim_config NAME [SAMPLES]
// The paper scenario calibrated for that configuration (random input gaps and output
// backpressure), corner inputs, and random register images with random inputs (the saturation
// paths); every RTL-visible output of every sample must equal FixedModel::step. Also checks that
// the build's LATENCY is what the RTL shows, that at full rate (input always valid, output always
// ready) a sample is taken exactly every CYCLES (= FOLD) clocks and comes out LATENCY clocks later,
// and that a long output stall (past the folded top's output FIFO) loses and repeats nothing.
//   cosim_config --long NAME [SAMPLES]
// The long regression (CTest label `long`, outside the default run): SAMPLES (default 10^7) in
// all, a fifth the paper scenario, the rest random inputs under random register images (a new
// image every 200000 samples), the corner inputs under each image; random input gaps and output
// backpressure throughout. Prints the samples, mismatches and seconds of each part.
// Exit 0 when all match, 1 on a mismatch, 2 on bad use.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "calibration/calibration.hpp"
#include "core/errors.hpp"
#include "cosim/cosim_stimuli.hpp"
#include "engine/estimator.hpp"
#include "engine/fixed_model.hpp"
#include "rtlsim/rtl_engine.hpp"
#include "support/paper_signals.hpp"

namespace acore {
namespace {

// Samples where the RTL differs from the model; prints the first.
size_t compare(const std::vector<FixedSample>& rtl, const FixedModel& model,
               const std::vector<ChannelCodes>& in, const char* what) {
  const cosim::Comparison c = cosim::compare(rtl, model, in);
  if (c.mismatches) std::printf("%s: %s\n", what, c.first.c_str());
  std::printf("%-28s %8zu samples, %zu mismatches\n", what, in.size(), c.mismatches);
  return c.mismatches;
}

// Clocks from the accepting edge to out_valid (a folded top may take a sample only some clocks
// after the last one: the input is held until accepted).
int measured_latency(const RtlBuild& build, const RegImage& img) {
  RtlHarness h(build, "", 2, 1);
  h.reset();
  h.load(img);
  h.drive(true, {1000, 2000, 0, 0}, true);
  for (int wait = 0; !h.in_ready() && wait < 100; ++wait) h.tick();
  h.tick();
  int n = 1;
  h.drive(false, {0, 0, 0, 0}, true);
  for (; !h.out_valid() && n < 100000; ++n) h.tick();
  return n;
}

// Full rate: in_valid and out_ready always high. Every accept must come exactly CYCLES clocks after
// the previous one and every output LATENCY clocks after its accept, in order. Returns the number
// of violations (printing the first).
size_t full_rate(const RtlBuild& build, const RegImage& img, const std::vector<ChannelCodes>& in) {
  RtlHarness h(build, "", 2, 7);
  const int cycles = h.cycles_per_sample(), latency = h.latency();
  h.reset();
  h.load(img);
  std::vector<uint64_t> taken, out;
  std::vector<FixedSample> rtl;
  size_t next = 0;
  while (out.size() < in.size() && h.cycles() < 100000 + 20 * in.size() * cycles) {
    h.drive(next < in.size(), next < in.size() ? in[next] : ChannelCodes{0, 0, 0, 0}, true);
    if (next < in.size() && h.in_ready()) taken.push_back(h.cycles()), ++next;
    if (h.out_valid()) out.push_back(h.cycles()), rtl.push_back(h.output());
    h.tick();
  }
  size_t bad = out.size() != in.size();
  for (size_t i = 0; i < taken.size(); ++i) {
    const bool gap_ok = i == 0 || taken[i] - taken[i - 1] == static_cast<uint64_t>(cycles);
    const bool lat_ok = i < out.size() && out[i] - taken[i] == static_cast<uint64_t>(latency);
    if (!gap_ok || !lat_ok) {
      if (!bad)
        std::printf(
            "full rate: sample %zu taken at clock %llu, out at %llu (CYCLES %d, LATENCY %d)\n", i,
            static_cast<unsigned long long>(taken[i]),
            static_cast<unsigned long long>(i < out.size() ? out[i] : 0), cycles, latency);
      ++bad;
    }
  }
  const cosim::Comparison c = cosim::compare(rtl, FixedModel(img), in);
  std::printf(
      "%-28s %8zu samples, %zu timing violations, %zu mismatches (a sample every %d clocks)\n",
      "full rate", in.size(), bad, c.mismatches, cycles);
  return bad + c.mismatches;
}

// The output held low for long stretches while the input is always offered: the folded top's
// credits must stop the input before its output FIFO overflows. Every sample must come out once,
// in order, equal to the model; in_ready must be low during reset.
size_t long_stall(const RtlBuild& build, const RegImage& img, const std::vector<ChannelCodes>& in) {
  RtlHarness h(build, "", 2, 9);
  size_t bad = 0;
  h.drive(true, in[0], false);
  h.set_reset(true);
  for (int i = 0; i < 4; ++i) {
    // in_ready low during reset, at every FOLD.
    if (h.in_ready()) ++bad;
    h.tick();
  }
  h.set_reset(false);
  h.drive(false, in[0], true);
  h.load(img);
  std::vector<FixedSample> rtl;
  size_t next = 0;
  while (rtl.size() < in.size() && h.cycles() < 400000 + 40 * in.size()) {
    // Output ready only 100 clocks in every 3000 (and in short bursts after that).
    const bool ready = (h.cycles() % 3000) >= 2900;
    h.drive(next < in.size(), next < in.size() ? in[next] : ChannelCodes{0, 0, 0, 0}, ready);
    if (next < in.size() && h.in_ready()) ++next;
    if (ready && h.out_valid()) rtl.push_back(h.output());
    h.tick();
  }
  const cosim::Comparison c = cosim::compare(rtl, FixedModel(img), in);
  if (c.mismatches) std::printf("long stall: %s\n", c.first.c_str());
  std::printf("%-28s %8zu samples, %zu mismatches%s\n", "long output stalls", in.size(),
              c.mismatches, bad ? ", in_ready high in reset" : "");
  return bad + c.mismatches;
}

int run(const std::string& name, size_t samples) {
  const RtlBuild& build = rtl_build_named(name);
  if (build.top == RtlTop::kShell)
    throw InputError("'" + name +
                     "' is a build of the register shell (tb/shell/test_apb_shell.cpp)");
  const DatapathConfig& cfg = build.cfg;
  cfg.validate();
  const int latency = build.plugin().latency, cycles = build.plugin().cycles;
  std::printf("configuration %s (%s): %s (%d words, LATENCY %d, CYCLES %d)\n", name.c_str(),
              build.module.c_str(), cfg.describe().c_str(), cfg.words(), latency, cycles);
  size_t bad = 0;
  const std::vector<cosim::Case> cases = cosim::config_cases(cfg, name, samples);
  const RegImage& paper = cases.front().img;
  const int lat = measured_latency(build, paper);
  std::printf("%-28s %8d clocks (LATENCY %d)\n", "latency", lat, latency);
  bad += lat != latency;
  for (const cosim::Case& c : cases) {
    RtlRunOptions ro;
    ro.top = build.top;
    ro.seed = c.seed;
    ro.gaps = c.gaps;
    ro.backpressure = c.backpressure;
    bad += compare(run_rtl(c.img, c.in, ro), FixedModel(c.img), c.in, c.what.c_str());
  }
  // The serial core computes a sample in CYCLES clocks and has no output FIFO: fewer samples.
  const std::vector<ChannelCodes>& in = cases.front().in;
  const size_t n_head = cycles > 8 ? 300 : 2000, n_stall = cycles > 8 ? 60 : 2000;
  const std::vector<ChannelCodes> head(in.begin(), in.begin() + std::min(in.size(), n_head));
  const std::vector<ChannelCodes> stall(in.begin(), in.begin() + std::min(in.size(), n_stall));
  bad += full_rate(build, paper, head);
  bad += long_stall(build, paper, stall);
  std::printf("%s: %s\n", name.c_str(), bad ? "MISMATCH" : "0 mismatches");
  return bad ? 1 : 0;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

int run_long(const std::string& name, size_t total) {
  const RtlBuild& build = rtl_build_named(name);
  if (build.top == RtlTop::kShell)
    throw InputError("'" + name +
                     "' is a build of the register shell (tb/shell/test_apb_shell.cpp)");
  const DatapathConfig& cfg = build.cfg;
  cfg.validate();
  std::printf("long co-sim of %s (%s): %s, %zu samples\n", name.c_str(), build.module.c_str(),
              cfg.describe().c_str(), total);
  const auto t0 = std::chrono::steady_clock::now();
  const RegImage paper = cosim::config_paper_image(cfg);
  const auto corners = cosim::corner_codes(cfg.in_w);
  const size_t block = 200000, n_paper = total / 5;
  size_t bad = 0, done = 0, blocks = 0;
  std::mt19937_64 rng(std::hash<std::string>{}(name) ^ 0x10e7);
  const auto run = [&](const RegImage& img, const std::vector<ChannelCodes>& in, const char* what) {
    RtlRunOptions ro;
    ro.top = build.top;
    ro.seed = ++blocks;
    ro.gaps = 0.2;
    ro.backpressure = 0.2;
    const cosim::Comparison c = cosim::compare(run_rtl(img, in, ro), FixedModel(img), in);
    if (c.mismatches) std::printf("%s (block %zu): %s\n", what, blocks, c.first.c_str());
    bad += c.mismatches;
    done += in.size();
  };
  const auto paper_in = to_codes(test::paper_recording(n_paper, true), paper.in_scale, cfg.in_w);
  for (size_t b = 0; b < paper_in.size(); b += block)
    run(paper, {paper_in.begin() + b, paper_in.begin() + std::min(paper_in.size(), b + block)},
        "paper scenario");
  run(paper, corners, "corner inputs");
  std::printf("%-28s %9zu samples, %zu mismatches, %.1f s\n", "paper scenario + corners", done, bad,
              seconds_since(t0));
  size_t images = 0;
  while (done < total) {
    const RegImage img = cosim::random_image(paper, rng, cfg.fourier_k > 0 && (rng() & 1));
    run(img, cosim::random_codes(rng, std::min(block, total - done), cfg.in_w), "random image");
    run(img, corners, "corners, random image");
    ++images;
  }
  std::printf("%-28s %9zu samples in all (%zu random images), %zu mismatches, %.1f s\n", "long",
              done, images, bad, seconds_since(t0));
  std::printf("%s: %s\n", name.c_str(), bad ? "MISMATCH" : "0 mismatches");
  return bad ? 1 : 0;
}

}  // namespace
}  // namespace acore

int main(int argc, char** argv) {
  const bool long_run = argc >= 2 && std::string(argv[1]) == "--long";
  const int first = long_run ? 2 : 1;
  if (argc < first + 1 || argc > first + 2) {
    std::fprintf(stderr,
                 "usage: cosim_config [--long] NAME [SAMPLES]   (NAME from rtl/configs.txt)\n");
    return 2;
  }
  try {
    const char* count = argc == first + 2 ? argv[first + 1] : nullptr;
    if (long_run)
      return acore::run_long(argv[first], count ? std::strtoul(count, nullptr, 10) : 10000000);
    return acore::run(argv[first], count ? std::strtoul(count, nullptr, 10) : 30000);
  } catch (const acore::InputError& e) {
    std::fprintf(stderr, "cosim_config: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cosim_config: %s\n", e.what());
    return 1;
  }
}
