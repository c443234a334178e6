// SPDX-License-Identifier: MIT
// The fixed-point contract of the estimator datapath: every width, Q-format and register address.
// The RTL parameters of rtl/acore_top.v have the same names in upper case (IN_W, S_W, ...), and the
// docs/datapath.md, "Fixed-point contract", documents the same numbers.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "core/correction_modes.hpp"

namespace acore {

// The correction modes (RTL parameter CORRECTION, image header `correction=poly|poly2d|none`):
// the rows of core/correction_modes.hpp, which also defines their constants kPoly, kPoly2d, kNone.
// The name of a mode's ID ("7" for an ID no row has: describe() shows what it was given).
std::string correction_name(int correction);
int parse_correction(const std::string& name);  // throws InputError

// Which RTL top a configuration is for: acore_top (pipelined, or folded by FOLD) or the serial
// core, which builds fewer of the modes and options (validate()).
enum class DatapathTop { kTop, kSerial };

// poly2d: the second argument v is the other curve's distance from the region's centre +-1, read
// by the multiplier as 2^kVShift v (a shift of its partial products), so that its range
// (|v| <= 0.35 on the paper scenario) is close to x's and the coefficients stay in Q3.15.
constexpr int kVShift = 2;

// FOLD's legal values, the one list of them: validate() checks it, and the RTL's rule
// (acore_fold_legal() in rtl/acore_modes.vh and its check in rtl/acore_mode_checks.vh) is
// generated from it (model/cli/gen_tables.cpp). 1 is the pipelined top; every other value is a
// power of two >= 2 (the folded datapath's rule: rtl/acore_fold_datapath.v).
const std::vector<int>& fold_values();
// fold_values() as text for a message: "1, 2, 4, 8, 16 or 32".
std::string fold_value_list();

struct DatapathConfig {
  // --- input and pre-filter ---
  int in_w = 16;  // IN_W: channel code width, signed two's complement
  // --- register file ---
  int reg_w = 18;  // REG_W: coefficient register word width
  // --- scaling: s = (d - O) * R, R = round(2^(S_F + R_SHIFT) / A) ---
  int s_w = 18;         // S_W: scaled/corrected curve width, signed
  int s_f = 16;         // S_F: fraction bits of s (Q2.16: 1.0 = 65536)
  int r_shift = 13;     // R_SHIFT: extra scale of the amplitude reciprocal R
  int scale_guard = 4;  // SCALE_G: guard fraction bits kept in the shift-add product
  // --- domain selection and correction ---
  int correction = 0;  // CORRECTION: a mode of core/correction_modes.hpp (kPoly, kPoly2d, kNone)
  int degree = 3;      // DEGREE: the mode's (total) degree, its limits in its row
  int regions = 4;     // REGIONS: 4 or 8
  int xcenter = 0;     // XCENTER (8 regions): polynomials in u = 2 (x -+ 3/8)
  int coef_f = 15;     // COEF_F: fraction bits of a polynomial coefficient (REG_W wide, signed)
  int acc_guard = 4;   // ACC_G: guard fraction bits of the Horner accumulator
  int acc_int = 6;     // ACC_I: integer bits (incl. sign) of the Horner accumulator
  // --- CORDIC ---
  int iterations = 16;   // K: CORDIC iterations = pipeline stages
  int cordic_guard = 3;  // CORDIC_G: guard fraction bits of the CORDIC x/y registers
  int z_w = 20;          // Z_W: CORDIC angle accumulator width, one turn = 2^Z_W
  int angle_w = 16;      // ANGLE_W: output angle width, unsigned, one turn = 2^ANGLE_W
  // --- angle-domain Fourier correction after the CORDIC (model/ip/stages/fourier_correct.hpp) ---
  // angle_out = theta - Delta(theta), Delta = a_0 + sum_k a_k cos k theta + b_k sin k theta.
  int fourier_k = 0;            // FOURIER_K: harmonics K; 0 = stage off (no words, no header keys)
  int fourier_iterations = 12;  // FOURIER_M: rotation-CORDIC stages per harmonic (<= iterations)
  int fourier_coef_f = 22;  // FOURIER_CF: coefficient fraction bits, in turns (word * 2^-CF turn)
  int fourier_word_w = 16;  // FOURIER_W: significant bits of a harmonic's word (signed; the
                            // register word's upper bits must repeat its sign); a_0 uses REG_W
  int fourier_guard = 2;    // FOURIER_G: guard fraction bits of the rotation x/y registers
  // --- zero position (docs/datapath.md "Zero offset") ---
  // ZERO: 1 = one more register word, after every other, holding the zero position z (the low
  // ANGLE_W bits, an angle code); the output is angle_out = (angle - z) mod 2^ANGLE_W, one adder
  // after the CORDIC (after the Fourier correction). 0 = no word, no adder (no header key).
  int zero_word = 0;
  // --- RTL schedule (not the arithmetic: the model and the register image do not depend on it) ---
  // FOLD: clocks per sample of rtl/acore_top.v: 1 (pipelined, one sample per clock) or another
  // value of fold_values() (folded: the hardware reused FOLD times per sample; the modes whose
  // row says so).
  int fold = 1;
  // --- multipliers ---
  // MULT: how every product of the datapath is built. 0: adders and shifters (the paper's minimum),
  // each partial product truncated on its own (fx::shift_add_mul); 1: the hardware multiplier
  // (the Verilog `*`, DSP blocks), the full product then one floor shift (fx::hw_mul). The two
  // rules differ in the last bits, so the register image records it (when 1).
  int mult = 0;

