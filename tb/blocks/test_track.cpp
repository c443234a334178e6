// SPDX-License-Identifier: MIT
// The tracking observer (rtl/acore_track.v) against the model (model/ip/stages/tracker.cpp) bit for
// bit, in the registry's parameter sets Verilated by tb/CMakeLists.txt (lines track, track_a20,
// track_l2: the loop over two clocks; track_s: time-shared, one adder, at the 20-bit widths with
// LEAD_F = 0; track_w, track_w3: word-serial, one and three bits of D a clock; track_c, track_c4:
// time-shared with coarse shifts, three and four bits a clock; the same outputs):
// every output word (angle, compensated angle, velocity, turns, LOT) of every sample, with random
// input gaps and output stalls, on an angle stream that accelerates, reverses, carries noise and
// jumps (LOT raised and cleared), at several bandwidth codes, LEAD and threshold values, with
// bandwidth codes out of range clamped by the RTL (the model is run at the clamped code).
#include <gtest/gtest.h>
#include <verilated.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <memory>
#include <random>
#include <vector>

#include "Vtrack.h"
#include "Vtrack_a20.h"
#include "Vtrack_l2.h"
#include "Vtrack_s.h"
#include "Vtrack_w.h"
#include "Vtrack_w3.h"
// The coarse-shift lines are long-sim: Verilated, and their tests built (test_track_long), only
// with -DACORE_RTL_LONG=ON.
#if __has_include("Vtrack_c.h") && __has_include("Vtrack_c4.h")
#define ACORE_TRACK_SHIFT 1
#include "Vtrack_c.h"
#include "Vtrack_c4.h"
#endif
#include "core/fixed_point.hpp"
#include "stages/tracker.hpp"

