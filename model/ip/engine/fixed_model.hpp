// SPDX-License-Identifier: MIT
// The bit-accurate model of the whole chain: pre-filter -> scaler -> region select -> polynomial
// correction -> CORDIC (-> Fourier correction when fourier_k > 0) (-> angle - zero position with
// the ZERO word), exactly the RTL's widths and roundings (rtl/acore_top.v), one sample at a time.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "regmap/regimage.hpp"
#include "stages/cordic.hpp"

namespace acore {

// The status window on the CORDIC magnitude (programmable in the RTL through mag_lo_i/mag_hi_i).
struct StatusWindow {
  int64_t mag_lo;  // below: loss of signal (LOS)
  int64_t mag_hi;  // above: degradation of signal / saturation (DOS)
  // Defaults: 0.5 and 1.5 times the nominal corrected vector length (1.0) times the CORDIC gain.
  static StatusWindow defaults(const DatapathConfig& cfg);
};

using ChannelCodes = std::array<int32_t, 4>;  // c1..c4 input codes (IN_W-bit signed, IN_W <= 24)

struct FixedSample {
  uint32_t angle = 0;              // ANGLE_W-bit unsigned, one turn = 2^ANGLE_W
  int region = 0;                  // selected polynomial region
  bool ovf = false;                // saturation in any stage
  bool los = false;                // magnitude < mag_lo
  bool dos = false;                // magnitude > mag_hi
  int64_t s13 = 0, s24 = 0;        // scaled curves (Q2.16)
  int64_t y13 = 0, y24 = 0;        // corrected curves (Q2.16)
  int64_t magnitude = 0;           // CORDIC X_K >>> G (the RTL's mag_o, delivered with the angle)
  uint32_t uncorrected_angle = 0;  // CORDIC of (s24, s13) (- zero): the chain without correction
  uint32_t cordic_angle = 0;       // CORDIC of (y24, y13): the angle before the Fourier correction
  // The RTL-visible fields: angle, region, flags, magnitude.
  bool operator==(const FixedSample& o) const;
};

// The RTL-visible outputs only, compact: what the batch path and the co-sim compare.
struct FixedOutput {
  uint32_t angle;
  uint8_t region;
  uint8_t flags;  // bit 0 ovf, 1 los, 2 dos
  bool operator==(const FixedOutput& o) const {
    return angle == o.angle && region == o.region && flags == o.flags;
  }
};
FixedOutput to_output(const FixedSample& s);

class FixedModel {
 public:
  explicit FixedModel(const RegImage& img, StatusWindow window);
  explicit FixedModel(const RegImage& img);
  FixedSample step(const ChannelCodes& c) const;
  // The same chain over many samples at once (engine/fixed_batch.cpp): structure-of-arrays loops
  // and explicit SIMD vectors, bit-identical to step() in the RTL-visible outputs
  // (tests/ip/engine/test_fixed_batch.cpp). Falls back to step() for configurations wider than 32
  // bits; the Fourier stage (it only reads the angle) runs per sample after the vectorized chain.
  void run_batch(const ChannelCodes* in, size_t n, FixedOutput* out) const;
  bool batch_fits_int32() const;
  const RegImage& image() const { return img_; }
  CordicConfig cordic_config() const;
  // Recording value -> input code: round to nearest, saturate to IN_W bits.
  static int64_t to_code(double v, double in_scale, int in_w);

 private:
  RegImage img_;
  StatusWindow window_;
  int64_t offset_[2] = {}, recip_[2] = {};  // the scaler's words, decoded once
  std::vector<int64_t> coef_;     // sign-extended polynomial words, [region][curve][power]
  std::vector<int64_t> atan_;     // CORDIC constants
  std::vector<int64_t> fourier_;  // sign-extended Fourier words (empty when fourier_k = 0)
  uint32_t zero_ = 0;             // the ZERO word's zero position (zero_word = 1)
};

}  // namespace acore
