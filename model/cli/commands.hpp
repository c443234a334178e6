// SPDX-License-Identifier: MIT
// One function per subcommand, each in its own cmd_<name>.cpp: it adds the subcommand to the app,
// with its options and a callback that throws acore::InputError (exit 2) or acore::CheckFailed
// (exit 1) on failure.
#pragma once
#include <CLI/CLI.hpp>

namespace acore::cli {

void add_demo(CLI::App& app);
void add_simulate(CLI::App& app);
void add_calibrate(CLI::App& app);
void add_selfcal_bench(CLI::App& app);
void add_estimate(CLI::App& app);
void add_diagnose(CLI::App& app);
void add_diagnose_bench(CLI::App& app);
void add_harmonics(CLI::App& app);
void add_sweep(CLI::App& app);
void add_cosim(CLI::App& app);

}  // namespace acore::cli
