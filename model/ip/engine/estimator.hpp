// SPDX-License-Identifier: MIT
// Runs an estimator engine over a whole recording: the common front of `estimate`, `demo` and
// `diagnose`. The RTL engine lives in tb/rtl_engine.hpp (the pipelined top, "rtl", and the serial
// core, "rtl-serial") and returns the same FixedSample rows.
#pragma once
#include <string>
#include <vector>

#include "core/recording.hpp"
#include "engine/fixed_model.hpp"
#include "regmap/coefficients.hpp"

namespace acore {

enum class Engine { Float, Fixed, Rtl, RtlSerial };
Engine parse_engine(const std::string& name);  // throws InputError
const char* engine_name(Engine e);

// Angles in the reference frame (docs/datapath.md "Zero offset"): the chain's output minus the zero
// offset, which the ZERO word subtracts in the chain or, without it, these functions in software.
struct AngleSeries {
  std::vector<double> angle;        // corrected electrical angle - zero offset, rad [0, 2 pi)
  std::vector<double> uncorrected;  // without the polynomial correction - zero offset, rad
  std::vector<int> region;
  std::vector<unsigned> flags;  // bit 0 ovf, 1 los, 2 dos (fixed/RTL engines)
  double zero_offset = 0;       // the zero offset removed (rad, [-pi, pi)) ...
  bool zero_word = false;       // ... by the ZERO word (true) or in software (false)
};

// The recording's channels as input codes: round(v * in_scale) saturated to IN_W bits;
// two-channel recordings become c1 = sin, c2 = cos, c3 = c4 = 0.
std::vector<ChannelCodes> to_codes(const Recording& rec, double in_scale, int in_w);

AngleSeries run_float(const Recording& rec, const FloatCoefficients& fc);
AngleSeries run_fixed(const Recording& rec, const RegImage& img);
// Converts bit-accurate rows (model or RTL) of this image into angles in the reference frame.
AngleSeries series_from_fixed(const std::vector<FixedSample>& rows, const RegImage& img);

}  // namespace acore
