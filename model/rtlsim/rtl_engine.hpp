// SPDX-License-Identifier: MIT
// The Verilated RTL as an engine beside the float and bit-accurate models, for both tops:
// run_rtl() picks the build of the register image's configuration (rtl_builds.hpp: the pipelined
// top acore_top at any FOLD, or the serial core acore_serial_top), loads the image through the
// register write port, streams the samples with optional random input gaps and output
// backpressure, and returns one FixedSample per input (angle, region, ovf, los, dos, magnitude; the
// model-only fields stay zero).
// RtlHarness is the pin-level driver underneath, one for both tops (they share their port list and
// host-port timing), for testbenches: reset mid-stream, reprogramming, host port while computing.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "engine/fixed_model.hpp"
#include "regmap/regimage.hpp"
#include "rtlsim/rtl_builds.hpp"

namespace acore {

struct RtlRunOptions {
  RtlTop top = RtlTop::kPipelined;     // which top: pipelined (acore_top) or serial
  uint64_t seed = 1;                   // random stream for gaps and backpressure
  double backpressure = 0.0;           // probability that out_ready is low in a clock
  double gaps = 0.0;                   // probability that in_valid is low in a clock (an input gap)
  std::string trace;                   // FST waveform file; empty = no tracing (no overhead)
  std::optional<StatusWindow> window;  // mag_lo/mag_hi; default StatusWindow::defaults(cfg)
  // The pipelined build's FOLD (clocks per sample): 0 = the image's configuration (cfg.fold, 1
  // for every image read from a file: a register image does not depend on FOLD); a value of
  // fold_values() = that build.
  int fold = 0;
  std::string module_dir;  // where the build's module is ("" = rtl_plugin_dir())
};

// Throws InputError when no Verilated build of opt.top has the image's configuration (with
// opt.fold), RtlNotBuilt when that build's module is not built.
std::vector<FixedSample> run_rtl(const RegImage& img, const std::vector<ChannelCodes>& in,
                                 const RtlRunOptions& opt);

class RtlHarness {
 public:
  // build: a build of acore_top or acore_serial_top (rtl_build_for, rtl_build_named).
  // trace: FST file ("" = none). rand_reset: Verilated::randReset mode for the initial state
  // (2 = random, proving that outputs are valid-gated and only control flops need a reset).
  // module_dir: where the build's module is ("" = rtl_plugin_dir()).
  explicit RtlHarness(const RtlBuild& build, const std::string& trace = "", int rand_reset = 2,
                      uint64_t seed = 1, const std::string& module_dir = "");
  ~RtlHarness();
  RtlHarness(const RtlHarness&) = delete;
  RtlHarness& operator=(const RtlHarness&) = delete;

  // rst_i high for `cycles` clocks (inputs idle), then low.
  void reset(int cycles = 2);
  // Writes every word through the register port (one word per clock), then reads all back and
  // throws CheckFailed on a read-back difference. (The serial core: call while it is idle.)
  void load(const RegImage& img);
  // One word through the host read port: address, two clocks, reg_rdata_o (the host port timing
  // of both tops).
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
  FixedSample output() const;  // angle, region, ovf, los, dos, magnitude of the current output pins
  // True when every data output is zero (they are forced to zero while out_valid is low).
  bool outputs_zero() const;
  uint64_t cycles() const;

  // Streams `in` with random gaps/backpressure from rng and collects every output in order.
  std::vector<FixedSample> stream(const std::vector<ChannelCodes>& in, double gaps,
                                  double backpressure, std::mt19937_64& rng);
  // From the accepting edge to out_valid: LATENCY of this build (Verilator public localparam).
  int latency() const;
  // Clocks per sample at full rate: CYCLES of this build (FOLD for acore_top).
  int cycles_per_sample() const;
  const DatapathConfig& config() const;
  const RtlBuild& build() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace acore
