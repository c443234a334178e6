// SPDX-License-Identifier: MIT
// Real coefficients <-> register words: quantize() writes a register image of a configuration from
// FloatCoefficients, dequantize() recovers the real values an image stands for.
#pragma once
#include "core/datapath_config.hpp"
#include "regmap/coefficients.hpp"
#include "regmap/regimage.hpp"

namespace acore {

// Quantizes into a register image of configuration cfg (degree and regions taken from coef; the
// ZERO word from cfg.zero_word, holding coef.zero_offset as an angle code; the header records
// coef.zero_offset). Throws InputError naming the register when a value does not fit its field.
RegImage quantize(const FloatCoefficients& coef, DatapathConfig cfg, double in_scale);

// quantize(), but when a coefficient does not fit, trade coefficient fraction bits for range (down
// to 8) while the Horner accumulator keeps its fraction bits; likewise a Fourier coefficient lowers
// fourier_coef_f (down to reg_w - 1). The image header records the result.
RegImage quantize_auto_range(const FloatCoefficients& coef, DatapathConfig cfg, double in_scale);

// The real values a register image stands for (so the float engine can run from an image).
FloatCoefficients dequantize(const RegImage& img);

}  // namespace acore
