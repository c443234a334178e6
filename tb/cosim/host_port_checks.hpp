// SPDX-License-Identifier: MIT
// The host port and reset contract that both tops share (docs/rtl.md "Port timing": host port,
// reset), as measurements on the one RtlHarness (for rtl/acore_top.v at any FOLD and for
// rtl/acore_serial_top.v). tb/cosim/test_cosim.cpp asserts the same numbers on every build of both,
// so the two tops cannot drift apart. Header-only, test code.
#pragma once
#include <cstdint>
#include <random>
#include <vector>

#include "regmap/regimage.hpp"

namespace acore::host_port {

// An image of the configuration whose every word differs from every other (so a read-back names
// its address) and from its value XOR 1 (the "other" word the checks write).
inline RegImage distinct_image(const RegImage& base) {
  RegImage img = base;
  const uint64_t mask = (uint64_t{1} << img.cfg.reg_w) - 1;
  for (size_t a = 0; a < img.words.size(); ++a) img.words[a] = ((a + 1) * 2 * 40503u) & mask;
  return img;
}

struct ResetBehaviour {
  int clocks = 0;           // clocks with rst_i high, a sample offered and a host write in each
  int in_ready_high = 0;    // clocks of them with in_ready_o high (must be 0)
  int out_valid_after = 0;  // clocks with out_valid_o high in LATENCY + 10 clocks after reset
  int words_changed = 0;    // words whose read-back differs from the image after reset
};

// Loads img, then holds rst_i high for `clocks` clocks while offering a sample and writing word i
// (XOR 1) in clock i; releases reset and watches the outputs and the register file.
template <class H>
ResetBehaviour reset_behaviour(H& h, const RegImage& img, int clocks) {
  ResetBehaviour r;
  r.clocks = clocks;
  h.reset();
  h.load(img);
  h.set_reset(true);
  for (int i = 0; i < clocks; ++i) {
    h.drive(true, {1000, 2000, -1000, -2000}, true);
    const int a = i % static_cast<int>(img.words.size());
    h.drive_host(a, true, img.words[a] ^ 1);
    r.in_ready_high += h.in_ready();
    h.tick();
  }
  h.drive_host(0, false, 0);
  h.drive(false, {0, 0, 0, 0}, true);
  h.set_reset(false);
  for (int n = 0; n < h.latency() + 10; ++n) {
    r.out_valid_after += h.out_valid();
    h.tick();
  }
  for (size_t a = 0; a < img.words.size(); ++a)
    r.words_changed += h.read_reg(static_cast<int>(a)) != img.words[a];
  return r;
}

// In rst_i's first clock from power-up (no edge yet, random state): is in_ready_o low?
template <class H>
bool in_ready_low_at_power_up_reset(H& h) {
  h.drive(true, {1000, 2000, 0, 0}, true);
  h.set_reset(true);
  const bool low = !h.in_ready();
  h.tick();
  return low && !h.in_ready();
}

// Read-back latency: an address held until its word shows, after a different one; the number of
// clocks from presenting it to reg_rdata_o showing its word (distinct_image loaded, core idle).
template <class H>
int read_latency(H& h, const RegImage& img, int from, int to) {
  h.drive_host(from, false, 0);
  for (int i = 0; i < 4; ++i) h.tick();
  if (h.reg_rdata() != img.words[from]) return -1;
  h.drive_host(to, false, 0);
  for (int n = 1; n <= 8; ++n) {
    h.tick();
    if (h.reg_rdata() == img.words[to]) return n;
  }
  return -1;
}

// A new address every clock (core idle): reads whose reg_rdata_o, `lag` clocks after the address,
// is not that address's word. 0 at lag = 2 means a full-rate pipelined read.
template <class H>
int streamed_read_errors(H& h, const RegImage& img, int lag, int n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<int> addr;
  int errors = 0;
  for (int t = 0; t < n; ++t) {
    addr.push_back(static_cast<int>(rng() % img.words.size()));
    h.drive_host(addr.back(), false, 0);
    h.tick();
    // After this clock's edge the pins show the word of the address of lag - 1 clocks before it.
    if (t >= lag - 1 && h.reg_rdata() != img.words[addr[t - (lag - 1)]]) ++errors;
  }
  return errors;
}

// Write word `a` (value v) with one clock, then read it with the address presented `gap` clocks
// after the write's clock: the value read back.
template <class H>
uint64_t read_after_write(H& h, int a, uint64_t v, int gap) {
  h.write_reg(a, v);  // the write's clock; the address stays on the pins with we low
  for (int i = 1; i < gap; ++i) h.tick();
  return h.read_reg(a);
}

struct PastLastWord {
  int addresses = 0;      // addresses past the last word written (up to the port's all-ones)
  int read_nonzero = 0;   // of them, reading back other than zero (must be 0)
  int words_changed = 0;  // words of the map whose read-back differs from the image (must be 0)
};

// Loads img, writes every address past the last word (WORDS .. 2^ADDR_W - 1) with a value that
// differs in every bit from each word's, then reads back those addresses and every word. A
// register file that let such a write through (into the last word, or any word the address
// aliases) changes a word; the datapath's view is checked by the caller on a stream.
template <class H>
PastLastWord writes_past_last_word(H& h, const RegImage& img) {
  PastLastWord r;
  const int words = static_cast<int>(img.words.size());
  int top = 1;
  while (top < words) top <<= 1;
  const uint64_t mask = (uint64_t{1} << img.cfg.reg_w) - 1;
  h.load(img);
  for (int a = words; a < top; ++a, ++r.addresses) h.write_reg(a, ~img.words[words - 1] & mask);
  for (int i = 0; i < 4; ++i) h.tick();
  for (int a = words; a < top; ++a) r.read_nonzero += h.read_reg(a) != 0;
  for (int a = 0; a < words; ++a) r.words_changed += h.read_reg(a) != img.words[a];
  return r;
}

}  // namespace acore::host_port
