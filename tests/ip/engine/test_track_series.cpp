// SPDX-License-Identifier: MIT
// The tracking observer over a whole angle series (model/ip/engine/track_series.cpp), as `anglecore
// estimate` and the Python package run it: against closed forms of a constant-speed angle (the
// velocity in rpm, the turn count, the compensated angle D samples ahead), the finite difference
// of a ramp, the -3 dB span of a moving average (the sinc's half-power point), the settings the
// command's options give and their refusal.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/errors.hpp"
#include "engine/track_series.hpp"

namespace acore {
namespace {

// Electrical angles of a constant mechanical speed (rpm) at fs samples/s, p periods a turn.
std::vector<double> constant_speed(double rpm, double fs, int p, size_t n) {
  std::vector<double> a(n);
  for (size_t i = 0; i < n; ++i) a[i] = std::remainder(2 * M_PI * p * rpm / 60 * i / fs, 2 * M_PI);
  return a;
}

TEST(TrackSeries, SampleRateFromTimes) {
  const std::vector<double> t = {0.5, 0.5 + 1e-5, 0.5 + 2e-5, 0.5 + 3e-5};
  EXPECT_NEAR(sample_rate_of_times(t.data(), t.size()), 1e5, 1e-6);
  EXPECT_EQ(sample_rate_of_times(t.data(), 1), 0);
  const std::vector<double> back = {1, 0};
  EXPECT_EQ(sample_rate_of_times(back.data(), 2), 0);  // not increasing: unknown
  EXPECT_EQ(recording_sample_rate(Recording{}), 0);
}

TEST(TrackSeries, ConstantSpeedVelocityTurnsAndLead) {
  const double fs = 1e5, rpm = 3000;
  const int p = 2;
  const size_t n = 40000;  // 20 mechanical turns, 40 electrical
  const auto a = constant_speed(rpm, fs, p, n);
  TrackSettings s;
  s.lead = 10;
  const TrackedSeries t = track_series(a, fs, p, 16, s);
  ASSERT_TRUE(t.has_rate());
  ASSERT_EQ(t.rpm.size(), n);
  // After the loop has settled (code 6: wn = 0.011 rad/sample) the velocity is the speed within
  // a few velocity LSBs of quantization of the input angle.
  for (size_t i = 5000; i < n; ++i) ASSERT_NEAR(t.rpm[i], rpm, 0.05) << i;
  // The turn count and the angle unwrap the electrical angle: 40 turns over the recording.
  EXPECT_EQ(t.turns.front(), 0);
  EXPECT_NEAR(
      static_cast<double>(t.turns.back()) + std::fmod(a.back() + 2 * M_PI, 2 * M_PI) / (2 * M_PI),
      p * rpm / 60 * (n - 1) / fs, 1e-3);
  // The compensated angle is the angle 10 samples later (one angle LSB is 0.0055 deg).
  for (size_t i = 5000; i + 10 < n; ++i)
    ASSERT_NEAR(std::remainder(t.comp[i] - a[i + 10], 2 * M_PI), 0, 3 * 2 * M_PI / 65536) << i;
  const nlohmann::json j = track_json(t);
  EXPECT_EQ(j["code"], 6);
  EXPECT_EQ(j["lead_samples"], 10.0);
  EXPECT_EQ(j["lot_threshold"], 4096);
  EXPECT_EQ(j["lot_samples"], 0);
  EXPECT_NEAR(j["bandwidth_hz"].get<double>(), track_bandwidth_hz(6, fs), 1e-9);
}

TEST(TrackSeries, VelocityErrorOfTheReferenceItselfIsZero) {
  const double fs = 1e6;
  const int p = 3;
  std::vector<double> theta(20000);
  for (size_t i = 0; i < theta.size(); ++i) theta[i] = 2 * M_PI * 50 * i / fs;  // 3000 rpm
  std::vector<double> electrical(theta.size());
  for (size_t i = 0; i < theta.size(); ++i) electrical[i] = p * theta[i];
  TrackSettings s;
  s.bandwidth_hz = 900;
  const TrackedSeries t = track_series(electrical, fs, p, 16, s);
  EXPECT_EQ(t.regs.bw, 8);  // 905 Hz at 1 MS/s
  for (double e : track_velocity_error_rpm(t, theta, p)) ASSERT_EQ(e, 0);
}

TEST(TrackSeries, LossOfTrackingThreshold) {
  // A jump of 1/8 turn (8192 LSBs) at sample 1000: lost at the default threshold (4096), not at the
  // largest one; a threshold of 0 flags every sample whose prediction error is not exactly 0.
  std::vector<double> a(3000, 0.0);
  for (size_t i = 1000; i < a.size(); ++i) a[i] = M_PI / 4;
  const TrackedSeries def = track_series(a, 0, 1, 16, TrackSettings{});
  EXPECT_EQ(def.lot[999], 0);
  EXPECT_EQ(def.lot[1000], 1);
  EXPECT_FALSE(def.has_rate());
  EXPECT_TRUE(def.rpm.empty());
  TrackSettings wide;
  wide.lot_threshold = 32767;
  const TrackedSeries w = track_series(a, 0, 1, 16, wide);
  for (uint8_t l : w.lot) ASSERT_EQ(l, 0);
  TrackSettings zero;
  zero.lot_threshold = 0;
  const TrackedSeries z = track_series(a, 0, 1, 16, zero);
  EXPECT_EQ(z.lot[500], 0);
  EXPECT_EQ(z.lot[1000], 1);
  EXPECT_EQ(z.lot[1001], 1);
}

TEST(TrackSeries, SettingsRefusedNamingTheOption) {
  const std::vector<double> a(10, 0.0);
  TrackSettings lead;
  lead.lead = 271;
  EXPECT_THROW(track_series(a, 1e5, 1, 16, lead), InputError);
  lead.lead = 270.9375;  // the largest: LATENCY 255 + LEAD 255/16
  EXPECT_EQ(track_json(track_series(a, 1e5, 1, 16, lead))["lead_samples"], 270.9375);
  TrackSettings lot;
  lot.lot_threshold = 32768;
  try {
    track_series(a, 1e5, 1, 16, lot);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--track-lot must be 0..32767"), std::string::npos);
  }
  TrackSettings bw;
  bw.bandwidth_hz = 100;
  try {
    track_series(a, 0, 1, 16, bw);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--track-bandwidth needs the recording's t"),
              std::string::npos);
  }
  bw.bandwidth_hz = 1e9;
  EXPECT_THROW(track_series(a, 1e5, 1, 16, bw), InputError);
}

TEST(TrackSeries, FiniteDifferenceOfARamp) {
  const double fs = 1e6;
  const auto a = constant_speed(3000, fs, 2, 5000);
  const auto v = finite_difference_rpm(a, 251, fs, 2);
  ASSERT_EQ(v.size(), 5000u - 251);
  for (double x : v) ASSERT_NEAR(x, 3000, 1e-6);
  EXPECT_TRUE(finite_difference_rpm(a, 6000, fs, 2).empty());
  EXPECT_THROW(finite_difference_rpm(a, 0, fs, 2), InputError);
}

TEST(TrackSeries, EqualBandwidthSpanIsTheSincHalfPower) {
  // A moving average of L samples is down 3 dB where sin(wL/2) / (L sin(w/2)) = 1/sqrt(2), for
  // large L at w L / 2 = 1.39156 (sin x / x = 1/sqrt(2)): L = 2.78311 / wn.
  for (int k = 4; k <= 12; ++k) {
    const int n = equal_bandwidth_difference_span(k);
    const double want = 2.78311 / track_wn(k);
    EXPECT_NEAR(n + 1, want, 0.01 * want + 1) << "k = " << k;
  }
  // The spans scripts/track_measure.py found for the same codes (docs/reports/track_measure.md).
  EXPECT_EQ(equal_bandwidth_difference_span(6), 251);
  EXPECT_EQ(equal_bandwidth_difference_span(8), 1007);
}

}  // namespace
}  // namespace acore
