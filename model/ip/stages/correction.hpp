// SPDX-License-Identifier: MIT
// Stage 4, the correction, across its modes: every mode's kernels, named in its row of
// core/correction_modes.hpp (the columns FIXED, VALUE, BASIS), with these signatures:
//   FIXED  void (int64_t s13, int64_t s24, int64_t x, int region, const int64_t* coef,
//                const DatapathConfig& cfg, int64_t* y13, int64_t* y24, bool* ovf)
//          both corrected curves of a sample, bit for bit the RTL stage; coef = the region's words
//          (c13's terms, then c24's); ovf is or-ed with any saturation
//   VALUE  double (const DatapathConfig& shape, const double* coef, double x, double y_other)
//          P(x, y_other) of one curve in double (the float model subtracts it)
//   BASIS  void (const DatapathConfig& shape, double x, double y_other, double* out)
//          the basis values in the register map's order, out[0 .. terms - 1] (the calibration's
//          least squares)
// The engines include this header and list the kernels from the rows (engine/fixed_model.cpp,
// engine/float_model.cpp, calibration/calibration.cpp through correction_basis()); a mode's
// stage header is included here, and the mode `none` (no stage) is defined here.
#pragma once
#include <cstdint>

#include "core/datapath_config.hpp"
#include "stages/poly2d_correct.hpp"
#include "stages/poly_correct.hpp"

namespace acore {

// none: y = s, no words, nothing to fit.
inline void none_correct_curves(int64_t s13, int64_t s24, int64_t /*x*/, int /*region*/,
                                const int64_t* /*coef*/, const DatapathConfig& /*cfg*/,
                                int64_t* y13, int64_t* y24, bool* /*ovf*/) {
  *y13 = s13;
  *y24 = s24;
}
inline double none_value(const DatapathConfig& /*shape*/, const double* /*coef*/, double /*x*/,
                         double /*y_other*/) {
  return 0.0;
}
inline void none_basis(const DatapathConfig& /*shape*/, double /*x*/, double /*y_other*/,
                       double* /*out*/) {}

}  // namespace acore
