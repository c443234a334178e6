// SPDX-License-Identifier: MIT
// The Verilated builds of the serial core (rtl/acore_serial_top.v) linked into this program: the
// default and each rtl/serial_<name>.cfg (tb/CMakeLists.txt generates the list). Like the pipelined
// top's rtl_builds.hpp: run_rtl_serial_for() picks the build whose configuration equals a register
// image's, so `anglecore estimate/cosim --engine rtl-serial` run any image a build exists for.
#pragma once
#include <string>
#include <vector>

#include "core/datapath_config.hpp"
#include "engine/fixed_model.hpp"
#include "regmap/regimage.hpp"
#include "rtl_engine.hpp"

namespace acore {

struct RtlSerialBuild {
  std::string name;  // "default", or the <name> of rtl/serial_<name>.cfg
  DatapathConfig (*config)();
  std::vector<FixedSample> (*run)(const RegImage& img, const std::vector<ChannelCodes>& in,
                                  const RtlRunOptions& opt);
};

// Every serial build, "default" first.
const std::vector<RtlSerialBuild>& rtl_serial_builds();
// The build for exactly this configuration; throws InputError listing the available ones.
const RtlSerialBuild& rtl_serial_build_for(const DatapathConfig& cfg);
// run_rtl_serial() of the image's build.
std::vector<FixedSample> run_rtl_serial_for(const RegImage& img,
                                            const std::vector<ChannelCodes>& in,
                                            const RtlRunOptions& opt);

}  // namespace acore
