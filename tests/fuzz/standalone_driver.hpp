// SPDX-License-Identifier: MIT
// The fuzz targets' own driver, for compilers without libFuzzer (built with ACORE_FUZZ_STANDALONE,
// tests/fuzz/CMakeLists.txt): it replays a seed corpus, then mutates it for a given time with a
// seeded generator, so a run is repeatable. Its mutations are blind (no coverage feedback), but
// mutants the parser accepts join the corpus, which takes it past the first syntax checks.
//
//   fuzz_X [-seconds S] [-runs N] [-seed K] SEED_FILE_OR_DIR...
//
// Seed files whose name starts with "valid" must be accepted by the target, "invalid" rejected
// (a parser that starts accepting NaN fails here); other names carry no expectation. Every input,
// seed or mutant, runs through the target's check, which aborts on a broken property (and the
// sanitizers, when built in, on memory errors and undefined behaviour).
#pragma once
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace acore::fuzz {

struct Target {
  const char* name;
  std::string alphabet;                       // characters worth inserting (the format's syntax)
  bool (*accepts)(const std::string& input);  // true: parsed (and checked), false: rejected
};

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// One random edit of s: insert, erase, overwrite, duplicate, truncate, or splice in a piece of
// another corpus entry (which keeps lines and columns plausible).
inline void mutate(std::string& s, const std::vector<std::string>& corpus, const std::string& abc,
                   std::mt19937_64& rng) {
  const size_t pos = s.empty() ? 0 : rng() % (s.size() + 1);
  switch (rng() % 7) {
    case 0:
      s.insert(pos, 1, abc[rng() % abc.size()]);
      break;
    case 1:
      if (pos < s.size()) s.erase(pos, 1 + rng() % 8);
      break;
    case 2:
      if (pos < s.size()) s[pos] = static_cast<char>(rng() & 0xff);
      break;
    case 3:
      if (pos < s.size()) s[pos] = abc[rng() % abc.size()];
      break;
    case 4:
      if (pos < s.size()) s.insert(pos, s.substr(pos, rng() % 64));
      break;
    case 5:
      s.resize(pos);
      break;
    default: {
      const std::string& o = corpus[rng() % corpus.size()];
      if (o.empty()) break;
      const size_t from = rng() % o.size();
      s.insert(pos, o.substr(from, 1 + rng() % 80));
      break;
    }
  }
}

inline int standalone_main(int argc, char** argv, const Target& t) {
  double seconds = 0;
  uint64_t seed = 1, runs = UINT64_MAX;
  std::vector<std::filesystem::path> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-seconds" && i + 1 < argc) {
      seconds = std::atof(argv[++i]);
    } else if (a == "-runs" && i + 1 < argc) {
      runs = std::strtoull(argv[++i], nullptr, 10);
    } else if (a == "-seed" && i + 1 < argc) {
      seed = std::strtoull(argv[++i], nullptr, 10);
    } else if (std::filesystem::is_directory(a)) {
      std::vector<std::filesystem::path> in_dir;
      for (const auto& e : std::filesystem::directory_iterator(a))
        if (e.is_regular_file()) in_dir.push_back(e.path());
      std::sort(in_dir.begin(), in_dir.end());
      files.insert(files.end(), in_dir.begin(), in_dir.end());
    } else if (std::filesystem::is_regular_file(a)) {
      files.push_back(a);
    } else {
      std::fprintf(stderr, "%s: '%s' is no option, file or directory\n", t.name, a.c_str());
      return 2;
    }
  }
  if (files.empty()) {
    std::fprintf(stderr, "usage: %s [-seconds S] [-runs N] [-seed K] SEED_FILE_OR_DIR...\n",
                 t.name);
    return 2;
  }
  std::vector<std::string> corpus;
  size_t accepted = 0;
  for (const auto& f : files) {
    const std::string text = read_file(f);
    const bool ok = t.accepts(text);
    const std::string base = f.filename().string();
    const bool want_ok = base.rfind("valid", 0) == 0, want_bad = base.rfind("invalid", 0) == 0;
    if ((want_ok && !ok) || (want_bad && ok)) {
      std::fprintf(stderr, "%s: seed %s was %s, its name says it must be %s\n", t.name,
                   f.string().c_str(), ok ? "accepted" : "rejected", ok ? "rejected" : "accepted");
      return 1;
    }
    accepted += ok;
    corpus.push_back(text);
  }
  std::mt19937_64 rng(seed);
  uint64_t n = 0, parsed = 0;
  const auto start = std::chrono::steady_clock::now();
  const auto end = start + std::chrono::duration<double>(seconds);
  // -runs alone is a count, -seconds alone a time, both: whichever ends first, neither: replay
  // only.
  const bool timed = seconds > 0 || runs == UINT64_MAX;
  while (n < runs && (!timed || std::chrono::steady_clock::now() < end)) {
    for (int batch = 0; batch < 64 && n < runs; ++batch, ++n) {
      std::string s = corpus[rng() % corpus.size()];
      for (int e = 1 + static_cast<int>(rng() % 6); e > 0; --e) mutate(s, corpus, t.alphabet, rng);
      if (t.accepts(s)) {
        ++parsed;
        if (corpus.size() < 512) corpus.push_back(s);
      }
    }
  }
  const double took =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "%s: %zu seeds (%zu accepted), %llu mutants (%llu accepted) in %.1f s, seed %llu, "
      "corpus %zu, no failure\n",
      t.name, files.size(), accepted, static_cast<unsigned long long>(n),
      static_cast<unsigned long long>(parsed), took, static_cast<unsigned long long>(seed),
      corpus.size());
  return 0;
}

}  // namespace acore::fuzz
