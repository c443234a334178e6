// SPDX-License-Identifier: MIT
// Angles as the datapath and the register image carry them: wrapped radians and ANGLE_W-bit codes
// (one turn = 2^ANGLE_W), shared by the zero offset, the ZERO word and the error statistics.
#pragma once
#include <cstdint>

namespace acore {

// pi and what follows from it, written once for the model, the tools and the tests (the C++17
// standard library has no std::numbers).
inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2 * kPi;
inline constexpr double kDegPerRad = 180 / kPi;

// rad wrapped to [-pi, pi).
double wrap_pi(double rad);
// An angle in rad as an ANGLE_W-bit code, rounded, modulo a turn (the ZERO word's format).
uint32_t angle_code(double rad, int angle_w);
// An ANGLE_W-bit code as an angle in rad, wrapped to [-pi, pi).
double code_angle(uint32_t code, int angle_w);

}  // namespace acore
