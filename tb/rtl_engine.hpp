// SPDX-License-Identifier: MIT
// The Verilated RTL (rtl/acore_top.v) as an engine beside the float and bit-accurate models:
// run_rtl() picks the build of the register image's configuration (rtl/configs.txt, see
// rtl_builds.hpp), loads the image through the register write port, streams the samples with
// optional random input gaps and output backpressure, and returns one FixedSample per input
// (angle, region, ovf, los, dos; the model-only fields stay zero).
// RtlHarness is the pin-level driver underneath, for testbenches (reset mid-stream, reprogramming).
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "engine/fixed_model.hpp"
#include "regmap/regimage.hpp"

namespace acore {

struct RtlRunOptions {
  uint64_t seed = 1;                   // random stream for gaps and backpressure
  double backpressure = 0.0;           // probability that out_ready is low in a clock
  double gaps = 0.0;                   // probability that in_valid is low in a clock (an input gap)
  std::string trace;                   // FST waveform file; empty = no tracing (no overhead)
  std::optional<StatusWindow> window;  // mag_lo/mag_hi; default StatusWindow::defaults(cfg)
  // The build's FOLD (clocks per sample): 0 = the image's configuration (cfg.fold, 1 for every
  // image read from a file: a register image does not depend on FOLD); 1, 2, 4, 8 = that build.
  int fold = 0;
};

// Throws InputError when no Verilated build has the image's configuration (with opt.fold).
std::vector<FixedSample> run_rtl(const RegImage& img, const std::vector<ChannelCodes>& in,
                                 const RtlRunOptions& opt);

class RtlHarness {
 public:
  // trace: FST file ("" = none). rand_reset: Verilated::randReset mode for the initial state
  // (2 = random, proving that outputs are valid-gated). cfg: which build (rtl_build_for; throws
  // InputError when none has it).
  explicit RtlHarness(const std::string& trace = "", int rand_reset = 2, uint64_t seed = 1,
                      const DatapathConfig& cfg = DatapathConfig{});
  ~RtlHarness();
  RtlHarness(const RtlHarness&) = delete;
  RtlHarness& operator=(const RtlHarness&) = delete;

  // rst_i high for `cycles` clocks (inputs idle), then low.
  void reset(int cycles = 2);
  // Writes every word through the register port (one word per clock), then reads all back and
  // throws CheckFailed on a read-back difference.
  void load(const RegImage& img);
  // One word through the host read port: address, two clocks, reg_rdata_o (the host port timing of
  // both tops: README "RTL").
  uint64_t read_reg(int addr);
  // One word through the host write port (one clock; the word lands at the next edge).
  void write_reg(int addr, uint64_t value);
  // Drives the host port pins (address, write enable, data) without a clock.
  void drive_host(int addr, bool we, uint64_t wdata);
  uint64_t reg_rdata() const;  // the current reg_rdata_o pins
  void set_window(const StatusWindow& w);

  // Pin-level access: drive inputs, advance one clock, sample outputs (after the edge).
  void drive(bool in_valid, const ChannelCodes& c, bool out_ready);
  void tick();
  void set_reset(bool rst);
  bool in_ready() const;
  bool out_valid() const;
  FixedSample output() const;  // angle, region, ovf, los, dos of the current output pins
  // True when every data output is zero (they are forced to zero while out_valid is low).
  bool outputs_zero() const;
  uint64_t cycles() const;

  // Streams `in` with random gaps/backpressure from rng and collects every output in order.
  std::vector<FixedSample> stream(const std::vector<ChannelCodes>& in, double gaps,
                                  double backpressure, std::mt19937_64& rng);
  // The pipeline latency: LATENCY of this build of rtl/acore_top.v (Verilator public parameter).
  int latency() const;
  // Clocks per sample at full rate: CYCLES of this build (= FOLD).
  int cycles_per_sample() const;
  const DatapathConfig& config() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace acore
