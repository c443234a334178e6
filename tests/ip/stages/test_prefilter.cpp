// SPDX-License-Identifier: MIT
// Stage 1, the pre-filter (stages/prefilter.hpp, paper Eq. 3): exact differences in D_W = IN_W + 1
// bits, common-mode cancellation, and the two-channel wiring (c3 = c4 = 0).
#include <gtest/gtest.h>

#include <cstdint>
#include <random>

#include "core/datapath_config.hpp"
#include "core/fixed_point.hpp"
#include "stages/prefilter.hpp"

namespace acore {
namespace {

TEST(Prefilter, DifferencesAreExactAndFitDW) {
  const DatapathConfig cfg;
  const int64_t lo = fx::smin(cfg.in_w), hi = fx::smax(cfg.in_w);
  // The extremes of IN_W-bit inputs: the differences need exactly one more bit, never more.
  for (int64_t a : {lo, lo + 1, int64_t{-1}, int64_t{0}, int64_t{1}, hi - 1, hi})
    for (int64_t b : {lo, int64_t{0}, hi}) {
      const DiffPair d = prefilter(a, b, b, a);
      EXPECT_EQ(d.d13, a - b);
      EXPECT_EQ(d.d24, b - a);
      EXPECT_EQ(fx::saturate(d.d13, cfg.d_w(), nullptr), d.d13) << a << " " << b;
    }
  EXPECT_EQ(prefilter(hi, 0, lo, 0).d13, fx::smax(cfg.d_w()));      // 2^IN_W - 1
  EXPECT_EQ(prefilter(lo, 0, hi, 0).d13, fx::smin(cfg.d_w()) + 1);  // -(2^IN_W - 1)
}

TEST(Prefilter, CommonModeCancelsAndOppositeSensorsAntisymmetric) {
  std::mt19937_64 rng(31);
  std::uniform_int_distribution<int64_t> code(-30000, 30000), common(-2000, 2000);
  for (int k = 0; k < 10000; ++k) {
    const int64_t c1 = code(rng), c2 = code(rng), c3 = code(rng), c4 = code(rng), m = common(rng);
    const DiffPair d = prefilter(c1, c2, c3, c4);
    const DiffPair dm = prefilter(c1 + m, c2 + m, c3 + m, c4 + m);
    ASSERT_EQ(dm.d13, d.d13);  // the paper's "temporal variation" is gone
    ASSERT_EQ(dm.d24, d.d24);
    const DiffPair swapped = prefilter(c3, c4, c1, c2);  // the sensor turned by half a turn
    ASSERT_EQ(swapped.d13, -d.d13);
    ASSERT_EQ(swapped.d24, -d.d24);
  }
}

TEST(Prefilter, TwoChannelSensorsPassThrough) {
  for (int64_t s : {-32768, -5, 0, 7, 32767}) {
    const DiffPair d = prefilter(s, -s / 2, 0, 0);
    EXPECT_EQ(d.d13, s);
    EXPECT_EQ(d.d24, -s / 2);
  }
}

}  // namespace
}  // namespace acore