  // Derived, do not set.
  int d_w() const { return in_w + 1; }              // D_W: c1 - c3
  int t_w() const { return d_w() + 1; }             // T_W: d - O
  int acc_f() const { return coef_f + acc_guard; }  // ACC_F
  int acc_w() const { return acc_f() + acc_int; }   // ACC_W
  // Coefficients per region and curve: the mode's terms (correction_modes.hpp); throws
  // InputError for an ID no row has.
  int coef_per_curve() const;
  int poly_words() const { return 2 * regions * coef_per_curve(); }
  int fourier_words() const { return fourier_k > 0 ? 2 * fourier_k + 1 : 0; }
  int zero_words() const { return zero_word ? 1 : 0; }
  int words() const { return 4 + poly_words() + iterations + fourier_words() + zero_words(); }
  int xy_w() const { return s_w + 2 + cordic_guard; }  // XY_W: CORDIC x/y (gain 1.65 * sqrt 2)
  int fourier_f() const {
    return fourier_coef_f + fourier_guard;
  }  // FOURIER_F: Delta fraction bits (turns)
  int fourier_xy_w() const {
    return fourier_word_w + 2 + fourier_guard;
  }  // FOURIER_XY_W: rotation x/y

  // Register map (docs/contracts.md, register image). curve 0 = sine curve c13, 1 = cosine curve
  // c24.
  int addr_offset(int curve) const { return curve; }
  int addr_recip(int curve) const { return 2 + curve; }
  // Word `term` of region r, curve c: 1-D, term = power j of x; 2-D, term = term2d(i, j).
  int addr_poly(int region, int curve, int term) const {
    return 4 + coef_per_curve() * (2 * region + curve) + term;
  }
  // poly2d: the term of x^i v^j (i + j <= d), grouped by the power of x: (0,0), (0,1) .. (0,d),
  // (1,0) .. (1,d-1), .., (d,0). Its coefficient is read when Q_i(v) = sum_j a_ij v^j is built.
  int term2d(int i, int j) const { return i * (degree + 1) - i * (i - 1) / 2 + j; }
  int addr_atan(int i) const { return 4 + poly_words() + i; }
  // Fourier words after the CORDIC constants: j = 0: a_0; j = 2k-1, 2k: a_k, b_k (k = 1..K).
  int addr_fourier(int j) const { return 4 + poly_words() + iterations + j; }
  // The ZERO word: the last word of the map (after the atan words and the Fourier words).
  int addr_zero() const { return 4 + poly_words() + iterations + fourier_words(); }

