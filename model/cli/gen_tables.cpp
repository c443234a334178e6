// SPDX-License-Identifier: MIT
// acore_gen_tables: constant tables of the RTL written from the model, so that no second
// implementation of them exists. Writes to standard output; run from the repository root:
//   acore_gen_tables cordic16_atan PARAM=value ... > synth/acore_cordic16_atan.vh
// cordic16_atan: the stand-alone 16-bit CORDIC of synth/acore_cordic16.v, its parameters those of
// the `cordic16` line of the registry (scripts/gen_tables.sh passes them, from scripts/registry.py)
// and its arctangent words from cordic_atan_table(). The CTest gen_tables_current fails when a
// checked-in table differs from what this writes.
// rtl_modes, rtl_mode_checks: the correction modes' constants, functions and rules for the RTL
// (rtl/acore_modes.vh, rtl/acore_mode_checks.vh), from the mode table of
// model/ip/core/correction_modes.hpp; modes_doc: its table for the docs.
// rtl_datapath_params, rtl_datapath_pass: the datapath parameters' declaration and pass-on list
// (rtl/acore_datapath_params.vh, rtl/acore_datapath_pass.vh), from config_fields().
#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "cli_util.hpp"
#include "core/correction_modes.hpp"
#include "core/datapath_config.hpp"
#include "core/errors.hpp"
#include "regmap/codec.hpp"
#include "stages/cordic.hpp"

