// SPDX-License-Identifier: MIT
// Kuntz's harmonic analysis (model/lab/harmonics/harmonics.hpp, harmonic_mismatch.hpp,
// harmonic_spectrum.hpp, harmonic_attribution.hpp): the paper's Eq. 33 example, the bounds on
// random spectra, Table 1, measured spectra, attribution and bad specs.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "core/angle.hpp"
#include "core/errors.hpp"
#include "harmonics/harmonic_attribution.hpp"
#include "harmonics/harmonic_mismatch.hpp"
#include "harmonics/harmonic_spectrum.hpp"
#include "harmonics/harmonics.hpp"

namespace acore {
namespace {

constexpr double kDeg = 180.0 / kPi;

SignalSpec eq33() {
  SignalSpec s;
  s.p = 2;
  s.terms = {{3, 0.05, kPi / 8, 0.02, kPi / 7}, {9, 0.075, 0, 0.09, kPi / 4}};
  return s;
}

const HarmonicRow& row(const HarmonicAnalysis& a, int order) { return a.harmonics.at(order); }

// The Eq. 33 numbers that docs/harmonics.md quotes.
TEST(HarmonicsEq33, MaxErrorAndResiduals) {
  const auto a = analyze(eq33());
  std::printf(
      "Eq. 33: max %.4f deg, residual first %.4f deg, second %.5f deg, bounds geo %.3f T1 %.3f T2 "
      "%.3f deg\n",
      a.max_error * kDeg, a.residual_first * kDeg, a.residual_second * kDeg,
      a.bound_geometric * kDeg, *a.bound_taylor_first * kDeg, *a.bound_taylor_second * kDeg);
  EXPECT_NEAR(a.max_error * kDeg, 7.76, 0.01);
  EXPECT_LT(a.residual_first * kDeg, 0.6);
  EXPECT_LT(a.residual_second * kDeg, 0.05);
  // The residuals are real approximation errors, not zero by construction.
  EXPECT_GT(a.residual_first * kDeg, 0.1);
  EXPECT_GT(a.residual_second * kDeg, 0.001);
  EXPECT_LE(a.max_error, a.bound_geometric);
  EXPECT_LE(a.residual_first, *a.bound_taylor_first);
  EXPECT_LE(a.residual_second, *a.bound_taylor_second);
}

TEST(HarmonicsEq33, DominantOrdersFromFirstOrder) {
  const auto a = analyze(eq33());
  for (int k : {1, 5, 7, 11}) {
    const auto& r = row(a, k);
    std::printf("order %2d: exact %.5f first %.5f second %.5f deg\n", k, r.exact * kDeg,
                r.first * kDeg, r.second * kDeg);
    EXPECT_GT(r.exact * kDeg, 0.5) << k;
    EXPECT_NEAR(r.first * kDeg, r.exact * kDeg, 0.001) << "order " << k;
  }
}

TEST(HarmonicsEq33, MinorOrdersFromSecondOrder) {
  const auto a = analyze(eq33());
  for (int k : {2, 4, 8, 10, 14, 16}) {
    const auto& r = row(a, k);
    std::printf("order %2d: exact %.5f first %.5f second %.5f deg\n", k, r.exact * kDeg,
                r.first * kDeg, r.second * kDeg);
    EXPECT_EQ(r.first, 0.0) << "first order cannot produce order " << k;
    EXPECT_GT(r.exact * kDeg, 0.01) << k;
    EXPECT_NEAR(r.second, r.exact, 0.02 * r.exact) << "order " << k;
  }
}

TEST(HarmonicsEq33, SpecFileAndJson) {
  const auto s = load_signal_spec(std::string(ACORE_SOURCE_DIR) + "/tests/data/kuntz_eq33.json");
  const auto a = analyze(s), b = analyze(eq33());
  EXPECT_DOUBLE_EQ(a.max_error, b.max_error);
  const auto j = a.to_json();
  for (const char* f :
       {"max_error_deg", "residual_first_deg", "residual_second_deg", "bounds", "harmonics"})
    EXPECT_TRUE(j.contains(f)) << f;
  for (const char* f : {"geometric_deg", "taylor_first_deg", "taylor_second_deg"})
    EXPECT_TRUE(j["bounds"].contains(f)) << f;
  const auto& h = j["harmonics"].at(5);
  EXPECT_EQ(h["order"].get<int>(), 5);
  EXPECT_NEAR(h["exact_deg"].get<double>(), a.harmonics[5].exact * kDeg, 1e-12);
  for (const char* f : {"first_deg", "second_deg"}) EXPECT_TRUE(h.contains(f)) << f;
}

std::vector<Disturbance> random_disturbances(std::mt19937& rng, int p, int count, double scale) {
  std::uniform_real_distribution<double> u(0, 1);
  std::uniform_int_distribution<int> order(0, 3 * p + 6);
  std::vector<Disturbance> d;
  for (int i = 0; i < count; ++i) {
    Disturbance x;
    x.n = order(rng);
    x.A = scale * u(rng);
    x.B = scale * u(rng);
    // Offsets and amplitude mismatches may be negative (section 4).
    if (x.n == 0 || x.n == p) {
      if (u(rng) < 0.5) x.A = -x.A;
      if (u(rng) < 0.5) x.B = -x.B;
    }
    x.theta = 2 * kPi * u(rng);
    x.psi = 2 * kPi * u(rng);
    d.push_back(x);
  }
  return d;
}

// The formula spectra (TrigSeries) and the time-domain Eq. 18 / Eq. 26 are the same functions.
TEST(HarmonicsTaylor, SeriesMatchesTimeDomain) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const int p = 1 + trial % 4;
    const auto d = random_disturbances(rng, p, 1 + trial % 5, 0.1);
    const auto phi = turn_grid(97);
    const auto t1 = first_order_term(d, p, phi), t2 = second_order_term(d, p, phi);
    const auto s1 = first_order_series(d, p), s2 = second_order_series(d, p);
    for (size_t j = 0; j < phi.size(); ++j) {
      EXPECT_NEAR(s1.value(phi[j]), t1[j], 1e-12);
      EXPECT_NEAR(s2.value(phi[j]), t2[j], 1e-12);
    }
  }
}

