// SPDX-License-Identifier: MIT
// The least-squares angle-error spectrum (harmonics/harmonic_spectrum.*) against closed forms: a
// series sampled at random angles is recovered exactly; amplitude and phase describe it as
// H sin(k theta + phase); the fit is linear, blind to whole turns added to the angles, and on a
// uniform grid leaves exactly the orders it does not fit (Parseval: RMS = amplitude / sqrt 2).
// The DFT equivalence and the noisy, non-uniform case are in test_harmonics.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/errors.hpp"
#include "harmonics/harmonic_spectrum.hpp"

namespace acore {
namespace {

struct Series {
  double mean;
  std::vector<double> a, b;  // a_k cos k theta + b_k sin k theta, k = 1..K
  double at(double th) const {
    double v = mean;
    for (size_t k = 1; k <= a.size(); ++k)
      v += a[k - 1] * std::cos(k * th) + b[k - 1] * std::sin(k * th);
    return v;
  }
};

Series random_series(std::mt19937_64& rng, int orders) {
  std::uniform_real_distribution<double> u(-2, 2);
  Series s{u(rng), {}, {}};
  for (int k = 1; k <= orders; ++k) s.a.push_back(u(rng)), s.b.push_back(u(rng));
  return s;
}

TEST(HarmonicSpectrum, RecoversAnySeriesFromRandomAngles) {
  std::mt19937_64 rng(121);
  std::uniform_real_distribution<double> angle(-7.0, 30.0);  // several turns, any range
  for (int orders : {1, 4, 9}) {
    const Series s = random_series(rng, orders);
    std::vector<double> th, e;
    for (int i = 0; i < 600; ++i) {
      th.push_back(angle(rng));
      e.push_back(s.at(th.back()));
    }
    const auto sp = error_spectrum(th, e, orders + 2);  // two orders more than present
    ASSERT_EQ(sp.size(), static_cast<size_t>(orders + 3));
    EXPECT_NEAR(sp[0].cos_deg, s.mean, 1e-10);
    EXPECT_NEAR(sp[0].amplitude_deg, std::fabs(s.mean), 1e-10);
    EXPECT_EQ(sp[0].phase_rad, s.mean >= 0 ? M_PI / 2 : -M_PI / 2);
    for (int k = 1; k <= orders + 2; ++k) {
      const double a = k <= orders ? s.a[k - 1] : 0, b = k <= orders ? s.b[k - 1] : 0;
      EXPECT_EQ(sp[k].order, k);
      EXPECT_NEAR(sp[k].cos_deg, a, 1e-10) << k;
      EXPECT_NEAR(sp[k].sin_deg, b, 1e-10) << k;
      EXPECT_NEAR(sp[k].amplitude_deg, std::hypot(a, b), 1e-10) << k;
      // H sin(k theta + phase) is the order's term.
      if (k <= orders)
        for (double t : {0.0, 0.4, 2.2, 5.0})
          EXPECT_NEAR(sp[k].amplitude_deg * std::sin(k * t + sp[k].phase_rad),
                      a * std::cos(k * t) + b * std::sin(k * t), 1e-10);
    }
    EXPECT_NEAR(spectrum_residual_rms(th, e, sp), 0.0, 1e-10);
  }
}

TEST(HarmonicSpectrum, LinearAndBlindToWholeTurns) {
  std::mt19937_64 rng(122);
  std::uniform_real_distribution<double> angle(0.0, 2 * M_PI), noise(-0.3, 0.3);
  std::vector<double> th, th_turns, e1, e2, sum;
  for (int i = 0; i < 500; ++i) {
    th.push_back(angle(rng));
    th_turns.push_back(th.back() + 2 * M_PI * (i % 7 - 3));
    e1.push_back(noise(rng));  // anything: least squares is linear in the data
    e2.push_back(std::cos(3 * th.back()) + noise(rng));
    sum.push_back(e1.back() + 2 * e2.back());
  }
  const auto s1 = error_spectrum(th, e1, 6), s2 = error_spectrum(th, e2, 6);
  const auto ss = error_spectrum(th, sum, 6), st = error_spectrum(th_turns, e1, 6);
  for (int k = 0; k <= 6; ++k) {
    EXPECT_NEAR(ss[k].cos_deg, s1[k].cos_deg + 2 * s2[k].cos_deg, 1e-11) << k;
    EXPECT_NEAR(ss[k].sin_deg, s1[k].sin_deg + 2 * s2[k].sin_deg, 1e-11) << k;
    EXPECT_NEAR(st[k].cos_deg, s1[k].cos_deg, 1e-9) << k;
    EXPECT_NEAR(st[k].sin_deg, s1[k].sin_deg, 1e-9) << k;
  }
}

TEST(HarmonicSpectrum, UniformGridLeavesTheUnfittedOrdersWhole) {
  // Orders 0..3 fitted, the data an order-7 term of amplitude 1.3 plus a fitted part: on a uniform
  // grid the orders are orthogonal, so the fit finds the fitted part exactly and the residual is
  // the order-7 term, RMS 1.3 / sqrt 2.
  const int n = 360;
  std::vector<double> th, e;
  for (int i = 0; i < n; ++i) {
    th.push_back(2 * M_PI * i / n);
    e.push_back(0.5 + 0.2 * std::sin(2 * th.back()) + 1.3 * std::sin(7 * th.back() + 0.4));
  }
  const auto sp = error_spectrum(th, e, 3);
  EXPECT_NEAR(sp[0].cos_deg, 0.5, 1e-12);
  EXPECT_NEAR(sp[1].amplitude_deg, 0.0, 1e-12);
  EXPECT_NEAR(sp[2].amplitude_deg, 0.2, 1e-12);
  EXPECT_NEAR(sp[2].phase_rad, 0.0, 1e-10);
  EXPECT_NEAR(sp[3].amplitude_deg, 0.0, 1e-12);
  EXPECT_NEAR(spectrum_residual_rms(th, e, sp), 1.3 / std::sqrt(2.0), 1e-12);
}

TEST(HarmonicSpectrum, InputErrors) {
  EXPECT_THROW(error_spectrum({0, 1, 2}, {0, 1, 2}, -1), InputError);
  EXPECT_THROW(error_spectrum({0, 1, 2, 3}, {0, 1, 2, INFINITY}, 1), InputError);
  // 2 K + 2 samples are the least for K orders.
  EXPECT_NO_THROW(error_spectrum({0, 1, 2, 3}, {0, 1, 2, 3}, 1));
  EXPECT_THROW(error_spectrum({0, 1, 2}, {0, 1, 2}, 1), InputError);
  EXPECT_THROW(spectrum_residual_rms({}, {}, {}), InputError);
  EXPECT_THROW(spectrum_residual_rms({0, 1}, {0}, {}), InputError);
}

}  // namespace
}  // namespace acore
