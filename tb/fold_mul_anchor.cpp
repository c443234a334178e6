// SPDX-License-Identifier: MIT
// The acore_fold_mul_rtl library is the Verilated folded multiplier in four parameter sets
// (tb/CMakeLists.txt); verilate() adds the generated sources to this target, which needs one
// source of its own.
namespace acore {
int fold_mul_rtl_library_anchor = 0;
}  // namespace acore