// T^1 and T^2 are the true Taylor terms: scaling the disturbances by 1/2 divides the first-order
// residual by ~4 and the second-order residual by ~8.
TEST(HarmonicsTaylor, ResidualOrder) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 10; ++trial) {
    const int p = 1 + trial % 3;
    auto d = random_disturbances(rng, p, 3, 0.02);
    const auto phi = turn_grid(1024);
    auto residuals = [&](const std::vector<Disturbance>& x) {
      const auto e = exact_error(x, p, phi), t1 = first_order_term(x, p, phi),
                 t2 = second_order_term(x, p, phi);
      double r1 = 0, r2 = 0;
      for (size_t j = 0; j < phi.size(); ++j) {
        r1 = std::max(r1, std::fabs(e[j] - t1[j]));
        r2 = std::max(r2, std::fabs(e[j] - t1[j] - t2[j]));
      }
      return std::make_pair(r1, r2);
    };
    const auto big = residuals(d);
    for (auto& x : d) x.A /= 2, x.B /= 2;
    const auto small = residuals(d);
    EXPECT_NEAR(small.first / big.first, 0.25, 0.04) << trial;
    EXPECT_NEAR(small.second / big.second, 0.125, 0.03) << trial;
  }
}

// Normalisation and equivalent disturbances reproduce the raw signals of Eq. 1 / 11 exactly.
TEST(HarmonicsSpec, EquivalentDisturbancesAreExact) {
  SignalSpec s;
  s.p = 3;
  s.A0 = 0.04;
  s.B0 = -0.03;
  s.Ap = 2.1;
  s.Bp = 1.9;
  s.delta_p = 0.05;
  s.terms = {{1, 0.05, 0.3, 0.02, 1.1}, {7, 0.03, 2.0, 0.04, -0.4}};
  const auto d = equivalent_disturbances(s);
  ASSERT_EQ(d.size(), 5u);
  const auto phi = turn_grid(777);
  const auto a = exact_error(s, phi), b = exact_error(d, s.p, phi);
  for (size_t j = 0; j < phi.size(); ++j) EXPECT_NEAR(a[j], b[j], 1e-13);
  // An offset-only signal has the offset at order p to first order: H_p = |B0 + i A0| / g.
  SignalSpec o;
  o.p = 2;
  o.A0 = 0.006;
  o.B0 = 0.008;
  const auto r = analyze(o);
  EXPECT_NEAR(r.harmonics[2].first, 0.01, 1e-15);
  EXPECT_NEAR(r.harmonics[2].exact, 0.01, 1e-6);
}

