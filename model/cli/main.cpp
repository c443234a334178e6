// SPDX-License-Identifier: MIT
// anglecore: the command-line front end (docs/contracts.md, command line). Exit 0 ok, 2 bad
// usage/input, 1 failed check.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "cli_util.hpp"
#include "commands.hpp"
#include "core/errors.hpp"

int main(int argc, char** argv) {
  acore::cli::set_command_line(argc, argv);  // provenance: images record the command verbatim
  CLI::App app{"AngleCore: angle-sensor calibration, estimation, co-simulation and diagnosis"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Print help for every subcommand");
  app.set_version_flag("--version", "anglecore " ACORE_VERSION, "Print the version and exit");
  acore::cli::add_demo(app);
  acore::cli::add_simulate(app);
  acore::cli::add_calibrate(app);
  acore::cli::add_selfcal_bench(app);
  acore::cli::add_estimate(app);
  acore::cli::add_diagnose(app);
  acore::cli::add_diagnose_bench(app);
  acore::cli::add_harmonics(app);
  acore::cli::add_sweep(app);
  acore::cli::add_cosim(app);
  // With `--json -` standard output carries the JSON alone: the human-readable report goes to
  // stderr.
  if (acore::cli::json_to_stdout(argc, argv)) {
    acore::cli::json_stdout();  // binds the real stdout first
    std::cout.rdbuf(std::cerr.rdbuf());
  }
  try {
    acore::cli::require_finite_numbers(app);
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  } catch (const acore::InputError& e) {
    std::cerr << "anglecore: error: " << e.what() << "\n";
    return 2;
  } catch (const acore::CheckFailed& e) {
    std::cerr << "anglecore: check failed: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "anglecore: internal error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
