// SPDX-License-Identifier: MIT
// DatapathConfig::validate() rule by rule: each limit is legal on its edge and illegal one step
// past it (the RTL's rtl/acore_config_check.v has the same rules; tb/lint/param_checks.py checks
// that the two agree on random parameter sets), and every named configuration of rtl/configs.txt is
// legal. The field table (config_fields()) against the top's parameters, describe() as it was
// written by hand before the table, rtl_params() and with_rtl_params(), and operator==.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/datapath_config.hpp"
#include "core/errors.hpp"
#include "registry_lines_generated.hpp"

namespace acore {
namespace {

bool legal(const std::string& overrides) {
  try {
    DatapathConfig{}.with_rtl_params(overrides).validate();
    return true;
  } catch (const InputError&) {
    return false;
  }
}

TEST(DatapathConfig, DefaultsAreLegal) { EXPECT_TRUE(legal("")); }

TEST(DatapathConfig, EachRuleOnItsEdgeAndOnePast) {
  // {legal on the edge, illegal one step past}, one pair per rule, in validate()'s order.
  const std::vector<std::pair<std::string, std::string>> edges = {
      {"IN_W=8", "IN_W=7"},
      {"IN_W=24 REG_W=26 ACC_I=12 Z_W=21", "IN_W=25 REG_W=30 ACC_I=16 Z_W=22"},
      {"REG_W=18", "REG_W=17 Z_W=19"},
      {"REG_W=30 ACC_I=16", "REG_W=31 ACC_I=17"},
      {"S_W=18 S_F=16", "S_W=17"},
      {"S_W=30", "S_W=31"},
      {"R_SHIFT=30", "R_SHIFT=31"},
      {"SCALE_G=0", "SCALE_G=-1"},
      {"SCALE_G=13", "SCALE_G=14"},
      {"CORRECTION=2", "CORRECTION=3"},
      {"CORRECTION=0", "CORRECTION=-1"},
      {"DEGREE=7", "DEGREE=8"},
      {"DEGREE=1", "DEGREE=0"},
      {"CORRECTION=1 DEGREE=3", "CORRECTION=1 DEGREE=4"},
      {"REGIONS=8", "REGIONS=6"},
      {"XCENTER=1 REGIONS=8", "XCENTER=1"},
      {"XCENTER=1 REGIONS=8 CORRECTION=2", "XCENTER=2 REGIONS=8"},
      {"S_F=3 S_W=5 K=9", "S_F=2 S_W=5 K=9"},
      {"COEF_F=17", "COEF_F=18"},
      {"COEF_F=12 ACC_G=4 ACC_I=7", "COEF_F=12 ACC_G=3 ACC_I=7"},
      {"ACC_G=0 COEF_F=17", "ACC_G=-1 COEF_F=17"},
      {"ACC_I=4", "ACC_I=3"},
      {"ACC_I=21", "ACC_I=22"},
      {"K=4", "K=3"},
      {"K=24 CORDIC_G=5", "K=25 CORDIC_G=5"},
      {"CORDIC_G=8", "CORDIC_G=9"},
      {"CORDIC_G=0", "CORDIC_G=-1"},
      {"K=22", "K=23"},
      {"Z_W=16", "Z_W=15"},
      {"Z_W=20", "Z_W=21"},
      {"ANGLE_W=8", "ANGLE_W=7"},
      {"FOURIER_K=31", "FOURIER_K=32"},
      {"FOURIER_K=4 FOURIER_M=16", "FOURIER_K=4 FOURIER_M=17"},
      {"FOURIER_K=4 FOURIER_M=4", "FOURIER_K=4 FOURIER_M=3"},
      {"FOURIER_K=4 Z_W=17", "FOURIER_K=4 Z_W=16"},
      {"FOURIER_K=4 FOURIER_W=8 FOURIER_M=11", "FOURIER_K=4 FOURIER_W=8 FOURIER_M=12"},
      {"FOURIER_K=4 ANGLE_W=12 Z_W=16 FOURIER_M=12", "FOURIER_K=4 ANGLE_W=12 Z_W=15 FOURIER_M=12"},
      {"FOURIER_K=4 FOURIER_W=18", "FOURIER_K=4 FOURIER_W=19"},
      {"FOURIER_K=4 FOURIER_W=8 FOURIER_M=11", "FOURIER_K=4 FOURIER_W=7 FOURIER_G=3 FOURIER_M=11"},
      {"FOURIER_K=4 FOURIER_G=8", "FOURIER_K=4 FOURIER_G=9"},
      {"FOURIER_K=4 FOURIER_CF=38", "FOURIER_K=4 FOURIER_CF=39"},
      {"FOURIER_K=4 FOURIER_CF=17", "FOURIER_K=4 FOURIER_CF=16"},
      {"MULT=1", "MULT=2"},
      {"MULT=0", "MULT=-1"},
  };
  for (const auto& [ok, bad] : edges) {
    EXPECT_TRUE(legal(ok)) << ok;
    EXPECT_FALSE(legal(bad)) << bad;
  }
  // Without the Fourier stage its parameters are not looked at.
  EXPECT_TRUE(legal("FOURIER_M=99 FOURIER_W=0 FOURIER_G=-5 FOURIER_CF=0"));
}

// FOLD: 1 (pipelined) and the folds of rtl/acore_fold_datapath.v, powers of two up to 32 (a
// drive's 1 MS/s at 16 or 32 clocks a sample); nothing else, on acore_top. The RTL's rule is
// generated from fold_values() (rtl/acore_mode_checks.vh), the message lists them.
TEST(DatapathConfig, FoldIsOneOrAPowerOfTwoUpTo32) {
  for (int f = -2; f <= 70; ++f) {
    const bool want = f == 1 || f == 2 || f == 4 || f == 8 || f == 16 || f == 32;
    EXPECT_EQ(legal(fmt::format("FOLD={}", f)), want) << f;
  }
  EXPECT_EQ(fold_value_list(), "1, 2, 4, 8, 16 or 32");
  try {
    DatapathConfig{}.with_rtl_params("FOLD=64").validate();
    ADD_FAILURE() << "FOLD=64 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("fold=64 must be 1, 2, 4, 8, 16 or 32"), std::string::npos)
        << e.what();
  }
}

// Every configuration of a datapath top in the registry: acore_top, acore_serial_top, and acore_apb
// around either (its SERIAL parameter picks the top). The lines (kRegistryLines) come from
// scripts/registry.py, the registry's one reader, through the variables CMake includes
// (tests/CMakeLists.txt writes them into the build tree).

TEST(DatapathConfig, NamedConfigurationsAreLegal) {
  int n = 0;
  for (const RegistryLine& l : kRegistryLines) {
    const std::string module = l.module;
    if (module != "acore_top" && module != "acore_serial_top" && module != "acore_apb") continue;
    std::istringstream cols(l.params);
    std::string tok, params;
    while (cols >> tok)
      if (tok.rfind("SERIAL=", 0) != 0) params += " " + tok;
    EXPECT_TRUE(legal(params)) << l.name << ": " << l.params;
    ++n;
  }
  EXPECT_GE(n, 10);
}

// describe() as it was written before the field table (a format string per field): the text the
// RTL builds, logs and tests have always seen.
std::string legacy_describe(const DatapathConfig& c) {
  std::string fourier;
  if (c.fourier_k > 0)
    fourier = fmt::format(
        " fourier_k={} fourier_iterations={} fourier_coef_f={} fourier_word_w={} fourier_guard={}",
        c.fourier_k, c.fourier_iterations, c.fourier_coef_f, c.fourier_word_w, c.fourier_guard);
  const std::string folded = c.fold != 1 ? fmt::format(" fold={}", c.fold) : "";
  return fmt::format(
      "correction={} in_w={} reg_w={} s_w={} s_f={} r_shift={} scale_guard={} degree={} regions={} "
      "xcenter={} coef_f={} acc_guard={} acc_int={} iterations={} cordic_guard={} z_w={} "
      "angle_w={}{}{}{}{}",
      correction_name(c.correction), c.in_w, c.reg_w, c.s_w, c.s_f, c.r_shift, c.scale_guard,
      c.degree, c.regions, c.xcenter, c.coef_f, c.acc_guard, c.acc_int, c.iterations,
      c.cordic_guard, c.z_w, c.angle_w, fourier, c.zero_word ? " zero_word=1" : "", folded,
      c.mult == 1 ? " mult=1" : "");
}

// A configuration with every field random (most of them illegal: describe, ==, and the RTL
// parameters do not care), the Fourier stage on in about half of them.
DatapathConfig random_config(std::mt19937_64& rng) {
  DatapathConfig c;
  for (const ConfigField& f : config_fields()) c.*f.member = static_cast<int>(rng() % 40);
  c.correction = static_cast<int>(rng() % 3);
  c.zero_word = static_cast<int>(rng() % 2);
  c.fold = 1 << (rng() % 4);
  c.mult = static_cast<int>(rng() % 2);
  if (rng() % 2) c.fourier_k = 0;
  return c;
}

TEST(DatapathConfig, TableCoversEveryFieldOnceAndTheTopsParameters) {
  // Every member of the struct is in the table once: setting each row's member of a zeroed
  // configuration to its row number reaches every int of the struct exactly once.
  static_assert(sizeof(DatapathConfig) % sizeof(int) == 0, "DatapathConfig holds ints only");
  const size_t fields = sizeof(DatapathConfig) / sizeof(int);
  ASSERT_EQ(config_fields().size(), fields);
  DatapathConfig c;
  int* raw = reinterpret_cast<int*>(&c);
  std::fill(raw, raw + fields, -1);
  for (size_t i = 0; i < fields; ++i) c.*config_fields()[i].member = static_cast<int>(i);
  std::set<int> seen(raw, raw + fields);
  EXPECT_EQ(seen.size(), fields);
  EXPECT_EQ(seen.count(-1), 0u);
  // The RTL names are the top's parameters that are not derived (rtl/acore_top.v names its derived
  // ones in "... is derived" elaboration checks), its text read with the files it includes (the
  // datapath's declaration, rtl/acore_datapath_params.vh), each at the default configuration's
  // value.
  const auto read = [](const std::string& name) {
    std::ifstream in(std::string(ACORE_SOURCE_DIR) + "/rtl/" + name);
    EXPECT_TRUE(in) << name;
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  std::string v = read("acore_top.v");
  const std::regex include(R"re(`include "([a-z_0-9]+\.vh)")re");
  for (std::smatch m; std::regex_search(v, m, include);)
    v = m.prefix().str() + read(m[1]) + m.suffix().str();
  std::set<std::string> top, derived, table;
  std::map<std::string, int> value;
  const std::regex param(R"(parameter\s+integer\s+([A-Z_0-9]+)\s*=\s*(-?[0-9]+)?)");
  const std::regex derived_msg(R"(illegal parameter: ([A-Z_0-9]+) is derived)");
  for (std::sregex_iterator it(v.begin(), v.end(), param), end; it != end; ++it) {
    top.insert((*it)[1]);
    if ((*it)[2].matched) value[(*it)[1]] = std::stoi((*it)[2]);
  }
  for (std::sregex_iterator it(v.begin(), v.end(), derived_msg), end; it != end; ++it)
    derived.insert((*it)[1]);
  EXPECT_GE(derived.size(), 4u);
  for (const auto& d : derived) top.erase(d);
  const DatapathConfig defaults;
  for (const ConfigField& f : config_fields()) {
    table.insert(f.rtl);
    EXPECT_EQ(value.count(f.rtl) ? value[f.rtl] : -1000, defaults.*f.member) << f.rtl;
  }
  EXPECT_EQ(table, top);
  // Keys are distinct and lower case; only the RTL schedule (fold) stays out of the image.
  std::set<std::string> keys;
  for (const ConfigField& f : config_fields()) {
    EXPECT_TRUE(keys.insert(f.key).second) << f.key;
    EXPECT_EQ(f.in_image, f.member != &DatapathConfig::fold) << f.key;
  }
}

TEST(DatapathConfig, TableDrivesDescribeAndRtlParams) {
  std::mt19937_64 rng(11);
  for (int n = 0; n < 2000; ++n) {
    const DatapathConfig c = random_config(rng);
    ASSERT_EQ(c.describe(), legacy_describe(c));
    // rtl_params(): one (name, value) per row, in the table's order.
    const auto p = c.rtl_params();
    ASSERT_EQ(p.size(), config_fields().size());
    std::string overrides;
    for (size_t i = 0; i < p.size(); ++i) {
      EXPECT_EQ(p[i].first, config_fields()[i].rtl);
      EXPECT_EQ(p[i].second, c.*config_fields()[i].member);
      overrides += fmt::format(" {}={}", p[i].first, p[i].second);
    }
    // with_rtl_params() inverts rtl_params(), field by field.
    const DatapathConfig back = DatapathConfig{}.with_rtl_params(overrides);
    for (const ConfigField& f : config_fields()) EXPECT_EQ(back.*f.member, c.*f.member) << f.rtl;
    // describe() names a key exactly when shows() says so, with field_text() as its value.
    for (const ConfigField& f : config_fields()) {
      const std::string kv = std::string(" ") + f.key + "=" + field_text(f, c) + " ";
      EXPECT_EQ((" " + c.describe() + " ").find(kv) != std::string::npos, shows(f, c)) << kv;
    }
  }
  EXPECT_EQ(DatapathConfig{}.describe().rfind("correction=poly in_w=16 ", 0), 0u);
}

TEST(DatapathConfig, EqualityIsFieldEqualityOverTheTable) {
  std::mt19937_64 rng(12);
  for (int n = 0; n < 2000; ++n) {
    const DatapathConfig a = random_config(rng);
    EXPECT_TRUE(a == a);
    EXPECT_TRUE(a == DatapathConfig{}.with_rtl_params([&] {
      std::string s;
      for (const auto& [k, v] : a.rtl_params()) s += fmt::format(" {}={}", k, v);
      return s;
    }()));
    // One field changed: unequal, except a Fourier parameter without the stage on either side.
    for (const ConfigField& f : config_fields()) {
      DatapathConfig b = a;
      b.*f.member += 1 + static_cast<int>(rng() % 3);
      const bool ignored =
          f.shown == FieldShown::kWithFourier && a.fourier_k == 0 && b.fourier_k == 0;
      EXPECT_EQ(a == b, ignored) << f.key;
      EXPECT_EQ(a != b, !ignored) << f.key;
    }
    // On legal values of zero_word (0, 1) and fold (1, 2, 4, 8 here), equality is describe()'s.
    const DatapathConfig b = random_config(rng);
    EXPECT_EQ(a == b, legacy_describe(a) == legacy_describe(b));
  }
  // The Fourier parameters of two configurations without the stage do not count.
  DatapathConfig x, y;
  y.fourier_iterations = 9;
  y.fourier_coef_f = 17;
  EXPECT_TRUE(x == y);
  x.fourier_k = y.fourier_k = 3;
  EXPECT_FALSE(x == y);
}

TEST(DatapathConfig, FieldTextNamesTheCorrectionAndParsesBack) {
  for (const ConfigField& f : config_fields()) {
    DatapathConfig c;
    if (f.member == &DatapathConfig::correction) {
      for (int mode : {kPoly, kPoly2d, kNone}) {
        c.correction = mode;
        EXPECT_EQ(field_text(f, c), correction_name(mode));
        DatapathConfig d;
        set_field_text(f, &d, field_text(f, c));
        EXPECT_EQ(d.correction, mode);
      }
      EXPECT_THROW(set_field_text(f, &c, "2"), InputError);
      continue;
    }
    c.*f.member = -17;
    EXPECT_EQ(field_text(f, c), "-17");
    DatapathConfig d;
    set_field_text(f, &d, "23");
    EXPECT_EQ(d.*f.member, 23) << f.key;
    EXPECT_THROW(set_field_text(f, &d, "23x"), std::invalid_argument) << f.key;
    EXPECT_THROW(set_field_text(f, &d, "poly"), std::invalid_argument) << f.key;
  }
}

}  // namespace
}  // namespace acore
