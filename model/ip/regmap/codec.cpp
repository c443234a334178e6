// SPDX-License-Identifier: MIT
#include "regmap/codec.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "core/fixed_point.hpp"
#include "stages/cordic.hpp"
#include "stages/fourier_correct.hpp"

namespace acore {

RegImage quantize(const FloatCoefficients& fc, DatapathConfig cfg, double in_scale) {
  cfg.correction = fc.correction;
  cfg.degree = fc.degree;
  cfg.regions = fc.regions;
  cfg.xcenter = fc.xcenter;
  cfg.fourier_k = fc.fourier_k();
  cfg.validate();
  RegImage img;
  img.cfg = cfg;
  img.in_scale = in_scale;
  img.zero_offset = wrap_pi(fc.zero_offset);
  img.words.assign(cfg.words(), 0);
  if (cfg.zero_word) img.set_unsigned(cfg.addr_zero(), img.zero_offset_code());
  for (int c = 0; c < 2; ++c) {
    const char* curve = c ? "c24" : "c13";
    // The offset and amplitude are in codes of the pre-filtered curve d (D_W bits).
    try {
      img.set_signed(cfg.addr_offset(c), std::llround(fc.offset[c] * in_scale));
    } catch (const InputError&) {
      throw InputError(fmt::format("offset of {} = {} does not fit the {}-bit register", curve,
                                   fc.offset[c], cfg.reg_w));
    }
    const double amp_codes = fc.amp[c] * in_scale;
    const double recip = std::ldexp(1.0, cfg.s_f + cfg.r_shift) / amp_codes;
    try {
      img.set_unsigned(cfg.addr_recip(c), std::llround(recip));
    } catch (const InputError&) {
      throw InputError(fmt::format(
          "amplitude of {} = {:.1f} codes is out of the reciprocal register's range (needs "
          "2^(S_F+R_SHIFT)/A < 2^REG_W, i.e. A > {:.0f} codes): raise in_scale or r_shift",
          curve, amp_codes, std::ldexp(1.0, cfg.s_f + cfg.r_shift - cfg.reg_w)));
    }
  }
  for (int r = 0; r < cfg.regions; ++r)
    for (int c = 0; c < 2; ++c)
      for (int j = 0; j < cfg.coef_per_curve(); ++j) {
        const double v = fc.coef(r, c, j);
        const long long q = std::llround(std::ldexp(v, cfg.coef_f));
        try {
          img.set_signed(cfg.addr_poly(r, c, j), q);
        } catch (const InputError&) {
          throw InputError(fmt::format(
              "polynomial coefficient region {} curve {} {}^{} = {:.4f} exceeds the Q{}.{} range: "
              "lower --coef-frac",
              r, c ? "c24" : "c13", cfg.correction == kPoly2d ? "term" : "x", j, v,
              cfg.reg_w - cfg.coef_f, cfg.coef_f));
        }
      }
  const auto table = cordic_atan_table(cfg.z_w, cfg.iterations);
  for (int i = 0; i < cfg.iterations; ++i) img.set_unsigned(cfg.addr_atan(i), table[i]);
  // Fourier words: turns with fourier_coef_f fraction bits; harmonics divided by the rotation gain.
  const double gain = fourier_gain(cfg);
  for (int j = 0; j < cfg.fourier_words(); ++j) {
    const double turns = fc.fourier[j] / (2 * M_PI) / (j == 0 ? 1.0 : gain);
    const long long q = std::llround(std::ldexp(turns, cfg.fourier_coef_f));
    const int w = j == 0 ? cfg.reg_w : cfg.fourier_word_w;  // a harmonic's word: its low W bits
    if (q > fx::smax(w) || q < fx::smin(w))
      throw InputError(
          fmt::format("fourier coefficient {} = {:.4f} deg exceeds the {}-bit range of "
                      "fourier_coef_f={} (+-{:.4f} deg)",
                      j, fc.fourier[j] * 180 / M_PI, w, cfg.fourier_coef_f,
                      std::ldexp(360.0, w - 1 - cfg.fourier_coef_f) * (j ? gain : 1)));
    img.set_signed(cfg.addr_fourier(j), q);
  }
  return img;
}

RegImage quantize_auto_range(const FloatCoefficients& coef, DatapathConfig cfg, double in_scale) {
  for (;;) {
    try {
      return quantize(coef, cfg, in_scale);
    } catch (const InputError& e) {
      if (std::string(e.what()).find("fourier coefficient") != std::string::npos &&
          cfg.fourier_coef_f >= cfg.reg_w) {
        --cfg.fourier_coef_f;
        continue;
      }
      if (cfg.coef_f <= 8 ||
          std::string(e.what()).find("polynomial coefficient") == std::string::npos)
        throw;
      const int acc_f = cfg.acc_f();
      --cfg.coef_f;
      cfg.acc_guard = acc_f - cfg.coef_f;
      cfg.acc_int = std::max(cfg.acc_int, cfg.reg_w - cfg.coef_f + 1);
    }
  }
}

FloatCoefficients dequantize(const RegImage& img) {
  const DatapathConfig& cfg = img.cfg;
  FloatCoefficients fc;
  fc.correction = cfg.correction;
  fc.degree = cfg.degree;
  fc.regions = cfg.regions;
  fc.xcenter = cfg.xcenter;
  fc.poly.assign(static_cast<size_t>(cfg.poly_words()), 0.0);
  for (int c = 0; c < 2; ++c) {
    fc.offset[c] = img.offset(c) / img.in_scale;
    if (img.recip(c) <= 0) throw InputError("register image: an amplitude reciprocal is zero");
    fc.amp[c] = std::ldexp(1.0, cfg.s_f + cfg.r_shift) / img.recip(c) / img.in_scale;
  }
  for (int r = 0; r < cfg.regions; ++r)
    for (int c = 0; c < 2; ++c)
      for (int j = 0; j < cfg.coef_per_curve(); ++j)
        fc.coef(r, c, j) = std::ldexp(static_cast<double>(img.poly(r, c, j)), -cfg.coef_f);
  const double gain = fourier_gain(cfg);
  for (int j = 0; j < cfg.fourier_words(); ++j)
    fc.fourier.push_back(2 * M_PI * (j == 0 ? 1.0 : gain) *
                         std::ldexp(static_cast<double>(img.fourier(j)), -cfg.fourier_coef_f));
  // With the ZERO word the chain subtracts the word's value (what the hardware holds).
  fc.zero_word = cfg.zero_word;
  fc.zero_offset = img.applied_zero_offset();
  return fc;
}

}  // namespace acore
