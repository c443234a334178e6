// SPDX-License-Identifier: MIT
#include "cli_util.hpp"

#include <fstream>
#include <iostream>

#include "core/errors.hpp"

namespace acore::cli {

std::ostream& json_stdout() {
  static std::ostream out(std::cout.rdbuf());  // bound before main() may redirect std::cout
  return out;
}

bool json_to_stdout(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--json=-" || (a == "--json" && i + 1 < argc && std::string(argv[i + 1]) == "-"))
      return true;
  }
  return false;
}

void write_json(const std::string& path, const nlohmann::json& j) {
  if (path.empty()) return;
  if (path == "-") {
    json_stdout() << j.dump(2) << "\n" << std::flush;
    return;
  }
  std::ofstream f(path);
  if (!f) throw InputError(path + ": cannot write JSON output");
  f << j.dump(2) << "\n";
  if (!f) throw InputError(path + ": write failed");
}

nlohmann::json stats_json(const ErrorStats& s) {
  return {{"rms", s.rms}, {"max_abs", s.max_abs}, {"mean", s.mean}};
}

int recording_periodicity(const Recording& rec, const std::string& path) {
  const auto it = rec.meta.find("p");
  if (it == rec.meta.end()) return 1;
  try {
    size_t used = 0;
    const int p = std::stoi(it->second, &used);
    if (used == it->second.size() && p >= 1 && p <= 64) return p;
  } catch (const std::exception&) {
  }
  throw InputError(path + ": metadata 'p': '" + it->second + "' is not a periodicity 1..64");
}

}  // namespace acore::cli
