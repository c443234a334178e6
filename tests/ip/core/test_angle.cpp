// SPDX-License-Identifier: MIT
// Angles and ANGLE_W-bit angle codes (core/angle.*) against long-double closed forms: wrapping
// moves an angle by whole turns only, a code is the nearest step of 2^-ANGLE_W turn (half steps
// up), and code -> angle -> code is the identity for every code.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "core/angle.hpp"

namespace acore {
namespace {

constexpr long double kTwoPiL = 6.283185307179586476925286766559L;

// A whole number of turns, within the rounding of one double.
void expect_whole_turns(double from, double to) {
  const long double turns = (static_cast<long double>(from) - to) / kTwoPiL;
  EXPECT_NEAR(static_cast<double>(turns - std::nearbyint(turns)), 0.0, 1e-13) << from;
}

TEST(Angle, WrapPiLandsInTheHalfOpenTurnAndMovesByWholeTurns) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> any(-2000.0, 2000.0);
  for (int k = 0; k < 20000; ++k) {
    const double a = any(rng), w = wrap_pi(a);
    ASSERT_GE(w, -M_PI) << a;
    ASSERT_LT(w, M_PI) << a;
    expect_whole_turns(a, w);
  }
  // The edges: -pi stays, +pi becomes -pi, and angles already inside do not move at all.
  EXPECT_EQ(wrap_pi(-M_PI), -M_PI);
  EXPECT_EQ(wrap_pi(M_PI), -M_PI);
  EXPECT_EQ(wrap_pi(3 * M_PI), -M_PI);
  for (double a : {0.0, 0.5, -0.5, 3.0, -3.1}) EXPECT_EQ(wrap_pi(a), a);
}

// The ANGLE_W-bit code of rad: round(frac(rad / 2 pi) 2^A) mod 2^A, half steps rounded up.
uint32_t code_closed_form(double rad, int angle_w) {
  const long double turns = static_cast<long double>(rad) / kTwoPiL;
  const long double frac = turns - std::floor(turns);
  const long double steps = std::floor(std::ldexp(frac, angle_w) + 0.5L);
  const uint64_t mask = (uint64_t{1} << angle_w) - 1;
  return static_cast<uint32_t>(static_cast<uint64_t>(steps) & mask);
}

TEST(Angle, CodeIsTheNearestStepOfATurn) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> any(-40.0, 40.0);
  for (int angle_w : {8, 12, 16, 18, 20}) {
    const double lsb = 2 * M_PI / std::ldexp(1.0, angle_w);
    for (int k = 0; k < 20000; ++k) {
      const double a = any(rng);
      // Off the half steps by more than the rounding of the division: the closed form decides.
      const double steps = a / lsb;
      if (std::fabs(steps - std::floor(steps) - 0.5) < 1e-6) continue;
      ASSERT_EQ(angle_code(a, angle_w), code_closed_form(a, angle_w)) << a << " w=" << angle_w;
    }
    // Just below and above half a step: down and up; one step below zero is the top code.
    for (int64_t c : {int64_t{0}, int64_t{1}, int64_t{77}, (int64_t{1} << angle_w) - 2}) {
      EXPECT_EQ(angle_code((c + 0.49) * lsb, angle_w), c);
      EXPECT_EQ(angle_code((c + 0.51) * lsb, angle_w), c + 1);
    }
    EXPECT_EQ(angle_code(-lsb, angle_w), (uint32_t{1} << angle_w) - 1);
    EXPECT_EQ(angle_code(-0.49 * lsb, angle_w), 0u);  // rounds up to a whole turn: code 0
  }
}

TEST(Angle, CodeToAngleIsTheSignedStepAndInvertsExactly) {
  for (int angle_w : {8, 12, 16}) {
    const uint32_t n = uint32_t{1} << angle_w;
    for (uint32_t c = 0; c < n; ++c) {
      const double a = code_angle(c, angle_w);
      // Codes of the upper half are the negative angles: [-pi, pi).
      const int64_t s = c < n / 2 ? static_cast<int64_t>(c) : static_cast<int64_t>(c) - n;
      ASSERT_EQ(a, static_cast<double>(s) * 2 * M_PI / n) << c;
      ASSERT_GE(a, -M_PI);
      ASSERT_LT(a, M_PI);
      ASSERT_EQ(angle_code(a, angle_w), c) << c << " w=" << angle_w;
      // A whole turn more or less is the same code.
      ASSERT_EQ(angle_code(a + 2 * M_PI, angle_w), c) << c;
      ASSERT_EQ(angle_code(a - 4 * M_PI, angle_w), c) << c;
    }
  }
  // Bits above ANGLE_W are ignored: the code is read modulo a turn.
  EXPECT_EQ(code_angle(0x10000 + 5, 16), code_angle(5, 16));
}

}  // namespace
}  // namespace acore
