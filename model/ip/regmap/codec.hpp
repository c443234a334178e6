// SPDX-License-Identifier: MIT
// The register map's codec: for a configuration, one CodecField per register address saying what
// the word holds (its kind and coordinates) and how (width, sign, fraction bits, unit). quantize()
// writes a register image from FloatCoefficients through it, dequantize() recovers the real values
// an image stands for, and RegImage's accessors and format_regimage() read the words with it: no
// other place knows a Q-format of the map. The addresses are DatapathConfig's addr_* functions.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/datapath_config.hpp"
#include "regmap/coefficients.hpp"
#include "regmap/regimage.hpp"

namespace acore {

enum class CodecKind {
  kOffset,           // O13, O24: the curve's offset in input codes
  kRecip,            // R13, R24: the amplitude reciprocal, 1/A per input code
  kPoly,             // a correction polynomial's coefficient
  kAtan,             // the CORDIC's atan(2^-i), in turns
  kFourierA0,        // the Fourier correction's constant a_0, in turns
  kFourierHarmonic,  // a_k, b_k in turns, the word holding value / G_M (the rotations' gain)
  kZero,             // the ZERO word: the zero position, an ANGLE_W-bit angle code
};

// One register word: value = gain * field * 2^-frac [unit], where field is the word's low `width`
// bits, two's complement when is_signed (the upper bits of the REG_W-bit word repeat the sign),
// unsigned otherwise (the upper bits are ignored).
struct CodecField {
  int addr = 0;
  CodecKind kind = CodecKind::kOffset;
  int region = -1, curve = -1, term = -1;  // offset, recip: curve; poly: region, curve, term
  int index = -1;  // atan: i of atan(2^-i); Fourier: j (0 = a_0; 2k-1, 2k = a_k, b_k)
  int width = 0;   // significant bits of the field
  bool is_signed = false;
  int frac = 0;       // fraction bits
  double gain = 1.0;  // scale of the stored value (Fourier harmonics: G_M, else 1)
  const char* unit = "";
  int word_w = 0;  // REG_W: the register word's width

  // The field's integer from a register word (sign-extended when signed).
  int64_t field(uint64_t word) const;
  // The real value of a word in `unit` times `per_unit` (e.g. 360 for degrees of a turn):
  // ldexp(field * per_unit, -frac) * gain.
  double value(uint64_t word, double per_unit = 1.0) const;
  // The nearest field integer of a real value in `unit` times `per_unit`:
  // llround(ldexp(value / per_unit / gain, frac)). Not range checked (see fits()).
  int64_t quantize(double value, double per_unit = 1.0) const;
  bool fits(int64_t field) const;
  // The REG_W-bit register word of a field integer. Throws InputError naming the register when
  // the integer does not fit the field.
  uint64_t word(int64_t field, const DatapathConfig& cfg) const;
  // "offset O13", "1/A24", "region 2 c24 x^3" (poly2d: "x^1 v^2"), "atan(2^-4)", "fourier b_3",
  // "zero position": what format_regimage() and the errors call the register.
  std::string name(const DatapathConfig& cfg) const;
};

// The field of one register, by kind and coordinates.
CodecField offset_field(const DatapathConfig& cfg, int curve);
CodecField recip_field(const DatapathConfig& cfg, int curve);
CodecField poly_field(const DatapathConfig& cfg, int region, int curve, int term);
CodecField atan_field(const DatapathConfig& cfg, int i);
CodecField fourier_field(const DatapathConfig& cfg, int j);
CodecField zero_field(const DatapathConfig& cfg);
// Every register of the map, in address order (entry a has addr a).
std::vector<CodecField> codec_table(const DatapathConfig& cfg);

// Quantizes into a register image of configuration cfg (degree and regions taken from coef; the
// ZERO word from cfg.zero_word, holding coef.zero_offset as an angle code; the header records
// coef.zero_offset). Throws InputError naming the register when a value does not fit its field.
RegImage quantize(const FloatCoefficients& coef, DatapathConfig cfg, double in_scale);

// quantize(), but when a coefficient does not fit, trade coefficient fraction bits for range (down
// to 8) while the Horner accumulator keeps its fraction bits; likewise a Fourier coefficient lowers
// fourier_coef_f (down to reg_w - 1). The image header records the result.
RegImage quantize_auto_range(const FloatCoefficients& coef, DatapathConfig cfg, double in_scale);

// The largest fraction bits <= cfg.coef_f (not below 8; cfg.coef_f itself when it is below 8) at
// which every polynomial coefficient of coef fits a REG_W-bit word; the lowest candidate when none
// fits.
int auto_coef_f(const FloatCoefficients& coef, const DatapathConfig& cfg);
// Likewise fourier_coef_f (not below reg_w - 1) for the Fourier coefficients (cfg.fourier_k > 0).
int auto_fourier_coef_f(const FloatCoefficients& coef, const DatapathConfig& cfg);

// The real values a register image stands for (so the float engine can run from an image).
FloatCoefficients dequantize(const RegImage& img);

}  // namespace acore
