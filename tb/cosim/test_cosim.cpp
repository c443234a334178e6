// SPDX-License-Identifier: MIT
// Co-sim regression of both tops through the one RTL harness: the Verilated pipelined top
// (acore_top, registry build `default`) and the serial core (acore_serial_top: `serial`,
// `serial_n5r8`, `serial_zero`) against the bit-accurate model (FixedModel::step), every output
// word of every sample: the paper scenario, random backpressure and input gaps, reset in
// mid-stream, register reprogramming between frames, corner inputs, random register images with
// random inputs (saturation paths, random status windows); the reset and host-port contract of
// both tops at every FOLD; the serial core's host port while it computes. The RTL starts from a
// random state (randReset(2)); outputs must be zero whenever out_valid is low.
// (One Verilated model alive at a time: Verilator 5.006 deadlocks destroying the second.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "calibration/calibration.hpp"
#include "core/errors.hpp"
#include "cosim/cosim_expect.hpp"
#include "cosim/host_port_checks.hpp"
#include "engine/estimator.hpp"
#include "engine/fixed_model.hpp"
#include "rtlsim/rtl_engine.hpp"
#include "support/paper_signals.hpp"

namespace acore {
namespace {

using cosim::mismatches;
using cosim::paper_codes;
using cosim::random_codes;

class Cosim : public ::testing::TestWithParam<const RtlBuild*> {
 protected:
  const RtlBuild& build() const { return *GetParam(); }
  const DatapathConfig& cfg() const { return build().cfg; }
  bool serial() const { return build().top == RtlTop::kSerial; }
  // A sample count for the pipelined top and for the serial core (86 to 226+ clocks a sample).
  size_t pick(size_t pipelined, size_t serial_core) const {
    return serial() ? serial_core : pipelined;
  }
  RtlRunOptions options() const {
    RtlRunOptions opt;
    opt.top = build().top;
    return opt;
  }

  // The paper scenario's calibrated, quantized coefficients for this build's configuration.
  RegImage paper_image() const {
    const Recording cal = test::paper_recording(4000, true);
    CalOptions opt;
    opt.degree = cfg().degree;
    opt.regions = cfg().regions;
    return quantize(calibrate(cal, opt), cfg(), choose_in_scale(cal, cfg().in_w));
  }
  RegImage identity_image() const { return cosim::identity_image(cfg()); }

