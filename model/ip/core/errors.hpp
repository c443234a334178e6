// SPDX-License-Identifier: MIT
// Error types shared by the library and the CLI: they decide the exit status (docs/contracts.md,
// command line).
#pragma once
#include <stdexcept>
#include <string>

namespace acore {

// Bad input or bad usage: a file, line or option the user must fix. The CLI exits with 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A check that ran and failed (mismatch, accuracy target missed). The CLI exits with 1.
class CheckFailed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace acore
