// SPDX-License-Identifier: MIT
// Table 1 of Kuntz (harmonics/harmonic_mismatch.*) against an exact angle error computed here from
// the mismatched signals themselves, a = A0 + sin(p phi + delta) + An sin(p phi), b = B0 + (1 + Bn)
// cos(p phi), with a long-double DFT (not the library's exact_error): every row within the
// second-order remainder; its first-order limits (the offset's H_p = r, H_2p = r^2 / 2, the
// amplitude's H_2p = |An - Bn| / 2, the phase's H_0 = H_2p = delta / 2); the equivalent
// disturbances rebuild the signals exactly; the names and flags agree.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "harmonics/harmonic_mismatch.hpp"

namespace acore {
namespace {

constexpr long double kPiL = 3.141592653589793238462643383279502884L;

// The mismatched pair at mechanical angle phi (only the row's parameters used).
std::complex<long double> signal(MismatchType t, const MismatchParams& m, int p, long double phi) {
  const long double x = p * phi;
  long double a = std::sin(x), b = std::cos(x);
  if (has_offset(t)) a += m.A0, b += m.B0;
  if (has_amplitude(t)) a += m.An * std::sin(x), b += m.Bn * std::cos(x);
  if (has_phase(t)) a += std::sin(x + m.delta) - std::sin(x);
  return {b, a};
}

// One-sided amplitudes at mechanical orders 0..4p of the exact electrical error atan2(a, b) - p
// phi.
std::vector<long double> exact_orders(MismatchType t, const MismatchParams& m, int p) {
  const int n = 512;  // the error is smooth: its orders above 4p fall off like size^k
  std::vector<std::complex<long double>> c(static_cast<size_t>(4 * p + 1));
  for (int j = 0; j < n; ++j) {
    const long double phi = 2 * kPiL * j / n;
    const long double e = std::remainder(std::arg(signal(t, m, p, phi)) - p * phi, 2 * kPiL);
    for (int k = 0; k <= 4 * p; ++k)
      c[static_cast<size_t>(k)] += e * std::polar(1.0L, -k * phi) / static_cast<long double>(n);
  }
  std::vector<long double> amp;
  for (int k = 0; k <= 4 * p; ++k) amp.push_back((k ? 2 : 1) * std::abs(c[static_cast<size_t>(k)]));
  return amp;
}

TEST(HarmonicMismatch, EveryRowWithinTheSecondOrderRemainderOfTheExactError) {
  std::mt19937_64 rng(131);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int p : {1, 3})
    for (double s : {0.01, 0.04})
      for (MismatchType t : all_mismatch_types())
        for (int trial = 0; trial < 4; ++trial) {
          const MismatchParams m{s * u(rng), s * u(rng), s * u(rng), s * u(rng), s * u(rng)};
          const auto ex = exact_orders(t, m, p);
          const MismatchHarmonics h = table1(t, m);
          // The neglected terms are third order in the disturbances' total size.
          double size = 0;
          if (has_offset(t)) size += std::fabs(m.A0) + std::fabs(m.B0);
          if (has_amplitude(t)) size += std::fabs(m.An) + std::fabs(m.Bn);
          if (has_phase(t)) size += 2 * std::fabs(std::sin(m.delta / 2));
          for (int mult = 0; mult <= 4; ++mult)
            EXPECT_NEAR(h.at_multiple(mult), static_cast<double>(ex[static_cast<size_t>(mult * p)]),
                        0.5 * size * size * size)
                << to_string(t) << " p " << p << " s " << s << " H_" << mult << "p";
          // The error is a function of p phi: orders between the multiples of p are absent.
          for (int k = 1; k < 4 * p; ++k)
            if (k % p) EXPECT_LT(ex[static_cast<size_t>(k)], 1e-15);
        }
}

TEST(HarmonicMismatch, FirstOrderLimitsOfTheSingleRows) {
  // Offset: a constant vector (A0, B0) of length r turns the angle by r sin(.) once per electrical
  // period (H_p = r) and its square at twice (H_2p = r^2 / 2, exactly as the row reads).
  for (double a0 : {0.0, 0.01, -0.03})
    for (double b0 : {0.02, -0.005}) {
      const MismatchHarmonics h = table1(MismatchType::Offset, {a0, b0, 0, 0, 0});
      const double r = std::hypot(a0, b0);
      EXPECT_DOUBLE_EQ(h.Hp, r);
      EXPECT_NEAR(h.H2p, r * r / 2, 1e-17);
      EXPECT_EQ(h.H0, 0.0);
      EXPECT_EQ(h.H3p, 0.0);
    }
  // Amplitude mismatch: H_2p = |An - Bn| / 2 to first order, H_4p its square / 8.
  const MismatchHarmonics ha = table1(MismatchType::Amplitude, {0, 0, 1e-4, -2e-4, 0});
  EXPECT_NEAR(ha.H2p, 1.5e-4, 1e-8);
  EXPECT_NEAR(ha.H4p, 9e-8 / 8, 1e-20);
  EXPECT_EQ(ha.Hp, 0.0);
  // Phase mismatch delta: a constant delta / 2 and a second harmonic delta / 2.
  const double d = 1e-4;
  const MismatchHarmonics hp = table1(MismatchType::Phase, {0, 0, 0, 0, d});
  EXPECT_NEAR(hp.H0, d / 2, 1e-12);
  EXPECT_NEAR(hp.H2p, d / 2, 1e-12);
  EXPECT_NEAR(hp.H4p, d * d / 8, 1e-15);
  // The row is even in delta, and its inverse finds |delta| back.
  EXPECT_DOUBLE_EQ(table1(MismatchType::Phase, {0, 0, 0, 0, -0.3}).H2p,
                   table1(MismatchType::Phase, {0, 0, 0, 0, 0.3}).H2p);
  double last = 0;
  for (double x = 0.05; x < 1.5; x += 0.05) {
    const double h = table1(MismatchType::Phase, {0, 0, 0, 0, x}).H2p;
    EXPECT_GT(h, last);  // monotone: the inverse is unique
    last = h;
    EXPECT_NEAR(phase_from_h2p(h), x, 1e-12);
  }
  EXPECT_THROW(phase_from_h2p(-1e-3), InputError);
  EXPECT_EQ(ha.at_multiple(5), 0.0);
}

TEST(HarmonicMismatch, DisturbancesRebuildTheSignalsExactly) {
  const MismatchParams m{0.03, -0.02, 0.05, -0.04, 0.07};
  for (int p : {1, 2, 5})
    for (MismatchType t : all_mismatch_types()) {
      const std::vector<Disturbance> d = mismatch_disturbances(t, m, p);
      EXPECT_EQ(d.size(), static_cast<size_t>(has_offset(t) + has_amplitude(t) + has_phase(t)));
      for (double phi = 0; phi < 2 * M_PI; phi += 0.3) {
        // e^{i p phi} + sum (B cos(n phi + psi) + i A sin(n phi + theta)) = b + i a.
        std::complex<double> z = std::polar(1.0, p * phi);
        for (const Disturbance& q : d) {
          EXPECT_TRUE(q.source == "offset" || q.source == "amplitude" || q.source == "phase");
          z += std::complex<double>(q.B * std::cos(q.n * phi + q.psi),
                                    q.A * std::sin(q.n * phi + q.theta));
        }
        const std::complex<long double> want = signal(t, m, p, phi);
        EXPECT_NEAR(z.real(), static_cast<double>(want.real()), 1e-13) << to_string(t);
        EXPECT_NEAR(z.imag(), static_cast<double>(want.imag()), 1e-13) << to_string(t);
      }
    }
}

TEST(HarmonicMismatch, NamesAndFlagsAgree) {
  const std::vector<std::string> want = {"offset",
                                         "amplitude",
                                         "phase",
                                         "offset+amplitude",
                                         "offset+phase",
                                         "amplitude+phase",
                                         "offset+amplitude+phase"};
  ASSERT_EQ(all_mismatch_types().size(), want.size());
  for (size_t k = 0; k < want.size(); ++k) {
    const MismatchType t = all_mismatch_types()[k];
    EXPECT_EQ(to_string(t), want[k]);
    EXPECT_EQ(has_offset(t), want[k].find("offset") != std::string::npos);
    EXPECT_EQ(has_amplitude(t), want[k].find("amplitude") != std::string::npos);
    EXPECT_EQ(has_phase(t), want[k].find("phase") != std::string::npos);
  }
  // A row ignores the parameters of the mismatches it does not have.
  const MismatchParams all{0.01, 0.02, 0.03, 0.04, 0.05};
  const MismatchHarmonics a = table1(MismatchType::Offset, all);
  const MismatchHarmonics b = table1(MismatchType::Offset, {0.01, 0.02, 0, 0, 0});
  EXPECT_EQ(a.Hp, b.Hp);
  EXPECT_EQ(a.H2p, b.H2p);
}

}  // namespace
}  // namespace acore