// Property test: every bound holds on thousands of random spectra inside the convergence domain.
TEST(HarmonicsBounds, HoldOnRandomSpectra) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(0, 1);
  int cases = 0, linear_cases = 0;
  double tightest_geo = 0, tightest_t1 = 0, tightest_t2 = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const int p = 1 + trial % 4;
    auto d = random_disturbances(rng, p, 1 + trial % 4, 1.0);
    // Scale into the Taylor convergence domain: sum(|A|+|B|) uniform in (0, 0.95).
    const double target = 0.95 * u(rng), at = taylor_amplitude_sum(d);
    for (auto& x : d) x.A *= target / at, x.B *= target / at;
    const double ag = geometric_amplitude_sum(d), att = taylor_amplitude_sum(d);
    ASSERT_LT(ag, 1);
    ASSERT_LT(att, 1);
    const auto phi = turn_grid(256);
    const auto e = exact_error(d, p, phi), t1 = first_order_term(d, p, phi),
               t2 = second_order_term(d, p, phi);
    double emax = 0, r1 = 0, r2 = 0;
    for (size_t j = 0; j < phi.size(); ++j) {
      emax = std::max(emax, std::fabs(e[j]));
      r1 = std::max(r1, std::fabs(e[j] - t1[j]));
      r2 = std::max(r2, std::fabs(e[j] - t1[j] - t2[j]));
    }
    const double geo = geometric_bound(ag), b1 = taylor_remainder_bound(att, 1),
                 b2 = taylor_remainder_bound(att, 2);
    ASSERT_LE(emax, geo * (1 + 1e-12)) << "Eq. 29, trial " << trial;
    if (ag < 0.5) {
      ASSERT_LE(emax, geometric_bound_linear(ag) * (1 + 1e-12)) << "Eq. 30, trial " << trial;
      ++linear_cases;
    }
    ASSERT_LE(emax, taylor_remainder_bound(att, 0) * (1 + 1e-12)) << "Eq. 32 k=0, trial " << trial;
    ASSERT_LE(r1, b1 * (1 + 1e-12)) << "Eq. 32 k=1, trial " << trial;
    ASSERT_LE(r2, b2 * (1 + 1e-12)) << "Eq. 32 k=2, trial " << trial;
    tightest_geo = std::max(tightest_geo, emax / geo);
    tightest_t1 = std::max(tightest_t1, r1 / b1);
    tightest_t2 = std::max(tightest_t2, r2 / b2);
    ++cases;
  }
  std::printf(
      "%d spectra (%d with A < 1/2); largest error/bound: geometric %.3f, Taylor k=1 %.3f, k=2 "
      "%.3f\n",
      cases, linear_cases, tightest_geo, tightest_t1, tightest_t2);
  EXPECT_GT(linear_cases, 1000);
  // The sweep reaches the bounds' neighbourhood, so a bound that is too small would have been hit.
  EXPECT_GT(tightest_geo, 0.8);
}

