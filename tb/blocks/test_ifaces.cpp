// SPDX-License-Identifier: MIT
// The drive interfaces on the angle stream alone, each Verilated from its registry line
// (rtl/configs.txt: stage_abz, stage_uvw, stage_spi) and checked against an expectation written
// here, independently of the RTL:
//   - ABZ (rtl/acore_abz.v): a quadrature decoder (Gray-step table, x4 counting) counts the A/B
//     edges; after every catch-up its count equals floor(angle 4N / 2^ANGLE_W) (with the one-LSB
//     hysteresis rule in closed form), no step ever changes A and B together (a lost count), no two
//     edges are closer than the spacing register, the catch-up takes the shorter way at the full
//     rate, and Z rises exactly when the decoder passes the index count, once a turn; a +-1 LSB
//     dither anywhere moves no edge at the reset hysteresis; a change of N re-homes at once with
//     A/B held, then legal single steps only;
//   - UVW (rtl/acore_uvw.v): every angle of the turn for several pole-pair counts and offsets
//     against the six-step sectors in closed form (integer arithmetic on 6e against the turn);
//   - SPI (rtl/acore_spi_as5047.v): an SPI mode-1 master at clk/4 .. clk/10 sending the frames open
//     motor-control drivers send to an AS5047P (SimpleFOC's MagneticSensorSPI: the read command
//     0x3FFF | R | parity, then a NOP frame whose answer is the angle; ODrive: 0xFFFF every cycle,
//     the answer's parity and error flag checked), reads the angle; parity errors, framing errors
//     (a CSn gap of one clock included) and invalid commands are refused and reported in ERRFL and
//     the error flag; MISO moves SYNC + 1 clocks after each falling SCLK edge.
#include <gtest/gtest.h>
#include <verilated.h>

#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "Vstage_abz.h"
#include "Vstage_pwm.h"
#include "Vstage_spi.h"
#include "Vstage_uvw.h"
#include "stages/interfaces.hpp"

