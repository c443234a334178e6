// SPDX-License-Identifier: MIT
// Co-sim regression: the Verilated RTL (rtl/acore_top.v) against the bit-accurate model
// (FixedModel::step), every output word of every sample: the paper scenario (10^6 samples), random
// backpressure and input gaps, reset in mid-stream, register reprogramming between frames, corner
// inputs, and random register images with random inputs (saturation paths). The RTL starts from a
// random state (randReset(2)); outputs must be zero whenever out_valid is low.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "calibration/calibration.hpp"
#include "core/errors.hpp"
#include "cosim_expect.hpp"
#include "engine/estimator.hpp"
#include "engine/fixed_model.hpp"
#include "host_port_checks.hpp"
#include "rtl_engine.hpp"
#include "support/paper_signals.hpp"

namespace acore {
namespace {

// The paper scenario's calibrated, quantized coefficients (docs/contracts.md, paper scenario).
RegImage paper_image() {
  const Recording cal = test::paper_recording(4000, true);
  CalOptions opt;
  const FloatCoefficients fc = calibrate(cal, opt);
  return quantize(fc, DatapathConfig{}, choose_in_scale(cal, DatapathConfig{}.in_w));
}

RegImage identity_image() { return cosim::identity_image(DatapathConfig{}); }

// Every word random (REG_W bits); atan words either the real table or random.
RegImage random_image(std::mt19937_64& rng, bool random_atan) {
  RegImage img = identity_image();
  const uint64_t mask = (uint64_t{1} << img.cfg.reg_w) - 1;
  for (int a = 0; a < img.cfg.addr_atan(0); ++a) img.words[a] = rng() & mask;
  // Small offsets and sane gains half of the time, so both saturating and normal paths occur.
  if (rng() & 1) {
    for (int c = 0; c < 2; ++c) {
      img.set_signed(img.cfg.addr_offset(c), static_cast<int64_t>(rng() % 2001) - 1000);
      img.set_unsigned(img.cfg.addr_recip(c), 40000 + rng() % 60000);
    }
    for (int a = img.cfg.addr_poly(0, 0, 0); a < img.cfg.addr_atan(0); ++a)
      img.set_signed(a, static_cast<int64_t>(rng() % 8001) - 4000);
  }
  if (random_atan)
    for (int i = 0; i < img.cfg.iterations; ++i) img.words[img.cfg.addr_atan(i)] = rng() & mask;
  return img;
}

using cosim::mismatches;
using cosim::paper_codes;
using cosim::random_codes;

TEST(Cosim, LatencyIsTheNamedLocalparam) {
  RtlHarness h;
  h.reset();
  h.load(identity_image());
  h.drive(true, {1000, 2000, 0, 0}, true);
  ASSERT_TRUE(h.in_ready());
  h.tick();
  int n = 1;
  h.drive(false, {0, 0, 0, 0}, true);
  while (!h.out_valid() && n < 1000) {
    h.tick();
    ++n;
  }
  EXPECT_EQ(n, h.latency());
  EXPECT_EQ(h.latency(), 55);  // 1 + 8 + 2 + 25 + 18 + 1 at the defaults
}

TEST(Cosim, OneSamplePerClock) {
  // No gaps, no backpressure: n samples take n + LATENCY clocks, and in_ready never drops.
  const RegImage img = identity_image();
  const auto in = paper_codes(img, 5000);
  RtlHarness h;
  h.reset();
  h.load(img);
  const uint64_t start = h.cycles();
  std::mt19937_64 rng(1);
  const auto out = h.stream(in, 0.0, 0.0, rng);
  EXPECT_EQ(out.size(), in.size());
  EXPECT_EQ(h.cycles() - start, in.size() + h.latency());
}

TEST(Cosim, PaperScenarioMillionSamples) {
  const RegImage img = paper_image();
  const auto in = paper_codes(img, 1000000);
  const auto rtl = run_rtl(img, in, RtlRunOptions{});
  const FixedModel model(img);
  EXPECT_EQ(mismatches(rtl, model, in, "paper scenario 1e6"), 0u);
  // The scenario must exercise all four regions.
  int seen[4] = {0, 0, 0, 0};
  for (const auto& s : rtl) seen[s.region & 3] = 1;
  EXPECT_EQ(seen[0] + seen[1] + seen[2] + seen[3], 4);
}

TEST(Cosim, RandomBackpressureAndGaps) {
  const RegImage img = paper_image();
  const auto in = paper_codes(img, 60000);
  const FixedModel model(img);
  for (const double p : {0.1, 0.5, 0.9}) {
    RtlRunOptions opt;
    opt.seed = static_cast<uint64_t>(p * 1000) + 7;
    opt.gaps = p;
    opt.backpressure = 1.0 - p;
    EXPECT_EQ(mismatches(run_rtl(img, in, opt), model, in, "gaps/backpressure"), 0u) << p;
  }
}

TEST(Cosim, OutputsZeroWhileInvalidAndResetMidStream) {
  const RegImage img = paper_image();
  const FixedModel model(img);
  const auto in = paper_codes(img, 5000);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  RtlHarness h("", 2, 99);
  // Before and during reset the outputs may be anything but never "valid" after one reset clock.
  h.reset(1);
  h.load(img);
  std::vector<FixedSample> out;
  size_t next = 0, invalid_nonzero = 0;
  bool did_reset = false;
  size_t first_after_reset = 0;
  for (int cyc = 0; out.size() < in.size() && cyc < 100000; ++cyc) {
    const bool valid = next < in.size() && u(rng) < 0.8;
    const bool ready = u(rng) < 0.8;
    h.drive(valid, valid ? in[next] : ChannelCodes{0, 0, 0, 0}, ready);
    if (!h.out_valid() && !h.outputs_zero()) ++invalid_nonzero;
    if (!did_reset && next == 2000) {
      // Reset with the pipeline full: everything in flight is dropped.
      did_reset = true;
      // The sample on the pins stays offered: in_ready_o must be low in every reset clock.
      h.set_reset(true);
      for (int i = 0; i < 3; ++i) {
        EXPECT_FALSE(h.in_ready());
        h.tick();
      }
      h.set_reset(false);
      EXPECT_FALSE(h.out_valid());
      first_after_reset = next;
      next = out.size();  // samples accepted but not delivered are lost: send them again
      continue;
    }
    if (valid && h.in_ready()) ++next;
    if (ready && h.out_valid()) out.push_back(h.output());
    h.tick();
  }
  EXPECT_TRUE(did_reset);
  EXPECT_GT(first_after_reset, 0u);
  EXPECT_EQ(invalid_nonzero, 0u);
  EXPECT_EQ(mismatches(out, model, in, "reset mid-stream"), 0u);
}

TEST(Cosim, RegisterReprogrammingBetweenFrames) {
  std::mt19937_64 rng(5);
  RtlHarness h;
  h.reset();
  const RegImage imgs[3] = {paper_image(), identity_image(), random_image(rng, false)};
  for (int frame = 0; frame < 6; ++frame) {
    const RegImage& img = imgs[frame % 3];
    h.load(img);
    const auto in = frame % 2 ? random_codes(rng, 3000, img.cfg.in_w) : paper_codes(img, 3000);
    const auto out = h.stream(in, 0.2, 0.2, rng);
    EXPECT_EQ(mismatches(out, FixedModel(img), in, "reprogrammed frame"), 0u) << frame;
  }
  // Read-back port: addresses past the last word read as zero and ignore writes.
  EXPECT_EQ(h.read_reg(60), 0u);
}

// The builds of the default configuration at every fold factor (named configurations default,
// fold2, fold4, fold8): the reset and host-port contract is the same at every FOLD.
std::vector<DatapathConfig> default_at_every_fold() {
  std::vector<DatapathConfig> out;
  for (int fold : {1, 2, 4, 8}) {
    DatapathConfig cfg;
    cfg.fold = fold;
    out.push_back(cfg);
  }
  return out;
}

TEST(Cosim, ResetHoldsInReadyLowAndIgnoresHostWrites) {
  // rst_i high: in_ready_o low from the first clock (random power-up state), a sample offered in
  // reset is not taken (no output follows), a host write in reset changes no word; at every FOLD.
  for (const DatapathConfig& cfg : default_at_every_fold()) {
    SCOPED_TRACE("FOLD=" + std::to_string(cfg.fold));
    {
      // (One Verilated model alive at a time: Verilator 5.006 deadlocks destroying the second.)
      RtlHarness fresh("", 2, 41, cfg);
      EXPECT_TRUE(host_port::in_ready_low_at_power_up_reset(fresh));
    }
    RtlHarness h("", 2, 42, cfg);
    const RegImage img = host_port::distinct_image(identity_image());
    const host_port::ResetBehaviour r = host_port::reset_behaviour(h, img, 8);
    EXPECT_EQ(r.in_ready_high, 0);
    EXPECT_EQ(r.out_valid_after, 0);
    EXPECT_EQ(r.words_changed, 0);
  }
}

TEST(Cosim, HostPortTimingIsTheTopsShared) {
  // Both tops, and acore_top at every FOLD: reg_rdata_o is the word at the address of two clocks
  // before, at one address per clock; a write lands at the edge after the one that takes it, so a
  // read whose address comes one clock after the write returns the old word and two clocks after
  // it the new one.
  for (const DatapathConfig& cfg : default_at_every_fold()) {
    SCOPED_TRACE("FOLD=" + std::to_string(cfg.fold));
    RtlHarness h("", 2, 43, cfg);
    h.reset();
    const RegImage img = host_port::distinct_image(identity_image());
    h.load(img);
    EXPECT_EQ(host_port::read_latency(h, img, 1, 2), 2);
    EXPECT_EQ(host_port::read_latency(h, img, 2, static_cast<int>(img.words.size()) - 1), 2);
    EXPECT_EQ(host_port::streamed_read_errors(h, img, 2, 500, 7), 0);
    EXPECT_GT(host_port::streamed_read_errors(h, img, 1, 500, 7), 400);
    EXPECT_EQ(host_port::read_after_write(h, 5, img.words[5] ^ 1, 1), img.words[5]);
    EXPECT_EQ(h.read_reg(5), img.words[5] ^ 1);
    EXPECT_EQ(host_port::read_after_write(h, 6, img.words[6] ^ 1, 2), img.words[6] ^ 1);
  }
}

TEST(Cosim, CornerInputs) {
  const int32_t F = 32767, N = -32768;
  std::vector<ChannelCodes> in;
  // Zero vector, full scale and saturated channels in every combination of extremes.
  const int32_t vals[] = {0, 1, -1, F, N, 8192, -8192, 16384, -16384, 4096};
  for (int32_t a : vals)
    for (int32_t b : vals)
      for (int32_t c : {0, F, N, 77})
        for (int32_t d : {0, F, N, -77}) in.push_back({a, b, c, d});
  // Region and quadrant boundaries: |s13| == |s24| (+-1 code), axes, both signs.
  for (int32_t m : {1, 2, 100, 4096, 8191, 8192, 11585, 16383, 32767})
    for (int32_t d : {-1, 0, 1})
      for (int sx : {-1, 1})
        for (int sy : {-1, 1}) {
          const int32_t md = std::min(m + d, F);
          in.push_back({sy * m, sx * md, 0, 0});
          in.push_back({sy * md, 0, 0, 0});
          in.push_back({0, sx * md, 0, 0});
        }
  // A fine sweep through every 45-degree boundary.
  for (int k = 0; k < 8; ++k)
    for (int j = -50; j <= 50; ++j) {
      const double th = k * M_PI / 4 + j * 1e-5;
      in.push_back({static_cast<int32_t>(std::lround(8192 * std::sin(th))),
                    static_cast<int32_t>(std::lround(8192 * std::cos(th))), 0, 0});
    }
  std::mt19937_64 rng(3);
  for (const RegImage& img : {identity_image(), paper_image()}) {
    RtlRunOptions opt;
    opt.gaps = 0.3;
    opt.backpressure = 0.3;
    const auto rtl = run_rtl(img, in, opt);
    EXPECT_EQ(mismatches(rtl, FixedModel(img), in, "corner inputs"), 0u);
  }
}

TEST(Cosim, RandomImagesAndInputsHitSaturation) {
  std::mt19937_64 rng(2024);
  size_t ovf = 0, los = 0, dos = 0, n = 0;
  for (int k = 0; k < 40; ++k) {
    const RegImage img = random_image(rng, k % 4 == 3);
    const auto in = random_codes(rng, 5000, img.cfg.in_w);
    RtlRunOptions opt;
    opt.seed = k + 1;
    opt.gaps = (k % 3) * 0.25;
    opt.backpressure = (k % 5) * 0.15;
    // Random status windows too.
    const int64_t a = rng() % 400000, b = rng() % 400000;
    opt.window = StatusWindow{std::min(a, b), std::max(a, b)};
    const auto rtl = run_rtl(img, in, opt);
    EXPECT_EQ(mismatches(rtl, FixedModel(img, *opt.window), in, "random image"), 0u) << k;
    for (const auto& s : rtl) {
      ovf += s.ovf;
      los += s.los;
      dos += s.dos;
    }
    n += in.size();
  }
  std::printf("random images: %zu samples, ovf %zu, los %zu, dos %zu\n", n, ovf, los, dos);
  EXPECT_GT(ovf, n / 100);
  EXPECT_GT(los, n / 100);
  EXPECT_GT(dos, n / 100);
}

TEST(Cosim, RejectsOtherConfigurations) {
  RegImage img = identity_image();
  img.cfg.iterations = 12;
  img.words.resize(img.cfg.words());
  EXPECT_THROW(run_rtl(img, {}, RtlRunOptions{}), InputError);
}

}  // namespace
}  // namespace acore
