// SPDX-License-Identifier: MIT
// The interface between the RTL engine and one Verilated build of the registry (rtl/configs.txt),
// loaded at run time. Every `sim` build of acore_top, acore_serial_top and acore_apb is compiled
// into its own shared module, build/rtl/acore_rtl_<name>.so, with its own copy of the Verilator
// runtime and its own VerilatedContext: a program (anglecore, a test) links no Verilated code,
// loads the builds it runs and nothing else, so building `anglecore` builds only the RTL it needs.
//
//   host (rtl_builds.cpp, rtl_engine.cpp)          plugin (rtl_plugin_impl.hpp + generated source)
//   dlopen("acore_rtl_fold2.so") ------------------> acore_rtl_plugin(): PluginInfo
//   info.make_top({trace, rand_reset, seed}) ------> new VerilatedTop<Vacore_rtl_fold2>
//   TopModel: set_in / tick / output ...  <-------- pins of that build, whatever their C++ widths
//
// The interfaces are abstract C++ classes; host and plugins are built by the same compiler from the
// same headers in one build tree (kAbi guards against a stale module).
#pragma once
#include <cstdint>

#include "engine/fixed_model.hpp"

namespace acore::rtl {

// Bumped whenever a class below changes: a plugin of another version is refused.
constexpr int kAbi = 1;

struct SimOptions {
  const char* trace = nullptr;  // FST waveform file; nullptr = none (tracing costs nothing then)
  int rand_reset = 2;           // Verilated randReset mode for the initial state (2 = random)
  uint64_t seed = 1;            // its seed
};

// A Verilated model with its context: clock, reset, trace, the sample stream, public variables.
class Model {
 public:
  virtual ~Model() = default;
  // Settles the combinational outputs; with dump, writes the trace at the current time.
  virtual void eval(bool dump) = 0;
  // One clock: clk_i high, evaluate, dump; clk_i low, evaluate, dump (two time units).
  virtual void tick() = 0;
  virtual void set_rst(bool v) = 0;
  // The sample stream (the same pins on every top and on the shell); the codes are ANDed with
  // in_mask (the build's IN_W bits).
  virtual void set_in(bool valid, const ChannelCodes& c, uint32_t in_mask) = 0;
  virtual void set_out_ready(bool v) = 0;
  virtual bool in_ready() const = 0;
  virtual bool out_valid() const = 0;
  // angle, region, ovf, los, dos, magnitude of the output pins
  virtual FixedSample output() const = 0;
  // The data of a Verilator-public variable (scope as "acore_apb.g_serial.u_top", name "mem_q"),
  // or nullptr when the build has no such public variable.
  virtual void* public_var(const char* scope, const char* name) = 0;
};

// acore_top (any FOLD) and acore_serial_top: the same port list.
class TopModel : public Model {
 public:
  // The register file's host port: address, write data, write enable.
  virtual void set_reg(uint32_t addr, uint64_t wdata, bool we) = 0;
  virtual uint64_t reg_rdata() const = 0;
  // The status window (mag_lo_i, mag_hi_i).
  virtual void set_window(uint64_t lo, uint64_t hi) = 0;
};

// acore_apb: the APB4 register shell around either top.
class ShellModel : public Model {
 public:
  virtual void set_apb(bool psel, bool penable, bool pwrite, uint32_t paddr, uint32_t pwdata,
                       uint32_t pstrb) = 0;
  virtual uint32_t prdata() const = 0;
  virtual bool pready() const = 0;
  virtual bool pslverr() const = 0;
  virtual bool irq() const = 0;
  virtual bool out_tag() const = 0;
};

// What a plugin exports (extern "C" acore_rtl_plugin()).
struct PluginInfo {
  int abi;             // kAbi of the plugin's build
  const char* name;    // registry name
  const char* module;  // acore_top, acore_serial_top or acore_apb
  const char* params;  // the registry line's parameters, "FOLD=2" ("" = the defaults)
  int latency;         // LATENCY of the built top (Verilator public localparam; 0 for the shell)
  int cycles;          // CYCLES: clocks per sample at full rate (0 for the shell)
  TopModel* (*make_top)(const SimOptions& opt);      // tops; nullptr for the shell
  ShellModel* (*make_shell)(const SimOptions& opt);  // the shell; nullptr for the tops
};

}  // namespace acore::rtl

// The one symbol a plugin exports.
extern "C" const acore::rtl::PluginInfo* acore_rtl_plugin();
