// SPDX-License-Identifier: MIT
// The Verilated serial core (rtl/acore_serial_top.v) as an engine beside the float and bit-accurate
// models and the pipelined RTL (tb/rtl_engine.hpp): run_rtl_serial() loads a register image through
// the register write port, streams the samples with optional random input gaps and output
// backpressure, and returns one FixedSample per input (angle, region, ovf, los, dos).
// RtlSerialHarness is the pin-level driver underneath, for testbenches.
//
// tb/rtl_serial_engine.cpp is compiled once per named configuration of the serial core: the default
// (library acore_rtl_serial) and rtl/serial_<name>.cfg (acore_rtl_serial_<name>); each build's
// code sits in its own inline namespace acore::serial_<name> (ACORE_SERIAL_NS, default
// serial_default), so a program can link several: a test sees the one it defines ACORE_SERIAL_NS
// for, rtl_serial_config() is that build's configuration, and rtl_serial_builds.hpp picks a build
// by a register image's configuration (what anglecore does).
#pragma once
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "engine/fixed_model.hpp"
#include "regmap/regimage.hpp"
#include "rtl_engine.hpp"

#ifndef ACORE_SERIAL_NS
#define ACORE_SERIAL_NS serial_default
#endif

namespace acore {
inline namespace ACORE_SERIAL_NS {

// Throws InputError when the image's configuration is not the one the serial RTL was built with.
std::vector<FixedSample> run_rtl_serial(const RegImage& img, const std::vector<ChannelCodes>& in,
                                        const RtlRunOptions& opt);

// The configuration the Verilated serial core was built with.
DatapathConfig rtl_serial_config();

class RtlSerialHarness {
 public:
  // trace: FST file ("" = none). rand_reset: Verilated::randReset mode for the initial state
  // (2 = random, proving that outputs are valid-gated and only control flops need a reset).
  explicit RtlSerialHarness(const std::string& trace = "", int rand_reset = 2, uint64_t seed = 1);
  ~RtlSerialHarness();
  RtlSerialHarness(const RtlSerialHarness&) = delete;
  RtlSerialHarness& operator=(const RtlSerialHarness&) = delete;

  // rst_i high for `cycles` clocks (inputs idle), then low.
  void reset(int cycles = 2);
  // Writes every word through the register port (one word per clock), then reads all back and
  // throws CheckFailed on a read-back difference. Call while the core is idle.
  void load(const RegImage& img);
  // One word through the host read port: address, two clocks, reg_rdata_o (while the core is idle).
  uint64_t read_reg(int addr);
  // One word through the host write port (one clock; the word lands at the next edge), whatever
  // the core is doing.
  void write_reg(int addr, uint64_t value);
  // Drives the host port pins (address, write enable, data) without a clock.
  void drive_host(int addr, bool we, uint64_t wdata);
  void set_window(const StatusWindow& w);

  // Pin-level access: drive inputs, advance one clock, sample outputs (after the edge).
  void drive(bool in_valid, const ChannelCodes& c, bool out_ready);
  void tick();
  void set_reset(bool rst);
  bool in_ready() const;
  bool out_valid() const;
  FixedSample output() const;  // angle, region, ovf, los, dos of the current output pins
  bool outputs_zero() const;   // every data output is zero (forced while out_valid is low)
  uint64_t reg_rdata() const;  // the current reg_rdata_o pins
  uint64_t cycles() const;

  // Streams `in` with random gaps/backpressure from rng and collects every output in order.
  std::vector<FixedSample> stream(const std::vector<ChannelCodes>& in, double gaps,
                                  double backpressure, std::mt19937_64& rng);
  // Clocks per sample (CYCLES) and from the accepting clock to out_valid (LATENCY) of
  // rtl/acore_serial_top.v (Verilator public parameters).
  static int cycles_per_sample();
  static int latency();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ACORE_SERIAL_NS
}  // namespace acore
