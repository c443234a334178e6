// SPDX-License-Identifier: MIT
#include "core/datapath_config.hpp"

#include <fmt/format.h>

#include <sstream>

#include "core/errors.hpp"

namespace acore {

const char* correction_name(int correction) {
  switch (correction) {
    case kPoly:
      return "poly";
    case kPoly2d:
      return "poly2d";
    case kNone:
      return "none";
  }
  return "?";
}

int parse_correction(const std::string& name) {
  for (int c : {kPoly, kPoly2d, kNone})
    if (name == correction_name(c)) return c;
  throw InputError("correction '" + name + "' is not one of poly, poly2d, none");
}

int DatapathConfig::coef_per_curve() const {
  switch (correction) {
    case kPoly:
      return degree + 1;
    case kPoly2d:
      return (degree + 1) * (degree + 2) / 2;
    default:
      return 0;
  }
}

void DatapathConfig::validate() const {
  auto need = [](bool ok, const std::string& why) {
    if (!ok) throw InputError("datapath configuration: " + why);
  };
  need(in_w >= 8 && in_w <= 24, fmt::format("in_w={} must be 8..24", in_w));
  need(reg_w >= d_w() + 1 && reg_w <= 30,
       fmt::format("reg_w={} must hold an offset of d_w+1={} bits and be <= 30", reg_w, d_w() + 1));
  need(s_w >= s_f + 2 && s_w <= 30, fmt::format("s_w={} must be s_f+2..30 (s_f={})", s_w, s_f));
  need(r_shift >= 0 && r_shift <= 30 && scale_guard >= 0 && scale_guard <= r_shift,
       fmt::format("need 0 <= scale_guard={} <= r_shift={} <= 30", scale_guard, r_shift));
  need(correction >= kPoly && correction <= kNone,
       fmt::format("correction={} must be 0 (poly), 1 (poly2d) or 2 (none)", correction));
  need(degree >= 1 && degree <= 7, fmt::format("degree={} must be 1..7", degree));
  need(correction != kPoly2d || degree <= 3,
       fmt::format("degree={} must be 1..3 for poly2d", degree));
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
  need(fold == 1 || fold == 2 || fold == 4 || fold == 8,
       fmt::format("fold={} must be 1, 2, 4 or 8", fold));
  need(fold == 1 || correction != kPoly2d,
       fmt::format("fold={}: the poly2d correction is not folded", fold));
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

std::string DatapathConfig::describe() const {
  std::string fourier;
  if (fourier_k > 0)
    fourier = fmt::format(
        " fourier_k={} fourier_iterations={} fourier_coef_f={} fourier_word_w={} fourier_guard={}",
        fourier_k, fourier_iterations, fourier_coef_f, fourier_word_w, fourier_guard);
  const std::string folded = fold != 1 ? fmt::format(" fold={}", fold) : "";
  return fmt::format(
      "correction={} in_w={} reg_w={} s_w={} s_f={} r_shift={} scale_guard={} degree={} regions={} "
      "xcenter={} coef_f={} acc_guard={} acc_int={} iterations={} cordic_guard={} z_w={} "
      "angle_w={}{}{}{}",
      correction_name(correction), in_w, reg_w, s_w, s_f, r_shift, scale_guard, degree, regions,
      xcenter, coef_f, acc_guard, acc_int, iterations, cordic_guard, z_w, angle_w, fourier,
      zero_word ? " zero_word=1" : "", folded);
}

namespace {
// RTL parameter name -> field. One table, so the model, the named configurations (rtl/configs.txt)
// and the synthesis sweep cannot disagree on a name.
using Field = int DatapathConfig::*;
const std::vector<std::pair<const char*, Field>>& rtl_param_table() {
  static const std::vector<std::pair<const char*, Field>> t = {
      {"IN_W", &DatapathConfig::in_w},
      {"REG_W", &DatapathConfig::reg_w},
      {"S_W", &DatapathConfig::s_w},
      {"S_F", &DatapathConfig::s_f},
      {"R_SHIFT", &DatapathConfig::r_shift},
      {"SCALE_G", &DatapathConfig::scale_guard},
      {"CORRECTION", &DatapathConfig::correction},
      {"DEGREE", &DatapathConfig::degree},
      {"REGIONS", &DatapathConfig::regions},
      {"XCENTER", &DatapathConfig::xcenter},
      {"COEF_F", &DatapathConfig::coef_f},
      {"ACC_G", &DatapathConfig::acc_guard},
      {"ACC_I", &DatapathConfig::acc_int},
      {"K", &DatapathConfig::iterations},
      {"CORDIC_G", &DatapathConfig::cordic_guard},
      {"Z_W", &DatapathConfig::z_w},
      {"ANGLE_W", &DatapathConfig::angle_w},
      {"FOURIER_K", &DatapathConfig::fourier_k},
      {"FOURIER_M", &DatapathConfig::fourier_iterations},
      {"FOURIER_CF", &DatapathConfig::fourier_coef_f},
      {"FOURIER_W", &DatapathConfig::fourier_word_w},
      {"FOURIER_G", &DatapathConfig::fourier_guard},
      {"ZERO", &DatapathConfig::zero_word},
      {"FOLD", &DatapathConfig::fold},
  };
  return t;
}
}  // namespace

std::vector<std::pair<std::string, int>> DatapathConfig::rtl_params() const {
  std::vector<std::pair<std::string, int>> v;
  for (const auto& [name, field] : rtl_param_table()) v.emplace_back(name, this->*field);
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
    Field field = nullptr;
    for (const auto& [n, f] : rtl_param_table())
      if (name == n) field = f;
    if (!field) {
      std::string known;
      for (const auto& [n, f] : rtl_param_table())
        known += std::string(known.empty() ? "" : ", ") + n;
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
    c.*field = v;
  }
  return c;
}

}  // namespace acore
