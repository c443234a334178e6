// SPDX-License-Identifier: MIT
// FixedModel::run_batch: the bit-accurate chain, stage by stage over chunks of samples, in int32
// structure-of-arrays loops. Each loop is the stage's model (scaler.cpp, poly_correct.cpp,
// cordic.cpp) written across samples instead of within one: plain loops GCC vectorizes, and
// explicit vectors (GCC/clang vector extensions: 16 int32 or 32 uint16 lanes) where state must stay
// in registers (the CORDIC) or where lanes narrower than int32 pay (the shift-add products, in
// fx::shift_add_mul_split's form). AVX-512 or AVX2 where the CPU has it, picked at run time by
// target_clones. Used where speed matters: co-sim, the benchmark, long sweeps.
#include <fmt/format.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "core/errors.hpp"
#include "core/fixed_point.hpp"
#include "engine/fixed_model.hpp"
#include "stages/fourier_correct.hpp"
#include "stages/region_select.hpp"

// The vector helpers below are inlined into each target clone; the ABI note on passing a vector
// by value (which never happens across a call here) does not apply.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace acore {

namespace {

constexpr int kChunk = 256;  // a multiple of every vector's lanes

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define ACORE_VECTOR_CLONES __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#else
#define ACORE_VECTOR_CLONES
#endif
// Helpers of a cloned function are inlined into each clone, so they get its instruction set.
#if defined(__GNUC__)
#define ACORE_INLINE inline __attribute__((always_inline))
#else
#define ACORE_INLINE inline
#endif

// Explicit vectors of 16 int32 lanes (one AVX-512 register, two AVX2 ones): the loops whose
// state must stay in registers across iterations (the CORDIC), and lane-wise table lookups.
typedef int32_t I32 __attribute__((vector_size(64)));
constexpr int kLanes32 = 16;
typedef uint32_t U32 __attribute__((vector_size(64)));

template <typename V, typename T>
ACORE_INLINE V load(const T* p) {
  V v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
template <typename V, typename T>
ACORE_INLINE void store(T* p, const V& v) {
  std::memcpy(p, &v, sizeof v);
}

// Scaler over a chunk: s = sat(round_shr(sum_j R_j * shr(d - O, R_SHIFT - G - j), G), S_W). The
// partial products j >= R_SHIFT - G are exact and add up to (d - O) (R >> (R_SHIFT - G)): one
// multiply; only the few below are shifted and floored one by one.
ACORE_VECTOR_CLONES
void scale_chunk(const int32_t* d, int n, int32_t offset, uint32_t recip, int reg_w, int rshift,
                 int guard, int s_w, int32_t* s, uint8_t* ovf) {
  const int r = rshift - guard;
  const int32_t whole = static_cast<int32_t>(recip >> r);
  int32_t acc[kChunk];
  for (int i0 = 0; i0 < n; i0 += kLanes32) {
    const I32 t = load<I32>(d + i0) - offset;
    I32 sum = t * whole;
    for (int j = 0; j < std::min(r, reg_w); ++j)
      if ((recip >> j) & 1u) sum += t >> (r - j);
    store(acc + i0, sum);
  }
  const int32_t hi = (1 << (s_w - 1)) - 1, lo = -(1 << (s_w - 1));
  const int32_t half = guard > 0 ? 1 << (guard - 1) : 0;
  for (int i = 0; i < n; ++i) {
    const int32_t v = (acc[i] + half) >> guard;
    ovf[i] |= static_cast<uint8_t>((v > hi) | (v < lo));
    s[i] = std::clamp(v, lo, hi);
  }
}

// The truncated partial products (fx::upper_partial_products) over a chunk, in explicit vectors of
// unsigned lanes L (16 bits when r <= 16: the sum is below 2^r, and 32 lanes fit one AVX-512
// register). Written by the bits of rho: bit i adds beta >> (r - i) (the same partial products
// counted the other way), and the shifted betas, shifted[k] = beta >> k, serve all six products of
// a sample (two curves, DEGREE Horner steps).
template <typename L>
struct Lanes;
template <>
struct Lanes<uint16_t> {
  typedef uint16_t type __attribute__((vector_size(64)));
};
template <>
struct Lanes<uint32_t> {
  typedef uint32_t type __attribute__((vector_size(64)));
};

template <typename L>
ACORE_INLINE void upper_chunk(const L* rho13, const L* rho24, const L* shifted, int n, int r,
                              L* u13, L* u24) {
  using V = typename Lanes<L>::type;
  constexpr int kLanes = static_cast<int>(sizeof(V) / sizeof(L));
  for (int i0 = 0; i0 < n; i0 += kLanes) {
    const V p13 = load<V>(rho13 + i0), p24 = load<V>(rho24 + i0);
    V sum13 = {}, sum24 = {};
#pragma GCC unroll 16
    for (int i = 1; i < r; ++i) {
      const V b = load<V>(shifted + (r - i) * kChunk + i0);
      const L bit = static_cast<L>(L{1} << i);
      sum13 += b & (V)((p13 & bit) != 0);  // all ones where bit i is set
      sum24 += b & (V)((p24 & bit) != 0);
    }
    store(u13 + i0, sum13);
    store(u24 + i0, sum24);
  }
}

// One Horner step of both curves, acc = sat(shift_add_mul(acc, x) + (c_j << ACC_G), ACC_W), the
// product in fx::shift_add_mul_split's form: acc h + q beta in int32 lanes, the rest in L lanes.
template <typename L>
ACORE_INLINE void horner_step(int32_t* a13, int32_t* a24, const int32_t* xh, const int32_t* xl,
                              const L* shifted, const int32_t* k13, const int32_t* k24, int n,
                              int r, int acc_guard, int acc_w, uint8_t* ovf) {
  alignas(64) L rho13[kChunk], rho24[kChunk], u13[kChunk], u24[kChunk];
  const int32_t m = (1 << r) - 1;
  for (int i = 0; i < kChunk; ++i) {  // the whole chunk: upper_chunk reads whole vectors
    rho13[i] = static_cast<L>(a13[i] & m);
    rho24[i] = static_cast<L>(a24[i] & m);
  }
  upper_chunk(rho13, rho24, shifted, n, r, u13, u24);
  const int32_t ahi = (1 << (acc_w - 1)) - 1, alo = -(1 << (acc_w - 1));
  for (int i = 0; i < n; ++i) {
    const int32_t v13 = a13[i] * xh[i] + (a13[i] >> r) * xl[i] + static_cast<int32_t>(u13[i]) +
                        k13[i] * (1 << acc_guard);
    const int32_t v24 = a24[i] * xh[i] + (a24[i] >> r) * xl[i] + static_cast<int32_t>(u24[i]) +
                        k24[i] * (1 << acc_guard);
    ovf[i] |= static_cast<uint8_t>((v13 > ahi) | (v13 < alo) | (v24 > ahi) | (v24 < alo));
    a13[i] = std::clamp(v13, alo, ahi);
    a24[i] = std::clamp(v24, alo, ahi);
  }
}

// Horner on the adder/shifter multiplier, both curves at once (they share x).
template <typename L>
ACORE_INLINE void poly_chunk(const int32_t* s13, const int32_t* s24, const int32_t* x,
                             const int32_t* c13, const int32_t* c24, int n, int degree, int s_w,
                             int s_f, int acc_guard, int acc_w, int out_shift, int32_t* y13,
                             int32_t* y24, uint8_t* ovf) {
  alignas(64) int32_t a13[kChunk] = {}, a24[kChunk] = {}, xh[kChunk], xl[kChunk];
  alignas(64) L shifted[32 * kChunk];
  const int32_t m = (1 << s_f) - 1;
  for (int i = 0; i < n; ++i) {
    xh[i] = x[i] >> s_f;
    xl[i] = x[i] & m;
    a13[i] = c13[degree * kChunk + i] * (1 << acc_guard);
    a24[i] = c24[degree * kChunk + i] * (1 << acc_guard);
  }
  for (int k = 1; k < s_f; ++k)
    for (int i = 0; i < kChunk; ++i) shifted[k * kChunk + i] = static_cast<L>((x[i] & m) >> k);
  for (int j = degree - 1; j >= 0; --j)
    horner_step(a13, a24, xh, xl, shifted, c13 + j * kChunk, c24 + j * kChunk, n, s_f, acc_guard,
                acc_w, ovf);
  const int32_t hi = (1 << (s_w - 1)) - 1, lo = -(1 << (s_w - 1));
  const int32_t half = out_shift > 0 ? 1 << (out_shift - 1) : 0;
  for (int i = 0; i < n; ++i) {
    const int32_t v13 = s13[i] - ((a13[i] + half) >> out_shift),
                  v24 = s24[i] - ((a24[i] + half) >> out_shift);
    ovf[i] |= static_cast<uint8_t>((v13 > hi) | (v13 < lo) | (v24 > hi) | (v24 < lo));
    y13[i] = std::clamp(v13, lo, hi);
    y24[i] = std::clamp(v24, lo, hi);
  }
}

ACORE_VECTOR_CLONES
void poly_chunk16(const int32_t* s13, const int32_t* s24, const int32_t* x, const int32_t* c13,
                  const int32_t* c24, int n, int degree, int s_w, int s_f, int acc_guard, int acc_w,
                  int out_shift, int32_t* y13, int32_t* y24, uint8_t* ovf) {
  poly_chunk<uint16_t>(s13, s24, x, c13, c24, n, degree, s_w, s_f, acc_guard, acc_w, out_shift, y13,
                       y24, ovf);
}

ACORE_VECTOR_CLONES
void poly_chunk32(const int32_t* s13, const int32_t* s24, const int32_t* x, const int32_t* c13,
                  const int32_t* c24, int n, int degree, int s_w, int s_f, int acc_guard, int acc_w,
                  int out_shift, int32_t* y13, int32_t* y24, uint8_t* ovf) {
  poly_chunk<uint32_t>(s13, s24, x, c13, c24, n, degree, s_w, s_f, acc_guard, acc_w, out_shift, y13,
                       y24, ovf);
}

// CORDIC vectoring with quadrant pre-rotation (cordic.cpp), Z kept modulo 2^Z_W: the state of 16
// samples in registers through the K iterations, two such groups interleaved (each iteration
// depends on the one before: two independent chains keep the pipelines busy).
struct CordicLanes {
  I32 X, Y;
  U32 Z;
  ACORE_INLINE CordicLanes(const int32_t* xin, const int32_t* yin, int guard, uint32_t half_turn) {
    const I32 x = load<I32>(xin) * (1 << guard), y = load<I32>(yin) * (1 << guard);
    const I32 neg = x < 0;  // all ones where x < 0: rotate by half a turn
    X = (x ^ neg) - neg;
    Y = (y ^ neg) - neg;
    Z = (U32)neg & half_turn;
  }
  ACORE_INLINE void iterate(int k, uint32_t atan_k) {
    const I32 xs = X >> k, ys = Y >> k;
    const I32 d = Y >> 31;  // 0 when Y >= 0, -1 when Y < 0
    X += (ys ^ d) - d;      // +ys or -ys
    Y -= (xs ^ d) - d;
    Z += (atan_k ^ (U32)d) - (U32)d;
  }
  ACORE_INLINE void finish(int guard, uint32_t zmask, uint32_t rnd, int drop, uint32_t amask,
                           uint32_t* angle, int32_t* mag) const {
    store(angle, (((Z & zmask) + rnd) >> drop) & amask);
    store(mag, X >> guard);
  }
};

ACORE_VECTOR_CLONES
void cordic_chunk(const int32_t* xin, const int32_t* yin, int n, const int32_t* atan,
                  int iterations, int guard, int z_w, int angle_w, uint32_t* angle, int32_t* mag) {
  const uint32_t half_turn = 1u << (z_w - 1), zmask = (z_w >= 32) ? ~0u : ((1u << z_w) - 1);
  const int drop = z_w - angle_w;
  const uint32_t amask = (1u << angle_w) - 1, rnd = drop > 0 ? 1u << (drop - 1) : 0u;
  for (int i0 = 0; i0 < n; i0 += 2 * kLanes32) {
    const int i1 = i0 + kLanes32;
    CordicLanes a(xin + i0, yin + i0, guard, half_turn), b(xin + i1, yin + i1, guard, half_turn);
    for (int k = 0; k < iterations; ++k) {
      a.iterate(k, static_cast<uint32_t>(atan[k]));
      b.iterate(k, static_cast<uint32_t>(atan[k]));
    }
    a.finish(guard, zmask, rnd, drop, amask, angle + i0, mag + i0);
    b.finish(guard, zmask, rnd, drop, amask, angle + i1, mag + i1);
  }
}

// Domain selection (region_select.hpp) across samples.
ACORE_VECTOR_CLONES
void region_chunk(const int32_t* s13, const int32_t* s24, int n, int regions, int32_t* region,
                  int32_t* x) {
  for (int i = 0; i < n; ++i) {
    const int32_t a13 = s13[i] < 0 ? -s13[i] : s13[i], a24 = s24[i] < 0 ? -s24[i] : s24[i];
    const bool sine = a13 <= a24;
    const int32_t r4 = sine ? (s24[i] >= 0 ? 0 : 2) : (s13[i] >= 0 ? 1 : 3);
    const int32_t xv = sine ? s13[i] : s24[i];
    x[i] = xv;
    region[i] = regions == 8 ? 2 * r4 + (xv >= 0 ? 1 : 0) : r4;
  }
}

// Lane i of the result is table[idx[i]] (0 <= idx < 16): one register permute.
ACORE_INLINE I32 lookup(const I32& table, const I32& idx) {
#if defined(__clang__)  // clang has no variable-index __builtin_shuffle
  I32 out;
  for (int i = 0; i < kLanes32; ++i) out[i] = table[idx[i] & 15];
  return out;
#else
  return __builtin_shuffle(table, idx);
#endif
}

// Each sample's polynomial coefficients, one array per power: a lane-wise lookup in the table of
// the regions' words.
ACORE_VECTOR_CLONES
void gather_chunk(const int32_t* region, int n, const int32_t* coef, int regions, int terms,
                  int32_t* c13, int32_t* c24) {
  for (int j = 0; j < terms; ++j) {
    I32 t13 = {}, t24 = {};
    for (int r = 0; r < regions; ++r) {
      t13[r] = coef[r * 2 * terms + j];
      t24[r] = coef[r * 2 * terms + terms + j];
    }
    for (int i0 = 0; i0 < n; i0 += kLanes32) {
      const I32 idx = load<I32>(region + i0);
      store(c13 + j * kChunk + i0, lookup(t13, idx));
      store(c24 + j * kChunk + i0, lookup(t24, idx));
    }
  }
}

// Input codes to the pre-filter's differences (prefilter.hpp).
ACORE_VECTOR_CLONES
void prefilter_chunk(const ChannelCodes* in, int n, int32_t* d13, int32_t* d24, uint8_t* ovf) {
  for (int i = 0; i < n; ++i) {
    d13[i] = in[i][0] - in[i][2];
    d24[i] = in[i][1] - in[i][3];
    ovf[i] = 0;
  }
}

// The RTL-visible outputs, each written as one 64-bit word (angle, region, flags, zero padding).
static_assert(sizeof(FixedOutput) == 8 && offsetof(FixedOutput, region) == 4 &&
                  offsetof(FixedOutput, flags) == 5,
              "output_chunk packs FixedOutput as angle | region << 32 | flags << 40");
ACORE_VECTOR_CLONES
void output_chunk(const uint32_t* angle, const int32_t* mag, const int32_t* region,
                  const uint8_t* ovf, int n, int64_t mag_lo, int64_t mag_hi, FixedOutput* out) {
  uint64_t packed[kChunk];
  for (int i = 0; i < n; ++i) {
    const uint64_t flags =
        (ovf[i] ? 1u : 0u) | (mag[i] < mag_lo ? 2u : 0u) | (mag[i] > mag_hi ? 4u : 0u);
    packed[i] = angle[i] | static_cast<uint64_t>(region[i]) << 32 | flags << 40;
  }
  std::memcpy(out, packed, sizeof(uint64_t) * n);
}

// The ZERO word's adder after everything else: angle - zero modulo a turn.
ACORE_VECTOR_CLONES
void zero_chunk(FixedOutput* out, size_t n, uint32_t zero, int angle_w) {
  const uint32_t mask = (uint32_t{1} << angle_w) - 1;
  for (size_t i = 0; i < n; ++i) out[i].angle = (out[i].angle - zero) & mask;
}

// One chunk through a mode's vector kernel (the BATCH column of core/correction_modes.hpp): the
// scaled curves, x and the region in, the corrected curves out. The kernels take x raw (no
// XCENTER: run_batch() runs step() for a centred argument).
struct BatchChunk {
  const DatapathConfig* cfg;
  int n;
  const int32_t *s13, *s24, *x, *region;
  const int32_t* coef;             // every polynomial word of the image, in map order
  int32_t *scratch13, *scratch24;  // terms * kChunk words each
  int32_t *y13, *y24;
  uint8_t* ovf;
};
using BatchKernel = void (*)(const BatchChunk&);

// poly: the region's coefficients gathered per lane, then Horner (poly_correct.cpp).
void batch_poly(const BatchChunk& b) {
  const DatapathConfig& cfg = *b.cfg;
  gather_chunk(b.region, b.n, b.coef, cfg.regions, cfg.degree + 1, b.scratch13, b.scratch24);
  (cfg.s_f <= 16 ? poly_chunk16 : poly_chunk32)(
      b.s13, b.s24, b.x, b.scratch13, b.scratch24, b.n, cfg.degree, cfg.s_w, cfg.s_f, cfg.acc_guard,
      cfg.acc_w(), cfg.acc_f() - cfg.s_f, b.y13, b.y24, b.ovf);
}

// none: the scaled curves go straight to the CORDIC.
void batch_none(const BatchChunk& b) {
  std::copy(b.s13, b.s13 + b.n, b.y13);
  std::copy(b.s24, b.s24 + b.n, b.y24);
}

// By ID; nullptr: the mode has no vector kernel, run_batch() runs step() per sample.
constexpr BatchKernel kBatchKernels[] = {ACORE_CORRECTION_MODES(ACORE_MODE_BATCH)};

}  // namespace

bool FixedModel::batch_fits_int32() const {
  const DatapathConfig& c = img_.cfg;
  return c.t_w() + c.reg_w - (c.r_shift - c.scale_guard) + 1 <= 31 &&
         c.acc_w() + c.s_w - c.s_f + 2 <= 31 && c.xy_w() + 1 <= 31 && c.z_w <= 31;
}

void FixedModel::run_batch(const ChannelCodes* in, size_t n, FixedOutput* out) const {
  const DatapathConfig& cfg = img_.cfg;
  const CorrectionMode& mode = correction_mode(cfg.correction);
  if (!mode.runs_on(kEngineBatch))
    throw InputError(
        fmt::format("the batch engine does not run the correction mode {}", mode.name));
  // The vector loops cover the modes with a vector kernel on the raw x; the others run step().
  const BatchKernel correct = kBatchKernels[mode.id];
  // MULT = 1 (the hardware product's rule) has no vector kernel either.
  if (!batch_fits_int32() || correct == nullptr || cfg.xcenter || cfg.mult) {
    for (size_t i = 0; i < n; ++i) out[i] = to_output(step(in[i]));
    return;
  }
  const int terms = cfg.coef_per_curve();
  int32_t d13[kChunk] = {}, d24[kChunk] = {}, s13[kChunk] = {}, s24[kChunk] = {}, x[kChunk] = {},
          y13[kChunk] = {}, y24[kChunk] = {}, mag[kChunk];
  uint32_t angle[kChunk];
  uint8_t ovf[kChunk];
  int32_t region[kChunk] = {};
  std::vector<int32_t> coef13(static_cast<size_t>(terms) * kChunk), coef24(coef13.size());
  std::vector<int32_t> atan32(atan_.begin(), atan_.end()), coef32(coef_.begin(), coef_.end());

  for (size_t base = 0; base < n; base += kChunk) {
    const int m = static_cast<int>(std::min<size_t>(kChunk, n - base));
    prefilter_chunk(in + base, m, d13, d24, ovf);
    scale_chunk(d13, m, static_cast<int32_t>(img_.offset(0)), static_cast<uint32_t>(img_.recip(0)),
                cfg.reg_w, cfg.r_shift, cfg.scale_guard, cfg.s_w, s13, ovf);
    scale_chunk(d24, m, static_cast<int32_t>(img_.offset(1)), static_cast<uint32_t>(img_.recip(1)),
                cfg.reg_w, cfg.r_shift, cfg.scale_guard, cfg.s_w, s24, ovf);
    region_chunk(s13, s24, m, cfg.regions, region, x);
    correct(
        {&cfg, m, s13, s24, x, region, coef32.data(), coef13.data(), coef24.data(), y13, y24, ovf});
    cordic_chunk(y24, y13, m, atan32.data(), cfg.iterations, cfg.cordic_guard, cfg.z_w, cfg.angle_w,
                 angle, mag);
    output_chunk(angle, mag, region, ovf, m, window_.mag_lo, window_.mag_hi, out + base);
  }
  if (cfg.fourier_k > 0)
    for (size_t i = 0; i < n; ++i)
      out[i].angle = fourier_correct(out[i].angle, fourier_.data(), atan_.data(), cfg);
  if (cfg.zero_word) zero_chunk(out, n, zero_, cfg.angle_w);
}

}  // namespace acore
