// SPDX-License-Identifier: MIT
// The folded shift-add multiplier (rtl/acore_fold_mul.v) alone, against the contract's
// fx::shift_add_mul (model/ip/core/fixed_point.hpp, every partial product floored on its own) plus
// the addend, in the four parameter sets Verilated by tb/CMakeLists.txt: the Horner step folded
// over 2 and over 4 clocks (signed b, the group scheme), the scaler's product over 16 clocks
// (unsigned b, two bits a clock accumulated in place, as at FOLD 32), and a product over 8 clocks
// whose right shift exceeds b's width (operand register loaded with a floored copy of a; in place).
// Products start every F clocks or with random gaps, with random, extreme and zero operands; each
// result must appear exactly LATENCY clocks after its start (the module's formula), from a random
// initial state.
#include <gtest/gtest.h>
#include <verilated.h>

#include <cstdint>
#include <deque>
#include <memory>
#include <random>

#include "Vfold_mul_h2.h"
#include "Vfold_mul_h4.h"
#include "Vfold_mul_r8.h"
#include "Vfold_mul_s16.h"
#include "core/fixed_point.hpp"

namespace acore {
namespace {

struct MulParams {
  int a_w, b_w, b_signed, rshift, init_w, p_w, f;
  int b() const { return (b_w + f - 1) / f; }
  // acore_fold_mul: two bits of b a clock accumulated in place when its ceil(B_W / 2) groups, the
  // clock that clears the accumulator and the addend's clock fit in F: the result held from then
  // to the next start (LATENCY = F), the addend read one clock after the start. Otherwise the group
  // scheme: L = clog2(B) tree levels, LATENCY = L + 1 + F, the addend read F clocks before the
  // result.
  bool in_place() const { return b() == 2 && (b_w + 1) / 2 + 2 <= f; }
  int latency() const {
    if (in_place()) return f;
    int l = 0;
    while ((1 << l) < b()) ++l;
    return l + 1 + f;
  }
  int init_at() const { return in_place() ? 1 : latency() - f; }
};

// The registry's parameter sets (rtl/configs.txt lines fold_mul_*, ACORE_FOLD_MUL_<SET>_<PARAM>).
#define ACORE_FOLD_MUL_PARAMS(S)                                                            \
  MulParams {                                                                               \
    ACORE_FOLD_MUL_##S##_A_W, ACORE_FOLD_MUL_##S##_B_W, ACORE_FOLD_MUL_##S##_B_SIGNED,      \
        ACORE_FOLD_MUL_##S##_RSHIFT, ACORE_FOLD_MUL_##S##_INIT_W, ACORE_FOLD_MUL_##S##_P_W, \
        ACORE_FOLD_MUL_##S##_F                                                              \
  }
MulParams params_h2() { return ACORE_FOLD_MUL_PARAMS(H2); }
MulParams params_h4() { return ACORE_FOLD_MUL_PARAMS(H4); }
MulParams params_s16() { return ACORE_FOLD_MUL_PARAMS(S16); }
MulParams params_r8() { return ACORE_FOLD_MUL_PARAMS(R8); }

int64_t random_value(std::mt19937_64& rng, int w, bool is_signed) {
  const uint64_t r = rng();
  const int64_t lo = is_signed ? -(int64_t{1} << (w - 1)) : 0;
  const int64_t hi = is_signed ? (int64_t{1} << (w - 1)) - 1 : (int64_t{1} << w) - 1;
  switch (r & 7) {
    case 0:
      return lo;
    case 1:
      return hi;
    case 2:
      return 0;
    default:
      return lo + static_cast<int64_t>((r >> 3) % static_cast<uint64_t>(hi - lo + 1));
  }
}

template <class V>
void run(const MulParams& p, uint64_t seed, bool gaps) {
  auto ctx = std::make_unique<VerilatedContext>();
  ctx->randReset(2);
  ctx->randSeed(static_cast<int>(seed));
  auto top = std::make_unique<V>(ctx.get());
  std::mt19937_64 rng(seed);
  struct Item {
    int64_t a, b, init;
    uint64_t start;
  };
  std::deque<Item> pending;  // started, result not yet checked (in start order)
  const uint64_t mask_a = (uint64_t{1} << p.a_w) - 1, mask_b = (uint64_t{1} << p.b_w) - 1;
  const uint64_t mask_i = (uint64_t{1} << p.init_w) - 1;
  int checked = 0, bad = 0;
  uint64_t next_start = 4;  // a few clocks of arbitrary state first
  for (uint64_t t = 0; checked < 20000; ++t) {
    top->clk_i = 0;
    top->start_i = t == next_start;
    if (top->start_i) {
      const Item it{random_value(rng, p.a_w, true), random_value(rng, p.b_w, p.b_signed != 0),
                    random_value(rng, p.init_w, true), t};
      top->a_i = static_cast<uint32_t>(static_cast<uint64_t>(it.a) & mask_a);
      top->b_i = static_cast<uint32_t>(static_cast<uint64_t>(it.b) & mask_b);
      pending.push_back(it);
      next_start = t + static_cast<uint64_t>(p.f) + (gaps ? rng() % 3 : 0);
    } else {
      top->a_i = static_cast<uint32_t>(rng() & mask_a);  // anything between products
      top->b_i = static_cast<uint32_t>(rng() & mask_b);
    }
    // The addend of the product started INIT_AT clocks ago (anything else otherwise).
    top->init_i = static_cast<uint32_t>(rng() & mask_i);
    for (const Item& it : pending)
      if (it.start + static_cast<uint64_t>(p.init_at()) == t)
        top->init_i = static_cast<uint32_t>(static_cast<uint64_t>(it.init) & mask_i);
    top->eval();
    if (!pending.empty() && pending.front().start + static_cast<uint64_t>(p.latency()) == t) {
      const Item it = pending.front();
      pending.pop_front();
      const int64_t want =
          fx::shift_add_mul(it.a, it.b, p.b_w, p.b_signed != 0, p.rshift) + it.init;
      const int64_t got = fx::sext(top->p_o, p.p_w);
      if (got != want && bad++ < 5)
        ADD_FAILURE() << "a=" << it.a << " b=" << it.b << " init=" << it.init << ": rtl " << got
                      << ", contract " << want;
      ++checked;
    }
    top->clk_i = 1;
    top->eval();
  }
  top->final();
  EXPECT_EQ(bad, 0);
}

TEST(FoldMul, HornerStepOverTwoClocks) {
  run<Vfold_mul_h2>(params_h2(), 1, false);
  run<Vfold_mul_h2>(params_h2(), 2, true);
}

TEST(FoldMul, HornerStepOverFourClocks) {
  run<Vfold_mul_h4>(params_h4(), 3, false);
  run<Vfold_mul_h4>(params_h4(), 4, true);
}

TEST(FoldMul, ScalerProductOverSixteenClocks) {
  run<Vfold_mul_s16>(params_s16(), 5, false);
  run<Vfold_mul_s16>(params_s16(), 6, true);
}

TEST(FoldMul, ShiftBeyondTheMultiplierWidthOverEightClocks) {
  run<Vfold_mul_r8>(params_r8(), 7, false);
  run<Vfold_mul_r8>(params_r8(), 8, true);
}

}  // namespace
}  // namespace acore