// Eq. 29 is tight: a single offset of magnitude a gives max error asin(a) = atan(a/sqrt(1-a^2)).
TEST(HarmonicsBounds, GeometricBoundIsTightForAnOffset) {
  for (double a : {0.1, 0.4, 0.8}) {
    const std::vector<Disturbance> d = {{0, a * 0.6, kPi / 2, a * 0.8, 0, "offset"}};
    const auto e = exact_error(d, 1, turn_grid(1 << 16));
    double m = 0;
    for (double x : e) m = std::max(m, std::fabs(x));
    EXPECT_NEAR(m, geometric_bound(a), 1e-6) << a;
  }
}

TEST(HarmonicsBounds, OutsideDomainIsAnError) {
  EXPECT_THROW(geometric_bound(1.0), InputError);
  EXPECT_THROW(geometric_bound_linear(0.5), InputError);
  EXPECT_THROW(taylor_remainder_bound(1.0, 1), InputError);
  EXPECT_NEAR(taylor_remainder_bound(0.5, 0), std::log(2.0), 1e-15);
  EXPECT_NEAR(taylor_remainder_bound(0.95, 2), -std::log(0.05) - 0.95 - 0.95 * 0.95 / 2, 1e-12);
  // Inside the geometric domain but outside the Taylor one: no Taylor bound, a note instead.
  SignalSpec s;
  s.p = 1;
  s.terms = {{3, 0.6, 0, 0.6, 0}};
  const auto a = analyze(s);
  EXPECT_FALSE(a.bound_taylor_first.has_value());
  EXPECT_FALSE(a.bound_taylor_second.has_value());
  ASSERT_FALSE(a.notes.empty());
  EXPECT_NE(a.notes[0].find("convergence domain"), std::string::npos);
  EXPECT_TRUE(a.to_json()["bounds"]["taylor_first_deg"].is_null());
}

// Table 1: each row equals the second-order Taylor amplitude (Eq. 26) exactly and the exact DFT
// within the second-order accuracy 2 R_2 (a DFT amplitude of a remainder |R| <= b is <= 2 b).
TEST(HarmonicsTable1, RowsMatchExactDft) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> mag(0.01, 0.1), u(0, 1);
  auto sgn = [&] { return u(rng) < 0.5 ? -1.0 : 1.0; };
  int checks = 0;
  for (int p : {1, 2, 4}) {
    const auto phi = turn_grid(1024);
    for (MismatchType t : all_mismatch_types()) {
      for (int trial = 0; trial < 12; ++trial) {
        MismatchParams m{sgn() * mag(rng), sgn() * mag(rng), sgn() * mag(rng), sgn() * mag(rng),
                         sgn() * mag(rng)};
        const auto d = mismatch_disturbances(t, m, p);
        const auto h = table1(t, m);
        const auto ex = dft_amplitudes(exact_error(d, p, phi), 4 * p);
        TrigSeries t2 = first_order_series(d, p);
        t2 += second_order_series(d, p);
        const double tol = taylor_remainder_bound(taylor_amplitude_sum(d), 2);
        for (int mult = 0; mult <= 4; ++mult) {
          const int k = mult * p;
          EXPECT_NEAR(h.at_multiple(mult), t2.amplitude(k), 1e-12)
              << to_string(t) << " p=" << p << " H_" << mult << "p";
          EXPECT_NEAR(h.at_multiple(mult), ex[k], (k == 0 ? 1 : 2) * tol)
              << to_string(t) << " p=" << p << " H_" << mult << "p";
          ++checks;
        }
        // No other order below 4p is produced up to second order.
        for (int k = 0; k <= 4 * p; ++k)
          if (k % p != 0) EXPECT_LT(t2.amplitude(k), 1e-15) << to_string(t) << " order " << k;
      }
    }
  }
  EXPECT_EQ(checks, 3 * 7 * 12 * 5);
}