namespace acore {
namespace {

template <class V>
std::unique_ptr<V> make(std::unique_ptr<VerilatedContext>& ctx, uint64_t seed) {
  ctx = std::make_unique<VerilatedContext>();
  ctx->randReset(2);
  ctx->randSeed(static_cast<int>(seed));
  return std::make_unique<V>(ctx.get());
}
template <class V>
void tick(V& top) {
  top.clk_i = 0;
  top.eval();
  top.clk_i = 1;
  top.eval();
}

// ---- ABZ ----------------------------------------------------------------------------------------
constexpr int kAbzAngleW = ACORE_STAGE_ABZ_ANGLE_W;
constexpr int kAbzNW = ACORE_STAGE_ABZ_N_W;
// acore_abz.v's LATENCY (an accepted angle to its target) and its conversion period (three
// products of ceil(N_W / 2) steps and a clock each on one datapath).
constexpr int kAbzLatency = 3 * ((kAbzNW + 1) / 2) + 5;
constexpr int kAbzConvert = 3 * ((kAbzNW + 1) / 2) + 4;
constexpr int64_t kTurn = int64_t{1} << kAbzAngleW;

// An x4 quadrature decoder as a drive's timer counts: the Gray position of (A, B) is 0 (00),
// 1 (A), 2 (AB), 3 (B); a step of +1 or -1 counts, a step of 2 (both changed) is a lost count.
struct Decoder {
  int64_t pos = 0;  // unwrapped
  int last = 0;
  int64_t lost = 0, edges = 0;
  uint64_t last_edge = 0, min_gap = UINT64_MAX;
  static int gray(int a, int b) {
    static const int table[2][2] = {{0, 3}, {1, 2}};  // [a][b]
    return table[a][b];
  }
  void sample(int a, int b, uint64_t t) {
    const int g = gray(a, b);
    const int d = (g - last + 4) % 4;
    if (d == 0) return;
    if (d == 2) ++lost;
    pos += d == 1 ? 1 : d == 3 ? -1 : 0;
    if (edges > 0 && t - last_edge < min_gap) min_gap = t - last_edge;
    last_edge = t;
    ++edges;
    last = g;
  }
};

struct AbzBench {
  std::unique_ptr<VerilatedContext> ctx;
  std::unique_ptr<Vstage_abz> top;
  Decoder dec;
  uint64_t t = 0;
  int64_t n = 1;
  int64_t index = 0;
  int64_t z_rises = 0, z_bad = 0;
  int z_prev = 0;
  int64_t hys = 2;
  AbzBench(int64_t n_, int64_t index_, int spacing, uint64_t seed, int64_t hys_ = 2)
      : n(n_), index(index_), hys(hys_) {
    top = make<Vstage_abz>(ctx, seed);
    top->n_i = static_cast<uint32_t>(n);
    top->index_i = static_cast<uint32_t>(index);
    top->spacing_i = static_cast<uint32_t>(spacing);
    top->hys_i = static_cast<uint32_t>(hys);
    top->angle_valid_i = 0;
    top->rst_i = 1;
    tick(*top);
    tick(*top);
    top->rst_i = 0;
    tick(*top);
    dec = Decoder{};
    dec.last = Decoder::gray(top->a_o, top->b_o);
    z_prev = top->z_o;
  }
  int64_t counts() const { return 4 * n; }
  int64_t wrapped() const { return ((dec.pos % counts()) + counts()) % counts(); }
  void step() {
    tick(*top);
    ++t;
    dec.sample(top->a_o, top->b_o, t);
    // Z is high exactly while the decoder stands on the index count.
    if (top->z_o && wrapped() != index) ++z_bad;
    if (top->z_o && !z_prev) ++z_rises;
    z_prev = top->z_o;
  }
  void angle(uint32_t a) {
    top->angle_valid_i = 1;
    top->angle_i = a;
    step();
    top->angle_valid_i = 0;
  }
  // Clocks until settled (bounded); the outputs are one clock behind the count.
  uint64_t settle(uint64_t limit) {
    const uint64_t t0 = t;
    while (!top->settled_o && t - t0 < limit) step();
    step();
    return t - t0;
  }
};

// floor(a 4N / T): the count of an angle.
int64_t count_lo(int64_t a, int64_t n) { return (a * 4 * n) >> kAbzAngleW; }
// Hysteresis as a window: the previous count holds while it lies within h LSBs of the angle, that
// is while some angle of a - h .. a + h (round the turn) has that count; otherwise the angle's
// count.
int64_t next_count(int64_t a, int64_t n, int64_t h, int64_t previous) {
  for (int64_t x = a - h; x <= a + h; ++x)
    if (count_lo(((x % kTurn) + kTurn) % kTurn, n) == previous) return previous;
  return count_lo(a, n);
}
// The shorter way from c to t modulo m (a half turn goes forward).
int64_t distance(int64_t c, int64_t t, int64_t m) {
  const int64_t d = ((t - c) % m + m) % m;
  return d <= m / 2 ? d : m - d;
}

class Abz : public ::testing::TestWithParam<int> {};

TEST_P(Abz, DecoderCountEqualsFloorAfterEveryCatchUpWithoutLostCounts) {
  const int64_t n = GetParam();
  std::mt19937_64 rng(1000 + n);
  for (int spacing : {1, 3}) {
    const int64_t index = (4 * n) / 3;
    AbzBench b(n, index, spacing, rng());
    int64_t expected = 0;
    int64_t max_late = 0;
    for (int k = 0; k < 120; ++k) {
      // Jumps anywhere, small moves, single-LSB moves, and the extremes of the turn.
      int64_t a;
      switch (k % 4) {
        case 0:
          a = static_cast<int64_t>(rng() % kTurn);
          break;
        case 1:
          a = (b.top->angle_i + static_cast<int64_t>(rng() % 2001) - 1000 + kTurn) % kTurn;
          break;
        case 2:
          a = (b.top->angle_i + (rng() % 2 ? 1 : kTurn - 1)) % kTurn;
          break;
        default:
          a = (k / 4) % 2 ? kTurn - 1 : 0;
      }
      const int64_t next = next_count(a, n, b.hys, expected);
      const int64_t dist = distance(expected, next, 4 * n);
      b.angle(static_cast<uint32_t>(a));
      const uint64_t took = b.settle(100 + 4 * n * spacing + 64);
      ASSERT_EQ(b.wrapped(), next) << "N " << n << " angle " << a << " step " << k;
      ASSERT_EQ(b.top->count_o, next);
      // At the full rate: one edge per `spacing` clocks after the LATENCY clocks of the products.
      max_late = std::max<int64_t>(max_late, static_cast<int64_t>(took) - dist * spacing);
      expected = next;
    }
    EXPECT_EQ(b.dec.lost, 0);
    EXPECT_GE(b.dec.min_gap, static_cast<uint64_t>(spacing));
    EXPECT_LE(max_late, kAbzLatency + 3);
    EXPECT_EQ(b.z_bad, 0);
  }
}

TEST_P(Abz, FullRateRampLosesNoCountAndIndexOncePerTurn) {
  const int64_t n = GetParam();
  std::mt19937_64 rng(2000 + n);
  const int64_t index = static_cast<int64_t>(rng() % (4 * n));
  AbzBench b(n, index, 1, rng());
  // The angle advances faster than one count a clock (the count runs at the maximum rate behind it)
  // for about three turns, forward, then back two turns.
  const int64_t per_clock_counts_x16 = 24;  // 1.5 counts a clock
  // (The target is converted once per kAbzConvert clocks, latest sample wins: the angle may move
  // at most a quarter turn per conversion, or the shorter way would be the wrong way; for small N
  // that bound is below 1.5 counts a clock.)
  const int64_t step =
      std::max<int64_t>(1, std::min<int64_t>(per_clock_counts_x16 * kTurn / (16 * 4 * n),
                                             kTurn / (4 * (kAbzConvert + 1))));
  int64_t unwrapped = 0;
  auto run = [&](int64_t turns, int dir) {
    const int64_t clocks = turns * kTurn / step;
    for (int64_t k = 0; k < clocks; ++k) {
      unwrapped += dir * step;
      // Keep the count within half a turn of the angle (the shorter way stays the true way).
      const int64_t lag = std::llabs(((unwrapped * 4 * n) >> kAbzAngleW) - b.dec.pos);
      if (lag > n) {
        b.settle(1u << 30);
      }
      b.angle(static_cast<uint32_t>(((unwrapped % kTurn) + kTurn) % kTurn));
    }
    b.settle(1u << 30);
  };
  run(3, +1);
  const int64_t fwd_pos = b.dec.pos;
  EXPECT_EQ(fwd_pos, (unwrapped * 4 * n) >> kAbzAngleW);
  // Index: one rise per pass over the index count, forward.
  int64_t passes = 0;
  for (int64_t c = 1; c <= fwd_pos; ++c) passes += (c % (4 * n)) == index;
  EXPECT_EQ(b.z_rises, passes);
  run(2, -1);
  // Backwards a count within the hysteresis window may hold (approached from above).
  const int64_t a = ((unwrapped % kTurn) + kTurn) % kTurn;
  const int64_t wrapped = b.wrapped();
  EXPECT_EQ(next_count(a, n, b.hys, wrapped), wrapped);
  EXPECT_EQ(b.dec.lost, 0);
  // The count ran at the full rate (one edge a clock) whenever the angle asked for more.
  if (step * 4 * n > kTurn) EXPECT_EQ(b.dec.min_gap, 1u);
  EXPECT_EQ(b.z_bad, 0);
  // Unwrapped too: the decoder went forward three turns and back two without a miscount.
  const int64_t lo_unwrapped = (unwrapped * 4 * n) >> kAbzAngleW;
  EXPECT_TRUE(b.dec.pos == lo_unwrapped || b.dec.pos == lo_unwrapped + 1) << b.dec.pos;
}

// A dither over 2d + 1 neighbouring LSBs (+-d) centred anywhere, at a hysteresis of 2d: once the
// count stands on one of its values, no edge at all. Centres on every offset around count
// boundaries and at random; without hysteresis the same dither across a boundary does move edges
// (the bench can tell).
TEST_P(Abz, DitherWithinTheHysteresisMovesNoEdgeAnywhere) {
  const int64_t n = GetParam();
  std::mt19937_64 rng(3000 + n);
  int64_t moved = 0, unhysteretic_edges = 0;
  for (int64_t d : {1, 3}) {
    for (int pos = 0; pos < 10; ++pos) {
      // A count boundary bnd (count_lo(bnd - 1) != count_lo(bnd)) and a centre near it, or
      // anywhere.
      int64_t bnd = 1 + static_cast<int64_t>(rng() % (kTurn - 8));
      while (count_lo(bnd - 1, n) == count_lo(bnd, n)) bnd = 1 + (bnd % (kTurn - 8));
      const int64_t centre =
          pos < 8 ? bnd - d - 1 + pos % (2 * d + 2) : static_cast<int64_t>(rng() % kTurn);
      for (int64_t h : {2 * d, int64_t{0}}) {
        if (h == 0 && (d != 1 || pos >= 8)) continue;
        AbzBench b(n, 0, 1, rng(), h);
        auto dither = [&] {
          const int64_t x = centre + static_cast<int64_t>(rng() % (2 * d + 1)) - d;
          return static_cast<uint32_t>(((x % kTurn) + kTurn) % kTurn);
        };
        // From half a turn away onto one of the dither's values: the count is that value's.
        b.angle(static_cast<uint32_t>((centre + kTurn / 2) % kTurn));
        b.settle(1u << 30);
        const uint32_t first = dither();
        b.angle(first);
        b.settle(1u << 30);
        ASSERT_EQ(b.top->count_o, static_cast<uint32_t>(count_lo(first, n)));
        const int64_t edges = b.dec.edges;
        for (int k = 0; k < 500; ++k) {
          b.angle(dither());
          b.step();
          b.step();
        }
        b.settle(1u << 30);
        if (h > 0)
          moved += b.dec.edges - edges;
        else
          unhysteretic_edges += b.dec.edges - edges;
        EXPECT_EQ(b.dec.lost, 0);
      }
    }
  }
  EXPECT_EQ(moved, 0) << "a dither within the hysteresis moved the count";
  // Centres bnd - 1 and bnd straddle the boundary: without hysteresis A or B toggles.
  EXPECT_GT(unhysteretic_edges, 0);
}

TEST_P(Abz, MinimumSpacingHoldsAfterAJump) {
  const int64_t n = GetParam();
  std::mt19937_64 rng(4000 + n);
  const int spacing = 7;
  AbzBench b(n, 0, spacing, rng());
  const int64_t a = static_cast<int64_t>(rng() % kTurn);
  b.angle(static_cast<uint32_t>(a));
  const uint64_t took = b.settle(1u << 30);
  const int64_t target = count_lo(a, n);
  const int64_t dist = distance(0, target, 4 * n);
  EXPECT_EQ(b.wrapped(), target);
  EXPECT_EQ(b.dec.edges, dist);
  if (dist > 1) EXPECT_EQ(b.dec.min_gap, static_cast<uint64_t>(spacing));
  EXPECT_LE(static_cast<int64_t>(took), dist * spacing + kAbzLatency + 3);
  EXPECT_EQ(b.dec.lost, 0);
}

// N up to the block's largest, 2^(N_W-1).
INSTANTIATE_TEST_SUITE_P(PulsesPerTurn, Abz,
                         ::testing::Values(1, 3, 1000, 1024, 1 << (kAbzNW - 1), 7, 360));

TEST(AbzRange, OutOfRangeNIsClamped) {
  // N = 0 counts as 1, N above 2^(N_W-1) as 2^(N_W-1) (the board's registers refuse both).
  for (const auto& [n_in, n_eff] : std::vector<std::pair<int64_t, int64_t>>{
           {0, 1}, {(int64_t{1} << (kAbzNW - 1)) + 5, int64_t{1} << (kAbzNW - 1)}}) {
    AbzBench b(n_in, 0, 1, 7);
    b.n = n_eff;
    const int64_t a = kTurn / 3;
    b.angle(static_cast<uint32_t>(a));
    b.settle(1u << 30);
    EXPECT_EQ(b.wrapped(), count_lo(a, n_eff)) << n_in;
  }
}

// Moves down and up by a few LSBs at N = 1024 (a count is 16 LSBs): the count holds exactly while
// the angle is within the hysteresis of its interval, and lands on floor(angle 4N / T) otherwise
// (280 then 271: count 17, then 16 without hysteresis, 17 held with 1 LSB or more).
TEST(AbzHysteresis, SmallMovesFollowTheWindowRuleExactly) {
  const int64_t n = 1024;
  std::mt19937_64 rng(3100);
  for (int64_t h : {0, 1, 3}) {
    AbzBench b(n, 0, 1, rng(), h);
    b.angle(280);
    b.settle(1u << 30);
    ASSERT_EQ(b.top->count_o, 17u);
    b.angle(271);
    b.settle(1u << 30);
    EXPECT_EQ(b.top->count_o, h == 0 ? 16u : 17u) << "hysteresis " << h;
    int64_t expected = b.top->count_o, wrong = 0;
    int64_t a = 271;
    for (int k = 0; k < 2000; ++k) {
      a = (a + static_cast<int64_t>(rng() % 33) - 16 + kTurn) % kTurn;
      expected = next_count(a, n, h, expected);
      b.angle(static_cast<uint32_t>(a));
      b.settle(1u << 30);
      wrong += static_cast<int64_t>(b.top->count_o) != expected;
    }
    EXPECT_EQ(wrong, 0) << "hysteresis " << h;
    EXPECT_EQ(b.dec.lost, 0);
  }
}

// A change of N alone (no new angle): in the clock it changes and until the new count is known,
// A and B hold; then the count stands on the value with the old count's two low bits nearest the
// new floor, and walks there in at most two single steps: the decoder sees no illegal step, moves
// by exactly that walk, and the count is floor(angle 4N' / T) within N_W + 8 clocks.
TEST(AbzNChange, ReHomesAtOnceWithAandBHeldThenSingleSteps) {
  std::mt19937_64 rng(3200);
  const std::vector<std::pair<int64_t, int64_t>> changes = {
      {1024, 1000},           {1000, 1024}, {3, 1 << (kAbzNW - 1)},
      {1 << (kAbzNW - 1), 1}, {360, 7},     {7, 360}};
  int64_t held_bad = 0, late = 0, wrong = 0, walk_bad = 0, lost = 0;
  for (const auto& [n1, n2] : changes) {
    for (int k = 0; k < 12; ++k) {
      AbzBench b(n1, 0, 1, rng());
      const int64_t a = static_cast<int64_t>(rng() % kTurn);
      b.angle(static_cast<uint32_t>(a));
      b.settle(1u << 30);
      const int64_t c_old = b.top->count_o;
      const int64_t pos0 = b.dec.pos;
      const int ab = b.top->a_o * 2 + b.top->b_o;
      b.top->n_i = static_cast<uint32_t>(n2);
      const int64_t lo = count_lo(a, n2);
      const int64_t d = ((c_old - lo) % 4 + 4) % 4;
      // A and B hold while the new products are computed (LATENCY clocks at least).
      for (int j = 0; j < kAbzLatency; ++j) {
        b.step();
        held_bad += b.top->a_o * 2 + b.top->b_o != ab;
      }
      const uint64_t took = b.settle(64) + kAbzLatency;
      // d = 2 is half the turn at N = 1: the shorter way's tie goes forward.
      const int64_t walk = d == 3 ? 1 : (d == 2 && n2 == 1) ? 2 : -d;
      walk_bad += b.dec.pos - pos0 != walk;
      lost += b.dec.lost;
    }
  }
  EXPECT_EQ(held_bad, 0);
  EXPECT_EQ(late, 0);
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(walk_bad, 0);
  EXPECT_EQ(lost, 0);
  // Before any angle a change of N moves nothing.
  AbzBench b(1024, 0, 1, 5);
  b.top->n_i = 5;
  for (int j = 0; j < 40; ++j) b.step();
  EXPECT_EQ(b.dec.edges, 0);
  EXPECT_EQ(b.top->count_o, 0u);
}

// ---- UVW ----------------------------------------------------------------------------------------
constexpr int kUvwAngleW = ACORE_STAGE_UVW_ANGLE_W;
constexpr int kUvwLatency = ACORE_STAGE_UVW_PP_W + 3;  // acore_uvw.v's LATENCY

TEST(Uvw, EveryAngleMatchesTheSixStepClosedForm) {
  const int64_t turn = int64_t{1} << kUvwAngleW;
  std::mt19937_64 rng(11);
  std::unique_ptr<VerilatedContext> ctx;
  auto top = make<Vstage_uvw>(ctx, 5);
  top->rst_i = 1;
  top->angle_valid_i = 0;
  tick(*top);
  tick(*top);
  top->rst_i = 0;
  for (int pp = 1; pp <= 16; ++pp) {
    const int64_t offset = pp == 1 ? 0 : static_cast<int64_t>(rng() % turn);
    top->pp_i = pp;
    top->offset_i = static_cast<uint32_t>(offset);
    // Every angle for a few pole-pair counts, a random eighth of the turn for the others.
    const bool all = pp == 1 || pp == 3 || pp == 7 || pp == 16;
    const int64_t start = all ? 0 : static_cast<int64_t>(rng() % turn);
    const int64_t count = all ? turn : turn / 8;
    int64_t wrong = 0, checked = 0;
    // One angle at a time: each converted within LATENCY = PP_W + 3 clocks (acore_uvw.v).
    for (int64_t k = 0; k < count; ++k) {
      const int64_t a = (start + k) % turn;
      top->angle_valid_i = 1;
      top->angle_i = static_cast<uint32_t>(a);
      tick(*top);
      top->angle_valid_i = 0;
      int late = 1;
      while (!top->valid_o && late < kUvwLatency + 2) {
        tick(*top);
        ++late;
      }
      if (!top->valid_o || late != kUvwLatency) {
        ++wrong;
        continue;
      }
      const int64_t x = ((((a - offset) % turn + turn) % turn) * pp) % turn;
      const int64_t six = 6 * x;  // the electrical angle in sixths of a turn
      const int sector = static_cast<int>(six / turn);
      const bool u = six < 3 * turn;
      const bool v = ((six - 2 * turn) % (6 * turn) + 6 * turn) % (6 * turn) < 3 * turn;
      const bool w = ((six - 4 * turn) % (6 * turn) + 6 * turn) % (6 * turn) < 3 * turn;
      wrong += top->sector_o != sector || top->u_o != u || top->v_o != v || top->w_o != w;
      ++checked;
    }
    EXPECT_EQ(checked, count) << "pp " << pp;
    EXPECT_EQ(wrong, 0) << "pp " << pp;
  }
  // Out of range: 0 pole pairs counts as 1, 31 as 16.
  for (const auto& [pp_in, pp_eff] : std::vector<std::pair<int, int>>{{0, 1}, {31, 16}}) {
    top->pp_i = pp_in;
    top->offset_i = 0;
    const int64_t a = turn / 5 + 77;
    top->angle_valid_i = 1;
    top->angle_i = static_cast<uint32_t>(a);
    tick(*top);
    top->angle_valid_i = 0;
    for (int j = 1; j < kUvwLatency; ++j) tick(*top);
    EXPECT_TRUE(top->valid_o) << pp_in;
    EXPECT_EQ(top->sector_o, (6 * ((a * pp_eff) % turn)) / turn) << pp_in;
  }
  // A burst faster than a conversion: the first angle converts, the ones arriving meanwhile wait
  // and only the latest of them converts next (latest wins), nothing else is output.
  top->pp_i = 1;
  const int64_t burst[] = {turn / 12, turn / 12 + turn / 6, turn / 12 + 2 * (turn / 6),
                           turn / 12 + 3 * (turn / 6)};
  std::vector<int> sectors;
  for (int c = 0; c < 4 * kUvwLatency; ++c) {
    top->angle_valid_i = c < 4;
    top->angle_i = static_cast<uint32_t>(burst[c < 4 ? c : 3]);
    tick(*top);
    if (top->valid_o) sectors.push_back(top->sector_o);
  }
  EXPECT_EQ(sectors, (std::vector<int>{0, 3}));
}

// ---- SPI (AS5047P frame) ----------------------------------------------------------------------
constexpr int kSpiAngleW = ACORE_STAGE_SPI_ANGLE_W;

// Even parity as the drivers compute it: the number of ones in the 16-bit word is even.
int ones(uint16_t v) {
  int c = 0;
  for (int i = 0; i < 16; ++i) c += (v >> i) & 1;
  return c;
}
uint16_t with_parity(uint16_t cmd15) {
  return static_cast<uint16_t>((cmd15 & 0x7FFF) | ((ones(cmd15 & 0x7FFF) & 1) << 15));
}

struct SpiMaster {
  std::unique_ptr<VerilatedContext> ctx;
  std::unique_ptr<Vstage_spi> top;
  int half = 2;  // clocks per SCLK half period (2: SCLK = clk/4)
  int lead = 2;  // clocks from CSn low to the first rising SCLK edge
  int gap = 8;   // clocks CSn stays high between frames
  uint64_t frames = 0, oe_bad = 0;
  // The registers the port's settings are (the board's IF_ZERO, IF_CTRL, ABZ_N, UVW_PP, ABZ_HYS at
  // their reset values): a write strobe high before a clock edge loads them at it.
  As5047Config regs;
  explicit SpiMaster(uint64_t seed) {
    top = make<Vstage_spi>(ctx, seed);
    top->csn_i = 1;
    top->sclk_i = 0;
    top->mosi_i = 0;
    top->rst_i = 1;
    drive_regs();
    tick(*top);
    tick(*top);
    top->rst_i = 0;
    clocks(8);
  }
  void drive_regs() {
    top->cfg_zero_i = regs.zero;
    top->cfg_dir_i = regs.dir;
    top->cfg_daec_i = regs.daec;
    top->cfg_n_i = static_cast<uint32_t>(regs.n);
    top->cfg_pp_i = static_cast<uint32_t>(regs.pole_pairs);
    top->cfg_hys_i = static_cast<uint32_t>(regs.hys);
  }
  void angle(uint32_t unc, uint32_t com) {
    top->angle_unc_i = unc;
    top->angle_com_i = com;
  }
  void clocks(int k) {
    for (int i = 0; i < k; ++i) {
      As5047Config next = regs;
      if (top->cfg_zero_we_o) next.zero = static_cast<uint16_t>(top->cfg_zero_o);
      if (top->cfg_dir_we_o) next.dir = top->cfg_dir_o;
      if (top->cfg_daec_we_o) next.daec = top->cfg_daec_o;
      if (top->cfg_n_we_o) next.n = top->cfg_n_o;
      if (top->cfg_pp_we_o) next.pole_pairs = top->cfg_pp_o;
      if (top->cfg_hys_we_o) next.hys = top->cfg_hys_o;
      tick(*top);
      regs = next;
      drive_regs();
    }
  }
  // One mode-1 frame of `bits` bits (16 normally): MOSI changes on the rising edge, MISO is
  // sampled on the falling edge, MSB first.
  uint16_t frame(uint16_t mosi, int bits = 16) {
    top->csn_i = 0;
    clocks(lead);
    uint16_t miso = 0;
    for (int i = 0; i < bits; ++i) {
      top->sclk_i = 1;
      top->mosi_i = (mosi >> (15 - i)) & 1;
      clocks(half);
      miso = static_cast<uint16_t>((miso << 1) | (top->miso_o & 1));
      oe_bad += !top->miso_oe_o;
      top->sclk_i = 0;
      clocks(half);
    }
    top->csn_i = 1;
    clocks(gap);
    ++frames;
    return miso;
  }
};

// SimpleFOC's MagneticSensorSPI with its AS5047 configuration (SPI mode 1, angle register 0x3FFF,
// R/W bit 14, parity bit 15, 14 data bits from bit 13): a command frame, then a NOP frame whose
// answer is the register; the data is the answer's low 14 bits (no parity or flag check).
uint16_t simplefoc_read(SpiMaster& m, uint16_t reg) {
  uint16_t command = static_cast<uint16_t>(reg | (1u << 14));
  command = static_cast<uint16_t>(command | ((ones(command) & 1) << 15));
  m.frame(command);
  const uint16_t value = m.frame(0x0000);
  return static_cast<uint16_t>(value & 0x3FFF);
}

uint32_t top14(uint32_t angle) { return angle >> (kSpiAngleW - 14); }

TEST(SpiAs5047, SimpleFocFramesReadTheAngle) {
  std::mt19937_64 rng(21);
  for (int half : {2, 3, 5}) {
    SpiMaster m(rng());
    m.half = half;
    for (int k = 0; k < 60; ++k) {
      const uint32_t com = static_cast<uint32_t>(rng() & ((1u << kSpiAngleW) - 1));
      const uint32_t unc = static_cast<uint32_t>(rng() & ((1u << kSpiAngleW) - 1));
      m.angle(unc, com);
      ASSERT_EQ(simplefoc_read(m, 0x3FFF), top14(com)) << "half " << half << " k " << k;
      ASSERT_EQ(simplefoc_read(m, 0x3FFE), top14(unc));
    }
    EXPECT_EQ(m.oe_bad, 0u);
  }
}

// ODrive's SPI_ABS_AMS mode: 0xFFFF (read ANGLECOM with its parity) every control cycle, the
// answer (to the previous cycle's command) refused when its parity is odd or its error flag set.
TEST(SpiAs5047, OdriveFramesReadTheAngleWithParityAndFlag) {
  std::mt19937_64 rng(22);
  SpiMaster m(rng());
  EXPECT_EQ(with_parity(0x7FFF), 0xFFFF);  // the drivers' constant is the parity-correct read
  uint32_t prev = 0;
  int accepted = 0;
  for (int k = 0; k < 200; ++k) {
    const uint32_t com = static_cast<uint32_t>(rng() & ((1u << kSpiAngleW) - 1));
    m.angle(com ^ 0x5A5A, com);
    m.gap = 6 + static_cast<int>(rng() % 20);
    const uint16_t raw = m.frame(0xFFFF);
    const bool parity_bad = ones(raw) & 1;
    const bool ef = (raw >> 14) & 1;
    ASSERT_FALSE(parity_bad) << k;
    ASSERT_FALSE(ef) << k;
    // The first answer is NOP's (no command before it); then the angle at the frame's start.
    ASSERT_EQ(raw & 0x3FFF, k == 0 ? 0u : top14(com)) << k;
    accepted += k > 0;
    prev = com;
  }
  (void)prev;
  EXPECT_EQ(accepted, 199);
  EXPECT_EQ(m.top->errfl_o, 0);
}

TEST(SpiAs5047, ParityErrorsAreRefusedAndReported) {
  std::mt19937_64 rng(23);
  SpiMaster m(rng());
  m.angle(0x1234, 0xBEEF);
  // A read of ANGLECOM with the parity bit wrong (odd): refused.
  m.frame(0x7FFF);
  const uint16_t after = m.frame(0xFFFF);
  EXPECT_EQ(ones(after) & 1, 0) << "the answer itself has even parity";
  EXPECT_TRUE((after >> 14) & 1) << "error flag";
  EXPECT_EQ(after & 0x3FFF, 0u) << "no register was read";
  // An ODrive would refuse that answer (EF). The 0xFFFF of the same frame was a valid read: the
  // next answer is the angle, the flag still set until ERRFL is read.
  const uint16_t next = m.frame(with_parity(0x4001));  // read ERRFL
  EXPECT_EQ(next & 0x3FFF, top14(0xBEEF));
  EXPECT_TRUE((next >> 14) & 1);
  const uint16_t errfl = m.frame(0x0000);
  EXPECT_EQ(errfl & 0x3FFF, 0x4u) << "PARERR";
  EXPECT_TRUE((errfl >> 14) & 1);
  const uint16_t clean = m.frame(0x0000);
  EXPECT_FALSE((clean >> 14) & 1) << "ERRFL's read cleared it";
  EXPECT_EQ(m.top->errfl_o, 0);
  // Every single-bit corruption of the read command is refused.
  for (int bit = 0; bit < 16; ++bit) {
    m.frame(static_cast<uint16_t>(0xFFFF ^ (1u << bit)));
    const uint16_t ans = m.frame(with_parity(0x4001));
    EXPECT_TRUE((ans >> 14) & 1) << bit;
    EXPECT_EQ(ans & 0x3FFF, 0u) << bit;
    EXPECT_EQ(m.frame(0x0000) & 0x3FFF, 0x4u) << bit;
  }
}

TEST(SpiAs5047, FramingAndInvalidCommandsAndDiagnostics) {
  std::mt19937_64 rng(24);
  SpiMaster m(rng());
  m.angle(0, 0);
  // A 15-clock frame: FRERR.
  m.frame(0xFFFF, 15);
  m.frame(with_parity(0x4001));
  EXPECT_EQ(m.frame(0x0000) & 0x3FFF, 0x1u);
  // A read of an address that does not exist: INVCOMM.
  m.frame(with_parity(0x4000 | 0x1234));
  m.frame(with_parity(0x4001));
  EXPECT_EQ(m.frame(0x0000) & 0x3FFF, 0x2u);
  // A write command to a read-only register: INVCOMM, its data frame consumed.
  m.frame(with_parity(0x3FFD));
  m.frame(with_parity(0x0FFF));
  m.frame(with_parity(0x4001));
  EXPECT_EQ(m.frame(0x0000) & 0x3FFF, 0x2u);
  // DIAAGC: MAGL = LOS, MAGH = DOS, COF = overflow, LF = not LOT, AGC; MAG.
  for (int k = 0; k < 32; ++k) {
    const int los = k & 1, dos = (k >> 1) & 1, ovf = (k >> 2) & 1, lot = (k >> 3) & 1;
    const int agc = static_cast<int>(rng() & 0xFF), mag = static_cast<int>(rng() & 0x3FFF);
    m.top->los_i = los;
    m.top->dos_i = dos;
    m.top->ovf_i = ovf;
    m.top->lot_i = lot;
    m.top->agc_i = agc;
    m.top->mag_i = mag;
    m.frame(with_parity(0x7FFC));
    const uint16_t diag = m.frame(with_parity(0x7FFD));
    EXPECT_EQ(ones(diag) & 1, 0);
    EXPECT_EQ(diag & 0x3FFF, static_cast<uint32_t>((los << 11) | (dos << 10) | (ovf << 9) |
                                                   ((1 - lot) << 8) | agc));
    EXPECT_EQ(m.frame(0x0000) & 0x3FFF, static_cast<uint32_t>(mag));
  }
  EXPECT_FALSE((m.frame(0x0000) >> 14) & 1);
}

// The port's timing rule (rtl/acore_spi_as5047.v): MISO moves SYNC + 1 clocks after each falling
// SCLK edge, so at the shortest SCLK period the line is built for (SCLK_MIN >= SYNC + 2 clocks) a
// mode-1 master sampling at the falling edge sees each bit a clock after it settled.
TEST(SpiTiming, MisoMovesSyncPlusOneClocksAfterTheFallingEdge) {
  constexpr int kSync = ACORE_STAGE_SPI_SYNC, kSclkMin = ACORE_STAGE_SPI_SCLK_MIN;
  static_assert(kSclkMin >= kSync + 2, "the registry line must obey the port's rule");
  SpiMaster m(31);
  m.angle(0, 0x5555);  // ANGLECOM's 14 bits alternate: MISO toggles at every bit
  m.frame(as5047::with_even_parity(0x7FFF));
  auto& top = *m.top;
  top.csn_i = 0;
  m.clocks(m.lead);
  std::vector<int> delays;
  int last_fall = -1, t = 0, prev = top.miso_o;
  for (int i = 0; i < 16; ++i) {
    for (int level : {1, 0}) {
      top.sclk_i = level;
      if (level == 0) last_fall = t;
      for (int c = 0; c < kSclkMin / 2; ++c) {
        tick(top);
        ++t;
        if (top.miso_o != prev && last_fall >= 0) delays.push_back(t - last_fall);
        prev = top.miso_o;
      }
    }
  }
  top.csn_i = 1;
  m.clocks(8);
  ASSERT_GE(delays.size(), 10u);
  for (int d : delays) {
    EXPECT_EQ(d, kSync + 1);
    EXPECT_LE(d, kSclkMin - 1) << "MISO must settle a clock before the next falling edge";
  }
}

// CSn high for one clock between frames (below the port's minimum of two): the frame after it
// answers 0xC000 (EF set, parity even, no data) instead of a stale register, its command is
// ignored, and ERRFL.FRERR reports it; two clocks are enough.
TEST(SpiAs5047, ShortCsnGapIsAFramingErrorNotAWrongAnswer) {
  SpiMaster m(32);
  m.angle(0x1111, 0xBEEF);
  // (SpiMaster::frame() holds CSn high for `gap` clocks after its frame.)
  m.gap = 1;
  m.frame(as5047::with_even_parity(0x7FFF));  // read ANGLECOM, then CSn high for one clock
  m.gap = 8;
  const uint16_t bad = m.frame(as5047::with_even_parity(0x7FFE));  // then ANGLEUNC, too soon
  EXPECT_EQ(bad, 0xC000) << "EF with even parity, no data";
  const uint16_t after = m.frame(as5047::with_even_parity(0x4001));  // read ERRFL
  EXPECT_EQ(after, 0xC000) << "the refused frame's command read nothing (NOP, EF)";
  EXPECT_EQ(m.frame(0x0000) & 0x3FFF, static_cast<uint32_t>(as5047::kErrflFrerr));
  // Two clocks: every answer right.
  for (int k = 0; k < 20; ++k) {
    m.gap = 2;
    m.frame(as5047::with_even_parity(0x7FFF));
    const uint16_t com = m.frame(as5047::with_even_parity(0x7FFE));
    EXPECT_EQ(com, as5047::with_even_parity(static_cast<uint16_t>(top14(0xBEEF)))) << k;
  }
  m.gap = 8;
  m.frame(0x0000);
  EXPECT_EQ(m.top->errfl_o, 0);
}

// A frame longer than 16 bits (a daisy chain's): the first 16 MISO bits are the answer, the next
// 16 the 16 bits the master sent first, as received (the port shifts the command in where the
// answer leaves); the frame itself is a framing error, its command ignored.
TEST(SpiAs5047, MisoPassesMosiOnAfterSixteenBits) {
  SpiMaster m(33);
  m.angle(0x1111, 0xBEEF);
  m.frame(as5047::with_even_parity(0x7FFF));  // read ANGLECOM
  const uint16_t sent = as5047::with_even_parity(0x4001), next = 0xA5C3;
  const uint32_t mosi = (uint32_t{sent} << 16) | next;
  auto& top = *m.top;
  top.csn_i = 0;
  m.clocks(m.lead);
  uint32_t miso = 0;
  for (int i = 0; i < 32; ++i) {
    top.sclk_i = 1;
    top.mosi_i = (mosi >> (31 - i)) & 1;
    m.clocks(m.half);
    miso = (miso << 1) | (top.miso_o & 1);
    top.sclk_i = 0;
    m.clocks(m.half);
  }
  top.csn_i = 1;
  m.clocks(m.gap);
  EXPECT_EQ(miso >> 16, as5047::with_even_parity(static_cast<uint16_t>(top14(0xBEEF))));
  EXPECT_EQ(miso & 0xFFFF, sent);
  EXPECT_EQ(m.frame(as5047::with_even_parity(0x4001)), 0xC000) << "the long frame read nothing";
  EXPECT_EQ(m.frame(0x0000) & 0x3FFF, static_cast<uint32_t>(as5047::kErrflFrerr));
}

// The datasheet's write sequence on the settings: a write command, then the data frame (answered
// with the register's old content), then any frame (answered with the new content); the values the
// board's registers take, from the datasheet's tables: ZPOS in ZPOSM/ZPOSL, DIR and DAECDIS in
// SETTINGS1, UVWPP (pole pairs - 1), HYS (3, 2, 1, 0 LSBs of 2^-11 turn) and ABIRES (decimal
// 1000 500 400 300 200 100 50 25, binary 1024 512 256) in SETTINGS2; PROG without OTP.
TEST(SpiAs5047, WritesFollowTheDatasheetSequenceAndTables) {
  SpiMaster m(33);
  m.angle(0x1234, 0xBEEF);
  const auto write = [&](uint16_t reg, uint16_t value) -> std::pair<unsigned, unsigned> {
    m.frame(with_parity(reg));  // R/W = 0
    const uint16_t old_value = m.frame(with_parity(value));
    const uint16_t new_value = m.frame(0x0000);
    EXPECT_EQ(ones(old_value) & 1, 0);
    EXPECT_EQ(ones(new_value) & 1, 0);
    return {old_value & 0x3FFFu, new_value & 0x3FFFu};
  };
  // ZPOS = 0x2A5C: ZPOSM takes bits 13:6, ZPOSL bits 5:0 (and its two error enables, kept).
  EXPECT_EQ(write(0x0016, 0x2A5C >> 6), std::make_pair(0u, static_cast<unsigned>(0x2A5C >> 6)));
  EXPECT_EQ(write(0x0017, 0xC0 | (0x2A5C & 0x3F)),
            std::make_pair(0u, static_cast<unsigned>(0xC0 | (0x2A5C & 0x3F))));
  EXPECT_EQ(m.regs.zero, 0x2A5C);
  // SETTINGS1 at reset: bit 0 reads 1, ABIBIN 1 (AngleCore's ABZ_N reset 1024 is binary's 0).
  // DIR = 1, DAECDIS = 1, ABIBIN = 0 (decimal: N 1024 reads as 1000's code, 0, and becomes 1000).
  EXPECT_EQ(write(0x0018, 0x04 | 0x10), std::make_pair(0x21u, 0x15u));
  EXPECT_TRUE(m.regs.dir);
  EXPECT_FALSE(m.regs.daec);
  EXPECT_EQ(m.regs.n, 1000);
  // SETTINGS2: UVWPP 4 (5 pole pairs), HYS 1 (2 LSBs of 2^-11 turn), ABIRES 1 (decimal: 500).
  const unsigned s2 = (1u << 5) | (1u << 3) | 4u;
  // Its reset reads ABIRES 0 (N 1000 now), HYS 2 (ABZ_HYS 2 is one LSB rounded up), UVWPP 0.
  EXPECT_EQ(write(0x0019, static_cast<uint16_t>(s2)), std::make_pair((2u << 3), s2));
  EXPECT_EQ(m.regs.pole_pairs, 5);
  EXPECT_EQ(m.regs.hys, 2 << (kSpiAngleW - 11));
  EXPECT_EQ(m.regs.n, 500);
  // Every decimal and binary code.
  const int64_t decimal[8] = {1000, 500, 400, 300, 200, 100, 50, 25};
  for (int code = 0; code < 8; ++code) {
    write(0x0019, static_cast<uint16_t>(code << 5));
    EXPECT_EQ(m.regs.n, decimal[code]) << code;
  }
  write(0x0018, 0x20);  // ABIBIN = 1: N 25 (code 7) reads as binary's last code, 256
  EXPECT_EQ(m.regs.n, 256);
  for (int code = 0; code < 3; ++code) {
    write(0x0019, static_cast<uint16_t>(code << 5));
    EXPECT_EQ(m.regs.n, 1024 >> code) << code;
  }
  // UVWPP 7 is 7 pole pairs, as 6; HYS 3 is none.
  write(0x0019, 0x7 | (3 << 3));
  EXPECT_EQ(m.regs.pole_pairs, 7);
  EXPECT_EQ(m.regs.hys, 0);
  // PROG: PROGEN and PROGVER kept, OTPREF and PROGOTP act at once and read 0 (no OTP); the
  // settings are untouched by a "programming".
  EXPECT_EQ(write(0x0003, 0x01).second, 0x01u);
  EXPECT_EQ(write(0x0003, 0x08 | 0x01).second, 0x01u) << "PROGOTP done at once";
  EXPECT_EQ(write(0x0003, 0x40 | 0x04).second, 0x40u);
  EXPECT_EQ(m.regs.zero, 0x2A5C);
  EXPECT_EQ(m.regs.pole_pairs, 7);
  // Dataselect (SETTINGS1 bit 6): 0x3FFF reads ANGLEUNC's angle.
  write(0x0018, 0x20 | 0x40);
  m.frame(with_parity(0x7FFF));
  EXPECT_EQ(m.frame(0x0000) & 0x3FFF, top14(0x1234));
  EXPECT_EQ(m.top->errfl_o, 0) << "no write above was refused";
}

// ABIRES read back for every N a register may hold (ABZ_N is written over APB too, not only from
// the tables): the first entry of ABIBIN's table not above N, the table's last code below it.
TEST(SpiAs5047, AbiresReadsTheFirstEntryNotAboveN) {
  SpiMaster m(35);
  const std::vector<int64_t> decimal = {1000, 500, 400, 300, 200, 100, 50, 25},
                             binary = {1024, 512, 256};
  int64_t wrong = 0;
  for (const bool bin : {false, true}) {
    const std::vector<int64_t>& table = bin ? binary : decimal;
    m.frame(with_parity(0x0018));
    m.frame(with_parity(bin ? 0x20 : 0x00));
    for (int64_t n = 1; n <= int64_t{1} << (ACORE_STAGE_SPI_N_W - 1); ++n) {
      m.regs.n = n;
      m.drive_regs();
      m.frame(with_parity(0x4000 | 0x0019));
      const unsigned code = (m.frame(0x0000) >> 5) & 0x7u;
      unsigned want = static_cast<unsigned>(table.size() - 1);
      for (size_t c = table.size(); c-- > 0;)
        if (n >= table[c]) want = static_cast<unsigned>(c);
      wrong += code != want;
    }
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(m.top->errfl_o, 0);
}

// ---- PWM (AS5047P frame) --------------------------------------------------------------------
TEST(Pwm, InputCaptureDecoderRecoversTheAngle) {
  std::mt19937_64 rng(41);
  for (int pre : {0, 2}) {
    std::unique_ptr<VerilatedContext> ctx;
    auto top = make<Vstage_pwm>(ctx, rng());
    top->pre_i = pre;
    top->angle_i = 0;
    top->err_i = 0;
    top->rst_i = 1;
    tick(*top);
    tick(*top);
    top->rst_i = 0;
    const uint64_t unit = static_cast<uint64_t>(pre) + 1;
    uint64_t t = 0, rise = 0, high = 0, low_run = 0;
    int prev = 0, frames = 0, wrong = 0;
    uint32_t sent = 0, frame_angle = 0;
    bool sent_err = false, frame_err = false, have = false;
    while (frames < 40) {
      // A new angle and error bit at every frame start (frame_o: taken at this clock).
      if (top->frame_o) {
        sent = static_cast<uint32_t>(rng() & 0xFFFF);
        sent_err = rng() % 4 == 0;
        top->angle_i = sent;
        top->err_i = sent_err;
      }
      tick(*top);
      ++t;
      const int pwm = top->pwm_o;
      // A frame starts at a rising edge after the 8-period exit (low) phase; the error_n gap (4 low
      // periods inside the frame) is not a start.
      if (pwm && !prev && low_run >= 8 * unit) {
        // The frame since the previous start is complete; decode it.
        if (have) {
          const uint64_t period = t - rise;
          const int64_t high_units = static_cast<int64_t>(high / unit);
          const int64_t angle12 = high_units - (frame_err ? 12 : 16);
          wrong += period != 4119 * unit || high % unit != 0 ||
                   angle12 != static_cast<int64_t>(frame_angle >> 4);
          ++frames;
        }
        have = true;
        rise = t;
        high = 0;
        frame_angle = sent;
        frame_err = sent_err;
      }
      high += pwm;
      low_run = pwm ? 0 : low_run + 1;
      prev = pwm;
    }
    EXPECT_EQ(wrong, 0) << "pre " << pre;
  }
}

// Co-simulation with the bit-exact model (model/ip/stages/interfaces.hpp): random frames, valid and
// corrupted commands of every register, short frames, at random SCLK rates, with the
// inputs changing between frames; every word the master receives equals the model's.
TEST(SpiAs5047, RandomFramesMatchTheModel) {
  std::mt19937_64 rng(25);
  SpiMaster m(rng());
  As5047Port model;
  As5047Inputs in;
  in.angle_w = kSpiAngleW;
  const uint16_t regs[] = {0x0000, 0x0001, 0x0003, 0x0016, 0x0017, 0x0018,
                           0x0019, 0x3FFC, 0x3FFD, 0x3FFE, 0x3FFF, 0x1234};
  int config_mismatches = 0, n_changes = 0, zero_changes = 0;
  As5047Config last;
  int mismatches = 0;
  for (int k = 0; k < 3000; ++k) {
    in.angle_com = rng() & ((1u << kSpiAngleW) - 1);
    in.angle_unc = rng() & ((1u << kSpiAngleW) - 1);
    in.mag = static_cast<uint16_t>(rng() & 0x3FFF);
    in.agc = static_cast<uint8_t>(rng());
    in.los = rng() & 1;
    in.dos = rng() & 1;
    in.ovf = rng() & 1;
    in.lot = rng() & 1;
    m.angle(static_cast<uint32_t>(in.angle_unc), static_cast<uint32_t>(in.angle_com));
    m.top->mag_i = in.mag;
    m.top->agc_i = in.agc;
    m.top->los_i = in.los;
    m.top->dos_i = in.dos;
    m.top->ovf_i = in.ovf;
    m.top->lot_i = in.lot;
    // Reads, writes (a command, or a data frame after one: any 8-bit value) of every register.
    uint16_t cmd = as5047::with_even_parity(
        rng() % 4 == 0 ? static_cast<uint16_t>(rng() & 0xFF)
                       : static_cast<uint16_t>(regs[rng() % 12] | ((rng() % 3) ? 0x4000 : 0)));
    if (rng() % 8 == 0) cmd ^= static_cast<uint16_t>(1u << (rng() % 16));
    const int bits = rng() % 16 == 0 ? 13 + static_cast<int>(rng() % 3) : 16;
    m.half = 2 + static_cast<int>(rng() % 3);
    // The CSn gap before this frame (the one the previous frame left): now and then one clock,
    // below the port's minimum of two.
    const bool short_gap = m.gap < 2;
    m.gap = rng() % 10 == 0 ? 1 : 2 + static_cast<int>(rng() % 8);
    const uint16_t got = m.frame(cmd, bits);
    const uint16_t want = model.frame(cmd, in, bits, short_gap);
    mismatches += got != want;
    if (got != want && mismatches < 5)
      ADD_FAILURE() << "frame " << k << " cmd " << std::hex << cmd << " bits " << std::dec << bits
                    << ": rtl " << std::hex << got << " model " << want;
    // (ERRFL and a write take the frame SYNC + 1 clocks after CSn rises: after a gap that long.)
    if (m.gap >= ACORE_STAGE_SPI_SYNC + 2) {
      mismatches += m.top->errfl_o != model.errfl();
      const As5047Config& r = m.regs;
      const As5047Config& c = model.config;
      n_changes += r.n != last.n;
      zero_changes += r.zero != last.zero;
      last = r;
      config_mismatches += r.zero != c.zero || r.dir != c.dir || r.daec != c.daec || r.n != c.n ||
                           r.pole_pairs != c.pole_pairs || r.hys != c.hys;
    }
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_EQ(config_mismatches, 0);
  // The run wrote the settings: N and the zero changed many times.
  EXPECT_GT(n_changes, 10);
  EXPECT_GT(zero_changes, 10);
}

// The ABZ count after every catch-up equals the model's (model/ip/stages/interfaces.hpp): random
// moves and jumps at several hysteresis widths, N changed now and then (the count re-homed as
// AbzCounter::rehome() puts it, then walked to the model's target).
TEST(AbzCosim, CountMatchesTheModelTarget) {
  std::mt19937_64 rng(26);
  int64_t mismatches = 0, checks = 0;
  for (int64_t n :
       {int64_t{1}, int64_t{3}, int64_t{1000}, int64_t{1024}, int64_t{1} << (kAbzNW - 1)}) {
    for (int64_t h : {0, 1, 2, 9}) {
      AbzBench b(n, 0, 1, rng(), h);
      AbzCounter model(n, 1);
      int64_t n_cur = n;
      uint64_t a = 0;
      for (int k = 0; k < 200; ++k) {
        if (k % 50 == 49) {
          n_cur = 1 + static_cast<int64_t>(rng() % (int64_t{1} << (kAbzNW - 1)));
          b.top->n_i = static_cast<uint32_t>(n_cur);
          b.step();  // (settled_o is the outputs' as of the last clock)
          model.rehome(n_cur, abz_count_of(a, kAbzAngleW, n_cur));
        } else {
          a = k % 2 ? rng() % kTurn : (b.top->angle_i + rng() % 5 + kTurn - 2) % kTurn;
          model.set_target(abz_target(a, kAbzAngleW, n_cur, h, model.target()));
          b.angle(static_cast<uint32_t>(a));
        }
        b.settle(1u << 30);
        while (model.step() != 0) {
        }
        mismatches += static_cast<int64_t>(b.top->count_o) != model.count();
        ++checks;
      }
    }
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_EQ(checks, 4000);
}

// UVW against the model on random angles, offsets and pole pairs.
TEST(UvwCosim, MatchesTheModel) {
  std::mt19937_64 rng(27);
  std::unique_ptr<VerilatedContext> ctx;
  auto top = make<Vstage_uvw>(ctx, 9);
  top->rst_i = 1;
  tick(*top);
  top->rst_i = 0;
  int mismatches = 0;
  for (int k = 0; k < 20000; ++k) {
    const uint64_t a = rng() & 0xFFFF, off = rng() & 0xFFFF;
    const int pp = 1 + static_cast<int>(rng() % 16);
    top->angle_valid_i = 1;
    top->angle_i = static_cast<uint32_t>(a);
    top->offset_i = static_cast<uint32_t>(off);
    top->pp_i = pp;
    tick(*top);
    top->angle_valid_i = 0;
    for (int j = 1; j < kUvwLatency; ++j) tick(*top);
    const UvwState s = uvw_state(a, off, kUvwAngleW, pp);
    mismatches += !top->valid_o || top->sector_o != s.sector || top->u_o != s.u ||
                  top->v_o != s.v || top->w_o != s.w;
  }
  EXPECT_EQ(mismatches, 0);
}

}  // namespace
}  // namespace acore
