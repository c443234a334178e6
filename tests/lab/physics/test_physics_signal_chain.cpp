// SPDX-License-Identifier: MIT
// The analog chain of the physics scenarios (physics/physics_signal_chain.*) against closed forms:
// the RC filter's exact ramp lag, sine response and exponential decay; the ADC's step, rounding
// (ties to even), offset and clamping; the multiplexer's slot delays.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/errors.hpp"
#include "physics/physics_signal_chain.hpp"

namespace acore {
namespace {

TEST(PhysicsChain, RcFilterLagsARampByTauAndFollowsTheSineResponse) {
  const double tau = 1e-3, h = 1e-4;
  RcFilter f(tau, h);
  double y = 0;
  for (int k = 0; k <= 2000; ++k) y = f.step(3.0 * k * h);
  EXPECT_NEAR(y, 3.0 * (2000 * h - tau), 1e-9);  // exact for a ramp once settled
  // A sine at omega: gain 1/sqrt(1 + (omega tau)^2), phase -atan(omega tau) (to O(h^2)).
  const double w = 2 * M_PI * 50;
  RcFilter g(tau, h);
  double a = 0, b = 0;
  const int n = 20000;
  for (int k = 0; k < n; ++k) {
    const double out = g.step(std::sin(w * k * h));
    if (k >= n / 2) a += out * std::sin(w * k * h), b += out * std::cos(w * k * h);
  }
  const double gain = 2 * std::hypot(a, b) / (n / 2), phase = std::atan2(b, a);
  EXPECT_NEAR(gain, 1 / std::sqrt(1 + w * tau * w * tau), 1e-3);
  EXPECT_NEAR(phase, -std::atan(w * tau), 1e-3);
  RcFilter through(0, h);
  EXPECT_EQ(through.step(0.25), 0.25);
  EXPECT_THROW(RcFilter(-1, h), std::exception);
}

TEST(PhysicsChain, AdcRoundsToItsStepAndClamps) {
  Adc adc{8, 1.0, 0.0};
  EXPECT_DOUBLE_EQ(adc.step(), 2.0 / 256);
  EXPECT_DOUBLE_EQ(adc.convert(0.3), std::nearbyint(0.3 / adc.step()) * adc.step());
  EXPECT_DOUBLE_EQ(adc.convert(2.0), 1.0 - adc.step());
  EXPECT_DOUBLE_EQ(adc.convert(-2.0), -1.0);
  EXPECT_DOUBLE_EQ(adc.convert(0.5 * adc.step()), 0.0);  // ties to even
  Adc ideal;
  EXPECT_EQ(ideal.convert(0.123456), 0.123456);
  const std::vector<double> d = multiplex_delays({2, 0, 3, 1}, 1e-5), want = {2e-5, 0, 3e-5, 1e-5};
  for (size_t c = 0; c < 4; ++c) EXPECT_NEAR(d[c], want[c], 1e-18);
  EXPECT_THROW(multiplex_delays({0, 0, 1, 2}, 1e-5), std::exception);
}

TEST(PhysicsChain, RcFilterDecaysByExpMinusHOverTauAfterAStep) {
  // Input 1 settled, then 0 from the next sample: the first interval is a ramp 1 -> 0 (first-order
  // hold), y_1 = 1 - b with b = 1 - tau (1 - a) / h; afterwards y_k = a^(k-1) y_1, a = exp(-h /
  // tau).
  const double tau = 2e-3, h = 5e-4;
  const double a = std::exp(-h / tau), b = 1 - tau * (1 - a) / h;
  RcFilter f(tau, h);
  EXPECT_EQ(f.step(1.0), 1.0);  // starts settled
  const double y1 = f.step(0.0);
  EXPECT_NEAR(y1, 1 - b, 1e-15);
  double y = y1;
  for (int k = 2; k < 40; ++k) {
    y = f.step(0.0);
    EXPECT_NEAR(y, std::pow(a, k - 1) * y1, 1e-15) << k;
  }
  // A constant input stays constant, whatever it is.
  RcFilter c(tau, h);
  for (int k = 0; k < 10; ++k) EXPECT_DOUBLE_EQ(c.step(-0.37), -0.37);
  EXPECT_THROW(RcFilter(1e-3, 0), InputError);
}

TEST(PhysicsChain, AdcOffsetAndEveryCodeOfASmallConverter) {
  // 4 bits over +-2: step 0.25, codes -8..7; the offset is added before the conversion.
  const Adc adc{4, 2.0, 0.1};
  EXPECT_DOUBLE_EQ(adc.step(), 0.25);
  for (int k = -8; k <= 7; ++k) {
    const double centre = k * 0.25 - 0.1;  // the input that lands on code k exactly
    EXPECT_DOUBLE_EQ(adc.convert(centre), k * 0.25) << k;
    EXPECT_DOUBLE_EQ(adc.convert(centre + 0.1), k * 0.25) << k;  // within half a step
  }
  EXPECT_DOUBLE_EQ(adc.convert(100.0), 7 * 0.25);
  EXPECT_DOUBLE_EQ(adc.convert(-100.0), -8 * 0.25);
  // Ties to even: 0.125 + 0.25 k halfway between two codes.
  const Adc plain{4, 2.0, 0.0};
  EXPECT_DOUBLE_EQ(plain.convert(0.375), 0.5);  // 1.5 steps -> 2
  EXPECT_DOUBLE_EQ(plain.convert(0.625), 0.5);  // 2.5 steps -> 2
  EXPECT_DOUBLE_EQ(plain.convert(-0.375), -0.5);
  const Adc ideal{0, 1.0, 0.25};
  EXPECT_EQ(ideal.step(), 0.0);
  EXPECT_EQ(ideal.convert(0.5), 0.75);  // an ideal converter still adds its offset
}

TEST(PhysicsChain, MultiplexerSlotsAreDelaysOfTheirIndex) {
  const std::vector<double> d = multiplex_delays({1, 0}, 2.5e-6);
  EXPECT_EQ(d, (std::vector<double>{2.5e-6, 0.0}));
  EXPECT_EQ(multiplex_delays({0, 1, 2, 3}, 0.0), std::vector<double>(4, 0.0));
  EXPECT_THROW(multiplex_delays({0, 2}, 1e-6), InputError);  // not a permutation
  EXPECT_THROW(multiplex_delays({0, 1}, -1e-6), InputError);
}

}  // namespace
}  // namespace acore
