// SPDX-License-Identifier: MIT
// DatapathConfig::validate() rule by rule: each limit is legal on its edge and illegal one step
// past it (the RTL's rtl/acore_config_check.v has the same rules; tb/param_checks.py checks that
// the two agree on random parameter sets), and every named configuration of rtl/configs.txt is
// legal.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/datapath_config.hpp"
#include "core/errors.hpp"

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
  };
  for (const auto& [ok, bad] : edges) {
    EXPECT_TRUE(legal(ok)) << ok;
    EXPECT_FALSE(legal(bad)) << bad;
  }
  // Without the Fourier stage its parameters are not looked at.
  EXPECT_TRUE(legal("FOURIER_M=99 FOURIER_W=0 FOURIER_G=-5 FOURIER_CF=0"));
}

TEST(DatapathConfig, NamedConfigurationsAreLegal) {
  std::ifstream in(std::string(ACORE_SOURCE_DIR) + "/rtl/configs.txt");
  ASSERT_TRUE(in) << "rtl/configs.txt";
  std::string line;
  int n = 0;
  // Registry lines: name module flows [PARAM=value ...]; the datapath's tops only.
  while (std::getline(in, line)) {
    if (line.empty() || line[0] < 'a' || line[0] > 'z') continue;
    std::istringstream fields(line);
    std::string name, module, flows, params, tok;
    fields >> name >> module >> flows;
    if (module != "acore_top" && module != "acore_serial_top") continue;
    while (fields >> tok) params += tok + " ";
    EXPECT_TRUE(legal(params)) << line;
    ++n;
  }
  EXPECT_GE(n, 10);
}

}  // namespace
}  // namespace acore
