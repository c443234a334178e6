// SPDX-License-Identifier: MIT
// The acore_cordic16_rtl library is the Verilated 16-bit CORDIC (rtl/cordic16.cfg); verilate() adds
// the generated sources to this target, which needs one source of its own.
namespace acore {
int cordic16_rtl_library_anchor = 0;
}  // namespace acore
