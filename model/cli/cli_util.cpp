// SPDX-License-Identifier: MIT
#include "cli_util.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "core/errors.hpp"

namespace acore::cli {

namespace {
std::string& recorded_command_line() {
  static std::string s;
  return s;
}
}  // namespace

std::string shell_quote(const std::string& t) {
  const char* safe = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_@%+=:,./-";
  if (!t.empty() && t.find_first_not_of(safe) == std::string::npos) return t;
  const bool control = std::any_of(t.begin(), t.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u < 0x20 || u == 0x7f;
  });
  std::string q;
  if (!control) {
    q = "'";
    for (const char c : t) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
  }
  q = "$'";
  for (const char c : t) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\\' || c == '\'')
      q += std::string("\\") + c;
    else if (c == '\n')
      q += "\\n";
    else if (c == '\t')
      q += "\\t";
    else if (c == '\r')
      q += "\\r";
    else if (u < 0x20 || u == 0x7f)
      q += fmt::format("\\x{:02x}", u);
    else
      q += c;
  }
  return q + "'";
}

void set_command_line(int argc, char** argv) {
  std::string s;
  for (int i = 0; i < argc; ++i) {
    std::string t = argv[i];
    if (i == 0) t = std::filesystem::path(t).filename().string();
    s += (i ? " " : "") + shell_quote(t);
  }
  recorded_command_line() = s;
}

const std::string& command_line() { return recorded_command_line(); }

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

void require_finite_numbers(CLI::App& app) {
  static const CLI::Validator finite(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double x = std::strtod(text.c_str(), &end);
        if (end == text.c_str() || *end != '\0') return "'" + text + "' is not a number";
        return std::isfinite(x) ? "" : "'" + text + "' is not a finite number";
      },
      "FINITE");
  for (CLI::Option* o : app.get_options())
    if (o->get_type_name().find("FLOAT") == 0) o->check(finite);
  for (CLI::App* sub : app.get_subcommands({})) require_finite_numbers(*sub);
}

}  // namespace acore::cli
