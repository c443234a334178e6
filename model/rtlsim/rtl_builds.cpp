// SPDX-License-Identifier: MIT
#include "rtlsim/rtl_builds.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <map>
#include <mutex>
#include <sstream>

#include "core/errors.hpp"

namespace acore {

namespace {

// The parameters of a shell line that are the shell's own, not the wrapped top's.
bool is_shell_param(const std::string& name) {
  return name == "SERIAL" || name == "CRC_W" || name == "INIT_FILE";
}

RtlBuild make_build(const RtlRegistryLine& line) {
  RtlBuild b;
  b.name = line.name;
  b.module = line.module;
  b.params = line.params;
  if (b.module == "acore_top") {
    b.top = RtlTop::kPipelined;
  } else if (b.module == "acore_serial_top") {
    b.top = RtlTop::kSerial;
  } else {
    b.top = RtlTop::kShell;
  }
  std::istringstream in(b.params);
  std::string tok, datapath;
  while (in >> tok) {
    const std::string key = tok.substr(0, tok.find('='));
    if (b.top == RtlTop::kShell && is_shell_param(key)) {
      b.serial = b.serial || tok == "SERIAL=1";
      continue;
    }
    datapath += tok + " ";
  }
  b.cfg = DatapathConfig{}.with_rtl_params(datapath);
  return b;
}

std::string list_of(const std::vector<const RtlBuild*>& builds) {
  std::string s;
  for (const RtlBuild* b : builds)
    s += "\n  " + b->name + (b->params.empty() ? " (defaults)" : " (" + b->params + ")");
  return s;
}

const char* top_name(RtlTop t) {
  switch (t) {
    case RtlTop::kPipelined:
      return "acore_top";
    case RtlTop::kSerial:
      return "acore_serial_top";
    default:
      return "acore_apb";
  }
}

std::string program_dir() {
  char buf[4096];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) return "";
  std::string p(buf, static_cast<size_t>(n));
  return p.substr(0, p.rfind('/'));
}

bool exists(const std::string& path) { return access(path.c_str(), R_OK) == 0; }

}  // namespace

std::string rtl_plugin_dir() {
  if (const char* env = std::getenv("ACORE_RTL_DIR"); env && *env) return env;
  const std::string beside = program_dir() + "/rtl";
  if (exists(beside)) return beside;
  return ACORE_RTL_PLUGIN_DIR;
}

const std::vector<RtlBuild>& rtl_builds() {
  static const std::vector<RtlBuild> builds = [] {
    std::vector<RtlBuild> v;
    for (int i = 0; i < kRtlRegistrySize; ++i) v.push_back(make_build(kRtlRegistry[i]));
    return v;
  }();
  return builds;
}

std::vector<const RtlBuild*> rtl_builds_of(RtlTop top) {
  std::vector<const RtlBuild*> v;
  for (const RtlBuild& b : rtl_builds())
    if (b.top == top) v.push_back(&b);
  return v;
}

const RtlBuild& rtl_build_named(const std::string& name) {
  std::vector<const RtlBuild*> all;
  for (const RtlBuild& b : rtl_builds()) {
    if (b.name == name) return b;
    all.push_back(&b);
  }
  throw InputError("no Verilated build is named '" + name +
                   "' (rtl/configs.txt). Builds:" + list_of(all));
}

const RtlBuild& rtl_build_for(RtlTop top, const DatapathConfig& cfg) {
  const std::vector<const RtlBuild*> same_top = rtl_builds_of(top);
  for (const RtlBuild* b : same_top)
    if (b->cfg == cfg) return *b;
  throw InputError(std::string("no Verilated build of ") + top_name(top) +
                   " has the configuration " + cfg.describe() +
                   "; add a line to rtl/configs.txt and rebuild. Builds of " + top_name(top) + ":" +
                   list_of(same_top));
}

const rtl::PluginInfo& RtlBuild::plugin() const {
  static std::mutex mu;
  static std::map<std::string, const rtl::PluginInfo*> loaded;
  const std::lock_guard<std::mutex> lock(mu);
  if (auto it = loaded.find(name); it != loaded.end()) return *it->second;
  const std::string path = rtl_plugin_dir() + "/acore_rtl_" + name + ".so";
  if (!exists(path))
    throw InputError("the Verilated build '" + name + "' (" + module + " " +
                     (params.empty() ? "defaults" : params) + ") is not built: " + path +
                     " is missing; build it with `cmake --build build --target acore_rtl_" + name +
                     "`");
  // RTLD_LOCAL: each module keeps its own Verilator runtime; never unloaded.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw InputError(path + ": cannot load the Verilated build: " + dlerror());
  using Entry = const rtl::PluginInfo* (*)();
  const auto entry = reinterpret_cast<Entry>(dlsym(handle, "acore_rtl_plugin"));
  if (!entry) throw InputError(path + ": not an RTL build (no acore_rtl_plugin)");
  const rtl::PluginInfo* info = entry();
  if (info->abi != rtl::kAbi || name != info->name)
    throw InputError(path + ": built for another version of the engine (rebuild it)");
  loaded[name] = info;
  return *info;
}

}  // namespace acore
