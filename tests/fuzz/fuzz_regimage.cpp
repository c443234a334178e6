// SPDX-License-Identifier: MIT
// Fuzz target for parse_regimage (docs/contracts.md, register image, the `// acore: key=value`
// header of every correction mode): any input either parses into an image that round-trips exactly
// through format_regimage and runs through the bit-accurate model without a crash, or throws
// InputError; nothing else may happen (no crash, no other exception, no sanitizer report). Built by
// tests/fuzz/CMakeLists.txt as a libFuzzer target with clang, as the standalone driver
// (standalone_driver.hpp) otherwise; its seeds are tests/fuzz/corpus/fuzz_regimage/.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/errors.hpp"
#include "engine/fixed_model.hpp"
#include "fuzz_target.hpp"
#include "regmap/regimage.hpp"

namespace {

bool accepts(const std::string& text) {
  acore::RegImage img;
  try {
    img = acore::parse_regimage(text, "fuzz");
  } catch (const acore::InputError&) {
    return false;
  }
  // A parsed image round-trips exactly.
  const acore::RegImage b = acore::parse_regimage(acore::format_regimage(img), "fuzz-roundtrip");
  if (b.words != img.words || b.in_scale != img.in_scale || b.cfg != img.cfg ||
      b.zero_offset != img.zero_offset)
    std::abort();
  if (static_cast<int>(img.words.size()) != img.cfg.words()) std::abort();
  // And the bit-accurate model runs on it (any words: saturation paths), extreme inputs included.
  const acore::FixedModel m(img);
  const int32_t hi = (1 << (img.cfg.in_w - 1)) - 1, lo = -hi - 1;
  for (const acore::ChannelCodes c :
       {acore::ChannelCodes{0, 0, 0, 0}, acore::ChannelCodes{hi, lo, lo, hi},
        acore::ChannelCodes{1000, -2000, 30, 7}})
    (void)m.step(c);
  return true;
}

}  // namespace

ACORE_FUZZ_TARGET(
    "fuzz_regimage",
    "0123456789abcdefx/:= \n-+.eacore:correctionfourier_kdegreeregionsxcenterzero_wordzero_"
    "offset_radcodecrc32in_scalepoly2dnone",
    accepts)
