// SPDX-License-Identifier: MIT
// JSON input files (scenario, sweep grid, harmonics spec): parsed by nlohmann-json, every failure
// of it turned into an InputError that names the file and the line, whatever nlohmann raised
// (a syntax error, or a number too large for a double, which nlohmann reports without a position).
#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace acore {

// Parses text read from `where` (a file name, used in the message).
nlohmann::json parse_json_text(const std::string& text, const std::string& where);
// Reads and parses a file; throws InputError when it cannot be opened.
nlohmann::json read_json_file(const std::string& path, const std::string& what);

}  // namespace acore
