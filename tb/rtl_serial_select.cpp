// SPDX-License-Identifier: MIT
#include "core/errors.hpp"
#include "rtl_serial_builds.hpp"

namespace acore {

const RtlSerialBuild& rtl_serial_build_for(const DatapathConfig& cfg) {
  for (const RtlSerialBuild& b : rtl_serial_builds())
    if (b.config().describe() == cfg.describe()) return b;
  std::string list;
  for (const RtlSerialBuild& b : rtl_serial_builds())
    list += "\n  " + b.name + ": " + b.config().describe();
  throw InputError("no Verilated build of the serial core has the configuration " + cfg.describe() +
                   " (it implements CORRECTION=poly with XCENTER=0 and no Fourier stage; add an "
                   "rtl/serial_<name>.cfg and rebuild). Available:" +
                   list);
}

std::vector<FixedSample> run_rtl_serial_for(const RegImage& img,
                                            const std::vector<ChannelCodes>& in,
                                            const RtlRunOptions& opt) {
  return rtl_serial_build_for(img.cfg).run(img, in, opt);
}

}  // namespace acore
