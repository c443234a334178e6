// SPDX-License-Identifier: MIT
// Stage 5, the vectoring CORDIC (stages/cordic.*), against closed forms: the arctangent table is
// round(atan(2^-i) / 2 pi 2^Z_W) in long double; the output angle is Z rounded to ANGLE_W bits,
// half up, modulo a turn (checked on a one-stage CORDIC whose single table word sets Z exactly, and
// as the zero mean of the angle error against a long-double atan2 over the circle); the quadrant
// pre-rotation adds exactly half a turn; the normalization is a common left shift.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include "stages/cordic.hpp"

namespace acore {
namespace {

constexpr long double kTwoPiL = 6.283185307179586476925286766559L;

TEST(Cordic, AtanTableIsTheRoundedArctangentOfEveryStage) {
  for (int z_w : {20, 22, 24}) {
    const std::vector<int64_t> t = cordic_atan_table(z_w, 24);
    ASSERT_EQ(t.size(), 24u);
    EXPECT_EQ(t[0], int64_t{1} << (z_w - 3));  // atan(1) = 1/8 turn
    for (int i = 0; i < 24; ++i) {
      const long double exact = std::atan(std::ldexp(1.0L, -i)) / kTwoPiL * std::ldexp(1.0L, z_w);
      EXPECT_EQ(t[i], static_cast<int64_t>(std::floor(exact + 0.5L)))
          << "z_w " << z_w << " i " << i;
      EXPECT_LE(std::fabs(t[i] - exact), 0.5L);
    }
  }
}

// A one-stage CORDIC with the table word T: Z leaves the stage as +-T (plus half a turn when the
// pre-rotation acts), so the output is that Z rounded to ANGLE_W bits.
uint32_t rounded_closed_form(int64_t z, const CordicConfig& c) {
  const long double turns = std::ldexp(static_cast<long double>(z), -c.z_w);
  const long double frac = turns - std::floor(turns);  // modulo a turn
  const long double steps = std::floor(std::ldexp(frac, c.angle_w) + 0.5L);
  return static_cast<uint32_t>(static_cast<uint64_t>(steps) & ((uint64_t{1} << c.angle_w) - 1));
}

TEST(Cordic, OutputAngleIsZRoundedToNearestHalfUp) {
  for (int z_w : {20, 22}) {
    for (int angle_w : {12, 16}) {
      CordicConfig c;
      c.z_w = z_w;
      c.angle_w = angle_w;
      c.iterations = 1;
      const int drop = z_w - angle_w;
      const int64_t half_turn = int64_t{1} << (z_w - 1);
      int ups = 0;
      for (int64_t t = 0; t < (int64_t{1} << (drop + 3)); ++t) {
        const int64_t table[1] = {t};
        // y >= 0 turns by +T, y < 0 by -T; x < 0 first adds half a turn.
        ASSERT_EQ(cordic_vector(1000, 0, c, table).angle, rounded_closed_form(t, c)) << t;
        ASSERT_EQ(cordic_vector(1000, -1, c, table).angle, rounded_closed_form(-t, c)) << t;
        ASSERT_EQ(cordic_vector(-1000, 0, c, table).angle, rounded_closed_form(half_turn + t, c));
        ASSERT_EQ(cordic_vector(-1000, 1, c, table).angle, rounded_closed_form(half_turn - t, c));
        ups += (t & ((int64_t{1} << drop) - 1)) >= (int64_t{1} << (drop - 1));
      }
      EXPECT_GT(ups, 0);
      // The ties themselves: +1/2 step rounds up to 1, -1/2 step up to 0 (not away from zero).
      const int64_t tie[1] = {int64_t{1} << (drop - 1)};
      EXPECT_EQ(cordic_vector(1000, 0, c, tie).angle, 1u);
      EXPECT_EQ(cordic_vector(1000, -1, c, tie).angle, 0u);
      // Less than half a step below zero: rounds up to a whole turn, i.e. code 0.
      const int64_t top[1] = {(int64_t{1} << (drop - 1)) - 1};
      EXPECT_EQ(cordic_vector(1000, -1, c, top).angle, 0u);
    }
  }
}

// Signed angle error in output LSBs against atan2 of the integer inputs, long double.
double error_lsb(const CordicResult& r, int64_t x, int64_t y, const CordicConfig& c) {
  const long double n = std::ldexp(1.0L, c.angle_w);
  long double want =
      std::atan2(static_cast<long double>(y), static_cast<long double>(x)) / kTwoPiL * n;
  long double e = r.angle - want;
  e -= n * std::nearbyint(e / n);
  return static_cast<double>(e);
}

TEST(Cordic, AngleErrorHasZeroMeanOverTheCircle) {
  // Round to nearest leaves no bias; a floor in its place would shift every angle by -1/2 LSB.
  // (Over the circle, not against a table of outputs: an independent, statistical closed form.)
  for (int angle_w : {12, 16}) {
    CordicConfig c;  // the chain's: 18-bit inputs, G 3, Z_W 20, K 16
    c.angle_w = angle_w;
    const auto table = cordic_atan_table(c.z_w, c.iterations);
    std::mt19937_64 rng(61);
    std::uniform_real_distribution<double> ang(0, 2 * M_PI), len(0.5, 1.9);
    double sum = 0, sq = 0;
    const int n = 100000;
    for (int k = 0; k < n; ++k) {
      const double a = ang(rng), r = len(rng) * 65536;
      const int64_t x = std::llround(r * std::cos(a)), y = std::llround(r * std::sin(a));
      const double e = error_lsb(cordic_vector(x, y, c, table.data()), x, y, c);
      sum += e;
      sq += e * e;
    }
    const double mean = sum / n, rms = std::sqrt(sq / n);
    std::printf("angle_w %d: mean %.4f rms %.4f LSB\n", angle_w, mean, rms);
    // At 12 bits the stages' own errors are 1/16 of an output LSB: the mean is the rounding's
    // alone. At 16 bits the floors of X and Y leave a small bias of their own (+0.07 LSB).
    EXPECT_LT(std::fabs(mean), angle_w == 12 ? 0.02 : 0.1) << "angle_w " << angle_w;
    // At least the rounding's own 1/sqrt(12) LSB, at most what the bound allows.
    EXPECT_GT(rms, 0.25);
    EXPECT_LT(rms, 0.5) << "angle_w " << angle_w;
  }
}

TEST(Cordic, PreRotationAddsExactlyHalfATurn) {
  CordicConfig c;
  const auto table = cordic_atan_table(c.z_w, c.iterations);
  const uint32_t half = uint32_t{1} << (c.angle_w - 1), mask = (uint32_t{1} << c.angle_w) - 1;
  std::mt19937_64 rng(62);
  std::uniform_int_distribution<int64_t> v(-131072 + 1, 131071);
  for (int k = 0; k < 20000; ++k) {
    int64_t x = v(rng), y = v(rng);
    if (x == 0) continue;
    if (x < 0) x = -x;
    const CordicResult a = cordic_vector(x, y, c, table.data());
    const CordicResult b = cordic_vector(-x, -y, c, table.data());
    ASSERT_EQ(b.angle, (a.angle + half) & mask) << x << "," << y;
    ASSERT_EQ(b.magnitude, a.magnitude);
  }
}

TEST(Cordic, NormalizationIsACommonLeftShift) {
  CordicConfig plain;
  plain.in_w = 16;
  CordicConfig norm = plain;
  norm.normalize = true;
  const auto table = cordic_atan_table(plain.z_w, plain.iterations);
  for (int64_t y = -300; y <= 300; y += 3)
    for (int64_t x = -300; x <= 300; x += 7) {
      if (x == 0 && y == 0) continue;
      // L = IN_W - 2 - msb(|x| | |y|): the larger magnitude's leading one moves to bit IN_W - 2.
      const uint64_t m =
          static_cast<uint64_t>(std::llabs(x)) | static_cast<uint64_t>(std::llabs(y));
      int msb = 63;
      while (!((m >> msb) & 1)) --msb;
      const int shift = plain.in_w - 2 - msb;
      const CordicResult want =
          cordic_vector(x * (int64_t{1} << shift), y * (int64_t{1} << shift), plain, table.data());
      const CordicResult got = cordic_vector(x, y, norm, table.data());
      ASSERT_EQ(got.angle, want.angle) << x << "," << y;
      ASSERT_EQ(got.magnitude, want.magnitude) << x << "," << y;
    }
  // Inputs already at full scale are not shifted.
  const CordicResult big = cordic_vector(16000, -9000, norm, table.data());
  EXPECT_EQ(big.angle, cordic_vector(16000, -9000, plain, table.data()).angle);
}

TEST(Cordic, OneStageMagnitudeIsTheRotatedXFloored) {
  CordicConfig c;
  c.iterations = 1;
  c.guard = 3;
  const int64_t t[1] = {0};
  // Stage 0 turns by +-45 deg without the 1/sqrt 2: X_1 = x + |y| (x >= 0), then >>> G.
  for (int64_t x : {0, 5, 1000})
    for (int64_t y : {-7, -1, 0, 3, 999})
      EXPECT_EQ(cordic_vector(x, y, c, t).magnitude, x + std::llabs(y));
  // A negative x is turned by half a turn first: the magnitude is |x| + |y| again.
  EXPECT_EQ(cordic_vector(-20, 6, c, t).magnitude, 26);
  // Two stages: the second adds |Y_1| / 2 with Y_1 = (y - x) 2^G, floored by the shift.
  c.iterations = 2;
  const int64_t t2[2] = {0, 0};
  const int64_t x = 5, y = 3, g = int64_t{1} << c.guard;
  const int64_t X1 = (x + y) * g, Y1 = (y - x) * g;
  const int64_t X2 = Y1 >= 0 ? X1 + (Y1 >> 1) : X1 - (Y1 >> 1);
  EXPECT_EQ(cordic_vector(x, y, c, t2).magnitude, X2 >> c.guard);
}

}  // namespace
}  // namespace acore
