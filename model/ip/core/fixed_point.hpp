// SPDX-License-Identifier: MIT
// Integer primitives of the bit-accurate model. Each maps to one RTL construct:
//   shr()            arithmetic shift right (floor), a wire slice / `>>>` in Verilog
//   round_shr()      add half an LSB then shift: round half up, one adder
//   saturate()       clamp to a signed width, sets the stage's overflow flag
//   shift_add_mul()  the adder/shifter multiplier: one conditional add of a shifted operand per
//                    bit of the other operand, every partial product truncated (floor) on its own
//   hw_mul()         the hardware multiplier (MULT = 1): `*`, then one floor shift
//
// A coverage build (-DACORE_SAT_COVERAGE: tb/cosim/sat_coverage.cpp compiles its own copy of the
// model) counts, for every call site of saturate(), the values below, inside and above its range.
#pragma once
#include <cstdint>
#ifdef ACORE_SAT_COVERAGE
#include <map>
#include <string>
#include <tuple>
#endif

namespace acore::fx {

#ifdef ACORE_SAT_COVERAGE
struct SatCount {
  uint64_t below = 0, inside = 0, above = 0;
};
// Keyed by (function, file, line) of the call and the width it saturates to.
using SatSite = std::tuple<std::string, std::string, int, int>;
inline std::map<SatSite, SatCount>& sat_counts() {
  static std::map<SatSite, SatCount> m;
  return m;
}
#define ACORE_SAT_SITE                                                                  \
  , const char *sat_fn = __builtin_FUNCTION(), const char *sat_file = __builtin_FILE(), \
               int sat_line = __builtin_LINE()
#define ACORE_SAT_COUNT(v, w)                                             \
  do {                                                                    \
    SatCount& c = sat_counts()[SatSite{sat_fn, sat_file, sat_line, (w)}]; \
    ++((v) > smax(w) ? c.above : (v) < smin(w) ? c.below : c.inside);     \
  } while (0)
#else
#define ACORE_SAT_SITE
#define ACORE_SAT_COUNT(v, w) \
  do {                        \
  } while (0)
#endif

// v * 2^-n with floor for n >= 0, v * 2^-n exactly (left shift) for n < 0.
inline int64_t shr(int64_t v, int n) {
  return n >= 0 ? (v >> n) : static_cast<int64_t>(static_cast<uint64_t>(v) << -n);
}

// Round half up: floor(v * 2^-n + 1/2), n >= 1; plain v for n == 0.
inline int64_t round_shr(int64_t v, int n) {
  return n > 0 ? ((v + (int64_t{1} << (n - 1))) >> n) : v;
}

inline int64_t smax(int w) { return (int64_t{1} << (w - 1)) - 1; }
inline int64_t smin(int w) { return -(int64_t{1} << (w - 1)); }

// Clamps v to a signed w-bit word; sets *ovf (if given) when it had to.
inline int64_t saturate(int64_t v, int w, bool* ovf ACORE_SAT_SITE) {
  ACORE_SAT_COUNT(v, w);
  if (v > smax(w)) {
    if (ovf) *ovf = true;
    return smax(w);
  }
  if (v < smin(w)) {
    if (ovf) *ovf = true;
    return smin(w);
  }
  return v;
}

// The low w bits set (w in 0..64).
inline uint64_t mask(int w) { return w >= 64 ? ~uint64_t{0} : (uint64_t{1} << w) - 1; }

// Sign-extends the low w bits of v (w in 1..64).
inline int64_t sext(int64_t v, int w) {
  const uint64_t m = uint64_t{1} << (w - 1);
  const uint64_t u = static_cast<uint64_t>(v) & ((m << 1) - 1);
  return static_cast<int64_t>((u ^ m) - m);
}

// a * b * 2^-rshift on adders and shifters: sum over the bits j of b (b_w bits, two's complement
// when b_signed, so its top bit weighs -2^(b_w-1)) of shr(a, rshift - j). Each partial product is
// truncated on its own, so the result is not a*b>>rshift but what the RTL's adder tree computes.
inline int64_t shift_add_mul(int64_t a, int64_t b, int b_w, bool b_signed, int rshift) {
  const uint64_t bits = static_cast<uint64_t>(b);
  int64_t sum = 0;
  for (int j = 0; j < b_w; ++j) {
    const int64_t pp = shr(a, rshift - j);
    const int64_t take = -static_cast<int64_t>((bits >> j) & 1u);  // all ones when bit j is set
    if (b_signed && j == b_w - 1)
      sum -= pp & take;
    else
      sum += pp & take;
  }
  return sum;
}

// a * b * 2^-rshift on a hardware multiplier (MULT = 1, the Verilog `*`): the exact product, then
// one floor shift, floor(a b 2^-rshift) (b two's complement of b_w bits when b_signed, else
// unsigned). Against shift_add_mul (b unsigned, or rshift <= b_w - 1 so that the negative top bit
// is exact): that sum is a b 2^-rshift less the fractions its c floors (the set bits of b below
// rshift) dropped, each in [0, 1), so hw_mul - shift_add_mul = floor(their sum), 0..max(0, c - 1).
// The product must fit 63 bits (the datapath's operands are at most 40 and 30 bits).
inline int64_t hw_mul(int64_t a, int64_t b, int b_w, bool b_signed, int rshift) {
  const int64_t bv =
      b_signed ? sext(b, b_w) : static_cast<int64_t>(static_cast<uint64_t>(b) & mask(b_w));
  return shr(a * bv, rshift);
}

// The product rule of a configuration's MULT: hw_mul (1) or shift_add_mul (0).
inline int64_t datapath_mul(int mult, int64_t a, int64_t b, int b_w, bool b_signed, int rshift) {
  return mult ? hw_mul(a, b, b_w, b_signed, rshift) : shift_add_mul(a, b, b_w, b_signed, rshift);
}

// The truncated part of shift_add_mul, alone: sum over the bits j < r of beta (0 <= beta < 2^r)
// of floor(rho * 2^(j-r)), for 0 <= rho < 2^r. It is below 2^r, so it fits the lanes of rho.
template <typename T>
T upper_partial_products(T rho, T beta, int r) {
  T sum = 0;
  for (int k = 1; k < r; ++k) sum += static_cast<T>((rho >> k) & (T{0} - ((beta >> (r - k)) & 1)));
  return sum;
}

// The same for r = 16 from a table of the 8-bit case: with rho = 2^8 rho1 + rho0 and
// beta = 2^8 beta1 + beta0, the bits j >= 8 of beta give rho1 beta1 + U8(rho0, beta1) and the
// bits j < 8 give U8(rho1, beta0) (rho0 < 2^8 is floored away there), U8 = the 8-bit sum.
// The 8-bit sums U8(rho, beta) at [rho << 8 | beta], built once from upper_partial_products.
const uint8_t* upper_partial_products8_table();
inline uint32_t upper_partial_products16(uint32_t rho, uint32_t beta) {
  static const uint8_t* const u8 = upper_partial_products8_table();
  const uint32_t rho1 = rho >> 8, rho0 = rho & 0xff, beta1 = beta >> 8, beta0 = beta & 0xff;
  return rho1 * beta1 + u8[rho0 << 8 | beta1] + u8[rho1 << 8 | beta0];
}

// shift_add_mul with rshift = r, split at bit r of both operands: with a = q 2^r + rho and
// b = h 2^r + beta (q, h floor, 0 <= rho, beta < 2^r), every partial product j >= r is exact (a h
// in total, the sign bit's negative weight included when r <= b_w - 1), and one of j < r is
// q 2^j + floor(rho 2^(j-r)), so
//   shift_add_mul(a, b, b_w, b_signed, r) = a h + q beta + upper_partial_products(rho, beta, r)
// for an unsigned b, and for a signed b when r <= b_w - 1. Only the last term needs the bit loop
// (or the table for r = 16); the per-sample stages and the batch path use it this way.
inline int64_t shift_add_mul_split(int64_t a, int64_t b, int r) {
  const int64_t m = (int64_t{1} << r) - 1;
  const uint64_t rho = static_cast<uint64_t>(a & m), beta = static_cast<uint64_t>(b & m);
  const uint64_t upper =
      r == 16 ? upper_partial_products16(static_cast<uint32_t>(rho), static_cast<uint32_t>(beta))
              : upper_partial_products<uint64_t>(rho, beta, r);
  return a * (b >> r) + (a >> r) * (b & m) + static_cast<int64_t>(upper);
}

}  // namespace acore::fx
