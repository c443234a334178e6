// SPDX-License-Identifier: MIT
#include "core/json_input.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"

namespace acore {

namespace {
// 1-based line of byte offset `at`; past the end (a truncated text), the line of its last
// visible character.
size_t line_of(const std::string& text, size_t at) {
  if (at >= text.size()) {
    const size_t last = text.find_last_not_of(" \t\r\n");
    at = last == std::string::npos ? 0 : last;
  }
  return 1 + static_cast<size_t>(std::count(text.begin(), text.begin() + at, '\n'));
}
}  // namespace

nlohmann::json parse_json_text(const std::string& text, const std::string& where) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // e.byte is 1-based and points just past the offending character.
    throw InputError(fmt::format("{}:{}: not valid JSON: {}", where,
                                 line_of(text, e.byte > 0 ? e.byte - 1 : 0), e.what()));
  } catch (const nlohmann::json::exception& e) {
    // An overflowing number ("number overflow parsing '1e999'") carries no position: find the
    // quoted token in the text.
    const std::string msg = e.what();
    const size_t q1 = msg.find('\''), q2 = msg.rfind('\'');
    size_t at = std::string::npos;
    if (q1 != std::string::npos && q2 > q1) at = text.find(msg.substr(q1 + 1, q2 - q1 - 1));
    if (at == std::string::npos)
      throw InputError(fmt::format("{}: not valid JSON: {}", where, msg));
    throw InputError(fmt::format("{}:{}: not valid JSON: {}", where, line_of(text, at), msg));
  }
}

nlohmann::json read_json_file(const std::string& path, const std::string& what) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError(fmt::format("{}: cannot open the {}", path, what));
  std::stringstream ss;
  ss << f.rdbuf();
  return parse_json_text(ss.str(), path);
}

}  // namespace acore