namespace {

using acore::InputError;

// PARAM=value arguments (the registry line's parameters, as scripts/registry.py prints them).
std::map<std::string, int> param_args(const std::vector<std::string>& args) {
  std::map<std::string, int> params;
  for (const std::string& tok : args) {
    const auto eq = tok.find('=');
    size_t used = 0;
    int v = 0;
    try {
      v = std::stoi(tok.substr(eq == std::string::npos ? tok.size() : eq + 1), &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (eq == std::string::npos || eq == 0 || used == 0 || eq + 1 + used != tok.size())
      throw InputError(fmt::format("'{}' is not PARAM=integer", tok));
    params[tok.substr(0, eq)] = v;
  }
  return params;
}

// The C16_* localparams synth/acore_cordic16.v passes to acore_cordic, and C16_ATAN: K words of
// AT_W bits, atan(2^-i) in the bits [i AT_W +: AT_W].
std::string cordic16_atan(const std::vector<std::string>& args) {
  const auto p = param_args(args);
  const char* names[] = {"IN_W", "G", "Z_W", "ANGLE_W", "K", "AT_W", "NORM", "SPLIT"};
  for (const char* n : names)
    if (!p.count(n)) throw InputError(fmt::format("cordic16_atan: no parameter {} given", n));
  const int k = p.at("K"), z_w = p.at("Z_W"), at_w = p.at("AT_W");
  const std::vector<int64_t> table = acore::cordic_atan_table(z_w, k);
  // The word's value in degrees as the register map reads an atan word (AT_W bits, Z_W a turn).
  acore::DatapathConfig turn;
  turn.reg_w = at_w;
  turn.z_w = z_w;
  turn.iterations = k;
  std::string out = fmt::format(
      "// SPDX-License-Identifier: MIT\n"
      "// The stand-alone 16-bit CORDIC's parameters and arctangent table, for "
      "synth/acore_cordic16.v:\n"
      "// the `cordic16` line of rtl/configs.txt, and atan_i = round(atan(2^-i) / 2 pi * 2^Z_W) "
      "from\n"
      "// cordic_atan_table() of model/ip/stages/cordic.cpp. Written by (from the repository "
      "root)\n"
      "//   {} > synth/acore_cordic16_atan.vh\n"
      "// (model/cli/gen_tables.cpp); do not edit: the CTest gen_tables_current compares it.\n",
      acore::cli::command_line());
  for (const char* n : names) out += fmt::format("localparam integer C16_{} = {};\n", n, p.at(n));
  std::vector<bool> bits(static_cast<size_t>(k) * at_w, false);
  for (int i = 0; i < k; ++i) {
    if (table[i] < 0 || table[i] >= (int64_t{1} << at_w))
      throw InputError(
          fmt::format("cordic16: atan(2^-{}) = {} does not fit AT_W={} bits", i, table[i], at_w));
    for (int b = 0; b < at_w; ++b) bits[static_cast<size_t>(i) * at_w + b] = (table[i] >> b) & 1;
    out += fmt::format("// atan(2^-{}) = {} = {:.6f} deg\n", i, table[i],
                       acore::atan_field(turn, i).value(static_cast<uint64_t>(table[i]), 360.0));
  }
  std::string hex;
  for (size_t nib = (bits.size() + 3) / 4; nib-- > 0;) {
    int d = 0;
    for (int b = 3; b >= 0; --b) {
      const size_t at = nib * 4 + static_cast<size_t>(b);
      d = 2 * d + (at < bits.size() && bits[at] ? 1 : 0);
    }
    if (!hex.empty() || d != 0 || nib == 0) hex += "0123456789abcdef"[d];
  }
  out += fmt::format("localparam [{}:0] C16_ATAN = {}'h{};\n", bits.size() - 1, bits.size(), hex);
  return out;
}

const char* kind_name(acore::CodecKind k) {
  switch (k) {
    case acore::CodecKind::kOffset:
      return "offset";
    case acore::CodecKind::kRecip:
      return "amplitude reciprocal";
    case acore::CodecKind::kPoly:
      return "polynomial coefficient";
    case acore::CodecKind::kAtan:
      return "CORDIC constant";
    case acore::CodecKind::kFourierA0:
      return "Fourier a_0";
    case acore::CodecKind::kFourierHarmonic:
      return "Fourier harmonic (word = value / G_M)";
    case acore::CodecKind::kZero:
      return "zero position (angle code)";
  }
  return "?";
}

std::string register_map(const std::string& overrides) {
  const acore::DatapathConfig cfg = acore::DatapathConfig{}.with_rtl_params(overrides);
  cfg.validate();
  const auto t = acore::codec_table(cfg);
  std::string out = fmt::format(
      "Register map of `{}` ({} words of {} bits; written by `{}` from the codec table, "
      "model/ip/regmap/codec.cpp). Value = gain x field x 2^-frac in the unit; a signed field is "
      "two's complement in its low `width` bits, the word's upper bits repeating its sign; an "
      "unsigned field's upper bits are ignored.\n\n"
      "| addresses | registers | kind | width | signed | fraction bits | gain | unit |\n"
      "|---|---|---|---|---|---|---|---|\n",
      cfg.describe(), cfg.words(), cfg.reg_w, acore::cli::command_line());
  for (size_t a = 0; a < t.size();) {
    size_t b = a;
    while (b + 1 < t.size() && t[b + 1].kind == t[a].kind) ++b;
    const acore::CodecField& f = t[a];
    out += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} |\n",
                       a == b ? std::to_string(a) : fmt::format("{}-{}", a, b),
                       a == b ? f.name(cfg) : fmt::format("{} .. {}", f.name(cfg), t[b].name(cfg)),
                       kind_name(f.kind), f.width, f.is_signed ? "yes" : "no", f.frac,
                       f.gain == 1.0 ? std::string("1") : fmt::format("{:.6f}", f.gain),
                       *f.unit ? f.unit : "-");
    a = b + 1;
  }
  return out;
}

// ---- the correction modes (core/correction_modes.hpp) and the datapath parameters
// (config_fields()) for the RTL and the docs ----

// The generated file's head: what it is, the command that writes it, do not edit.
std::string generated_head(const std::string& what, const std::string& out) {
  return fmt::format(
      "// SPDX-License-Identifier: MIT\n{}"
      "// Written by (from the repository root)\n"
      "//   {} > {}\n"
      "// (model/cli/gen_tables.cpp, scripts/gen_tables.sh); do not edit: the CTest "
      "gen_tables_current\n"
      "// compares it.\n",
      what, acore::cli::command_line(), out);
}

// TERMS of a mode as a Verilog expression of `d` (C(d + args, args), 0 without arguments).
std::string terms_expr(const acore::CorrectionMode& m, const std::string& d) {
  if (m.args == 0) return "0";
  if (m.args == 1) return d + " + 1";
  std::string num;
  long long fact = 1;
  for (int k = 1; k <= m.args; ++k) {
    num += fmt::format("{}({} + {})", k > 1 ? " * " : "", d, k);
    fact *= k;
  }
  return fmt::format("({}) / {}", num, fact);
}

// TERMS as the docs write it: "n + 1", "(d + 1)(d + 2) / 2", "0".
std::string terms_text(const acore::CorrectionMode& m) {
  if (m.args == 0) return "0";
  const char* d = m.args == 1 ? "n" : "d";
  if (m.args == 1) return fmt::format("{} + 1", d);
  std::string num;
  long long fact = 1;
  for (int k = 1; k <= m.args; ++k) {
    num += fmt::format("({} + {})", d, k);
    fact *= k;
  }
  return fmt::format("{} / {}", num, fact);
}

// A constant function of f_correction: `value` for the listed modes, `otherwise` for every other
// CORRECTION (the case labels are the table's IDs).
std::string mode_case(const std::string& fn, const std::string& args,
                      const std::vector<std::pair<const acore::CorrectionMode*, std::string>>& arms,
                      const std::string& otherwise, const std::string& otherwise_why) {
  std::string s = fmt::format("function integer {}({});\n  case (f_correction)\n", fn, args);
  for (const auto& [m, value] : arms)
    s += fmt::format("    {}: {} = {};  // {}\n", m->id, fn, value, m->name);
  s += fmt::format("    default: {} = {};  // {}\n  endcase\nendfunction\n", fn, otherwise,
                   otherwise_why);
  return s;
}

std::string engines_text(unsigned e) {
  const std::pair<unsigned, const char*> names[] = {
      {acore::kEngineFloat, "float"},   {acore::kEngineFixed, "bit-accurate"},
      {acore::kEngineBatch, "batch"},   {acore::kEnginePipelined, "pipelined"},
      {acore::kEngineFolded, "folded"}, {acore::kEngineSerial, "serial"}};
  std::string s;
  for (const auto& [bit, name] : names)
    if (e & bit) s += (s.empty() ? "" : ", ") + std::string(name);
  return s;
}

// rtl/acore_modes.vh: the modes' constants and the functions the RTL sizes and schedules with.
std::string rtl_modes() {
  const auto& modes = acore::correction_modes();
  std::string out = generated_head(
      "// The correction modes (the RTL parameter CORRECTION) for the RTL, from the model's mode\n"
      "// table (model/ip/core/correction_modes.hpp): their constants, and the functions that "
      "size\n"
      "// and schedule a mode. Included by rtl/acore_derived.vh into every module that uses a\n"
      "// derived quantity. The functions take CORRECTION as a number (their case labels are the\n"
      "// table's IDs): a module's parameter defaults call them before its body declares the\n"
      "// constants. Every comparison of CORRECTION elsewhere uses the constants.\n",
      "rtl/acore_modes.vh");
  out +=
      "//\n// The rows (CORRECTION name: DEGREE, TERMS, the RTL stage; the tops that build it):\n";
  for (const auto& m : modes)
    out +=
        fmt::format("//   {} {}: DEGREE {}..{}, TERMS = {}, {}; {}\n", m.id, m.name, m.degree_min,
                    m.degree_max, terms_expr(m, "DEGREE"), *m.rtl_stage ? m.rtl_stage : "no stage",
                    engines_text(m.engines & ~acore::kEngineModel));
  out += "\n// The CORRECTION value of each mode.\n";
  for (const auto& m : modes)
    out += fmt::format("localparam integer {} = {};\n", m.rtl_constant(), m.id);
  std::vector<std::pair<const acore::CorrectionMode*, std::string>> known, terms, latency, folded;
  for (const auto& m : modes) {
    known.emplace_back(&m, "1");
    if (m.args > 0)
      terms.emplace_back(&m, fmt::format("acore_terms_{}(f_degree)", m.name));
    else
      terms.emplace_back(&m, "0");
    latency.emplace_back(
        &m, *m.rtl_latency ? fmt::format("{}(f_degree, f_s_w)", m.rtl_latency) : std::string("0"));
    if (m.runs_on(acore::kEngineFolded)) folded.emplace_back(&m, "1");
  }
  out += "\n// 1 when a row of the table has this CORRECTION.\n";
  out += mode_case("acore_mode_known", "input integer f_correction", known, "0", "no mode");
  for (const auto& m : modes) {
    if (m.args == 0) continue;
    out += fmt::format(
        "\n// Coefficients per region and curve of {}: its basis, {} ({} terms at DEGREE = 3).\n"
        "function integer acore_terms_{}(input integer f_degree);\n  acore_terms_{} = {};\n"
        "endfunction\n",
        m.name, m.basis_text, m.terms(3), m.name, m.name, terms_expr(m, "f_degree"));
  }
  out +=
      "\n// TERMS, coefficients per region and curve, by CORRECTION: 0 for a CORRECTION no row "
      "has (no\n// words and no stage; acore_config_check stops elaboration).\n";
  out += mode_case("acore_terms", "input integer f_correction, input integer f_degree", terms, "0",
                   "no mode");
  out +=
      "\n// The correction stage's latency by CORRECTION (its function in rtl/acore_derived.vh, "
      "0 without\n// a stage).\n";
  out += mode_case("acore_correction_latency",
                   "input integer f_correction, input integer f_degree, input integer f_s_w",
                   latency, "0", "no mode");
  out += "\n// 1 when acore_top builds the mode folded (FOLD > 1).\n";
  out += mode_case("acore_mode_on_folded", "input integer f_correction", folded, "0",
                   "not folded, or no mode");
  // FOLD's values, from the model's one list (acore_config_check's rule, acore_top's choice of
  // the folded datapath).
  std::string folds, fold_cases;
  for (int f : acore::fold_values()) {
    folds += fmt::format("{}{}", folds.empty() ? "" : ", ", f);
    fold_cases += fmt::format("    {}: acore_fold_legal = 1;\n", f);
  }
  out += fmt::format(
      "\n// 1 when FOLD is a fold factor of acore_top (fold_values(), model/ip/core/"
      "datapath_config.hpp:\n// {}): 1 the pipeline, the others the folded datapath.\n"
      "function integer acore_fold_legal(input integer f_fold);\n  case (f_fold)\n{}"
      "    default: acore_fold_legal = 0;\n  endcase\nendfunction\n",
      folds, fold_cases);
  return out;
}

// rtl/acore_mode_checks.vh: the modes' parameter rules, inside rtl/acore_config_check.v.
std::string rtl_mode_checks() {
  const auto& modes = acore::correction_modes();
  std::string out = generated_head(
      "// The correction modes' parameter rules, from the model's mode table\n"
      "// (model/ip/core/correction_modes.hpp), included in rtl/acore_config_check.v: the same\n"
      "// rules as DatapathConfig::validate() (a known mode, its DEGREE, FOLD's values, the tops "
      "that\n// build it).\n",
      "rtl/acore_mode_checks.vh");
  std::string ids;
  for (size_t i = 0; i < modes.size(); ++i)
    ids += fmt::format("{}{}", i == 0 ? "" : i + 1 == modes.size() ? "_or_" : "_", modes[i].id);
  out += fmt::format(
      "\n  // CORRECTION is a row of the table.\n"
      "  acore_check #(.OK(acore_mode_known(CORRECTION) != 0), .VALUE(CORRECTION),\n"
      "    .MSG(\"illegal parameter: CORRECTION must be {}\"))\n"
      "    CORRECTION_must_be_{} ();\n",
      acore::correction_mode_list(), ids);
  out += "\n  // Each mode's DEGREE.\n";
  for (const auto& m : modes)
    out += fmt::format(
        "  acore_check #(.OK(CORRECTION != {} || (DEGREE >= {} && DEGREE <= {})), .VALUE(DEGREE),\n"
        "    .MSG(\"illegal parameter: DEGREE must be {}..{} for {} (CORRECTION={})\"))\n"
        "    DEGREE_must_be_{}_to_{}_for_{} ();\n",
        m.rtl_constant(), m.degree_min, m.degree_max, m.degree_min, m.degree_max, m.name, m.id,
        m.degree_min, m.degree_max, m.name);
  std::string fold_ids;
  const auto& folds = acore::fold_values();
  for (size_t i = 0; i < folds.size(); ++i)
    fold_ids += fmt::format("{}{}", i == 0 ? "" : i + 1 == folds.size() ? "_or_" : "_", folds[i]);
  out += fmt::format(
      "\n  // FOLD is a fold factor of acore_top (fold_values()).\n"
      "  acore_check #(.OK(acore_fold_legal(FOLD) != 0), .VALUE(FOLD),\n"
      "    .MSG(\"illegal parameter: FOLD must be {}\"))\n"
      "    FOLD_must_be_{} ();\n",
      acore::fold_value_list(), fold_ids);
  out +=
      "\n  // The modes a top does not build: acore_top pipelined (FOLD = 1) or folded (FOLD > 1),"
      "\n  // the serial core (SERIAL = 1).\n";
  for (const auto& m : modes) {
    if (!m.runs_on(acore::kEnginePipelined))
      out += fmt::format(
          "  acore_check #(.OK(SERIAL != 0 || FOLD != 1 || CORRECTION != {}), .VALUE(CORRECTION),\n"
          "    .MSG(\"illegal parameter: CORRECTION must not be {} ({}) on the pipelined top: it "
          "builds {}\"))\n"
          "    CORRECTION_must_not_be_{}_on_the_pipelined_top ();\n",
          m.rtl_constant(), m.id, m.name, acore::correction_mode_list(acore::kEnginePipelined),
          m.name);
    if (!m.runs_on(acore::kEngineFolded))
      out += fmt::format(
          "  acore_check #(.OK(FOLD == 1 || CORRECTION != {}), .VALUE(FOLD),\n"
          "    .MSG(\"illegal parameter: FOLD must be 1 with {} (CORRECTION={}): {} is not "
          "folded\"))\n"
          "    FOLD_must_be_1_with_{} ();\n",
          m.rtl_constant(), m.name, m.id, m.name, m.name);
    if (!m.runs_on(acore::kEngineSerial))
      out += fmt::format(
          "  acore_check #(.OK(SERIAL == 0 || CORRECTION != {}), .VALUE(CORRECTION),\n"
          "    .MSG(\"illegal parameter: CORRECTION must not be {} ({}) on the serial core: it "
          "builds {}\"))\n"
          "    CORRECTION_must_not_be_{}_on_the_serial_core ();\n",
          m.rtl_constant(), m.id, m.name, acore::correction_mode_list(acore::kEngineSerial),
          m.name);
  }
  return out;
}

// Writes `items` as lines of at most `width` characters, each item followed by a comma.
std::string wrapped(const std::vector<std::string>& items, const std::string& indent,
                    size_t width) {
  std::string out, line;
  for (const auto& it : items) {
    const std::string piece = it + ",";
    if (!line.empty() && line.size() + 1 + piece.size() > width) {
      out += line + "\n";
      line.clear();
    }
    line += line.empty() ? indent + piece : " " + piece;
  }
  return line.empty() ? out : out + line + "\n";
}

// The meaning of a field for the RTL comment (the correction: with the table's modes).
std::string field_meaning(const acore::ConfigField& f) {
  std::string s = f.meaning;
  if (f.member == &acore::DatapathConfig::correction) {
    std::string list;
    for (const auto& m : acore::correction_modes())
      list += fmt::format("{}{} {}", list.empty() ? "" : ", ", m.id, m.name);
    s = s.substr(0, s.size() - 1) + ": " + list + ".";
  }
  return s;
}

// rtl/acore_datapath_params.vh: the datapath's parameter declarations.
std::string rtl_datapath_params() {
  std::string out = generated_head(
      "// The datapath parameters, declared alike in every module that takes the whole datapath\n"
      "// (acore_top, acore_serial_top, acore_apb, acore_board, acore_config_check, the pin "
      "wrappers\n"
      "// of synth/, the formal harness tb/formal/acore_stream_formal.sv), from the model's field\n"
      "// table config_fields() (model/ip/core/datapath_config.cpp): name, default (a default\n"
      "// DatapathConfig's) and meaning. `include it first inside the module's ANSI parameter "
      "list:\n"
      "// every declaration ends with a comma, the module's own parameters follow.\n",
      "rtl/acore_datapath_params.vh");
  const acore::DatapathConfig d;
  for (const auto& f : acore::config_fields())
    out += fmt::format("  // {}\n  parameter integer {} = {},\n", field_meaning(f), f.rtl,
                       d.*f.member);
  return out;
}

// rtl/acore_datapath_pass.vh: the datapath's parameters passed on to an instance.
std::string rtl_datapath_pass() {
  std::string out = generated_head(
      "// The datapath parameters passed on, each to the parameter of the same name: `include it\n"
      "// first inside the parameter list of an instance that takes the whole datapath (both\n"
      "// modules declare them with rtl/acore_datapath_params.vh); every item ends with a comma,\n"
      "// the instance's own parameters follow.\n",
      "rtl/acore_datapath_pass.vh");
  std::vector<std::string> items;
  for (const auto& f : acore::config_fields()) items.push_back(fmt::format(".{0}({0})", f.rtl));
  return out + wrapped(items, "    ", 100);
}

// docs/reports/correction_modes.md: the table for the docs.
std::string modes_doc() {
  std::string out = fmt::format(
      "# The correction modes\n\n"
      "Generated by `scripts/gen_tables.sh build/model/cli/acore_gen_tables` (`{}`) from the mode "
      "table,\nmodel/ip/core/correction_modes.hpp; checked by the CTest gen_tables_current.\n\n"
      "| mode (`CORRECTION`) | correction | basis | terms T per region and curve | degree | "
      "words (R regions, K CORDIC words) | RTL stage | runs on |\n"
      "|---|---|---|---|---|---|---|---|\n",
      acore::cli::command_line());
  for (const auto& m : acore::correction_modes())
    out += fmt::format("| `{}` ({}) | {} | {} | {} | {} | {} | {} | {} |\n", m.name, m.id,
                       m.meaning, m.basis_text, terms_text(m),
                       fmt::format("{} {}..{}", *m.degree_word() ? m.degree_word() : "unused,",
                                   m.degree_min, m.degree_max),
                       m.args == 0 ? "4 + K" : "4 + 2·R·T + K",
                       *m.rtl_stage ? fmt::format("`{}`", m.rtl_stage) : std::string("-"),
                       engines_text(m.engines));
  out +=
      "\nThe model's kernels of each mode (stages/correction.hpp lists their signatures; the "
      "batch engine runs\nstep() per sample for a mode without a vector kernel):\n\n"
      "| mode | bit-accurate | float | calibration basis | vector batch |\n|---|---|---|---|---|\n";
  for (const auto& m : acore::correction_modes())
    out += fmt::format(
        "| `{}` | `{}` | `{}` | `{}` | {} |\n", m.name, m.fixed_kernel, m.value_kernel,
        m.basis_kernel,
        *m.batch_kernel ? fmt::format("`{}`", m.batch_kernel) : std::string("- (step)"));
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  acore::cli::set_command_line(argc, argv);
  const std::string what = argc > 1 ? argv[1] : "";
  // The tables without arguments.
  const std::map<std::string, std::string (*)()> plain = {
      {"rtl_modes", rtl_modes},
      {"rtl_mode_checks", rtl_mode_checks},
      {"rtl_datapath_params", rtl_datapath_params},
      {"rtl_datapath_pass", rtl_datapath_pass},
      {"modes_doc", modes_doc}};
  if (!(what == "cordic16_atan" || what == "register_map" || (plain.count(what) && argc == 2))) {
    std::cerr << "usage: acore_gen_tables cordic16_atan PARAM=value ...   (the registry line "
                 "cordic16's)\n"
                 "       acore_gen_tables register_map [PARAM=value ...]\n"
                 "       acore_gen_tables rtl_modes | rtl_mode_checks | rtl_datapath_params |\n"
                 "                        rtl_datapath_pass | modes_doc\n"
                 "writes to standard output\n";
    return 2;
  }
  try {
    if (plain.count(what)) {
      std::cout << plain.at(what)();
    } else if (what == "cordic16_atan") {
      std::cout << cordic16_atan(std::vector<std::string>(argv + 2, argv + argc));
    } else {
      std::string overrides;
      for (int i = 2; i < argc; ++i) overrides += std::string(" ") + argv[i];
      std::cout << register_map(overrides);
    }
  } catch (const InputError& e) {
    std::cerr << "acore_gen_tables: error: " << e.what() << "\n";
    return 2;
  }
  return std::cout ? 0 : 1;
}
