// SPDX-License-Identifier: MIT
// Small helpers shared by the subcommands: JSON output (`--json FILE`, `-` for stdout) and the
// periodicity a recording declares in its metadata.
#pragma once
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "core/error_stats.hpp"
#include "core/recording.hpp"

namespace acore::cli {

// The command line as given, for provenance (an image header's `command=`): main() records argv
// once; command_line() joins it with each token shell-quoted where it needs it, so that pasting
// the text into a POSIX shell runs the same command. argv[0] is written by its base name
// ("anglecore"), so the text does not depend on where the binary was built or how it was reached.
void set_command_line(int argc, char** argv);
const std::string& command_line();
// A token as a POSIX shell reads it back: as is when it holds only [A-Za-z0-9_@%+=:,./-], else in
// single quotes, or as $'...' when it holds a control character (the text stays on one line).
std::string shell_quote(const std::string& token);

// `-` writes to json_stdout(): the process's standard output, kept pure JSON (main() sends the
// human-readable report to stderr when any `--json -` is given).
void write_json(const std::string& path, const nlohmann::json& j);
std::ostream& json_stdout();
// True when argv asks for JSON on standard output (`--json -` or `--json=-`).
bool json_to_stdout(int argc, char** argv);
// Every floating-point option of every subcommand must be finite: CLI11's range checks compare,
// and NaN fails no comparison (it would pass them). Called once, after the subcommands are added.
void require_finite_numbers(CLI::App& app);

}  // namespace acore::cli
