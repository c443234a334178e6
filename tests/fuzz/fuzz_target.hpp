// SPDX-License-Identifier: MIT
// The two entry points every fuzz target has, from its `accepts` function (true: the input was
// parsed and its properties checked, false: refused with an InputError; anything else aborts):
// libFuzzer's LLVMFuzzerTestOneInput, and with ACORE_FUZZ_STANDALONE (no libFuzzer) a main() that
// runs the project's own driver (standalone_driver.hpp) with the format's alphabet.
//   ACORE_FUZZ_TARGET("fuzz_x", "characters of the format", accepts)
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#ifdef ACORE_FUZZ_STANDALONE
#include "standalone_driver.hpp"
#define ACORE_FUZZ_MAIN(name, alphabet, accepts)                                \
  int main(int argc, char** argv) {                                             \
    return acore::fuzz::standalone_main(argc, argv, {name, alphabet, accepts}); \
  }
#else
#define ACORE_FUZZ_MAIN(name, alphabet, accepts)
#endif

#define ACORE_FUZZ_TARGET(name, alphabet, accepts)                          \
  extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { \
    accepts(std::string(reinterpret_cast<const char*>(data), size));        \
    return 0;                                                               \
  }                                                                         \
  ACORE_FUZZ_MAIN(name, alphabet, accepts)