// Second-order accuracy in practice: the Table 1 amplitude differs from the exact DFT by less than
// 5% of the first-order size of the mismatches, cubed (the neglected third-order terms).
TEST(HarmonicsTable1, ThirdOrderAgreement) {
  for (int p : {1, 2, 4})
    for (double s : {0.01, 0.03, 0.1})
      for (MismatchType t : all_mismatch_types()) {
        const MismatchParams m{0.9 * s, -0.7 * s, s, -0.5 * s, 0.8 * s};
        const auto d = mismatch_disturbances(t, m, p);
        const auto ex = dft_amplitudes(exact_error(d, p, turn_grid(1024)), 4 * p);
        const auto h = table1(t, m);
        const double at = taylor_amplitude_sum(d);
        for (int mult = 0; mult <= 4; ++mult)
          EXPECT_LE(std::fabs(h.at_multiple(mult) - ex[mult * p]), 0.5 * at * at * at)
              << to_string(t) << " p=" << p << " s=" << s << " H_" << mult << "p";
      }
}

// The two rows as printed in the paper disagree with the exact result; the corrected ones do not.
TEST(HarmonicsTable1, PrintedRowsThatAreWrong) {
  const int p = 2;
  const MismatchParams m{0.05, 0.03, 0.08, -0.06, 0.07};
  const auto phi = turn_grid(1024);
  {
    const auto d = mismatch_disturbances(MismatchType::OffsetAmplitude, m, p);
    const double ex = dft_amplitudes(exact_error(d, p, phi), 2 * p)[2 * p];
    const double A0 = m.A0, B0 = m.B0, An = m.An, Bn = m.Bn;
    const double printed = std::sqrt(
        B0 * B0 * A0 * A0 +
        std::pow(2 * B0 * B0 + Bn * Bn - 2 * Bn - 2 * A0 * A0 - An * An - 2 * An, 2) / 16);
    const double fixed = table1(MismatchType::OffsetAmplitude, m).H2p;
    EXPECT_GT(std::fabs(printed - ex), 0.3 * ex);
    EXPECT_LT(std::fabs(fixed - ex), 0.01 * ex);
  }
  {
    const auto d = mismatch_disturbances(MismatchType::OffsetAmplitudePhase, m, p);
    const double ex = dft_amplitudes(exact_error(d, p, phi), 0)[0];
    const double printed =
        std::fabs(0.25 * (3 - m.An + m.Bn) * std::sin(m.delta) - 0.125 * std::sin(2 * m.delta));
    const double fixed = table1(MismatchType::OffsetAmplitudePhase, m).H0;
    EXPECT_GT(std::fabs(printed - ex), 0.05 * ex);
    EXPECT_LT(std::fabs(fixed - ex), 0.01 * ex);
  }
}

TEST(HarmonicsTable1, PhaseInverse) {
  for (double d : {0.01, 0.1, 0.5, 1.2})
    EXPECT_NEAR(phase_from_h2p(table1(MismatchType::Phase, {0, 0, 0, 0, d}).H2p), d, 1e-12);
  EXPECT_THROW(phase_from_h2p(10), InputError);
}

// A measured series: on a uniform grid the least-squares spectrum is the DFT; on a non-uniform
// one it recovers a known series.
TEST(HarmonicsSpectrum, UniformEqualsDft) {
  const auto a = analyze(eq33(), 4096);
  std::vector<double> err_deg;
  for (double e : a.exact) err_deg.push_back(e * kDeg);
  const auto s = error_spectrum(a.phi, err_deg, 20);
  for (int k = 0; k <= 20; ++k)
    EXPECT_NEAR(s[k].amplitude_deg, a.harmonics[k].exact * kDeg, 1e-9) << k;
}

