// SPDX-License-Identifier: MIT
// Small helpers shared by the subcommands: JSON output (`--json FILE`, `-` for stdout) and the
// periodicity a recording declares in its metadata.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "core/error_stats.hpp"
#include "core/recording.hpp"

namespace acore::cli {

// `-` writes to json_stdout(): the process's standard output, kept pure JSON (main() sends the
// human-readable report to stderr when any `--json -` is given).
void write_json(const std::string& path, const nlohmann::json& j);
std::ostream& json_stdout();
// True when argv asks for JSON on standard output (`--json -` or `--json=-`).
bool json_to_stdout(int argc, char** argv);
nlohmann::json stats_json(const ErrorStats& s);
// `# p=N` in the recording's metadata, else 1; throws InputError on a malformed value.
int recording_periodicity(const Recording& rec, const std::string& path);

}  // namespace acore::cli
