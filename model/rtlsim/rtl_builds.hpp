// SPDX-License-Identifier: MIT
// The Verilated builds of the registry (rtl/configs.txt): every line with the `sim` flow whose
// module is acore_top, acore_serial_top or acore_apb, as a table generated at configure time
// (tb/CMakeLists.txt), each build a run-time module build/rtl/acore_rtl_<name>.so (rtl_plugin.hpp)
// loaded on first use. A register image finds its build by field equality of its configuration.
#pragma once
#include <ostream>
#include <string>
#include <vector>

#include "core/datapath_config.hpp"
#include "rtlsim/rtl_plugin.hpp"

namespace acore {

enum class RtlTop { kPipelined, kSerial, kShell };

struct RtlBuild {
  std::string name;    // registry name
  std::string module;  // acore_top, acore_serial_top, acore_apb
  std::string params;  // the registry line's parameters ("" = the module's defaults)
  RtlTop top;
  // The datapath configuration the build computes (the estimator's parameters of the line applied
  // to the defaults); for the shell, that of the top it wraps.
  DatapathConfig cfg;
  bool serial = false;  // the shell wraps the serial core (SERIAL=1)
  // The loaded module; throws InputError naming the build target when it is not built.
  const rtl::PluginInfo& plugin() const;
};

// Every build of the registry with the `sim` flow, in the registry's order.
const std::vector<RtlBuild>& rtl_builds();
// The build of this name; throws InputError listing the builds.
const RtlBuild& rtl_build_named(const std::string& name);
// The build of this top whose configuration equals cfg (every field, FOLD included); throws
// InputError naming the configuration and listing the builds of that top.
const RtlBuild& rtl_build_for(RtlTop top, const DatapathConfig& cfg);
// The builds of one top (the co-sim tests run over them).
std::vector<const RtlBuild*> rtl_builds_of(RtlTop top);
// The registry's lines as tb/CMakeLists.txt writes them into the generated rtl_registry.cpp.
struct RtlRegistryLine {
  const char* name;
  const char* module;
  const char* params;
};
extern const RtlRegistryLine kRtlRegistry[];
extern const int kRtlRegistrySize;

// GoogleTest prints a build parameter by its name.
inline void PrintTo(const RtlBuild* b, std::ostream* os) { *os << b->name; }
// Where the modules are looked for: $ACORE_RTL_DIR, else rtl/ beside the running program, else
// the build tree's rtl/ this program was built in.
std::string rtl_plugin_dir();

}  // namespace acore
