// SPDX-License-Identifier: MIT
// Co-sim of one named configuration (rtl/configs.txt) against the bit-accurate model:
//   cosim_config NAME [SAMPLES]
// The paper scenario calibrated for that configuration (random input gaps and output
// backpressure), corner inputs, and random register images with random inputs (the saturation
// paths); every RTL-visible output of every sample must equal FixedModel::step. Also checks that
// the build's LATENCY is what the RTL shows. Exit 0 when all match, 1 on a mismatch, 2 on bad use.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "calibration.hpp"
#include "cosim_stimuli.hpp"
#include "errors.hpp"
#include "estimator.hpp"
#include "fixed_model.hpp"
#include "paper_signals.hpp"
#include "rtl_builds.hpp"
#include "rtl_engine.hpp"

namespace acore {
namespace {

// Samples where the RTL differs from the model; prints the first.
size_t compare(const std::vector<FixedSample>& rtl, const FixedModel& model, const std::vector<ChannelCodes>& in,
               const char* what) {
  const cosim::Comparison c = cosim::compare(rtl, model, in);
  if (c.mismatches) std::printf("%s: %s\n", what, c.first.c_str());
  std::printf("%-28s %8zu samples, %zu mismatches\n", what, in.size(), c.mismatches);
  return c.mismatches;
}

// The paper scenario calibrated for cfg: the calibration may only lower COEF_F (quantize_auto_range);
// the result must be exactly the build's configuration.
RegImage paper_image(const DatapathConfig& cfg) {
  const Recording cal = test::paper_recording(8000, true);
  const RegImage img = calibrate_image(cal, cfg, 1);
  if (img.cfg.describe() != cfg.describe())
    throw InputError("the paper calibration for this configuration needs " + img.cfg.describe() +
                     "; set those parameters in rtl/configs.txt");
  return img;
}

// Every word random below the CORDIC constants (half the time tamed to sane offsets and gains), and
// every Fourier word and the ZERO word; with the Fourier stage, every other image also gets random
// CORDIC constants (its rotations' trimmed angle registers then wrap, in the model as in the RTL).
RegImage random_image(const RegImage& base, std::mt19937_64& rng) {
  RegImage img = base;
  const DatapathConfig& cfg = img.cfg;
  const uint64_t mask = (uint64_t{1} << cfg.reg_w) - 1;
  for (int a = 0; a < cfg.addr_atan(0); ++a) img.words[a] = rng() & mask;
  for (int j = 0; j < cfg.fourier_words(); ++j) img.words[cfg.addr_fourier(j)] = rng() & mask;
  if (cfg.zero_word)
    img.words[cfg.addr_zero()] = rng() & mask;  // any bits: only the low ANGLE_W count
  if (cfg.fourier_k > 0 && (rng() & 1))
    for (int i = 0; i < cfg.iterations; ++i) img.words[cfg.addr_atan(i)] = rng() & mask;
  if (rng() & 1)
    for (int c = 0; c < 2; ++c) {
      img.set_signed(cfg.addr_offset(c), static_cast<int64_t>(rng() % 2001) - 1000);
      img.set_unsigned(cfg.addr_recip(c), static_cast<int64_t>(img.words[cfg.addr_recip(c)] % 60000) + 40000);
    }
  return img;
}

// A fine sweep through every 45-degree boundary plus the zero vector and full scale.
std::vector<ChannelCodes> corner_codes(int in_w) {
  const int32_t F = (1 << (in_w - 1)) - 1, N = -(1 << (in_w - 1)), q = 1 << (in_w - 3);
  std::vector<ChannelCodes> in;
  for (int32_t a : {0, 1, -1, F, N, q, -q})
    for (int32_t b : {0, 1, -1, F, N, q, -q})
      for (int32_t c : {0, F, N})
        for (int32_t d : {0, F, N}) in.push_back({a, b, c, d});
  for (int k = 0; k < 8; ++k)
    for (int j = -50; j <= 50; ++j) {
      const double th = k * M_PI / 4 + j * 1e-5;
      in.push_back({static_cast<int32_t>(std::lround(q * std::sin(th))),
                    static_cast<int32_t>(std::lround(q * std::cos(th))), 0, 0});
    }
  return in;
}

int measured_latency(const DatapathConfig& cfg, const RegImage& img) {
  RtlHarness h("", 2, 1, cfg);
  h.reset();
  h.load(img);
  h.drive(true, {1000, 2000, 0, 0}, true);
  h.tick();
  int n = 1;
  h.drive(false, {0, 0, 0, 0}, true);
  for (; !h.out_valid() && n < 100000; ++n) h.tick();
  return n;
}

int run(const std::string& name, size_t samples) {
  const RtlBuild& build = rtl_build_named(name);
  const DatapathConfig cfg = build.config();
  cfg.validate();
  std::printf("configuration %s: %s (%d words, LATENCY %d)\n", name.c_str(), cfg.describe().c_str(), cfg.words(),
              build.latency);
  size_t bad = 0;
  const RegImage paper = paper_image(cfg);
  const int lat = measured_latency(cfg, paper);
  std::printf("%-28s %8d clocks (LATENCY %d)\n", "latency", lat, build.latency);
  bad += lat != build.latency;

  RtlRunOptions opt;
  opt.gaps = 0.3;
  opt.backpressure = 0.3;
  const auto in = to_codes(test::paper_recording(samples, true), paper.in_scale, cfg.in_w);
  bad += compare(run_rtl(paper, in, opt), FixedModel(paper), in, "paper scenario");
  const auto corners = corner_codes(cfg.in_w);
  bad += compare(run_rtl(paper, corners, opt), FixedModel(paper), corners, "corner inputs");

  std::mt19937_64 rng(std::hash<std::string>{}(name));
  for (int k = 0; k < 8; ++k) {
    const RegImage img = random_image(paper, rng);
    const auto rin = cosim::random_codes(rng, 2000, cfg.in_w);
    RtlRunOptions ro;
    ro.seed = k + 1;
    ro.gaps = 0.2;
    ro.backpressure = 0.2;
    bad += compare(run_rtl(img, rin, ro), FixedModel(img), rin, "random image");
  }
  std::printf("%s: %s\n", name.c_str(), bad ? "MISMATCH" : "0 mismatches");
  return bad ? 1 : 0;
}

}  // namespace
}  // namespace acore

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: cosim_config NAME [SAMPLES]   (NAME from rtl/configs.txt)\n");
    return 2;
  }
  try {
    return acore::run(argv[1], argc == 3 ? std::strtoul(argv[2], nullptr, 10) : 30000);
  } catch (const acore::InputError& e) {
    std::fprintf(stderr, "cosim_config: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cosim_config: %s\n", e.what());
    return 1;
  }
}
