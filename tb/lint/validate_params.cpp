// SPDX-License-Identifier: MIT
// The model's side of the parameter rules, for tb/lint/param_checks.py: reads RTL parameter
// override sets from stdin, one per line ("DEGREE=8 K=30", the syntax of rtl/configs.txt; empty =
// the defaults), applies each to the default configuration (DatapathConfig::with_rtl_params) and
// prints one line per set: "legal" or "illegal: <validate()'s message>".
//   acore_validate_params < sets.txt
// Exit 0 when every line was judged, 2 on bad usage or a malformed set (unknown parameter, not an
// integer), naming the line.
#include <cstdio>
#include <iostream>
#include <string>

#include "core/datapath_config.hpp"
#include "core/errors.hpp"

int main(int argc, char** argv) {
  if (argc > 1) {
    const std::string a = argv[1];
    std::printf(
        "usage: acore_validate_params < SETS\n"
        "  one RTL parameter override set per line (e.g. \"DEGREE=8 K=30\"); prints \"legal\" or\n"
        "  \"illegal: MESSAGE\" per line (DatapathConfig::validate() on the default configuration\n"
        "  with the overrides).\n");
    return a == "--help" || a == "-h" ? 0 : 2;
  }
  std::string line;
  int n = 0;
  while (std::getline(std::cin, line)) {
    ++n;
    acore::DatapathConfig cfg;
    try {
      cfg = acore::DatapathConfig{}.with_rtl_params(line);
    } catch (const acore::InputError& e) {
      std::fprintf(stderr, "acore_validate_params: stdin line %d: %s\n", n, e.what());
      return 2;
    }
    try {
      cfg.validate();
      std::printf("legal\n");
    } catch (const acore::InputError& e) {
      std::printf("illegal: %s\n", e.what());
    }
  }
  return 0;
}
