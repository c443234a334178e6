// SPDX-License-Identifier: MIT
// The Verilated builds of rtl/acore_top.v linked into this program: one per named configuration
// of rtl/configs.txt (tb/CMakeLists.txt generates the list). The RTL engine picks the build whose
// configuration equals a register image's.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/datapath_config.hpp"
#include "rtl_pins.hpp"

namespace acore {

struct RtlBuild {
  std::string name;    // configuration name in rtl/configs.txt
  std::string params;  // its RTL parameter overrides, "DEGREE=5 REGIONS=8" ("" = the defaults)
  int latency;         // LATENCY of that build (Verilator public parameter)
  int cycles;          // CYCLES: clocks per sample at full rate (= FOLD)
  std::unique_ptr<RtlPins> (*make)(VerilatedContext* ctx, const char* name);
  DatapathConfig config() const { return DatapathConfig{}.with_rtl_params(params); }
};

// Every build, "default" first.
const std::vector<RtlBuild>& rtl_builds();
// The build for exactly this configuration; throws InputError listing the available ones.
const RtlBuild& rtl_build_for(const DatapathConfig& cfg);
// The build of this name; throws InputError listing the available ones.
const RtlBuild& rtl_build_named(const std::string& name);

}  // namespace acore
