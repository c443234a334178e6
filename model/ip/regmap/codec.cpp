// SPDX-License-Identifier: MIT
#include "regmap/codec.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <string>

#include "core/angle.hpp"
#include "core/errors.hpp"
#include "core/fixed_point.hpp"
#include "stages/cordic.hpp"
#include "stages/fourier_correct.hpp"

namespace acore {

namespace {

using fx::mask;

const char* curve_name(int curve) { return curve ? "c24" : "c13"; }

// The Q-format of every kind of register word: the one place that knows them.
CodecField make(const DatapathConfig& cfg, CodecKind kind, int region, int curve, int term,
                int index) {
  CodecField f;
  f.kind = kind;
  f.region = region;
  f.curve = curve;
  f.term = term;
  f.index = index;
  f.word_w = cfg.reg_w;
  f.width = cfg.reg_w;
  switch (kind) {
    case CodecKind::kOffset:  // O in codes of the pre-filtered curve d (D_W bits)
      f.addr = cfg.addr_offset(curve);
      f.is_signed = true;
      f.unit = "input code";
      break;
    case CodecKind::kRecip:  // R = round(2^(S_F + R_SHIFT) / A): s = (d - O) * R * 2^-R_SHIFT
      f.addr = cfg.addr_recip(curve);
      f.frac = cfg.s_f + cfg.r_shift;
      f.unit = "1/input code";
      break;
    case CodecKind::kPoly:  // Q(REG_W - COEF_F).COEF_F
      f.addr = cfg.addr_poly(region, curve, term);
      f.is_signed = true;
      f.frac = cfg.coef_f;
      break;
    case CodecKind::kAtan:  // one turn = 2^Z_W
      f.addr = cfg.addr_atan(index);
      f.frac = cfg.z_w;
      f.unit = "turn";
      break;
    case CodecKind::kFourierA0:  // word * 2^-FOURIER_CF turn
      f.addr = cfg.addr_fourier(index);
      f.is_signed = true;
      f.frac = cfg.fourier_coef_f;
      f.unit = "turn";
      break;
    case CodecKind::kFourierHarmonic:  // FOURIER_W significant bits, divided by the rotations' gain
      f.addr = cfg.addr_fourier(index);
      f.width = cfg.fourier_word_w;
      f.is_signed = true;
      f.frac = cfg.fourier_coef_f;
      f.gain = fourier_gain(cfg);
      f.unit = "turn";
      break;
    case CodecKind::kZero:  // the low ANGLE_W bits: an angle code, one turn = 2^ANGLE_W
      f.addr = cfg.addr_zero();
      f.width = cfg.angle_w;
      f.frac = cfg.angle_w;
      f.unit = "turn";
      break;
  }
  return f;
}

// The real coefficients, the configuration already shaped by them (quantize()'s first step).
DatapathConfig shaped(const FloatCoefficients& fc, DatapathConfig cfg) {
  cfg.correction = fc.correction;
  cfg.degree = fc.degree;
  cfg.regions = fc.regions;
  cfg.xcenter = fc.xcenter;
  cfg.fourier_k = fc.fourier_k();
  return cfg;
}

RegImage blank_image(const FloatCoefficients& fc, const DatapathConfig& cfg, double in_scale) {
  RegImage img;
  img.cfg = cfg;
  img.in_scale = in_scale;
  img.zero_offset = wrap_pi(fc.zero_offset);
  img.words.assign(cfg.words(), 0);
  return img;
}

// The field integer of one register for the real coefficients fc (not range checked).
int64_t field_value(const CodecField& f, const FloatCoefficients& fc, const RegImage& img,
                    const std::vector<int64_t>& atan) {
  switch (f.kind) {
    case CodecKind::kOffset:
      return f.quantize(fc.offset[f.curve] * img.in_scale);
    case CodecKind::kRecip:
      return f.quantize(1.0 / (fc.amp[f.curve] * img.in_scale));
    case CodecKind::kPoly:
      return f.quantize(fc.coef(f.region, f.curve, f.term));
    case CodecKind::kAtan:
      return atan.at(f.index);
    case CodecKind::kFourierA0:
    case CodecKind::kFourierHarmonic:
      return f.quantize(fc.fourier[f.index], 2 * M_PI);
    case CodecKind::kZero:
      return img.zero_offset_code();
  }
  return 0;
}

// Throws the InputError for a value of fc that does not fit register f: which value, and what
// to change.
[[noreturn]] void refuse(const CodecField& f, const FloatCoefficients& fc, const RegImage& img) {
  const DatapathConfig& cfg = img.cfg;
  switch (f.kind) {
    case CodecKind::kOffset:
      throw InputError(fmt::format("offset of {} = {} does not fit the {}-bit register",
                                   curve_name(f.curve), fc.offset[f.curve], f.width));
    case CodecKind::kRecip:
      throw InputError(fmt::format(
          "amplitude of {} = {:.1f} codes is out of the reciprocal register's range (needs "
          "2^(S_F+R_SHIFT)/A < 2^REG_W, i.e. A > {:.0f} codes): raise in_scale or r_shift",
          curve_name(f.curve), fc.amp[f.curve] * img.in_scale, std::ldexp(1.0, f.frac - f.width)));
    case CodecKind::kPoly:
      throw InputError(fmt::format(
          "polynomial coefficient region {} curve {} {}^{} = {:.4f} exceeds the Q{}.{} range: "
          "lower --coef-frac",
          f.region, curve_name(f.curve), correction_mode(cfg.correction).args > 1 ? "term" : "x",
          f.term, fc.coef(f.region, f.curve, f.term), f.width - f.frac, f.frac));
    case CodecKind::kFourierA0:
    case CodecKind::kFourierHarmonic:
      throw InputError(
          fmt::format("fourier coefficient {} = {:.4f} deg exceeds the {}-bit range of "
                      "fourier_coef_f={} (+-{:.4f} deg)",
                      f.index, fc.fourier[f.index] * 180 / M_PI, f.width, f.frac,
                      std::ldexp(360.0, f.width - 1 - f.frac) * f.gain));
    case CodecKind::kAtan:
    case CodecKind::kZero:
      break;
  }
  throw InputError(fmt::format("register {} ({}) does not fit its field", f.addr, f.name(cfg)));
}

// True when every register of one of the kinds takes its value of fc at configuration cfg.
bool all_fit(const FloatCoefficients& fc, const DatapathConfig& cfg, double in_scale,
             std::initializer_list<CodecKind> kinds) {
  const RegImage img = blank_image(fc, cfg, in_scale);
  for (const CodecField& f : codec_table(cfg))
    if (std::find(kinds.begin(), kinds.end(), f.kind) != kinds.end() &&
        !f.fits(field_value(f, fc, img, {})))
      return false;
  return true;
}

}  // namespace

int64_t CodecField::field(uint64_t word) const {
  return is_signed ? fx::sext(static_cast<int64_t>(word), width)
                   : static_cast<int64_t>(word & mask(width));
}

double CodecField::value(uint64_t word, double per_unit) const {
  return std::ldexp(static_cast<double>(field(word)) * per_unit, -frac) * gain;
}

int64_t CodecField::quantize(double v, double per_unit) const {
  return std::llround(std::ldexp(v / per_unit / gain, frac));
}

bool CodecField::fits(int64_t q) const {
  return is_signed ? q >= fx::smin(width) && q <= fx::smax(width)
                   : q >= 0 && static_cast<uint64_t>(q) <= mask(width);
}

uint64_t CodecField::word(int64_t q, const DatapathConfig& cfg) const {
  if (!fits(q))
    throw InputError(fmt::format("register {} ({}): {} does not fit a {} {}-bit field", addr,
                                 name(cfg), q, is_signed ? "signed" : "unsigned", width));
  return static_cast<uint64_t>(q) & mask(word_w);
}

std::string CodecField::name(const DatapathConfig& cfg) const {
  switch (kind) {
    case CodecKind::kOffset:
      return fmt::format("offset O{}", curve ? "24" : "13");
    case CodecKind::kRecip:
      return fmt::format("1/A{}", curve ? "24" : "13");
    case CodecKind::kPoly: {
      // The term's monomial from the mode's basis: "x^3", "x^1 v^2" (u for a centred argument).
      const char* vars[] = {cfg.xcenter ? "u" : "x", "v"};
      const auto powers = correction_mode(cfg.correction).basis_powers(cfg.degree);
      std::string monomial;
      for (size_t k = 0; k < powers.at(static_cast<size_t>(term)).size(); ++k)
        monomial += fmt::format("{}{}^{}", k ? " " : "", k < 2 ? vars[k] : "w",
                                powers[static_cast<size_t>(term)][k]);
      return fmt::format("region {} {} {}", region, curve_name(curve), monomial);
    }
    case CodecKind::kAtan:
      return fmt::format("atan(2^-{})", index);
    case CodecKind::kFourierA0:
      return "fourier a_0";
    case CodecKind::kFourierHarmonic:
      return fmt::format("fourier {}_{}", index % 2 ? "a" : "b", (index + 1) / 2);
    case CodecKind::kZero:
      return "zero position";
  }
  return "?";
}

CodecField offset_field(const DatapathConfig& cfg, int curve) {
  return make(cfg, CodecKind::kOffset, -1, curve, -1, -1);
}
CodecField recip_field(const DatapathConfig& cfg, int curve) {
  return make(cfg, CodecKind::kRecip, -1, curve, -1, -1);
}
CodecField poly_field(const DatapathConfig& cfg, int region, int curve, int term) {
  return make(cfg, CodecKind::kPoly, region, curve, term, -1);
}
CodecField atan_field(const DatapathConfig& cfg, int i) {
  return make(cfg, CodecKind::kAtan, -1, -1, -1, i);
}
CodecField fourier_field(const DatapathConfig& cfg, int j) {
  return make(cfg, j == 0 ? CodecKind::kFourierA0 : CodecKind::kFourierHarmonic, -1, -1, -1, j);
}
CodecField zero_field(const DatapathConfig& cfg) {
  return make(cfg, CodecKind::kZero, -1, -1, -1, -1);
}

std::vector<CodecField> codec_table(const DatapathConfig& cfg) {
  std::vector<CodecField> t;
  t.reserve(cfg.words());
  for (int c = 0; c < 2; ++c) t.push_back(offset_field(cfg, c));
  for (int c = 0; c < 2; ++c) t.push_back(recip_field(cfg, c));
  for (int r = 0; r < cfg.regions; ++r)
    for (int c = 0; c < 2; ++c)
      for (int j = 0; j < cfg.coef_per_curve(); ++j) t.push_back(poly_field(cfg, r, c, j));
  for (int i = 0; i < cfg.iterations; ++i) t.push_back(atan_field(cfg, i));
  for (int j = 0; j < cfg.fourier_words(); ++j) t.push_back(fourier_field(cfg, j));
  if (cfg.zero_word) t.push_back(zero_field(cfg));
  // The addresses are DatapathConfig's: the enumeration above must meet them in order.
  for (size_t a = 0; a < t.size(); ++a)
    if (t[a].addr != static_cast<int>(a) || t.size() != static_cast<size_t>(cfg.words()))
      throw std::logic_error(fmt::format("codec table: entry {} has address {} ({} words)", a,
                                         t[a].addr, cfg.words()));
  return t;
}

RegImage quantize(const FloatCoefficients& fc, DatapathConfig cfg, double in_scale) {
  cfg = shaped(fc, cfg);
  cfg.validate();
  RegImage img = blank_image(fc, cfg, in_scale);
  const auto atan = cordic_atan_table(cfg.z_w, cfg.iterations);
  for (const CodecField& f : codec_table(cfg)) {
    const int64_t q = field_value(f, fc, img, atan);
    if (!f.fits(q)) refuse(f, fc, img);
    img.words[f.addr] = f.word(q, cfg);
  }
  return img;
}

int auto_coef_f(const FloatCoefficients& fc, const DatapathConfig& base) {
  DatapathConfig cfg = shaped(fc, base);
  const int lowest = std::min(cfg.coef_f, 8);
  while (cfg.coef_f > lowest && !all_fit(fc, cfg, 1.0, {CodecKind::kPoly})) --cfg.coef_f;
  return cfg.coef_f;
}

int auto_fourier_coef_f(const FloatCoefficients& fc, const DatapathConfig& base) {
  DatapathConfig cfg = shaped(fc, base);
  const int lowest = std::min(cfg.fourier_coef_f, cfg.reg_w - 1);
  while (cfg.fourier_coef_f > lowest &&
         !all_fit(fc, cfg, 1.0, {CodecKind::kFourierA0, CodecKind::kFourierHarmonic}))
    --cfg.fourier_coef_f;
  return cfg.fourier_coef_f;
}

RegImage quantize_auto_range(const FloatCoefficients& fc, DatapathConfig cfg, double in_scale) {
  // The range is computed, then reached one fraction bit at a time so that every configuration
  // on the way is validated: an accumulator too wide for a lower coef_f is reported at the first
  // coef_f where it is. Whatever does not fit at the end, quantize() reports: an offset or
  // amplitude first (they do not depend on the fraction bits), then the first coefficient that
  // does not fit at the lowest coef_f, before any Fourier word.
  cfg = shaped(fc, cfg);
  cfg.validate();
  if (!all_fit(fc, cfg, in_scale, {CodecKind::kOffset, CodecKind::kRecip}))
    return quantize(fc, cfg, in_scale);
  const int coef_f = auto_coef_f(fc, cfg);
  while (cfg.coef_f > coef_f) {
    const int acc_f = cfg.acc_f();  // the Horner accumulator keeps its fraction bits
    --cfg.coef_f;
    cfg.acc_guard = acc_f - cfg.coef_f;
    cfg.acc_int = std::max(cfg.acc_int, cfg.reg_w - cfg.coef_f + 1);
    cfg.validate();
  }
  if (!all_fit(fc, cfg, in_scale, {CodecKind::kPoly})) return quantize(fc, cfg, in_scale);
  const int fourier_coef_f = auto_fourier_coef_f(fc, cfg);
  while (cfg.fourier_coef_f > fourier_coef_f) {
    --cfg.fourier_coef_f;
    cfg.validate();
  }
  return quantize(fc, cfg, in_scale);
}

FloatCoefficients dequantize(const RegImage& img) {
  const DatapathConfig& cfg = img.cfg;
  FloatCoefficients fc;
  fc.correction = cfg.correction;
  fc.degree = cfg.degree;
  fc.regions = cfg.regions;
  fc.xcenter = cfg.xcenter;
  fc.poly.assign(static_cast<size_t>(cfg.poly_words()), 0.0);
  for (const CodecField& f : codec_table(cfg)) {
    const uint64_t w = img.words.at(f.addr);
    switch (f.kind) {
      case CodecKind::kOffset:
        fc.offset[f.curve] = f.value(w) / img.in_scale;
        break;
      case CodecKind::kRecip:
        if (f.field(w) <= 0) throw InputError("register image: an amplitude reciprocal is zero");
        fc.amp[f.curve] = 1.0 / f.value(w) / img.in_scale;
        break;
      case CodecKind::kPoly:
        fc.coef(f.region, f.curve, f.term) = f.value(w);
        break;
      case CodecKind::kFourierA0:
      case CodecKind::kFourierHarmonic:
        fc.fourier.push_back(f.value(w, 2 * M_PI));
        break;
      case CodecKind::kAtan:  // the CORDIC's constants, not a coefficient
      case CodecKind::kZero:  // below: the offset the chain removes
        break;
    }
  }
  // With the ZERO word the chain subtracts the word's value (what the hardware holds).
  fc.zero_word = cfg.zero_word;
  fc.zero_offset = img.applied_zero_offset();
  return fc;
}

}  // namespace acore
