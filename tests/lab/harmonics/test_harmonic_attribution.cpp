// SPDX-License-Identifier: MIT
// Attribution of angle-error orders (harmonics/harmonic_attribution.*) on spectra written here
// order by order, so every figure has a closed form: the candidates of each order (signal
// harmonics n = k +- p, the mismatches of Table 1 at p, 2p, 4p and 0), their parameters (offset r =
// H_p, amplitude |An - Bn| = 2 H_2p, a harmonic's A_n + B_n = 2 H_k), the explained share and the
// consistency of the other fingerprints, the ranking rules, the mechanical-to-electrical factor p,
// the thresholds. The end-to-end case (a spectrum measured from signals) is in test_harmonics.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "harmonics/harmonic_attribution.hpp"
#include "harmonics/harmonic_mismatch.hpp"

namespace acore {
namespace {

constexpr double kDeg = 180.0 / M_PI;

// A spectrum of orders 0..max with the given amplitudes (deg), phases irrelevant here.
std::vector<OrderAmplitude> spectrum(const std::vector<double>& amp_deg) {
  std::vector<OrderAmplitude> s;
  for (size_t k = 0; k < amp_deg.size(); ++k)
    s.push_back({static_cast<int>(k), amp_deg[k], 0.0, 0.0, amp_deg[k]});
  return s;
}

const Cause* find(const OrderCauses& o, const std::string& kind, int signal_order = -1) {
  for (const Cause& c : o.causes)
    if (c.kind == kind && (signal_order < 0 || c.signal_order == signal_order)) return &c;
  return nullptr;
}

TEST(HarmonicAttribution, AnOffsetWithItsSecondOrderFingerprintRanksFirst) {
  AttributionOptions opt;
  opt.p = 2;
  opt.mechanical = false;  // electrical amplitudes: no factor p
  const double h = 0.02;   // rad
  // Order p = 2 alone: the offset explains it but misses its H_2p = h^2 / 2 at order 4, so the
  // harmonic n = 2p = 4 (which predicts nothing else) ranks first.
  std::vector<double> amp(9, 0.0);
  amp[2] = h * kDeg;
  auto at = attribute(spectrum(amp), opt);
  ASSERT_EQ(at.size(), 1u);
  EXPECT_EQ(at[0].order, 2);
  ASSERT_EQ(at[0].causes.size(), 2u);  // n = |k - p| = 0 is no harmonic
  EXPECT_EQ(at[0].causes[0].kind, "harmonic");
  EXPECT_EQ(at[0].causes[0].signal_order, 4);
  EXPECT_NEAR(at[0].causes[0].parameter, 2 * h, 1e-15);
  const Cause* off = find(at[0], "offset");
  ASSERT_NE(off, nullptr);
  EXPECT_NEAR(off->parameter, h, 1e-15);
  EXPECT_NEAR(off->explained, 1.0, 1e-12);
  EXPECT_EQ(off->consistency, 0.0);
  // With H_2p = h^2 / 2 present at order 4 the offset is consistent and, a mismatch, ranks first.
  amp[4] = h * h / 2 * kDeg;
  opt.relative_threshold = 0;
  at = attribute(spectrum(amp), opt);
  ASSERT_EQ(at[0].order, 2);
  EXPECT_EQ(at[0].causes[0].kind, "offset");
  EXPECT_NEAR(at[0].causes[0].consistency, 1.0, 1e-12);
  EXPECT_EQ(at[0].causes[0].taylor_order, 1);
}

TEST(HarmonicAttribution, SecondHarmonicOfTheElectricalPeriodNamesAmplitudeAndPhase) {
  AttributionOptions opt;
  opt.p = 1;
  opt.mechanical = false;
  opt.relative_threshold = 0;
  const double h = 0.01;
  std::vector<double> amp(6, 0.0);
  amp[2] = h * kDeg;
  const auto at = attribute(spectrum(amp), opt);
  ASSERT_EQ(at.size(), 1u);
  const OrderCauses& o = at[0];
  const Cause* a = find(o, "amplitude");
  ASSERT_NE(a, nullptr);
  EXPECT_NEAR(a->parameter, 2 * h, 1e-15);  // |An - Bn|
  EXPECT_NEAR(a->predicted_deg, table1(MismatchType::Amplitude, {0, 0, h, -h, 0}).H2p * kDeg,
              1e-12);
  const Cause* ph = find(o, "phase");
  ASSERT_NE(ph, nullptr);
  EXPECT_NEAR(table1(MismatchType::Phase, {0, 0, 0, 0, ph->parameter}).H2p, h, 1e-14);
  EXPECT_NEAR(ph->explained, 1.0, 1e-9);
  // No offset seen at order p: its second-order term explains nothing.
  const Cause* off = find(o, "offset");
  ASSERT_NE(off, nullptr);
  EXPECT_EQ(off->parameter, 0.0);
  EXPECT_EQ(off->explained, 0.0);
  EXPECT_EQ(off->taylor_order, 2);
  // Harmonics n = k + p = 3 and n = |k - p| = 1 = p (the main one: skipped).
  EXPECT_NE(find(o, "harmonic", 3), nullptr);
  EXPECT_EQ(find(o, "harmonic", 1), nullptr);
  // Best first: explained, then consistent, then mismatch before harmonic.
  for (size_t i = 1; i < o.causes.size(); ++i)
    EXPECT_GE(o.causes[i - 1].explained + 1e-9, o.causes[i].explained);
}

TEST(HarmonicAttribution, MechanicalSpectraAreScaledByPToElectrical) {
  // A mechanical order-5 error of 0.1 deg with p = 2 is 0.2 deg electrical: harmonics n = 7, 3
  // with A_n + B_n = 2 * 0.2 deg in rad; predictions reported back in mechanical degrees.
  AttributionOptions opt;
  opt.p = 2;
  std::vector<double> amp(8, 0.0);
  amp[5] = 0.1;
  const auto at = attribute(spectrum(amp), opt);
  ASSERT_EQ(at.size(), 1u);
  const Cause* n7 = find(at[0], "harmonic", 7);
  const Cause* n3 = find(at[0], "harmonic", 3);
  ASSERT_NE(n7, nullptr);
  ASSERT_NE(n3, nullptr);
  EXPECT_NEAR(n7->parameter, 2 * 0.2 / kDeg, 1e-15);
  EXPECT_NEAR(n7->predicted_deg, 0.1, 1e-15);
  EXPECT_EQ(n7->explained, 1.0);
}

TEST(HarmonicAttribution, ThresholdsDcAndOrder) {
  AttributionOptions opt;
  opt.p = 1;
  // Orders 1..5 at 1, 0.5, 0.04, 0.2, 0.06 deg and a DC of 3 deg.
  const std::vector<double> amp = {3.0, 1.0, 0.5, 0.04, 0.2, 0.06};
  auto at = attribute(spectrum(amp), opt);
  // 5 % of the largest non-DC order (1 deg): 0.04 is out, 0.06 in; DC excluded by default.
  std::vector<int> orders;
  for (const auto& o : at) orders.push_back(o.order);
  EXPECT_EQ(orders, (std::vector<int>{1, 2, 4, 5}));  // largest first
  opt.min_amplitude_deg = 0.3;
  at = attribute(spectrum(amp), opt);
  EXPECT_EQ(at.size(), 2u);
  // With DC: order 0 first (3 deg), its cause a phase mismatch whose H_0 is the DC.
  opt.min_amplitude_deg = 0;
  opt.include_dc = true;
  opt.mechanical = false;
  std::vector<double> small = amp;
  small[0] = 0.5;  // rad must stay within the phase row's range
  at = attribute(spectrum(small), opt);
  const OrderCauses* dc = nullptr;
  for (const auto& o : at)
    if (o.order == 0) dc = &o;
  ASSERT_NE(dc, nullptr);
  const Cause* ph = find(*dc, "phase");
  ASSERT_NE(ph, nullptr);
  EXPECT_NEAR(table1(MismatchType::Phase, {0, 0, 0, 0, ph->parameter}).H0, 0.5 / kDeg, 1e-12);
  // Bad input.
  EXPECT_THROW(attribute(spectrum(amp), AttributionOptions{0}), InputError);
  std::vector<OrderAmplitude> gap = spectrum(amp);
  gap.erase(gap.begin() + 2);
  EXPECT_THROW(attribute(gap, AttributionOptions{}), InputError);
}

}  // namespace
}  // namespace acore