TEST(HarmonicsSpectrum, NonUniformRecoversKnownSeries) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 2 * kPi);
  std::normal_distribution<double> noise(0, 0.01);
  std::vector<double> th, e;
  for (int i = 0; i < 5000; ++i) {
    // Two turns, unevenly sampled (denser near the start), with noise.
    const double t = 4 * kPi * std::pow(u(rng) / (2 * kPi), 1.5);
    th.push_back(t);
    e.push_back(0.3 + 1.5 * std::sin(t + 0.2) + 0.4 * std::sin(3 * t - 1.0) +
                0.05 * std::cos(8 * t) + noise(rng));
  }
  const auto s = error_spectrum(th, e, 10);
  EXPECT_NEAR(s[0].cos_deg, 0.3, 0.002);
  EXPECT_NEAR(s[1].amplitude_deg, 1.5, 0.002);
  EXPECT_NEAR(s[1].phase_rad, 0.2, 0.002);
  EXPECT_NEAR(s[3].amplitude_deg, 0.4, 0.002);
  EXPECT_NEAR(s[3].phase_rad, -1.0, 0.01);
  EXPECT_NEAR(s[8].amplitude_deg, 0.05, 0.002);
  EXPECT_LT(s[5].amplitude_deg, 0.002);
  EXPECT_NEAR(spectrum_residual_rms(th, e, s), 0.01, 0.001);
}

TEST(HarmonicsSpectrum, BadInput) {
  EXPECT_THROW(error_spectrum({0, 1, 2}, {0, 1}, 1), InputError);
  EXPECT_THROW(error_spectrum({0, 1, 2}, {0, 1, 2}, 5), InputError);
  EXPECT_THROW(error_spectrum({0, 1, NAN, 3}, {0, 1, 2, 3}, 1), InputError);
  // A tenth of a turn cannot separate 12 orders.
  std::vector<double> th, e;
  for (int i = 0; i < 1000; ++i) th.push_back(0.0006 * i), e.push_back(0);
  EXPECT_THROW(error_spectrum(th, e, 12), InputError);
}

// Mechanical-angle error of a spec at angles theta, degrees (what an `estimate` run reports).
std::vector<double> mechanical_error_deg(const SignalSpec& s, const std::vector<double>& theta) {
  auto e = exact_error(s, theta);
  for (double& x : e) x = x * kDeg / s.p;
  return e;
}

TEST(HarmonicsAttribution, NamesTheCauses) {
  SignalSpec s;
  s.p = 2;
  s.A0 = 0.02;
  s.B0 = 0.015;                       // offset: order p = 2
  s.delta_p = 0.04;                   // phase: order 2p = 4
  s.terms = {{7, 0.01, 0, 0.01, 0}};  // A = B, same phase: only order n - p = 5
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0, 2 * kPi);
  std::vector<double> th;
  for (int i = 0; i < 3000; ++i) th.push_back(u(rng));
  const auto spec = error_spectrum(th, mechanical_error_deg(s, th), 16);
  AttributionOptions opt;
  opt.p = 2;
  const auto at = attribute(spec, opt);
  ASSERT_GE(at.size(), 3u);
  auto find = [&](int k) -> const OrderCauses& {
    for (const auto& o : at)
      if (o.order == k) return o;
    throw std::runtime_error("order not attributed");
  };
  // Order p: the offset, with its magnitude.
  const auto& o2 = find(2);
  EXPECT_EQ(o2.causes.at(0).kind, "offset");
  EXPECT_NEAR(o2.causes[0].parameter, std::hypot(0.02, 0.015), 0.002);
  EXPECT_GT(o2.causes[0].consistency, 0.5);
  // Order 2p: phase or amplitude mismatch (indistinguishable by amplitudes), not the offset.
  const auto& o4 = find(4);
  EXPECT_TRUE(o4.causes.at(0).kind == "phase" || o4.causes[0].kind == "amplitude");
  for (const auto& c : o4.causes)
    if (c.kind == "phase")
      EXPECT_NEAR(c.parameter, 0.04, 0.004);
    else if (c.kind == "offset")
      EXPECT_LT(c.explained, 0.2);
  // Order 5: a signal harmonic n = 7 (= 5 + p) or n = 3 (= 5 - p), explaining all of it.
  const auto& o5 = find(5);
  EXPECT_EQ(o5.causes.at(0).kind, "harmonic");
  EXPECT_EQ(o5.causes[0].signal_order, 7);
  EXPECT_NEAR(o5.causes[0].explained, 1.0, 1e-12);
  EXPECT_NEAR(o5.causes[0].parameter, 0.02, 0.002);
  bool has3 = false;
  for (const auto& c : o5.causes) has3 |= c.kind == "harmonic" && c.signal_order == 3;
  EXPECT_TRUE(has3);
  // Largest first, nothing below the threshold.
  for (size_t i = 1; i < at.size(); ++i) EXPECT_GE(at[i - 1].amplitude_deg, at[i].amplitude_deg);
  for (const auto& o : at) EXPECT_GE(o.amplitude_deg, 0.05 * at[0].amplitude_deg);
  EXPECT_THROW(attribute(spec, AttributionOptions{0}), InputError);
}

