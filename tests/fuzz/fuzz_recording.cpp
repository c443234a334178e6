// SPDX-License-Identifier: MIT
// Fuzz target for parse_recording (docs/contracts.md, recording file): any input either parses
// into a consistent recording that survives a write/read round trip, or throws InputError; nothing
// else may happen (no crash, no other exception, no sanitizer report). Built by
// tests/fuzz/CMakeLists.txt as a libFuzzer target with clang, as the standalone driver
// (standalone_driver.hpp) otherwise; its seeds are tests/fuzz/corpus/fuzz_recording/.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/errors.hpp"
#include "core/recording.hpp"
#include "fuzz_target.hpp"

namespace {

bool accepts(const std::string& text) {
  acore::Recording r;
  try {
    r = acore::parse_recording(text, "fuzz");
  } catch (const acore::InputError&) {
    return false;
  }
  // A parsed recording is consistent and round-trips exactly (numbers; metadata keys/values that
  // contain no newline).
  r.check_consistent("fuzz");
  if (r.size() == 0 || (r.channels != 2 && r.channels != 4)) std::abort();
  const acore::Recording b = acore::parse_recording(acore::format_recording(r), "fuzz-roundtrip");
  if (b.channels != r.channels || b.size() != r.size() || b.theta_ref != r.theta_ref ||
      b.t != r.t || b.temp != r.temp)
    std::abort();
  for (size_t c = 0; c < 4; ++c)
    if (b.ch[c] != r.ch[c]) std::abort();
  return true;
}

}  // namespace

ACORE_FUZZ_TARGET("fuzz_recording", "0123456789.-+eE,#= \r\nabcinfnantheta_refc1c2c3c4sincostemp",
                  accepts)