  // Throws InputError naming the first illegal combination (like the RTL's elaboration checks,
  // rtl/acore_config_check.v): for acore_top (pipelined or folded by FOLD), or for the serial
  // core (only its modes, no XCENTER, Fourier stage or FOLD).
  void validate(DatapathTop top = DatapathTop::kTop) const;
  // "correction=poly in_w=16 ..." for headers and logs: every field of config_fields() that it
  // shows (shows()), the correction first, then in the table's order.
  std::string describe() const;
  // Field equality over config_fields(). The Fourier stage's parameters count only when either
  // side has the stage (fourier_k > 0): without it they are not part of the datapath (validate()
  // and describe() ignore them, and the image header does not record them), so two legal
  // configurations are equal exactly when their describe() strings are. FOLD counts: this is how
  // the RTL engine finds the Verilated build of an image's configuration.
  bool operator==(const DatapathConfig& o) const;
  bool operator!=(const DatapathConfig& o) const { return !(*this == o); }

  // Every field as its RTL parameter (name in upper case as in rtl/acore_top.v, value), in the
  // order of config_fields().
  std::vector<std::pair<std::string, int>> rtl_params() const;
  // A copy with RTL parameter overrides applied, e.g. "DEGREE=5 REGIONS=8" (a named configuration
  // line of rtl/configs.txt). Throws InputError naming an unknown parameter or a malformed token.
  DatapathConfig with_rtl_params(const std::string& overrides) const;
};

// When a field is written into describe() and the image header. Fields added after images were
// first written appear only when they differ from the value that older images imply, so those
// images keep their exact text.
enum class FieldShown {
  kAlways,
  kWithFourier,  // only with the Fourier stage (fourier_k > 0)
  kWhenOne,      // only when 1 (zero_word, mult)
  kWhenNotOne,   // only when not 1 (fold)
};

// One row per field of DatapathConfig: the one table behind describe(), operator==, rtl_params(),
// with_rtl_params() and the register image header (regmap/regimage.cpp reads and writes its keys).
struct ConfigField {
  int DatapathConfig::*member;
  const char* rtl;  // RTL parameter (rtl/acore_datapath_params.vh declares it in every top)
  const char* key;  // describe() key, and the image header key when in_image
  FieldShown shown;
  bool in_image;  // false: the RTL's schedule (fold), which the image does not record
  // What the parameter is, one line: the comment above its RTL declaration.
  const char* meaning;
  // A field written as a name (correction: poly, poly2d, none) instead of a number.
  std::string (*name)(int) = nullptr;
  int (*parse)(const std::string&) = nullptr;  // the name's inverse; throws InputError
};
// The rows in the order of the RTL's parameter list (ZERO before FOLD: the order rtl_params() has
// always had, the sweep's reports list the parameters in it). The RTL's declaration of them,
// rtl/acore_datapath_params.vh (each default a default-constructed DatapathConfig's, each comment
// the row's meaning), and the pass-on list rtl/acore_datapath_pass.vh are written from these rows
// by acore_gen_tables (scripts/gen_tables.sh): a new datapath parameter is a member above, a row
// here, its rules (validate(), rtl/acore_config_check.v) and the stages that use it.
const std::vector<ConfigField>& config_fields();
// True when describe() and the image header write the field for configuration c.
bool shows(const ConfigField& f, const DatapathConfig& c);
// The field's value as describe() and the header write it (a number, or its name).
std::string field_text(const ConfigField& f, const DatapathConfig& c);
// Sets the field from its text (a number, or its name). Throws InputError (an unknown name) or
// std::invalid_argument (not a whole integer).
void set_field_text(const ConfigField& f, DatapathConfig* c, const std::string& text);

// The default configuration with the CORDIC sized for an ANGLE_W-bit output (docs/datapath.md
// "CORDIC widths"): 8..16 -> K=16, CORDIC_G=3, Z_W=20, REG_W=18 (the paper's point); 18 -> K=18,
// G=4, Z_W=22, REG_W=20; 20 -> K=20, G=5, Z_W=24, REG_W=22. atan(2^0) = 2^(Z_W-3) needs a Z_W-2-bit
// word, so the wider angles widen every register word; COEF_F grows with REG_W (the coefficients
// stay Q3.x). Throws InputError for other widths.
DatapathConfig cordic_width_preset(int angle_w);

}  // namespace acore