void expect_bad(const std::string& json, const std::string& field) {
  try {
    parse_signal_spec(nlohmann::json::parse(json));
    ADD_FAILURE() << "accepted: " << json;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
  }
}

TEST(HarmonicsSpec, BadSpecs) {
  expect_bad(R"({"p": 2, "terms": [{"n": 3, "A": -0.1, "B": 0.1}]})", "terms[0].A");
  expect_bad(R"({"p": 2, "terms": [{"n": 3, "A": 0.1, "B": -0.1}]})", "terms[0].B");
  expect_bad(R"({"p": 2, "terms": [{"n": 3, "A": 0.1}, {"n": 2, "A": 0.01}]})", "terms[1].n");
  expect_bad(R"({"p": 2, "terms": [{"n": 2.5, "A": 0.1}]})", "terms[0].n");
  expect_bad(R"({"p": 2, "terms": [{"n": 0, "A": 0.1}]})", "terms[0].n");
  expect_bad(R"({"p": 0})", "'p'");
  expect_bad(R"({"A0": 0.1})", "'p'");
  expect_bad(R"({"p": 1, "Ap": 0})", "'Ap'");
  expect_bad(R"({"p": 1, "Bp": -1})", "'Bp'");
  expect_bad(R"({"p": 1, "delta_p": 2})", "'delta_p'");
  expect_bad(R"({"p": 1, "A0": "x"})", "'A0'");
  expect_bad(R"({"p": 1, "Apx": 1})", "'Apx'");
  expect_bad(R"({"p": 1, "terms": {}})", "'terms'");
  expect_bad(R"({"p": 1, "A0": 0.7, "B0": 0.8})", "convergence domain");
  expect_bad(R"({"p": 2, "terms": [{"n": 3, "A": 0.6, "B": 0.6}, {"n": 5, "A": 0.2, "B": 0.2}]})",
             "convergence domain");
  // Non-finite values cannot be written in JSON text but can reach the parser from code.
  nlohmann::json j = {{"p", 1}, {"A0", std::nan("")}};
  EXPECT_THROW(parse_signal_spec(j), InputError);
  nlohmann::json k = {{"p", 1}, {"terms", {{{"n", 3}, {"A", 0.1}, {"theta", INFINITY}}}}};
  try {
    parse_signal_spec(k);
    ADD_FAILURE() << "accepted an infinite phase";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("terms[0].theta"), std::string::npos) << e.what();
  }
  // A valid spec with a mismatch is accepted.
  EXPECT_NO_THROW(parse_signal_spec(
      nlohmann::json::parse(R"({"p": 2, "Ap": 1.05, "Bp": 0.95, "delta_p": 0.02})")));
}

}  // namespace
}  // namespace acore
