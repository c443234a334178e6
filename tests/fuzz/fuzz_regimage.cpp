// SPDX-License-Identifier: MIT
// Fuzz target for parse_regimage (docs/contracts.md, register image, the `// acore: key=value`
// header of every correction mode): any input either parses into an image that round-trips exactly
// through format_regimage and runs through the bit-accurate model without a crash, or throws
// InputError; nothing else may happen (no crash, no other exception, no sanitizer report).
//   clang++ -std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined -Imodel
//   tests/fuzz/fuzz_regimage.cpp \
//     model/*.cpp -lfmt -lz -o fuzz_regimage && ./fuzz_regimage -max_total_time=60
// With -DACORE_FUZZ_STANDALONE any compiler builds a driver that mutates images of every mode
// (see tests/fuzz/CMakeLists.txt for the g++ command) for `-seconds N` (default 30).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/errors.hpp"
#include "engine/fixed_model.hpp"
#include "regmap/regimage.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  acore::RegImage img;
  try {
    img = acore::parse_regimage(text, "fuzz");
  } catch (const acore::InputError&) {
    return 0;
  }
  // A parsed image round-trips exactly.
  const acore::RegImage b = acore::parse_regimage(acore::format_regimage(img), "fuzz-roundtrip");
  if (b.words != img.words || b.in_scale != img.in_scale ||
      b.cfg.describe() != img.cfg.describe() || b.zero_offset != img.zero_offset)
    std::abort();
  if (static_cast<int>(img.words.size()) != img.cfg.words()) std::abort();
  // And the bit-accurate model runs on it (any words: saturation paths), extreme inputs included.
  const acore::FixedModel m(img);
  const int32_t hi = (1 << (img.cfg.in_w - 1)) - 1, lo = -hi - 1;
  for (const acore::ChannelCodes c :
       {acore::ChannelCodes{0, 0, 0, 0}, acore::ChannelCodes{hi, lo, lo, hi},
        acore::ChannelCodes{1000, -2000, 30, 7}})
    (void)m.step(c);
  return 0;
}

#ifdef ACORE_FUZZ_STANDALONE
#include <chrono>
#include <random>
#include <vector>

#include "calibration/calibration.hpp"
#include "sim/simulator.hpp"

int main(int argc, char** argv) {
  double seconds = 30;
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "-seconds" && i + 1 < argc) seconds = std::atof(argv[++i]);
  // Seeds: calibrated images of every correction mode (the reference 160 deg off the sensor, so
  // every image carries a zero offset), with and without the ZERO word.
  acore::Recording cal = acore::simulate(acore::builtin_scenario("paper-noiseless"), 4096, 1);
  for (double& t : cal.theta_ref) t += 2.792526803190927;
  std::vector<std::string> corpus;
  for (const char* p :
       {"", "DEGREE=1 REGIONS=8", "CORRECTION=1", "CORRECTION=2 FOURIER_K=3",
        "DEGREE=7 REGIONS=8 XCENTER=1", "REG_W=22 COEF_F=19 K=20 CORDIC_G=5 Z_W=24 ANGLE_W=20",
        "ZERO=1", "CORRECTION=2 FOURIER_K=3 ZERO=1"}) {
    const std::string text = acore::format_regimage(
        acore::calibrate_image(cal, acore::DatapathConfig{}.with_rtl_params(p), 1));
    corpus.push_back(text);
    // Without its crc32 line too, so that mutated words still parse and reach the model.
    const size_t at = text.find("// acore: crc32=");
    corpus.push_back(text.substr(0, at) + text.substr(text.find('\n', at) + 1));
  }
  const std::string alphabet =
      "0123456789abcdefx/:= "
      "\n-+.eacore:correctionfourier_kdegreeregionsxcenterzero_wordzero_offset_radcodecrc32";
  std::mt19937_64 rng(4321);
  size_t runs = 0, parsed = 0;
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    for (int batch = 0; batch < 200; ++batch, ++runs) {
      std::string s = corpus[rng() % corpus.size()];
      const int edits = 1 + static_cast<int>(rng() % 6);
      for (int e = 0; e < edits; ++e) {
        const size_t pos = s.empty() ? 0 : rng() % (s.size() + 1);
        switch (rng() % 5) {
          case 0:
            s.insert(pos, 1, alphabet[rng() % alphabet.size()]);
            break;
          case 1:
            if (pos < s.size()) s.erase(pos, 1 + rng() % 6);
            break;
          case 2:
            if (pos < s.size()) s[pos] = static_cast<char>(rng() & 0xff);
            break;
          case 3:
            if (pos < s.size()) s.insert(pos, s.substr(pos, rng() % 60));
            break;
          default:
            if (pos < s.size()) s[pos] = alphabet[rng() % alphabet.size()];
            break;
        }
      }
      LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(s.data()), s.size());
      try {
        acore::parse_regimage(s, "x");
        ++parsed;
        if (corpus.size() < 128) corpus.push_back(s);
      } catch (const acore::InputError&) {
      }
    }
  }
  std::printf("fuzz_regimage: %zu inputs (%zu parsed), corpus %zu, no failure\n", runs, parsed,
              corpus.size());
  return 0;
}
#endif
