// SPDX-License-Identifier: MIT
// libFuzzer target for parse_recording (docs/contracts.md, recording file): any input either parses
// into a consistent recording that survives a write/read round trip, or throws InputError; nothing
// else may happen (no crash, no other exception, no sanitizer report).
//   clang++ -std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined -Imodel
//   tests/fuzz/fuzz_recording.cpp \
//     model/recording.cpp -lfmt -o fuzz_recording && ./fuzz_recording -max_total_time=60
// With -DACORE_FUZZ_STANDALONE it builds a driver for any compiler: it runs each file named on the
// command line, or mutates a built-in valid recording for `-seconds N` (default 30).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/errors.hpp"
#include "core/recording.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  acore::Recording r;
  try {
    r = acore::parse_recording(text, "fuzz");
  } catch (const acore::InputError&) {
    return 0;
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
  return 0;
}

#ifdef ACORE_FUZZ_STANDALONE
#include <chrono>
#include <fstream>
#include <random>
#include <sstream>
#include <vector>

int main(int argc, char** argv) {
  double seconds = 30;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "-seconds" && i + 1 < argc)
      seconds = std::atof(argv[++i]);
    else
      files.push_back(argv[i]);
  }
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string s = ss.str();
    LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(s.data()), s.size());
  }
  if (!files.empty()) return 0;
  const std::string seed_text =
      "# scenario=paper\n# p=1\n# a comment\nt,theta_ref,c1,c2,c3,c4,temp\r\n"
      "0,0,0.11,1.1,0.5,-0.87,25\n0.25,1.5707963267948966,1.2,0.1,-0.9,0.01,25.5\n"
      "0.5,3.141592653589793,-0.04,-1.02,0.13,1.1,26\n";
  const std::string alphabet = "0123456789.-+eE,#= \r\nabcinfstheta_refc1c2c3c4sincostemp";
  std::mt19937_64 rng(12345);
  std::vector<std::string> corpus = {seed_text, "theta_ref,sin,cos\n0,0,1\n1,0.8,0.5\n"};
  size_t runs = 0;
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    for (int batch = 0; batch < 1000; ++batch, ++runs) {
      std::string s = corpus[rng() % corpus.size()];
      const int edits = 1 + static_cast<int>(rng() % 8);
      for (int e = 0; e < edits; ++e) {
        const size_t pos = s.empty() ? 0 : rng() % (s.size() + 1);
        switch (rng() % 5) {
          case 0:
            s.insert(pos, 1, alphabet[rng() % alphabet.size()]);
            break;
          case 1:
            if (pos < s.size()) s.erase(pos, 1 + rng() % 4);
            break;
          case 2:
            if (pos < s.size()) s[pos] = static_cast<char>(rng() & 0xff);
            break;
          case 3:
            if (pos < s.size()) s.insert(pos, s.substr(pos, rng() % 40));
            break;
          default:
            s = s.substr(0, pos);
            break;
        }
      }
      LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(s.data()), s.size());
      // Keep parsable mutants as new seeds (a poor man's coverage feedback).
      if (corpus.size() < 256) {
        try {
          acore::parse_recording(s, "x");
          corpus.push_back(s);
        } catch (const acore::InputError&) {
        }
      }
    }
  }
  std::printf("fuzz_recording: %zu inputs, corpus %zu, no failure\n", runs, corpus.size());
  return 0;
}
#endif
