// SPDX-License-Identifier: MIT
// The rotation-mode CORDIC (stages/cordic_rotate.*) against closed forms: the gain is
// prod sqrt(1 + 2^-2i) (1.6467602581... in the limit); one stage is the exact +-45 deg shear
// (x +- y, y -+ x); M stages turn by exactly sum +-atan(2^-i) in the directions z chose, so against
// a long-double rotation by that angle only the floors remain (sqrt 2 M G_M LSB at most); z wraps
// in its trimmed width.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/fixed_point.hpp"
#include "stages/cordic.hpp"
#include "stages/cordic_rotate.hpp"

namespace acore {
namespace {

TEST(CordicRotate, GainIsTheProductOfTheStageStretches) {
  EXPECT_EQ(cordic_rotate_gain(0), 1.0);
  EXPECT_NEAR(cordic_rotate_gain(1), std::sqrt(2.0), 1e-15);
  long double g = 1;
  for (int m = 1; m <= 30; ++m) {
    g *= std::sqrt(1.0L + std::ldexp(1.0L, -2 * (m - 1)));
    EXPECT_NEAR(cordic_rotate_gain(m), static_cast<double>(g), 4e-16 * m) << m;
  }
  // The CORDIC constant K^-1 = 1.646760258121065648366051...
  EXPECT_NEAR(cordic_rotate_gain(30), 1.6467602581210656, 1e-15);
}

TEST(CordicRotate, TrimmedZWidths) {
  for (int zw : {20, 22, 24}) {
    for (int i = 0; i <= 2; ++i) EXPECT_EQ(cordic_rotate_z_width(zw, i), zw - 2);
    for (int i = 3; i < 20; ++i) EXPECT_EQ(cordic_rotate_z_width(zw, i), zw - i);
  }
}

TEST(CordicRotate, OneStageIsTheExactShear) {
  const int64_t table[1] = {12345};  // the word only moves z
  std::mt19937_64 rng(71);
  std::uniform_int_distribution<int64_t> v(-(1 << 20), (1 << 20) - 1), z(-(1 << 16), (1 << 16));
  for (int k = 0; k < 10000; ++k) {
    const int64_t x = v(rng), y = v(rng), a = z(rng);
    const RotateResult r = cordic_rotate(x, y, a, 1, 20, table);
    if (a >= 0) {  // clockwise by 45 deg, times sqrt 2
      ASSERT_EQ(r.x, x + y);
      ASSERT_EQ(r.y, y - x);
    } else {
      ASSERT_EQ(r.x, x - y);
      ASSERT_EQ(r.y, y + x);
    }
  }
}

// floor(a / 2^i) by division.
int64_t floor_div_pow2(int64_t a, int i) {
  const int64_t d = int64_t{1} << i;
  return a / d - ((a % d != 0 && a < 0) ? 1 : 0);
}

TEST(CordicRotate, TurnsByTheAngleItsStagesChoseUpToTheFloors) {
  const int zw = 20;
  for (int m : {8, 12, 16}) {
    const std::vector<int64_t> atan = cordic_atan_table(zw, m);
    const long double g = cordic_rotate_gain(m);
    std::mt19937_64 rng(72 + m);
    std::uniform_int_distribution<int64_t> v(-(1 << 20), (1 << 20) - 1),
        z(-(1 << (zw - 3)) + 1, (1 << (zw - 3)) - 1);
    long double worst = 0;
    for (int k = 0; k < 20000; ++k) {
      const int64_t x = v(rng), y = v(rng), a = z(rng);
      // The directions and the angle they add up to, from the z recurrence alone.
      // Stage i turns by exactly atan(2^-i) (its word only steers z).
      int64_t zz = a;
      long double ang = 0;
      for (int i = 0; i < m; ++i) {
        const bool cw = zz >= 0;
        ang += (cw ? 1 : -1) * std::atan(std::ldexp(1.0L, -i));
        zz -= cw ? atan[i] : -atan[i];
      }
      const long double ex = g * (x * std::cos(ang) + y * std::sin(ang));
      const long double ey = g * (y * std::cos(ang) - x * std::sin(ang));
      const RotateResult r = cordic_rotate(x, y, a, m, zw, atan.data());
      const long double err = std::hypot(r.x - ex, r.y - ey);
      // One floor per stage and word (< 1 LSB each, a vector < sqrt 2), grown by at most G_M.
      ASSERT_LE(err, std::sqrt(2.0L) * m * g) << x << "," << y << " z " << a;
      worst = std::max(worst, err);
      // And the residual |z_M| is below the last stage's arctangent plus the table rounding.
      ASSERT_LE(std::llabs(zz), atan[m - 1] + m) << a;
    }
    EXPECT_GT(worst, 1.0L) << "the floors do show";
  }
  // Two stages by hand, negative values included: stage 1 shifts by one with floor.
  const int64_t t2[2] = {0, 0};
  const int64_t x = -7, y = 2;
  const int64_t x1 = x + y, y1 = y - x;  // z = 0 >= 0 at stage 0, then z stays 0 >= 0
  const RotateResult r = cordic_rotate(x, y, 0, 2, 20, t2);
  EXPECT_EQ(r.x, x1 + floor_div_pow2(y1, 1));
  EXPECT_EQ(r.y, y1 - floor_div_pow2(x1, 1));
}

TEST(CordicRotate, ZWrapsInItsTrimmedWidth) {
  // z enters stage 0 as a Z_W - 2 bit signed word: z and z + 2^(Z_W-2) are the same rotation, and
  // +1/8 turn (2^(Z_W-3)) reads as -1/8 turn.
  const int zw = 20, m = 12;
  const std::vector<int64_t> atan = cordic_atan_table(zw, m);
  const int64_t wrap = int64_t{1} << (zw - 2);
  for (int64_t a : {int64_t{0}, int64_t{777}, int64_t{-40000}, (int64_t{1} << (zw - 3)) - 1}) {
    const RotateResult p = cordic_rotate(100000, -5000, a, m, zw, atan.data());
    const RotateResult q = cordic_rotate(100000, -5000, a + wrap, m, zw, atan.data());
    EXPECT_EQ(p.x, q.x) << a;
    EXPECT_EQ(p.y, q.y) << a;
  }
  const int64_t eighth = int64_t{1} << (zw - 3);
  const RotateResult up = cordic_rotate(100000, 0, eighth, m, zw, atan.data());
  const RotateResult down = cordic_rotate(100000, 0, -eighth, m, zw, atan.data());
  EXPECT_EQ(up.x, down.x);
  EXPECT_EQ(up.y, down.y);
  EXPECT_GT(up.y, 0) << "-1/8 turn clockwise is counter-clockwise: y grows";
}

}  // namespace
}  // namespace acore
