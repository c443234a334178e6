// SPDX-License-Identifier: MIT
// Runs an estimator engine over a whole recording: the common front of `estimate`, `demo` and
// `diagnose`. The RTL engine lives in model/rtlsim/rtl_engine.hpp (the pipelined top, "rtl", and
// the serial core, "rtl-serial") and returns the same FixedSample rows; model/rtlsim/run_engine.hpp
// is the one dispatch from an engine name to these functions or the RTL.
#pragma once
#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/error_stats.hpp"
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
// The bit-accurate model's rows for these input codes (FixedModel::step each): run_fixed's rows.
std::vector<FixedSample> run_fixed_rows(const RegImage& img,
                                        const std::vector<ChannelCodes>& codes);
// Converts bit-accurate rows (model or RTL) of this image into angles in the reference frame.
AngleSeries series_from_fixed(const std::vector<FixedSample>& rows, const RegImage& img);

// Recording columns in caller-owned memory (numpy arrays in the Python package): channels c1..c4,
// or sin, cos in ch[0], ch[1]; theta_ref may be null.
struct ChannelColumns {
  int channels = 4;
  std::array<const double*, 4> ch{};
  const double* theta_ref = nullptr;
  size_t n = 0;
};
// The error an image is judged by: angle_error_deg against the reference, about its own mean when
// the image's zero is unknown (zero_reference=none, a self-calibration).
std::vector<double> judged_error_deg(const RegImage& img, const std::vector<double>& angle_rad,
                                     const std::vector<double>& theta_ref, int periodicity);
// The same judgement of errors already taken against the reference (angle_error_deg's, or
// run_fixed_batch's error_deg): returned as they are, or about their mean.
std::vector<double> judged_error_deg(const RegImage& img, std::vector<double> error_deg);

// Caller-owned outputs of n samples each; error_deg is written only when it and theta_ref are set.
struct BatchAngles {
  double* angle = nullptr;  // as AngleSeries::angle of run_fixed, bit for bit
  uint8_t* flags = nullptr;
  uint8_t* region = nullptr;
  double* error_deg = nullptr;  // angle - p theta_ref, as angle_error_deg
};
// run_fixed's angles, region and flags through FixedModel::run_batch (the vectorized path), chunk
// by chunk, with no copy of the columns; without the uncorrected angle (the batch has none).
void run_fixed_batch(const RegImage& img, const ChannelColumns& in, int periodicity,
                     const BatchAngles& out);

// The `estimate --json` object (docs/contracts.md): engine, samples, fold (rtl), zero_offset,
// error_deg and uncorrected_error_deg (each when given), flagged_samples.
nlohmann::json estimate_json(Engine engine, size_t samples, int fold, const RegImage& img,
                             double zero_offset, bool zero_word, const ErrorStats* error,
                             const ErrorStats* uncorrected, size_t flagged);

}  // namespace acore
