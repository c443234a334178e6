// SPDX-License-Identifier: MIT
// The one dispatch from an engine (float, fixed, rtl, rtl-serial: engine/estimator.hpp) and its
// options to the results on a recording: what `anglecore estimate`, `anglecore demo`,
// `anglecore cosim` and the Python package run. The bit-accurate model and the two RTL tops
// return the chain's output words per sample (rows) as well as the angles in the reference frame;
// the float engine returns the angles only.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "engine/estimator.hpp"
#include "engine/float_model.hpp"
#include "rtlsim/rtl_engine.hpp"

namespace acore {

struct EngineOptions {
  // rtl: the pipelined build folded to this many clocks per sample (fold_values(); a register image
  // does not depend on it); 1 for every other engine.
  int fold = 1;
  // The RTL engines only: the stream's random input gaps and output backpressure (probabilities
  // per clock) and their seed, an FST waveform file ("" = none), the status window (default
  // StatusWindow::defaults), the folder of the run-time modules ("" = rtl_plugin_dir()).
  double gaps = 0.0;
  double backpressure = 0.0;
  uint64_t seed = 1;
  std::string trace;
  std::optional<StatusWindow> window;
  std::string module_dir;
  // float: these coefficients instead of the image's dequantized ones (the demo's float row runs
  // the calibration's own, unquantized).
  std::optional<FloatCoefficients> float_coefficients;
};

struct EngineRun {
  // Angles in the reference frame; for the RTL engines the uncorrected angle is the bit-accurate
  // model's (the RTL has no such output; the front end is the same).
  AngleSeries series;
  // fixed, rtl, rtl-serial: one row per sample (angle, region, ovf, los, dos, magnitude; the
  // model's intermediate fields too for fixed); empty for float.
  std::vector<FixedSample> rows;
};

bool is_rtl(Engine e);
// Throws InputError (in the command's words) when an option does not apply to the engine: a fold
// other than 1 for any engine but rtl, gaps, backpressure, a trace or a window for float or fixed.
void check_engine_options(Engine e, const EngineOptions& opt);
// Runs the engine over the recording with the image. Throws InputError as check_engine_options,
// or when no Verilated build has the image's configuration; RtlNotBuilt when its module is not
// built (the message names the command that builds it).
EngineRun run_engine(Engine e, const Recording& rec, const RegImage& img,
                     const EngineOptions& opt = {});

}  // namespace acore
