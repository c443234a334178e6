// SPDX-License-Identifier: MIT
// The Cramér-Rao floor and the noise measurement (diagnose/noise_floor.*) against closed forms:
// an ellipse of semi-axes A, B has |dv/dtheta|^2 = A^2 cos^2 + B^2 sin^2, whose mean inverse over a
// turn is 1 / (A B), so the floor is sigma / sqrt(A B) rad; p electrical periods per turn divide it
// by p; the paper's figure (docs/contracts.md: about 2.2 deg RMS with independent noise sigma =
// 0.05 per channel, i.e. sigma sqrt 2 on each difference); the measured sigma of a known noise.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/errors.hpp"
#include "diagnose/noise_floor.hpp"
#include "support/paper_signals.hpp"

namespace acore {
namespace {

constexpr double kDeg = 180.0 / M_PI;

// A two-channel recording of an ellipse, p periods per turn, on n angles of one turn (shuffled
// start: the floor does not care where the turn begins).
Recording ellipse(double a, double b, int p, int n, double start = 0.4) {
  Recording r;
  r.channels = 2;
  for (int k = 0; k < n; ++k) {
    const double th = start + 2 * M_PI * k / n;
    r.theta_ref.push_back(th);
    r.ch[0].push_back(a * std::sin(p * th));
    r.ch[1].push_back(b * std::cos(p * th));
  }
  return r;
}

TEST(NoiseFloor, EllipseFloorIsSigmaOverTheRootOfTheSemiAxes) {
  for (double a : {1.0, 2.0, 0.3})
    for (double b : {1.0, 0.5})
      for (int p : {1, 2, 3}) {
        const double sigma = 0.01;
        const double want = sigma / std::sqrt(a * b) / p * kDeg;
        // The central difference over 2 / 4096 of a turn errs by O(step^2): 1e-6 relative.
        EXPECT_NEAR(crlb_rms_deg(ellipse(a, b, p, 4096), sigma), want, 1e-5 * want)
            << a << " " << b << " p " << p;
      }
  // Linear in sigma; blind to the angle the turn starts at and to a constant offset.
  const Recording e = ellipse(1.5, 0.7, 1, 2048);
  EXPECT_NEAR(crlb_rms_deg(e, 0.03), 3 * crlb_rms_deg(e, 0.01), 1e-12);
  Recording shifted = ellipse(1.5, 0.7, 1, 2048, -2.0);
  for (double& v : shifted.ch[0]) v += 0.2;
  EXPECT_NEAR(crlb_rms_deg(shifted, 0.01), crlb_rms_deg(e, 0.01), 1e-9);
}

TEST(NoiseFloor, PaperScenarioWithIndependentNoiseIsAbout2Point2Degrees) {
  // Four channels of the paper's table, independent noise 0.05 each: sigma_d = 0.05 sqrt 2.
  const Recording clean = test::paper_recording(4096);
  const double floor = crlb_rms_deg(clean, 0.05 * std::sqrt(2.0));
  EXPECT_NEAR(floor, 2.2, 0.1);
  // Against a pure circle of the same mean power: the harmonics make it worse, not better.
  EXPECT_GT(floor, 0.05 * std::sqrt(2.0) / 2 * kDeg);
}

TEST(NoiseFloor, MeasuredSigmaOfAKnownNoise) {
  // Four channels: d13 carries c1's and c3's noise. Deterministic "noise" of known power.
  const Recording clean = test::paper_recording(1000);
  Recording noisy = clean;
  double ss = 0;
  for (size_t i = 0; i < clean.size(); ++i) {
    const double n1 = 0.01 * std::sin(7.0 * i), n3 = 0.02 * std::cos(3.0 * i);
    const double n2 = 0.005 * ((i % 3) - 1.0);
    noisy.ch[0][i] += n1;
    noisy.ch[2][i] += n3;
    noisy.ch[1][i] += n2;
    noisy.ch[3][i] += n2;  // common to c2 and c4: cancels in d24
    ss += (n1 - n3) * (n1 - n3);
  }
  EXPECT_NEAR(differential_noise_sigma(noisy, clean), std::sqrt(ss / (2.0 * clean.size())), 1e-15);
  // Gaussian noise of sigma on two channels (sin, cos) is measured within its sampling error.
  Recording two = ellipse(1, 1, 1, 20000), two_noisy = two;
  std::mt19937_64 rng(141);
  std::normal_distribution<double> g(0, 0.03);
  for (int c = 0; c < 2; ++c)
    for (double& v : two_noisy.ch[c]) v += g(rng);
  EXPECT_NEAR(differential_noise_sigma(two_noisy, two), 0.03, 0.03 * 4 / std::sqrt(2 * 40000.0));
  EXPECT_THROW(differential_noise_sigma(two, clean), InputError);
}

TEST(NoiseFloor, InputErrors) {
  EXPECT_THROW(crlb_rms_deg(ellipse(1, 1, 1, 7), 0.1), InputError);  // fewer than 8 samples
  Recording no_ref = ellipse(1, 1, 1, 100);
  no_ref.theta_ref.clear();
  EXPECT_THROW(crlb_rms_deg(no_ref, 0.1), InputError);
  Recording repeated = ellipse(1, 1, 1, 100);
  repeated.theta_ref[10] = repeated.theta_ref[8];  // the neighbours of sample 9 coincide
  EXPECT_THROW(crlb_rms_deg(repeated, 0.1), InputError);
}

}  // namespace
}  // namespace acore
