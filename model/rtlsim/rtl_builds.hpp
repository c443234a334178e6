// SPDX-License-Identifier: MIT
// The Verilated builds of the registry (rtl/configs.txt): every line with the `sim` flow whose
// module is acore_top, acore_serial_top or acore_apb, as a table generated at configure time
// (model/rtlsim/CMakeLists.txt), each build a run-time module build/rtl/acore_rtl_<name>.so
// (rtl_plugin.hpp) loaded on first use. A register image finds its build by field equality of its
// configuration.
#pragma once
#include <ostream>
#include <string>
#include <vector>

#include "core/datapath_config.hpp"
#include "core/errors.hpp"
#include "rtlsim/rtl_plugin.hpp"

namespace acore {

// A build's run-time module is not where the engine looks: the message names the module, the
// folder and the command that builds it. An InputError (the CLI exits with 2).
class RtlNotBuilt : public InputError {
 public:
  using InputError::InputError;
};

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
  // The loaded module from rtl_plugin_dir(dir); throws RtlNotBuilt naming the module, the folder
  // and the command that builds it when it is not there.
  const rtl::PluginInfo& plugin(const std::string& dir = "") const;
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
// Those of rtl_builds_of(top) this CMake build Verilates: without -DACORE_RTL_LONG=ON the lines
// tagged long-sim are left out (the benches parametrized over builds run on these).
std::vector<const RtlBuild*> rtl_builds_made(RtlTop top);
// The registry's lines as model/rtlsim/CMakeLists.txt writes them into the generated
// rtl_registry.cpp.
struct RtlRegistryLine {
  const char* name;
  const char* module;
  const char* params;
};
extern const RtlRegistryLine kRtlRegistry[];
extern const int kRtlRegistrySize;

// GoogleTest prints a build parameter by its name.
inline void PrintTo(const RtlBuild* b, std::ostream* os) { *os << b->name; }
// Where the modules are looked for: dir when given; else $ACORE_RTL_DIR; else rtl/ beside the
// running program when it exists; else the folder fixed when this library was built
// (ACORE_RTL_PLUGIN_DIR: the build tree's rtl/, or for the Python package the one its set-up
// passes). "" when there is none.
std::string rtl_plugin_dir(const std::string& dir = "");

}  // namespace acore