namespace acore {
namespace {

#define ACORE_TRACK_CONFIG(S)                                                              \
  TrackConfig {                                                                            \
    ACORE_##S##_ANGLE_W, ACORE_##S##_FRAC_W, ACORE_##S##_TURN_W, ACORE_##S##_COMP_LATENCY, \
        ACORE_##S##_LEAD_W, ACORE_##S##_LEAD_F                                             \
  }

using fx::mask;

// An angle stream in input LSBs: speed ramps, a reversal, noise, and a jump every so often.
std::vector<uint32_t> stimulus(const TrackConfig& c, std::mt19937_64& rng, int n) {
  std::normal_distribution<double> noise(0, 3.0);
  std::uniform_real_distribution<double> u(0, 1);
  const double scale = std::ldexp(1.0, c.angle_w - 16);
  std::vector<uint32_t> out;
  double pos = u(rng) * std::ldexp(1.0, c.angle_w), w = 0;
  const double acc = (u(rng) - 0.5) * 0.2 * scale;
  for (int i = 0; i < n; ++i) {
    w += (i < n / 2) ? acc : -2 * acc;  // accelerate, then reverse
    pos += w;
    if (u(rng) < 0.002) pos += (u(rng) - 0.5) * std::ldexp(1.0, c.angle_w - 2);  // a jump
    out.push_back(static_cast<uint32_t>(std::llround(pos + noise(rng) * scale)) &
                  static_cast<uint32_t>(mask(c.angle_w)));
  }
  return out;
}

template <class V>
void run(const TrackConfig& c, uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto ctx = std::make_unique<VerilatedContext>();
  ctx->randReset(2);
  ctx->randSeed(static_cast<int>(seed));
  auto top = std::make_unique<V>(ctx.get());
  long checked = 0, bad = 0, lots = 0;
  for (int pass = 0; pass < 6; ++pass) {
    // Registers: a code out of range on the first pass (the RTL clamps it: 0 -> K_MIN).
    TrackRegs r;
    const int bw_reg = pass == 0   ? 0
                       : pass == 1 ? 15
                                   : static_cast<int>(2 + rng() % (c.k_max() - 1));
    r.bw = std::min(std::max(bw_reg, TrackConfig::kMin), c.k_max());
    r.lead = static_cast<uint32_t>(rng() & mask(c.lead_w));
    r.lot_thr = static_cast<uint32_t>(rng() % (uint64_t{1} << (c.angle_w - 4)));
    Tracker model(c, r);
    top->bw_i = bw_reg;
    top->lead_i = r.lead;
    top->lot_thr_i = r.lot_thr;
    top->rst_i = 1;
    top->in_valid_i = 0;
    top->out_ready_i = 0;
    for (int i = 0; i < 3; ++i) {
      top->clk_i = 0, top->eval(), top->clk_i = 1, top->eval();
    }
    top->rst_i = 0;
    const auto in = stimulus(c, rng, 20000);
    std::deque<TrackOutput> expect;
    size_t next = 0;
    int idle = 0;
    while ((next < in.size() || !expect.empty()) && idle < 200) {
      const bool offer = next < in.size() && (rng() % 4 != 0);
      top->clk_i = 0;
      top->in_valid_i = offer;
      top->in_angle_i = offer ? in[next] : 0;
      top->out_ready_i = (rng() % 3 != 0);
      top->eval();
      const bool take = offer && top->in_ready_o;
      const bool give = top->out_valid_o && top->out_ready_i;
      if (give) {
        ++checked;
        if (expect.empty()) {
          ++bad;
        } else {
          const TrackOutput e = expect.front();
          expect.pop_front();
          const int64_t vel = static_cast<int64_t>(
              (static_cast<uint64_t>(top->out_velocity_o) ^ (uint64_t{1} << (c.p_w() - 1))) -
              (uint64_t{1} << (c.p_w() - 1)));
          const int64_t turns = static_cast<int64_t>(
              (static_cast<uint64_t>(top->out_turns_o) ^ (uint64_t{1} << (c.turn_w - 1))) -
              (uint64_t{1} << (c.turn_w - 1)));
          const bool same = top->out_angle_o == e.angle && top->out_angle_comp_o == e.angle_comp &&
                            vel == e.velocity && turns == e.turns && top->out_lot_o == e.lot;
          if (!same && bad < 5)
            ADD_FAILURE() << "sample " << checked << ": rtl angle " << top->out_angle_o << " comp "
                          << top->out_angle_comp_o << " v " << vel << " turns " << turns << " lot "
                          << int(top->out_lot_o) << "; model " << e.angle << " " << e.angle_comp
                          << " " << e.velocity << " " << e.turns << " " << e.lot;
          bad += !same;
          lots += e.lot;
        }
      }
      if (take) expect.push_back(model.step(in[next++]));
      idle = (take || give) ? 0 : idle + 1;
      top->clk_i = 1;
      top->eval();
    }
  }
  EXPECT_EQ(checked, 6 * 20000);
  EXPECT_EQ(bad, 0) << "mismatches of " << checked;
  EXPECT_GT(lots, 0) << "the stimulus never raised LOT";
  std::printf("acore_track ANGLE_W=%d FRAC_W=%d: %ld samples, %ld mismatches, %ld with LOT\n",
              c.angle_w, c.frac_w, checked, bad, lots);
}

// The bits of D = COMP_LATENCY + LEAD / 2^LEAD_F that can be nonzero (DE_W).
int d_bits(const TrackConfig& c) {
  const uint64_t dmax = (static_cast<uint64_t>(c.comp_latency) << c.lead_f) + mask(c.lead_w);
  int de_w = 0;
  while ((dmax >> de_w) != 0) ++de_w;
  return de_w;
}

// The word-serial form's rate: one sample every 7 + ceil(DE_W / PROD_BITS) clocks (five loop
// clocks, the product over D's nonzero bits, the compensated angle, the output register), the
// figure the board's choice of PROD_BITS rests on.
int word_clocks(const TrackConfig& c, int prod_bits) {
  return 7 + (d_bits(c) + prod_bits - 1) / prod_bits;
}

#ifdef ACORE_TRACK_SHIFT
// The coarse-shift form's rate: 3 clocks to the error, one to the loss of tracking; the loop, as
// long as the slowest code
// needs (the error shifted by k and by k + 1 more, SHIFT_BITS bits a clock while that many remain,
// else one; a clock for each update); 2 to the rounded angle; DE_W + 2 product steps; the
// compensated angle; the output register. The figure the board's choice of SHIFT_BITS rests on.
int shift_clocks(const TrackConfig& c, int shift_bits) {
  const auto steps = [shift_bits](int n) { return n / shift_bits + n % shift_bits; };
  int loop = 0;
  for (int k = TrackConfig::kMin; k <= c.k_max(); ++k)
    loop = std::max(loop, steps(k) + steps(k + 1) + 2);
  return 4 + loop + 2 + d_bits(c) + 2 + 2;
}
#endif

// With the input always offered and the output always read, one sample every `expect` clocks.
template <class V>
void rate(const TrackConfig& c, int expect) {
  auto ctx = std::make_unique<VerilatedContext>();
  auto top = std::make_unique<V>(ctx.get());
  top->bw_i = 4;
  top->lead_i = 0;
  top->lot_thr_i = 0;
  top->out_ready_i = 1;
  top->in_valid_i = 0;
  top->rst_i = 1;
  for (int i = 0; i < 3; ++i) top->clk_i = 0, top->eval(), top->clk_i = 1, top->eval();
  top->rst_i = 0;
  std::vector<long> takes;
  for (long t = 0; t < 40L * expect; ++t) {
    top->clk_i = 0;
    top->in_valid_i = 1;
    top->in_angle_i = static_cast<uint32_t>(t * 37) & static_cast<uint32_t>(mask(c.angle_w));
    top->eval();
    if (top->in_ready_o) takes.push_back(t);
    top->clk_i = 1;
    top->eval();
  }
  ASSERT_GT(takes.size(), 10u);
  for (size_t i = 1; i < takes.size(); ++i)
    EXPECT_EQ(takes[i] - takes[i - 1], expect) << "between samples " << i - 1 << " and " << i;
}

TEST(Track, RtlEqualsModel) { run<Vtrack>(ACORE_TRACK_CONFIG(TRACK), 1); }
TEST(Track, RtlEqualsModelA20) { run<Vtrack_a20>(ACORE_TRACK_CONFIG(TRACK_A20), 2); }
TEST(Track, RtlEqualsModelLoop2) { run<Vtrack_l2>(ACORE_TRACK_CONFIG(TRACK_L2), 3); }
TEST(Track, RtlEqualsModelSerial) { run<Vtrack_s>(ACORE_TRACK_CONFIG(TRACK_S), 4); }
TEST(Track, RtlEqualsModelWordSerial) { run<Vtrack_w>(ACORE_TRACK_CONFIG(TRACK_W), 5); }
TEST(Track, RtlEqualsModelWordSerial3) { run<Vtrack_w3>(ACORE_TRACK_CONFIG(TRACK_W3), 6); }
TEST(Track, WordSerialRate) {
  rate<Vtrack_w>(ACORE_TRACK_CONFIG(TRACK_W),
                 word_clocks(ACORE_TRACK_CONFIG(TRACK_W), ACORE_TRACK_W_PROD_BITS));
  rate<Vtrack_w3>(ACORE_TRACK_CONFIG(TRACK_W3),
                  word_clocks(ACORE_TRACK_CONFIG(TRACK_W3), ACORE_TRACK_W3_PROD_BITS));
}
#ifdef ACORE_TRACK_SHIFT
TEST(Track, RtlEqualsModelShift) { run<Vtrack_c>(ACORE_TRACK_CONFIG(TRACK_C), 7); }
TEST(Track, RtlEqualsModelShift4) { run<Vtrack_c4>(ACORE_TRACK_CONFIG(TRACK_C4), 8); }
// (30 clocks at track_c: the board's widths and FOLD 32's COMP_LATENCY, within its 32)
TEST(Track, ShiftRate) {
  rate<Vtrack_c>(ACORE_TRACK_CONFIG(TRACK_C),
                 shift_clocks(ACORE_TRACK_CONFIG(TRACK_C), ACORE_TRACK_C_SHIFT_BITS));
  rate<Vtrack_c4>(ACORE_TRACK_CONFIG(TRACK_C4),
                  shift_clocks(ACORE_TRACK_CONFIG(TRACK_C4), ACORE_TRACK_C4_SHIFT_BITS));
}

#endif

}  // namespace
}  // namespace acore