  RegImage random_image(std::mt19937_64& rng, bool random_atan) const {
    return cosim::random_image(identity_image(), rng, random_atan);
  }
};

TEST_P(Cosim, LatencyAndCyclesAreTheNamedLocalparams) {
  RtlHarness h(build());
  const DatapathConfig& c = cfg();
  if (serial()) {
    // The schedule of rtl/acore_serial_ctrl.v, counted state by state: 22 single clocks, the two
    // scaling products (REG_W each; MULT = 1: one operation each), the two Horner evaluations
    // (DEGREE steps of S_W bits, an add and a wait; MULT = 1: the leading coefficient's load,
    // then DEGREE steps of one operation and a wait), the CORDIC (Y, X, Z per iteration), with
    // the ZERO word the rounding before the subtraction. The result comes one clock after the
    // core is idle.
    const int scaling = c.mult ? 1 : c.reg_w;
    const int horner = c.mult ? 1 + 2 * c.degree : c.degree * (c.s_w + 2);
    const int expected = 22 + c.zero_word + 2 * scaling + 2 * horner + 3 * c.iterations;
    EXPECT_EQ(h.cycles_per_sample(), expected);
    EXPECT_EQ(h.latency(), expected + 1);
    DatapathConfig with_mult;
    with_mult.mult = 1;
    if (c == DatapathConfig{}) EXPECT_EQ(expected, 226);
    if (c == with_mult) EXPECT_EQ(expected, 86);
  } else {
    EXPECT_EQ(h.cycles_per_sample(), c.fold);
    if (c == DatapathConfig{}) EXPECT_EQ(h.latency(), 55);  // 1 + 8 + 2 + 25 + 18 + 1
  }
  // Measured: accept one sample, count clocks until in_ready and out_valid rise.
  h.reset();
  h.load(identity_image());
  h.drive(true, {1000, 2000, 0, 0}, true);
  ASSERT_TRUE(h.in_ready());
  h.tick();
  h.drive(false, {0, 0, 0, 0}, true);
  int ready_at = 0, valid_at = 0;
  for (int n = 1; n < 100000 && !valid_at; ++n) {
    if (!ready_at && h.in_ready()) ready_at = n;
    if (h.out_valid()) valid_at = n;
    h.tick();
  }
  EXPECT_EQ(ready_at, h.cycles_per_sample());
  EXPECT_EQ(valid_at, h.latency());
}

TEST_P(Cosim, OneSampleEveryCyclesClocks) {
  // No gaps, no backpressure: sample k is taken at clock k CYCLES and appears LATENCY clocks
  // later, so n samples take (n-1) CYCLES + LATENCY + 1 clocks in RtlHarness::stream (the last
  // result is collected before its final tick); in_ready never drops on the pipelined top.
  const RegImage img = identity_image();
  const auto in = paper_codes(img, pick(5000, 300));
  RtlHarness h(build());
  h.reset();
  h.load(img);
  const uint64_t start = h.cycles();
  std::mt19937_64 rng(1);
  const auto out = h.stream(in, 0.0, 0.0, rng);
  EXPECT_EQ(out.size(), in.size());
  EXPECT_EQ(h.cycles() - start,
            (in.size() - 1) * static_cast<uint64_t>(h.cycles_per_sample()) + h.latency() + 1);
  EXPECT_EQ(mismatches(out, FixedModel(img), in, "identity image"), 0u);
}

TEST_P(Cosim, PaperScenario) {
  const RegImage img = paper_image();
  const auto in = paper_codes(img, pick(1000000, 20000));
  const auto rtl = run_rtl(img, in, options());
  EXPECT_EQ(mismatches(rtl, FixedModel(img), in, "paper scenario"), 0u);
  // The scenario must exercise every region.
  std::vector<int> seen(cfg().regions, 0);
  for (const auto& s : rtl) seen.at(s.region) = 1;
  for (int r = 0; r < cfg().regions; ++r) EXPECT_EQ(seen[r], 1) << "region " << r;
}

TEST_P(Cosim, RandomBackpressureAndGaps) {
  const RegImage img = paper_image();
  const auto in = paper_codes(img, pick(60000, 3000));
  const FixedModel model(img);
  for (const double p : {0.1, 0.5, 0.9}) {
    RtlRunOptions opt = options();
    opt.seed = static_cast<uint64_t>(p * 1000) + 7;
    opt.gaps = p;
    opt.backpressure = 1.0 - p;
    EXPECT_EQ(mismatches(run_rtl(img, in, opt), model, in, "gaps/backpressure"), 0u) << p;
  }
}

TEST_P(Cosim, OutputsZeroWhileInvalidAndResetMidStream) {
  const RegImage img = paper_image();
  const FixedModel model(img);
  const auto in = paper_codes(img, pick(5000, 2000));
  const size_t reset_at = pick(2000, 700);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  RtlHarness h(build(), "", 2, 99);
  // Before and during reset the outputs may be anything but never "valid" after one reset clock.
  h.reset(1);
  h.load(img);
  std::vector<FixedSample> out;
  size_t next = 0, invalid_nonzero = 0;
  bool did_reset = false;
  for (int cyc = 0; out.size() < in.size() && cyc < 2000000; ++cyc) {
    const bool valid = next < in.size() && u(rng) < 0.8;
    const bool ready = u(rng) < 0.8;
    h.drive(valid, valid ? in[next] : ChannelCodes{0, 0, 0, 0}, ready);
    if (!h.out_valid() && !h.outputs_zero()) ++invalid_nonzero;
    // Reset with samples in flight (the pipeline full; the serial core busy with one).
    if (!did_reset && next == reset_at && (!serial() || !h.in_ready())) {
      did_reset = true;
      // The sample on the pins stays offered: in_ready_o must be low in every reset clock.
      h.set_reset(true);
      for (int i = 0; i < 3; ++i) {
        EXPECT_FALSE(h.in_ready());
        h.tick();
      }
      h.set_reset(false);
      EXPECT_FALSE(h.out_valid());
      next = out.size();  // samples accepted but not delivered are lost: send them again
      continue;
    }
    if (valid && h.in_ready()) ++next;
    if (ready && h.out_valid()) out.push_back(h.output());
    h.tick();
  }
  EXPECT_TRUE(did_reset);
  EXPECT_EQ(invalid_nonzero, 0u);
  EXPECT_EQ(mismatches(out, model, in, "reset mid-stream"), 0u);
}

TEST_P(Cosim, RegisterReprogrammingBetweenFrames) {
  std::mt19937_64 rng(5);
  RtlHarness h(build());
  h.reset();
  const RegImage imgs[3] = {paper_image(), identity_image(), random_image(rng, false)};
  const size_t n = pick(3000, 600);
  for (int frame = 0; frame < 6; ++frame) {
    const RegImage& img = imgs[frame % 3];
    h.load(img);
    const auto in = frame % 2 ? random_codes(rng, n, img.cfg.in_w) : paper_codes(img, n);
    const auto out = h.stream(in, 0.2, 0.2, rng);
    EXPECT_EQ(mismatches(out, FixedModel(img), in, "reprogrammed frame"), 0u) << frame;
  }
  // Addresses past the last word read as zero and ignore writes: every word keeps its value,
  // and the datapath still computes with the image (every configuration of the registry).
  const RegImage& last = imgs[5 % 3];
  const host_port::PastLastWord p = host_port::writes_past_last_word(h, last);
  EXPECT_EQ(p.read_nonzero, 0);
  EXPECT_EQ(p.words_changed, 0);
  const auto in = random_codes(rng, n, last.cfg.in_w);
  EXPECT_EQ(
      mismatches(h.stream(in, 0.2, 0.2, rng), FixedModel(last), in, "after writes past the end"),
      0u);
}

TEST_P(Cosim, CornerInputs) {
  const int32_t F = (1 << (cfg().in_w - 1)) - 1, N = -(1 << (cfg().in_w - 1));
  std::vector<ChannelCodes> in;
  // Zero vector, full scale and saturated channels in combinations of extremes.
  const int32_t vals[] = {0, 1, -1, F, N, 8192, -8192, 16384, -16384, 4096};
  const std::vector<int32_t> c3 =
      serial() ? std::vector<int32_t>{0, F, N} : std::vector<int32_t>{0, F, N, 77};
  const std::vector<int32_t> c4 =
      serial() ? std::vector<int32_t>{0, F, N} : std::vector<int32_t>{0, F, N, -77};
  for (int32_t a : vals)
    for (int32_t b : vals)
      for (int32_t c : c3)
        for (int32_t d : c4) in.push_back({a, b, c, d});
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
  const int span = static_cast<int>(pick(50, 20));
  for (int k = 0; k < 8; ++k)
    for (int j = -span; j <= span; ++j) {
      const double th = k * M_PI / 4 + j * 1e-5;
      in.push_back({static_cast<int32_t>(std::lround(8192 * std::sin(th))),
                    static_cast<int32_t>(std::lround(8192 * std::cos(th))), 0, 0});
    }
  for (const RegImage& img : {identity_image(), paper_image()}) {
    RtlRunOptions opt = options();
    opt.gaps = 0.3;
    opt.backpressure = 0.3;
    const auto rtl = run_rtl(img, in, opt);
    EXPECT_EQ(mismatches(rtl, FixedModel(img), in, "corner inputs"), 0u);
  }
}

TEST_P(Cosim, RandomImagesAndInputsHitSaturation) {
  std::mt19937_64 rng(2024);
  size_t ovf = 0, los = 0, dos = 0, n = 0;
  const int images = static_cast<int>(pick(40, 20));
  for (int k = 0; k < images; ++k) {
    const RegImage img = random_image(rng, k % 4 == 3);
    const auto in = random_codes(rng, pick(5000, 800), img.cfg.in_w);
    RtlRunOptions opt = options();
    opt.seed = k + 1;
    opt.gaps = (k % 3) * 0.25;
    opt.backpressure = (k % 5) * 0.15;
    // Random status windows too, over the whole unsigned MAG_W-bit range.
    const int64_t span = int64_t{1} << (img.cfg.s_w + 1);
    const int64_t a = static_cast<int64_t>(rng() % span), b = static_cast<int64_t>(rng() % span);
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

TEST_P(Cosim, RejectsOtherConfigurations) {
  RegImage img = identity_image();
  img.cfg.iterations = img.cfg.iterations == 12 ? 13 : 12;
  img.words.resize(img.cfg.words());
  EXPECT_THROW(run_rtl(img, {}, options()), InputError);
}

std::string build_name(const ::testing::TestParamInfo<const RtlBuild*>& i) { return i.param->name; }

// The pipelined top in its default configuration and every build of the serial core.
std::vector<const RtlBuild*> data_builds() {
  std::vector<const RtlBuild*> v = {&rtl_build_named("default")};
  for (const RtlBuild* b : rtl_builds_made(RtlTop::kSerial)) v.push_back(b);
  return v;
}
INSTANTIATE_TEST_SUITE_P(Cosim, Cosim, ::testing::ValuesIn(data_builds()), build_name);

// The reset and host-port contract is the same on both tops and at every FOLD: the default
// configuration at FOLD 1, 2, 4, 8 and every serial build.
class CosimHostPort : public Cosim {};

std::vector<const RtlBuild*> host_port_builds() {
  std::vector<const RtlBuild*> v;
  for (int fold : {1, 2, 4, 8}) {
    DatapathConfig c;
    c.fold = fold;
    v.push_back(&rtl_build_for(RtlTop::kPipelined, c));
  }
  for (const RtlBuild* b : rtl_builds_made(RtlTop::kSerial)) v.push_back(b);
  return v;
}

TEST_P(CosimHostPort, ResetHoldsInReadyLowAndIgnoresHostWrites) {
  // rst_i high: in_ready_o low from the first clock (random power-up state), a sample offered in
  // reset is not taken (no output follows), a host write in reset changes no word.
  {
    RtlHarness fresh(build(), "", 2, 41);
    EXPECT_TRUE(host_port::in_ready_low_at_power_up_reset(fresh));
  }
  RtlHarness h(build(), "", 2, 42);
  const RegImage img = host_port::distinct_image(identity_image());
  const host_port::ResetBehaviour r = host_port::reset_behaviour(h, img, 8);
  EXPECT_EQ(r.in_ready_high, 0);
  EXPECT_EQ(r.out_valid_after, 0);
  EXPECT_EQ(r.words_changed, 0);
}

TEST_P(CosimHostPort, HostPortTimingIsTheTopsShared) {
  // reg_rdata_o is the word at the address of two clocks before, at one address per clock; a
  // write lands at the edge after the one that takes it, so a read whose address comes one clock
  // after the write returns the old word and two clocks after it the new one.
  RtlHarness h(build(), "", 2, 43);
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

TEST_P(CosimHostPort, WritesPastTheLastWordChangeNoWord) {
  // Every address from WORDS to the port's all-ones, written with the complement of the last word
  // (the word a missing range check would most likely hit): every word reads back unchanged,
  // those addresses read zero, and the outputs are the model's with the image as loaded.
  std::mt19937_64 rng(44);
  RtlHarness h(build(), "", 2, 44);
  h.reset();
  for (const RegImage& base : {paper_image(), random_image(rng, false)}) {
    const host_port::PastLastWord p = host_port::writes_past_last_word(h, base);
    EXPECT_GT(p.addresses, 0);
    EXPECT_EQ(p.read_nonzero, 0);
    EXPECT_EQ(p.words_changed, 0);
    const auto in = random_codes(rng, pick(2000, 400), base.cfg.in_w);
    EXPECT_EQ(mismatches(h.stream(in, 0.1, 0.1, rng), FixedModel(base), in, "past the last word"),
              0u);
  }
}

INSTANTIATE_TEST_SUITE_P(Cosim, CosimHostPort, ::testing::ValuesIn(host_port_builds()), build_name);

// The serial core only: its one RAM read port belongs to the datapath while a sample is computed.
class CosimSerial : public Cosim {};

TEST_P(CosimSerial, HostPortWhileComputing) {
  // reg_rdata_o, two clocks after an address, reads zero for an address given in a busy clock and
  // the word for one given in an idle clock. Host writes land in any clock; one that meets a
  // scratch write delays the sample by a clock. Rewriting the loaded words (same values) in random
  // clocks of a stream must leave every result equal to the model's and cost at most one clock
  // per write.
  const RegImage img = paper_image();
  const auto in = paper_codes(img, 300);
  std::mt19937_64 rng(17);
  RtlHarness h(build());
  h.reset();
  h.load(img);
  const uint64_t start = h.cycles();
  std::vector<FixedSample> out;
  size_t next = 0, writes = 0, busy_reads = 0, busy_nonzero = 0, idle_reads = 0, idle_wrong = 0;
  const int words = static_cast<int>(img.words.size());
  bool prev_idle = false;
  int prev_addr = -1;
  while (out.size() < in.size() && h.cycles() - start < 1000000) {
    const bool idle = h.in_ready();
    const int addr = static_cast<int>(rng() % words);
    const bool we = (rng() % 3) == 0;
    h.drive_host(addr, we, img.words[addr]);
    h.drive(next < in.size(), next < in.size() ? in[next] : ChannelCodes{0, 0, 0, 0}, true);
    if (next < in.size() && h.in_ready()) ++next;
    if (h.out_valid()) out.push_back(h.output());
    h.tick();
    writes += we;
    // After this edge the pins show the read of the previous clock's address.
    if (prev_addr >= 0) {
      if (prev_idle) {
        ++idle_reads;
        idle_wrong += h.reg_rdata() != img.words[prev_addr];
      } else {
        ++busy_reads;
        busy_nonzero += h.reg_rdata() != 0;
      }
    }
    prev_idle = idle;
    prev_addr = addr;
  }
  h.drive_host(0, false, 0);
  EXPECT_EQ(mismatches(out, FixedModel(img), in, "host port while computing"), 0u);
  const uint64_t clocks = h.cycles() - start;
  const uint64_t ideal =
      (in.size() - 1) * static_cast<uint64_t>(h.cycles_per_sample()) + h.latency() + 1;
  EXPECT_GE(clocks, ideal);
  EXPECT_LE(clocks, ideal + writes + 1);
  EXPECT_GT(clocks, ideal);  // some writes met a scratch write
  // Every clock of a sample but the accepting one is busy (86 to 226+ of them).
  EXPECT_GT(busy_reads, static_cast<size_t>(h.cycles_per_sample() - 2) * in.size());
  EXPECT_EQ(busy_nonzero, 0u);
  EXPECT_GE(idle_reads, in.size());
  EXPECT_EQ(idle_wrong, 0u);
}

INSTANTIATE_TEST_SUITE_P(Cosim, CosimSerial, ::testing::ValuesIn(rtl_builds_made(RtlTop::kSerial)),
                         build_name);

}  // namespace
}  // namespace acore
