// SPDX-License-Identifier: MIT
// The whole of `anglecore calibrate` as one call: every option of the command in one struct, the
// datapath configuration it implies, the fit, the quantization and the fit-quality report. The CLI
// (model/cli/cmd_calibrate.cpp) and the Python package (python/) both call it, so that an image
// made either way holds the same words.
#pragma once
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "calibration/calibration.hpp"
#include "calibration/self_calibration.hpp"
#include "core/error_stats.hpp"

namespace acore {

// One field per option of `anglecore calibrate` (the option's name with '-' -> '_'); the defaults
// are the command's. Unset optionals take the --angle-w preset's value (iterations) or the
// automatic choice (coef_frac, in_scale = 0, periodicity = 0: the recording's `# p=`).
struct CalibrateSpec {
  std::string correction = "poly";  // a mode's name (core/correction_modes.hpp)
  int degree = 3;                   // the mode's (total) degree, its limits in its row
  int regions = 4;                  // 4 or 8
  bool xcenter = false;             // 8 regions only
  std::optional<int> iterations;    // CORDIC iterations 4..24
  std::optional<int> coef_frac;     // fraction bits of a coefficient 1..17
  int angle_w = 16;                 // 8..20
  int in_w = 16;                    // 8..24
  double in_scale = 0;              // input codes per recording unit; 0: automatic power of two
  int periodicity = 0;              // 1..64; 0: the recording's
  int fourier = 0;                  // harmonics K of the Fourier correction, 0..31
  int fourier_iterations = DatapathConfig{}.fourier_iterations;  // 4..24
  int fourier_guard = DatapathConfig{}.fourier_guard;            // 0..8
  std::string zero_offset = "auto";     // "auto" or an electrical angle in degrees
  bool zero_word = false;               // store the zero offset in one more register word
  int mult = 0;                         // MULT: 0 adders and shifters, 1 hardware multipliers
  std::string reference = "theta_ref";  // theta_ref | none (self-calibration, no reference encoder)
  int selfcal_harmonics = 0;            // --reference none: harmonics of the error model, 0 = auto

  // Throws InputError naming the option ("--degree 9: ...") for a value the command refuses.
  void validate() const;
};

struct CalibrateOutcome {
  RegImage image;                                    // provenance: command=COMMAND, periodicity=P
  FloatCoefficients fc;                              // the float coefficients behind it
  CalOptions options;                                // the fit's options
  ErrorStats fit_float, fit_fixed, fit_uncorrected;  // on the calibration recording itself
  bool self = false;      // --reference none: fit errors are about their mean
  SelfCalReport selfcal;  // what the self-calibration found and assumed (self only)
  nlohmann::json report;  // the `calibrate --json` object (docs/contracts.md)
};

// Fits, quantizes and reports; `what` names the recording in errors (its path), `command` is the
// call that made the image, for its header (`command=` line). Throws InputError.
CalibrateOutcome calibrate_recording(const Recording& rec, const CalibrateSpec& spec,
                                     const std::string& what, const std::string& command);

}  // namespace acore
