// SPDX-License-Identifier: MIT
// acore_gen_tables: constant tables of the RTL written from the model, so that no second
// implementation of them exists. Writes to standard output; run from the repository root:
//   acore_gen_tables cordic16_atan PARAM=value ... > synth/acore_cordic16_atan.vh
// cordic16_atan: the stand-alone 16-bit CORDIC of synth/acore_cordic16.v, its parameters those of
// the `cordic16` line of the registry (scripts/gen_tables.sh passes them, from scripts/registry.py)
// and its arctangent words from cordic_atan_table(). The CTest gen_tables_current fails when a
// checked-in table differs from what this writes.
#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "cli_util.hpp"
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

}  // namespace

int main(int argc, char** argv) {
  acore::cli::set_command_line(argc, argv);
  const std::string what = argc > 1 ? argv[1] : "";
  if (what != "cordic16_atan" && what != "register_map") {
    std::cerr << "usage: acore_gen_tables cordic16_atan PARAM=value ...   (the registry line "
                 "cordic16's)\n"
                 "       acore_gen_tables register_map [PARAM=value ...]\n"
                 "writes to standard output\n";
    return 2;
  }
  try {
    if (what == "cordic16_atan") {
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
