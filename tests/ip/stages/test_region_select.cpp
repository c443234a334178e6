// SPDX-License-Identifier: MIT
// Stage 3, domain selection (stages/region_select.hpp, paper Fig. 1) against a rule written from
// the angle instead of the magnitudes: region = the quarter turn of atan2(s13, s24) centred on
// 0, 90, 180, 270 deg, halved at the zero crossing of x with 8 regions; ties go to the sine curve.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "core/fixed_point.hpp"
#include "stages/region_select.hpp"

namespace acore {
namespace {

// The four-region rule from the angle theta = atan2(s13, s24) (only off the diagonals, where it
// is unambiguous), with x the curve that crosses zero in that quarter.
struct Expected {
  int region4;
  int64_t x;
};
Expected from_angle(int64_t s13, int64_t s24) {
  const double th = std::atan2(static_cast<double>(s13), static_cast<double>(s24));
  int r = static_cast<int>(std::floor((th + M_PI / 4) / (M_PI / 2)));
  r = (r % 4 + 4) % 4;
  return {r, r % 2 == 0 ? s13 : s24};
}

TEST(RegionSelect, QuarterTurnsOfTheAngleOffTheDiagonals) {
  for (int regions : {4, 8})
    for (int64_t a = -64; a <= 64; ++a)
      for (int64_t b = -64; b <= 64; ++b) {
        if (std::llabs(a) == std::llabs(b)) continue;  // the diagonals: the tie rule below
        const Expected e = from_angle(a, b);
        const RegionChoice got = select_region(a, b, regions);
        const int want = regions == 8 ? 2 * e.region4 + (e.x >= 0 ? 1 : 0) : e.region4;
        ASSERT_EQ(got.region, want) << a << "," << b << " regions " << regions;
        ASSERT_EQ(got.x, e.x) << a << "," << b;
        ASSERT_EQ(x_is_sine(got.region, regions), e.region4 % 2 == 0) << a << "," << b;
      }
}

TEST(RegionSelect, TiesGoToTheSineCurveAndZeroIsTheUpperHalf) {
  // |s13| == |s24|: x = s13, region 0 (s24 >= 0) or 2.
  for (int64_t m : {1, 5, 65536}) {
    EXPECT_EQ(select_region(m, m, 4).region, 0);
    EXPECT_EQ(select_region(-m, m, 4).region, 0);
    EXPECT_EQ(select_region(m, -m, 4).region, 2);
    EXPECT_EQ(select_region(-m, -m, 4).region, 2);
    EXPECT_EQ(select_region(-m, -m, 4).x, -m);
    // 8 regions: the half by the sign of x, x = 0 counting as positive.
    EXPECT_EQ(select_region(m, m, 8).region, 1);
    EXPECT_EQ(select_region(-m, m, 8).region, 0);
    EXPECT_EQ(select_region(0, m, 8).region, 1);   // at 0 deg exactly
    EXPECT_EQ(select_region(m, 0, 8).region, 3);   // at 90 deg: x = s24 = 0
    EXPECT_EQ(select_region(0, -m, 8).region, 5);  // at 180 deg
    EXPECT_EQ(select_region(-m, 0, 8).region, 7);  // at 270 deg
  }
  EXPECT_EQ(select_region(0, 0, 4).region, 0);
  EXPECT_EQ(select_region(0, 0, 4).x, 0);
}

TEST(RegionSelect, FullScaleWordsDoNotOverflowTheMagnitudes) {
  // S_W = 18: the most negative word has no positive twin; |s| is formed in 64 bits.
  const int64_t lo = fx::smin(18), hi = fx::smax(18);
  EXPECT_EQ(select_region(lo, hi, 4).region, 3);  // |lo| > |hi|: x = s24, s13 < 0
  EXPECT_EQ(select_region(lo, hi, 4).x, hi);
  EXPECT_EQ(select_region(hi, lo, 4).region, 2);  // |hi| < |lo|: x = s13, s24 < 0
  EXPECT_EQ(select_region(lo, lo, 8).region, 4);  // tie, s24 < 0, x = lo < 0
}

TEST(RegionSelect, XIsSineNamesTheArgumentOfEveryRegion) {
  // Regions 0 and 2 of four (0, 1, 4, 5 of eight) take x from the sine curve.
  const bool want4[4] = {true, false, true, false};
  for (int r = 0; r < 4; ++r) EXPECT_EQ(x_is_sine(r, 4), want4[r]) << r;
  for (int r = 0; r < 8; ++r) EXPECT_EQ(x_is_sine(r, 8), want4[r / 2]) << r;
}

}  // namespace
}  // namespace acore
