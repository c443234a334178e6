// SPDX-License-Identifier: MIT
#include "core/datapath_config.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "core/errors.hpp"

namespace acore {

std::string correction_name(int correction) {
  const CorrectionMode* m = find_correction_mode(correction);
  return m ? m->name : std::to_string(correction);
}

int parse_correction(const std::string& name) { return correction_mode(name).id; }

const std::vector<int>& fold_values() {
  static const std::vector<int> v = {1, 2, 4, 8, 16, 32};
  return v;
}

std::string fold_value_list() {
  const auto& v = fold_values();
  std::string s;
  for (size_t i = 0; i < v.size(); ++i)
    s += fmt::format("{}{}", i == 0 ? "" : i + 1 == v.size() ? " or " : ", ", v[i]);
  return s;
}

int DatapathConfig::coef_per_curve() const { return correction_mode(correction).terms(degree); }

void DatapathConfig::validate(DatapathTop top) const {
  auto need = [](bool ok, const std::string& why) {
    if (!ok) throw InputError("datapath configuration: " + why);
  };
  need(in_w >= 8 && in_w <= 24, fmt::format("in_w={} must be 8..24", in_w));
  need(reg_w >= d_w() + 1 && reg_w <= 30,
       fmt::format("reg_w={} must hold an offset of d_w+1={} bits and be <= 30", reg_w, d_w() + 1));
  need(s_w >= s_f + 2 && s_w <= 30, fmt::format("s_w={} must be s_f+2..30 (s_f={})", s_w, s_f));
  need(r_shift >= 0 && r_shift <= 30 && scale_guard >= 0 && scale_guard <= r_shift,
       fmt::format("need 0 <= scale_guard={} <= r_shift={} <= 30", scale_guard, r_shift));
  // The mode's row: its limits, and the engines that build it (core/correction_modes.hpp).
  const CorrectionMode* mode = find_correction_mode(correction);
  need(mode != nullptr,
       fmt::format("correction={} must be {}", correction, correction_mode_list()));
  need(degree >= mode->degree_min && degree <= mode->degree_max,
       fmt::format("degree={} must be {}..{} for {}", degree, mode->degree_min, mode->degree_max,
                   mode->name));
  need(regions == 4 || regions == 8, fmt::format("regions={} must be 4 or 8", regions));
  need(xcenter == 0 || (xcenter == 1 && regions == 8),
       fmt::format("xcenter={} must be 0, or 1 with 8 regions (regions={})", xcenter, regions));
  need(s_f >= kVShift + 1, fmt::format("s_f={} must be >= {}", s_f, kVShift + 1));
  need(coef_f >= 1 && coef_f < reg_w, fmt::format("coef_f={} must be 1..reg_w-1", coef_f));
  need(acc_f() >= s_f, fmt::format("coef_f+acc_guard={} must be >= s_f={}", acc_f(), s_f));
  // A coefficient is shifted left by acc_guard into the accumulator (a << acc_guard).
  need(acc_guard >= 0, fmt::format("acc_guard={} must be >= 0", acc_guard));
  need(acc_int >= reg_w - coef_f + 1,
       fmt::format("acc_int={} too small for the coefficients", acc_int));
  need(acc_w() <= 40, fmt::format("acc_w={} must be <= 40", acc_w()));
  need(iterations >= 4 && iterations <= 24, fmt::format("iterations={} must be 4..24", iterations));
  need(cordic_guard >= 0 && cordic_guard <= 8,
       fmt::format("cordic_guard={} must be 0..8", cordic_guard));
  // Stage i shifts X and Y right by i: the RTL's CORDIC trims its widths for i < xy_w.
  need(iterations < xy_w(),
       fmt::format("iterations={} must be < xy_w={} (s_w+2+cordic_guard)", iterations, xy_w()));
  need(z_w >= angle_w && z_w <= reg_w + 2,
       fmt::format("z_w={} must be angle_w={}..reg_w+2={} (atan(1) must fit a word)", z_w, angle_w,
                   reg_w + 2));
  need(angle_w >= 8 && angle_w <= 24, fmt::format("angle_w={} must be 8..24", angle_w));
  need(fourier_k >= 0 && fourier_k <= 31, fmt::format("fourier_k={} must be 0..31", fourier_k));
  need(zero_word == 0 || zero_word == 1, fmt::format("zero_word={} must be 0 or 1", zero_word));
  need(!zero_word || angle_w <= reg_w, fmt::format("zero_word=1 needs angle_w={} <= reg_w={} (the "
                                                   "zero position is an angle code in one word)",
                                                   angle_w, reg_w));
  need(mult == 0 || mult == 1, fmt::format("mult={} must be 0 or 1", mult));
  const auto& folds = fold_values();
  need(std::find(folds.begin(), folds.end(), fold) != folds.end(),
       fmt::format("fold={} must be {}", fold, fold_value_list()));
  need(fold == 1 || mode->runs_on(kEngineFolded),
       fmt::format("fold={}: the {} correction is not folded", fold, mode->name));
  need(fold != 1 || top != DatapathTop::kTop || mode->runs_on(kEnginePipelined),
       fmt::format("correction={}: the pipelined top does not build {} (it builds {})", correction,
                   mode->name, correction_mode_list(kEnginePipelined)));
  if (top == DatapathTop::kSerial) {
    need(mode->runs_on(kEngineSerial),
         fmt::format("correction={}: the serial core does not build {} (it builds {})", correction,
                     mode->name, correction_mode_list(kEngineSerial)));
    need(xcenter == 0,
         fmt::format("xcenter={}: the serial core has no centred arguments", xcenter));
    need(fourier_k == 0,
         fmt::format("fourier_k={}: the serial core has no Fourier correction", fourier_k));
    need(fold == 1, fmt::format("fold={}: the serial core is not folded", fold));
    need(mult == 0, fmt::format("mult={}: the serial core multiplies on its adder only", mult));
  }
  need(
      fold == 1 || fourier_k == 0,
      fmt::format("fold={}: the Fourier correction (fourier_k={}) is not folded", fold, fourier_k));
  if (fourier_k == 0) return;
  need(fourier_iterations >= 4 && fourier_iterations <= iterations,
       fmt::format(
           "fourier_iterations={} must be 4..iterations={} (it uses the CORDIC's atan words)",
           fourier_iterations, iterations));
  need(z_w > angle_w,
       fmt::format("the Fourier correction needs z_w={} > angle_w={}", z_w, angle_w));
  // The Fourier stage's rotation CORDIC runs fourier_iterations stages on (fourier_word_w + 2 +
  // fourier_guard)-bit vectors and z_w - 2-bit angles (rtl/acore_cordic_rotate.v's rule).
  need(fourier_iterations < fourier_word_w + 2 + fourier_guard,
       fmt::format("fourier_iterations={} must be < fourier_word_w+2+fourier_guard={}",
                   fourier_iterations, fourier_word_w + 2 + fourier_guard));
  need(fourier_iterations <= z_w - 4,
       fmt::format("fourier_iterations={} must be <= z_w-4={}", fourier_iterations, z_w - 4));
  need(fourier_word_w >= 8 && fourier_word_w <= reg_w,
       fmt::format("fourier_word_w={} must be 8..reg_w={}", fourier_word_w, reg_w));
  need(fourier_guard >= 0 && fourier_guard <= 8,
       fmt::format("fourier_guard={} must be 0..8", fourier_guard));
  need(fourier_f() > angle_w && fourier_f() <= 40,
       fmt::format("fourier_coef_f+fourier_guard={} must be angle_w+1={}..40", fourier_f(),
                   angle_w + 1));
  need(fourier_coef_f >= reg_w - 1,
       fmt::format(
           "fourier_coef_f={} must be >= reg_w-1={} (a coefficient is less than half a turn)",
           fourier_coef_f, reg_w - 1));
}

DatapathConfig cordic_width_preset(int angle_w) {
  DatapathConfig c;
  if (angle_w >= 8 && angle_w <= 16) {
    c.angle_w = angle_w;
    return c;
  }
  if (angle_w != 18 && angle_w != 20)
    throw InputError(fmt::format("angle width {} must be 8..16, 18 or 20", angle_w));
  const int extra = angle_w - 16;  // 2 or 4
  c.angle_w = angle_w;
  c.iterations = 16 + extra;
  c.cordic_guard = 3 + extra / 2;
  c.z_w = 20 + extra;
  c.reg_w = 18 + extra;
  c.coef_f = 15 + extra;
  return c;
}

namespace {
// The correction names the map's shape, so describe() and the image header name it first.
bool leads(const ConfigField& f) { return f.member == &DatapathConfig::correction; }
}  // namespace

const std::vector<ConfigField>& config_fields() {
  using D = DatapathConfig;
  using S = FieldShown;
  static const std::vector<ConfigField> t = {
      {&D::in_w, "IN_W", "in_w", S::kAlways, true, "Channel code width, signed."},
      {&D::reg_w, "REG_W", "reg_w", S::kAlways, true, "Register word width."},
      {&D::s_w, "S_W", "s_w", S::kAlways, true, "Scaled and corrected curve width, signed."},
      {&D::s_f, "S_F", "s_f", S::kAlways, true,
       "Fraction bits of the scaled curves (1.0 = 2^S_F)."},
      {&D::r_shift, "R_SHIFT", "r_shift", S::kAlways, true,
       "Extra scale of the amplitude reciprocal, R = round(2^(S_F + R_SHIFT) / A)."},
      {&D::scale_guard, "SCALE_G", "scale_guard", S::kAlways, true,
       "Guard fraction bits of the scaling product."},
      {&D::correction, "CORRECTION", "correction", S::kAlways, true,
       "Correction mode, a row of the mode table (rtl/acore_modes.vh).", correction_name,
       parse_correction},
      {&D::degree, "DEGREE", "degree", S::kAlways, true,
       "Polynomial degree of the correction (the total degree for two arguments)."},
      {&D::regions, "REGIONS", "regions", S::kAlways, true,
       "Regions of the domain selection, 4 or 8."},
      {&D::xcenter, "XCENTER", "xcenter", S::kAlways, true,
       "1 (8 regions only): the polynomials are in u = 2 (x -+ 3/8), centred in their half "
       "region."},
      {&D::coef_f, "COEF_F", "coef_f", S::kAlways, true,
       "Fraction bits of a polynomial coefficient (a signed REG_W-bit word)."},
      {&D::acc_guard, "ACC_G", "acc_guard", S::kAlways, true,
       "Guard fraction bits of the Horner accumulator."},
      {&D::acc_int, "ACC_I", "acc_int", S::kAlways, true,
       "Integer bits (with the sign) of the Horner accumulator."},
      {&D::iterations, "K", "iterations", S::kAlways, true, "CORDIC iterations (= stages)."},
      {&D::cordic_guard, "CORDIC_G", "cordic_guard", S::kAlways, true,
       "Guard fraction bits of the CORDIC's X/Y registers."},
      {&D::z_w, "Z_W", "z_w", S::kAlways, true,
       "CORDIC angle accumulator width, one turn = 2^Z_W."},
      {&D::angle_w, "ANGLE_W", "angle_w", S::kAlways, true,
       "Output angle width, unsigned, one turn = 2^ANGLE_W."},
      {&D::fourier_k, "FOURIER_K", "fourier_k", S::kWithFourier, true,
       "Harmonics of the Fourier correction after the CORDIC (0 = no stage, no words)."},
      {&D::fourier_iterations, "FOURIER_M", "fourier_iterations", S::kWithFourier, true,
       "Rotation-CORDIC stages per harmonic (<= K)."},
      {&D::fourier_coef_f, "FOURIER_CF", "fourier_coef_f", S::kWithFourier, true,
       "Fraction bits of a Fourier coefficient, in turns."},
      {&D::fourier_word_w, "FOURIER_W", "fourier_word_w", S::kWithFourier, true,
       "Significant bits of a harmonic's word, signed."},
      {&D::fourier_guard, "FOURIER_G", "fourier_guard", S::kWithFourier, true,
       "Guard fraction bits of the Fourier rotations."},
      {&D::zero_word, "ZERO", "zero_word", S::kWhenOne, true,
       "1: one more register word (the last), the zero position, subtracted from the angle."},
      {&D::fold, "FOLD", "fold", S::kWhenNotOne, false,
       "Clocks per sample of acore_top: 1 pipelined, more folded (fold_values(); serial core: 1)."},
      {&D::mult, "MULT", "mult", S::kWhenOne, true,
       "Products: 0 adders and shifters (each partial product floored), 1 the multiply operator "
       "(DSP blocks; the full product floored once)."},
  };
  return t;
}

bool shows(const ConfigField& f, const DatapathConfig& c) {
  switch (f.shown) {
    case FieldShown::kAlways:
      return true;
    case FieldShown::kWithFourier:
      return c.fourier_k > 0;
    case FieldShown::kWhenOne:
      return c.*f.member == 1;
    case FieldShown::kWhenNotOne:
      return c.*f.member != 1;
  }
  return true;
}

std::string field_text(const ConfigField& f, const DatapathConfig& c) {
  return f.name ? std::string(f.name(c.*f.member)) : std::to_string(c.*f.member);
}

void set_field_text(const ConfigField& f, DatapathConfig* c, const std::string& text) {
  if (f.parse) {
    c->*f.member = f.parse(text);
    return;
  }
  size_t used = 0;
  const int v = std::stoi(text, &used);
  if (used != text.size()) throw std::invalid_argument(text);
  c->*f.member = v;
}

std::string DatapathConfig::describe() const {
  std::string s;
  auto add = [&](const ConfigField& f) {
    if (shows(f, *this))
      s += fmt::format("{}{}={}", s.empty() ? "" : " ", f.key, field_text(f, *this));
  };
  for (const ConfigField& f : config_fields())
    if (leads(f)) add(f);
  for (const ConfigField& f : config_fields())
    if (!leads(f)) add(f);
  return s;
}

bool DatapathConfig::operator==(const DatapathConfig& o) const {
  for (const ConfigField& f : config_fields()) {
    if (f.shown == FieldShown::kWithFourier && fourier_k == 0 && o.fourier_k == 0) continue;
    if (this->*f.member != o.*f.member) return false;
  }
  return true;
}

std::vector<std::pair<std::string, int>> DatapathConfig::rtl_params() const {
  std::vector<std::pair<std::string, int>> v;
  for (const ConfigField& f : config_fields()) v.emplace_back(f.rtl, this->*f.member);
  return v;
}

DatapathConfig DatapathConfig::with_rtl_params(const std::string& overrides) const {
  DatapathConfig c = *this;
  std::istringstream in(overrides);
  std::string tok;
  while (in >> tok) {
    const auto eq = tok.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == tok.size())
      throw InputError(fmt::format("RTL parameter '{}': expected NAME=value", tok));
    const std::string name = tok.substr(0, eq), value = tok.substr(eq + 1);
    const ConfigField* field = nullptr;
    for (const ConfigField& f : config_fields())
      if (name == f.rtl) field = &f;
    if (!field) {
      std::string known;
      for (const ConfigField& f : config_fields())
        known += std::string(known.empty() ? "" : ", ") + f.rtl;
      throw InputError(fmt::format("RTL parameter '{}' is unknown (known: {})", name, known));
    }
    size_t used = 0;
    int v = 0;
    try {
      v = std::stoi(value, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != value.size())
      throw InputError(fmt::format("RTL parameter {}: '{}' is not an integer", name, value));
    c.*(field->member) = v;
  }
  return c;
}

}  // namespace acore
