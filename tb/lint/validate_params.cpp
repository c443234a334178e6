// SPDX-License-Identifier: MIT
// The model's side of the parameter rules, for tb/lint/param_checks.py: reads RTL parameter
// override sets from stdin, one per line ("DEGREE=8 K=30", the syntax of rtl/configs.txt; empty =
// the defaults), optionally after the top they are for ("acore_serial_top DEGREE=5"; default
// acore_top), applies each to the default configuration (DatapathConfig::with_rtl_params) and
// prints one line per set: "legal" or "illegal: <validate()'s message>" (validate(DatapathTop) of
// that top).
//   acore_validate_params < sets.txt
// Exit 0 when every line was judged, 2 on bad usage or a malformed set (unknown top or parameter,
// not an integer), naming the line.
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
        "  one RTL parameter override set per line (e.g. \"DEGREE=8 K=30\"), optionally after its\n"
        "  top (acore_top, acore_serial_top); prints \"legal\" or \"illegal: MESSAGE\" per line\n"
        "  (DatapathConfig::validate() of that top on the default configuration with the\n"
        "  overrides).\n");
    return a == "--help" || a == "-h" ? 0 : 2;
  }
  std::string line;
  int n = 0;
  while (std::getline(std::cin, line)) {
    ++n;
    acore::DatapathConfig cfg;
    acore::DatapathTop top = acore::DatapathTop::kTop;
    const size_t first = line.find_first_not_of(' ');
    if (first != std::string::npos && line.compare(first, 6, "acore_") == 0) {
      const size_t end = line.find(' ', first);
      const std::string name = line.substr(first, end - first);
      if (name == "acore_serial_top") {
        top = acore::DatapathTop::kSerial;
      } else if (name != "acore_top") {
        std::fprintf(stderr, "acore_validate_params: stdin line %d: unknown top '%s'\n", n,
                     name.c_str());
        return 2;
      }
      line = end == std::string::npos ? "" : line.substr(end);
    }
    try {
      cfg = acore::DatapathConfig{}.with_rtl_params(line);
    } catch (const acore::InputError& e) {
      std::fprintf(stderr, "acore_validate_params: stdin line %d: %s\n", n, e.what());
      return 2;
    }
    try {
      cfg.validate(top);
      std::printf("legal\n");
    } catch (const acore::InputError& e) {
      std::printf("illegal: %s\n", e.what());
    }
  }
  return 0;
}
