// SPDX-License-Identifier: MIT
// The drive interfaces' model (model/ip/stages/interfaces.hpp) against closed forms written here:
// the ABZ count as floor of the exact rational angle 4N / 2^W (128-bit), its hysteresis band, the
// counter's walk (never more than one count a step, the shorter way, the spacing); the UVW sector
// from the electrical angle in degrees against 60-degree boundaries (rational compare); the
// AS5047P frame's parity, answers, ERRFL and error flag; MAG and AGC of a magnitude against the
// shift and against 128 + 32 (S_F + 0.625 - log2 m) in floating point; and the refusal of
// out-of-range values.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/errors.hpp"
#include "stages/board_regs.hpp"
#include "stages/interfaces.hpp"

namespace acore {
namespace {

// The largest N and pole-pair count: the board's register ranges (rtl/acore_board_regs.txt).
constexpr int64_t kNMax = board::kAbzNNMax;
constexpr int kPpMax = static_cast<int>(board::kUvwPpPolePairsMax);

TEST(AbzModel, CountIsTheFloorOfTheExactProduct) {
  std::mt19937_64 rng(1);
  for (int64_t n :
       {int64_t{1}, int64_t{3}, int64_t{7}, int64_t{360}, int64_t{1000}, int64_t{1024}, kNMax}) {
    for (int w : {14, 16, 20}) {
      for (int k = 0; k < 2000; ++k) {
        const uint64_t a = rng() & ((uint64_t{1} << w) - 1);
        const unsigned __int128 p = static_cast<unsigned __int128>(a) * 4 * n;
        EXPECT_EQ(abz_count_of(a, w, n), static_cast<int64_t>(p >> w));
      }
      const uint64_t last = (uint64_t{1} << w) - 1;
      EXPECT_EQ(abz_count_of(last, w, n), 4 * n - 1) << "the last angle is the last count";
      EXPECT_EQ(abz_count_of(0, w, n), 0);
    }
  }
}

// The window rule against its definition, count by count: the previous count holds when some
// angle within hys LSBs (round the turn) has it, i.e. the window's first and last counts in closed
// form floor((a -+ hys) 4N / T) taken modulo the turn.
TEST(AbzModel, HysteresisHoldsEveryCountTheWindowTouches) {
  const int w = 16;
  const int64_t turn = int64_t{1} << w;
  for (int64_t n : {int64_t{1}, int64_t{1000}, int64_t{1024}, kNMax}) {
    for (int64_t hys : {0, 1, 2, 7}) {
      for (int64_t a : {int64_t{0}, int64_t{271}, int64_t{12345}, turn - 1, turn - 3}) {
        const auto floor_count = [&](int64_t x) {
          return static_cast<int64_t>((((x % turn) + turn) % turn) * 4 * n / turn);
        };
        for (int64_t prev = 0; prev < std::min<int64_t>(4 * n, 64); ++prev) {
          bool touched = false;
          for (int64_t x = a - hys; x <= a + hys; ++x) touched |= floor_count(x) == prev;
          EXPECT_EQ(abz_target(static_cast<uint64_t>(a), w, n, hys, prev),
                    touched ? prev : floor_count(a))
              << "n " << n << " hys " << hys << " a " << a << " prev " << prev;
        }
        // The counts at the end of the turn too (the window wraps past 0).
        const int64_t last = 4 * n - 1;
        bool touched = false;
        for (int64_t x = a - hys; x <= a + hys; ++x) touched |= floor_count(x) == last;
        EXPECT_EQ(abz_target(static_cast<uint64_t>(a), w, n, hys, last),
                  touched ? last : floor_count(a));
      }
    }
  }
  // 280 then 271 at N = 1024: 17, then 16 without hysteresis, 17 held from 1 LSB on.
  EXPECT_EQ(abz_target(271, w, 1024, 0, 17), 16);
  EXPECT_EQ(abz_target(271, w, 1024, 1, 17), 17);
  EXPECT_THROW(abz_target(0, w, 1024, turn / 4, 0), InputError);
  EXPECT_THROW(abz_target(0, w, 1024, -1, 0), InputError);
}

// Re-homing after a change of N keeps the two low bits (A, B) and lands at most two counts from
// the target, round the turn.
TEST(AbzModel, ReHomeKeepsTheLowBitsNearestTheTarget) {
  for (int64_t n : {int64_t{1}, int64_t{7}, int64_t{1000}}) {
    for (int64_t target : {int64_t{0}, int64_t{1}, 4 * n - 1, 2 * n + 1}) {
      for (int64_t count = 0; count < 8; ++count) {
        const int64_t r = abz_rehome(count, target, n);
        EXPECT_EQ(r % 4, count % 4);
        EXPECT_GE(r, 0);
        EXPECT_LT(r, 4 * n);
        const int64_t up = ((r - target) % (4 * n) + 4 * n) % (4 * n);
        EXPECT_TRUE(up <= 2 || up == 4 * n - 1) << n << " " << target << " " << count;
      }
    }
  }
}

TEST(AbzModel, CounterWalksTheShorterWayAtTheSpacing) {
  for (int spacing : {1, 4}) {
    AbzCounter c(1000, spacing);
    c.set_target(3990);  // 10 counts backwards
    int steps = 0, clocks = 0;
    while (c.count() != c.target()) {
      const int s = c.step();
      ++clocks;
      if (s != 0) {
        EXPECT_EQ(s, -1);
        ++steps;
      }
    }
    EXPECT_EQ(steps, 10);
    EXPECT_EQ(clocks, 1 + (steps - 1) * spacing);
    c.set_target(3990 + 2000 - 4000);  // exactly half a turn: forward
    int first = 0;
    while (first == 0) first = c.step();
    EXPECT_EQ(first, 1);
  }
}

TEST(AbzModel, PinsAreGrayAndIndexOneCount) {
  const bool a[4] = {false, true, true, false}, b[4] = {false, false, true, true};
  for (int c = 0; c < 16; ++c) {
    const AbzPins p = abz_pins(c, 5);
    EXPECT_EQ(p.a, a[c % 4]);
    EXPECT_EQ(p.b, b[c % 4]);
    EXPECT_EQ(p.z, c == 5);
  }
}

TEST(UvwModel, SectorsAgainstSixtyDegreeBoundaries) {
  std::mt19937_64 rng(2);
  const int w = 16;
  for (int pp = 1; pp <= kPpMax; ++pp) {
    for (int k = 0; k < 3000; ++k) {
      const uint64_t a = rng() & 0xFFFF, off = rng() & 0xFFFF;
      // Electrical angle in 1/2^16 turn units, then degrees as a rational: deg = 360 e / 2^16.
      const uint64_t e = (((a - off) & 0xFFFF) * static_cast<uint64_t>(pp)) & 0xFFFF;
      int sector = 0;
      while (sector < 5 && 360 * e >= static_cast<uint64_t>(60 * (sector + 1)) << w) ++sector;
      const UvwState s = uvw_state(a, off, w, pp);
      EXPECT_EQ(s.sector, sector);
      // U high on [0, 180), V on [120, 300), W on [240, 360) + [0, 60) degrees.
      const uint64_t deg_x = 360 * e;  // degrees << w
      const auto in = [&](int lo, int hi) {
        return deg_x >= (static_cast<uint64_t>(lo) << w) &&
               deg_x < (static_cast<uint64_t>(hi) << w);
      };
      EXPECT_EQ(s.u, in(0, 180));
      EXPECT_EQ(s.v, in(120, 300));
      EXPECT_EQ(s.w, in(240, 360) || in(0, 60));
    }
  }
}

// MAG: the magnitude's upper 14 bits below its top bit (every magnitude of 20 bits, the defaults,
// sampled). AGC: exact at powers of two (lg m = log2 m there), within the linear interpolation's
// 0.0861 (times 32 codes) plus the truncation to 1/32 of the real logarithm elsewhere, monotone
// non-increasing in m, 255 for no field, 128 at the nominal 1.6468 * 2^S_F.
TEST(As5047Model, MagAndAgcOfTheMagnitude) {
  const int mag_w = 20, s_f = 16;
  EXPECT_EQ(as5047::mag_field(0, mag_w), 0);
  EXPECT_EQ(as5047::mag_field((int64_t{1} << 19) - 1, mag_w), 0x3FFF);
  EXPECT_EQ(as5047::mag_field(int64_t{1} << 19, mag_w), 0x3FFF) << "saturated";
  EXPECT_EQ(as5047::mag_field(107925, mag_w), 107925 / 32);
  EXPECT_EQ(as5047::agc_field(0, s_f), 255);
  EXPECT_EQ(as5047::agc_field(107925, s_f), 128) << "the nominal magnitude";
  EXPECT_EQ(as5047::agc_field(107925 / 2, s_f), 160) << "half the field: +32";
  EXPECT_EQ(as5047::agc_field(107925 * 2, s_f), 96) << "twice the field: -32";
  for (int e = 0; e < 20; ++e) {
    const double want = 128 + 32 * (s_f + 0.625 - e);
    EXPECT_EQ(as5047::agc_field(int64_t{1} << e, s_f),
              static_cast<int>(std::clamp(want, 0.0, 255.0)))
        << "2^" << e;
  }
  int prev = 256;
  for (int64_t m = 1; m < (int64_t{1} << 20); m += 1 + m / 97) {
    EXPECT_EQ(as5047::mag_field(m, mag_w), std::min<int64_t>(m >> 5, 0x3FFF));
    const int agc = as5047::agc_field(m, s_f);
    EXPECT_LE(agc, prev) << m;
    prev = agc;
    const double exact = 128 + 32 * (s_f + 0.625 - std::log2(static_cast<double>(m)));
    if (exact > 0 && exact < 255) {
      EXPECT_GE(agc, exact - 1e-9) << m;
      EXPECT_LE(agc, exact + 32 * 0.0861 + 1) << m;
    }
  }
  EXPECT_THROW(as5047::mag_field(5, 14), InputError);
  EXPECT_THROW(as5047::mag_field(-1, mag_w), InputError);
  EXPECT_THROW(as5047::agc_field(-1, s_f), InputError);
}

TEST(InterfaceModels, OutOfRangeValuesAreRefused) {
  EXPECT_THROW(abz_count_of(0, 16, 0), InputError);
  EXPECT_THROW(abz_count_of(0, 16, kNMax + 1), InputError);
  EXPECT_NO_THROW(abz_count_of(0, 16, kNMax));
  EXPECT_THROW(AbzCounter(kNMax + 1, 1), InputError);
  EXPECT_THROW(uvw_state(0, 0, 16, 0), InputError);
  EXPECT_THROW(uvw_state(0, 0, 16, kPpMax + 1), InputError);
  EXPECT_NO_THROW(uvw_state(0, 0, 16, kPpMax));
  try {
    uvw_state(0, 0, 16, kPpMax + 1);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("pole pairs must be 1.." + std::to_string(kPpMax)),
              std::string::npos);
  }
}

TEST(As5047Model, FramesAnswersAndErrors) {
  using namespace as5047;
  EXPECT_EQ(with_even_parity(0x7FFF), 0xFFFF);
  EXPECT_EQ(with_even_parity(0x4001), 0x4001);
  As5047Port port;
  As5047Inputs in;
  in.angle_com = 0xBEEF;
  in.angle_unc = 0x1234;
  EXPECT_EQ(port.frame(0xFFFF, in), 0x0000);  // NOP's answer first
  EXPECT_EQ(port.frame(with_even_parity(0x7FFE), in) & 0x3FFF, 0xBEEF >> 2);
  EXPECT_EQ(port.frame(0x0000, in) & 0x3FFF, 0x1234 >> 2);
  // A parity error: the next answer carries EF, data 0; ERRFL.PARERR until read.
  port.frame(0x7FFF, in);
  const uint16_t ans = port.frame(with_even_parity(0x4001), in);
  EXPECT_TRUE(parity_even(ans));
  EXPECT_EQ(ans, with_even_parity(0x4000));
  EXPECT_EQ(port.frame(0x0000, in), with_even_parity(0x4000 | kErrflParerr));
  EXPECT_EQ(port.frame(0x0000, in), 0x0000);
  // Framing and invalid commands.
  port.frame(0xFFFF, in, 15);
  EXPECT_EQ(port.errfl(), kErrflFrerr);
  port.frame(with_even_parity(0x4000 | 0x0123), in);
  EXPECT_EQ(port.errfl(), kErrflFrerr | kErrflInvcomm);
  // A frame after a CSn gap below the minimum: 0xC000, its command ignored, FRERR.
  port.frame(with_even_parity(0x4001), in);  // ERRFL (read clears)
  EXPECT_EQ(port.frame(with_even_parity(0x7FFF), in) & 0x3FFF, kErrflFrerr | kErrflInvcomm);
  EXPECT_EQ(port.errfl(), 0);
  EXPECT_EQ(port.frame(with_even_parity(0x7FFE), in, 16, true), 0xC000);
  EXPECT_EQ(port.errfl(), kErrflFrerr);
  EXPECT_EQ(port.frame(0x0000, in), 0xC000) << "the ANGLEUNC read was ignored: NOP, EF";
}

}  // namespace
}  // namespace acore
