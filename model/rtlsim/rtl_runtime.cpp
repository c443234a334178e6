// SPDX-License-Identifier: MIT
// A library that verilate() fills: acore_vlt_runtime (the Verilator runtime, compiled once and
// linked into every RTL module) and the stand-alone test builds (acore_sim_<name>) need a source of
// their own besides the generated ones.
namespace acore {
int rtl_library_anchor = 0;
}  // namespace acore
