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

// The folder the modules are looked for in, and what chose it (for the error message).
struct ModuleDir {
  std::string dir;
  std::string chosen_by;
};

ModuleDir module_dir(const std::string& dir) {
  if (!dir.empty()) return {dir, "the folder given"};
  if (const char* env = std::getenv("ACORE_RTL_DIR"); env && *env) return {env, "$ACORE_RTL_DIR"};
  const std::string beside = program_dir() + "/rtl";
  if (exists(beside)) return {beside, "rtl/ beside the program"};
  return {ACORE_RTL_PLUGIN_DIR, "the module folder fixed at build time"};
}

// A line tagged long-sim in rtl/configs.txt, which this build leaves out without
// -DACORE_RTL_LONG=ON.
bool long_left_out(const std::string& name) {
  const std::string unbuilt = std::string(",") + ACORE_RTL_LONG_UNBUILT + ",";
  return unbuilt.find("," + name + ",") != std::string::npos;
}

// The command that builds a module. The build tree is the parent of the module folder fixed at
// build time (CMake writes the modules to <build>/rtl); ACORE_RTL_MODULES_HERE says whether that
// build makes them (1), was configured without them (0), or is another build (-1: the Python
// package's, whose set-up names the repository's build/rtl). elsewhere: the engine looked in
// another folder than the one the command writes to, so say where that is.
std::string build_command(const std::string& name, bool elsewhere) {
  const std::string target = "acore_rtl_" + name;
  std::string build = ACORE_RTL_PLUGIN_DIR;
  const std::string tail = "/rtl";
  if (build.size() > tail.size() &&
      build.compare(build.size() - tail.size(), tail.size(), tail) == 0)
    build.resize(build.size() - tail.size());
  else
    build.clear();
  if (build.empty())
    return "`cmake --build build --target " + target + "` in the repository (it writes build/rtl/)";
  const std::string writes = elsewhere ? " (it writes " + build + "/rtl/)" : "";
  if (long_left_out(name))
    return "`cmake -DACORE_RTL_LONG=ON " + build + " && cmake --build " + build + " --target " +
           target + "` (a line tagged long-sim)" + writes;
  if (ACORE_RTL_MODULES_HERE == 0)
    return "`cmake -DACORE_WITH_RTL=ON " + build + " && cmake --build " + build + " --target " +
           target + "` (this build was configured with -DACORE_WITH_RTL=OFF)" + writes;
  return "`cmake --build " + build + " --target " + target + "`" + writes;
}

}  // namespace

std::string rtl_plugin_dir(const std::string& dir) { return module_dir(dir).dir; }

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

std::vector<const RtlBuild*> rtl_builds_made(RtlTop top) {
  std::vector<const RtlBuild*> v;
  for (const RtlBuild* b : rtl_builds_of(top))
    if (!long_left_out(b->name)) v.push_back(b);
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

const rtl::PluginInfo& RtlBuild::plugin(const std::string& dir) const {
  static std::mutex mu;
  static std::map<std::string, const rtl::PluginInfo*> loaded;  // by path
  const std::lock_guard<std::mutex> lock(mu);
  const ModuleDir where = module_dir(dir);
  const std::string file = "acore_rtl_" + name + ".so";
  const std::string what = "the RTL engine's module " + file + " (the Verilated build '" + name +
                           "': " + module + ", " + (params.empty() ? "defaults" : params) + ")";
  const std::string or_dir = ", or set ACORE_RTL_DIR to the rtl/ folder of a build that has it";
  if (where.dir.empty())
    throw RtlNotBuilt("the RTL engine has no folder to find " + what +
                      " in: set ACORE_RTL_DIR to the rtl/ folder of a build that has it; build it "
                      "with " +
                      build_command(name, false));
  const std::string path = where.dir + "/" + file;
  if (auto it = loaded.find(path); it != loaded.end()) return *it->second;
  if (!exists(path))
    throw RtlNotBuilt(what + " is not built: " + path + " (" + where.chosen_by +
                      ") does not exist; build it with " +
                      build_command(name, where.dir != ACORE_RTL_PLUGIN_DIR) + or_dir);
  // RTLD_LOCAL: each module keeps its own Verilator runtime; never unloaded.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw InputError(path + ": cannot load the Verilated build: " + dlerror());
  using Entry = const rtl::PluginInfo* (*)();
  const auto entry = reinterpret_cast<Entry>(dlsym(handle, "acore_rtl_plugin"));
  if (!entry) throw InputError(path + ": not an RTL build (no acore_rtl_plugin)");
  const rtl::PluginInfo* info = entry();
  if (info->abi != rtl::kAbi || name != info->name || params != info->params)
    throw InputError(path + ": built for another version of the engine or of rtl/configs.txt; " +
                     "rebuild it with " + build_command(name, where.dir != ACORE_RTL_PLUGIN_DIR));
  loaded[path] = info;
  return *info;
}

}  // namespace acore
