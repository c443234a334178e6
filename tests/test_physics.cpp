// SPDX-License-Identifier: MIT
// The magnet + sensor + ADC-chain model of the physics scenarios (model/physics_*.hpp) against
// closed forms and the physics the scenario truths rest on. The field itself is also checked
// against magpylib at 4800 points by the CTest physics_field_vs_magpylib.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "physics/physics_rig.hpp"

namespace acore {
namespace {

constexpr double kDeg = M_PI / 180;

TEST(PhysicsMagnet, OnAxisFieldMatchesTheClosedForm) {
  const DiametricCylinder m(3e-3, 2.5e-3, 1.25);
  for (double z : {-1.3e-3, -2e-3, -3e-3, -6e-3, 2e-3, 9e-3}) {
    const Eigen::Vector3d b = m.field({0, 0, z});
    const double want = axial_bx_closed_form(3e-3, 2.5e-3, 1.25, z);
    EXPECT_NEAR(b.x(), want, 1e-9 * std::fabs(want)) << z;
    EXPECT_NEAR(b.y(), 0, 1e-12);
    EXPECT_NEAR(b.z(), 0, 1e-12);
    EXPECT_LT(b.x(), 0) << "on the axis outside the magnet the field opposes M";
  }
  // Just outside the end face the in-plane field tends to -Br/4 * (1 - h/sqrt(R^2 + h^2)) ... the
  // limit of the closed form at u1 -> 0: -Br/4 * (0 - (-h)/sqrt(R^2 + h^2)).
  const double h = 2.5e-3, r = 3e-3;
  EXPECT_NEAR(m.field({0, 0, -h / 2 - 1e-9}).x(), -1.25 / 4 * h / std::sqrt(r * r + h * h), 1e-6);
}

TEST(PhysicsMagnet, FarFieldIsTheDipoleOfMomentBrTimesVolume) {
  const DiametricCylinder m(3e-3, 2.5e-3, 1.25);
  double previous = 1;
  for (double dist : {30e-3, 60e-3, 120e-3}) {
    double worst = 0;
    for (int k = 0; k < 12; ++k) {
      const double a = 0.3 + k * 0.5, pol = 0.2 + k * 0.23;
      const Eigen::Vector3d p = dist * Eigen::Vector3d(std::sin(pol) * std::cos(a),
                                                       std::sin(pol) * std::sin(a), std::cos(pol));
      const Eigen::Vector3d want = dipole_field(m.moment_T_m3(), p);
      worst = std::max(worst, (m.field(p) - want).norm() / want.norm());
    }
    // The next multipole (octupole) falls off as (size / distance)^2 relative to the dipole.
    EXPECT_LT(worst, 2 * std::pow(3e-3 / dist, 2)) << dist;
    if (dist > 30e-3) EXPECT_NEAR(previous / worst, 4, 0.5) << dist;
    previous = worst;
  }
}

TEST(PhysicsMagnet, AxialFieldBelowFollowsTheCosineOfTheAzimuth) {
  // sigma ~ cos(phi') on the curved surface: Bz(rho, phi) = f(rho, z) cos(phi) exactly.
  const DiametricCylinder m(3e-3, 2.5e-3, 1.25);
  const double rho = 1.1e-3, z = -3e-3;
  const double bz0 = m.field({rho, 0, z}).z();
  for (double a = 0; a < 2 * M_PI; a += 0.37)
    EXPECT_NEAR(m.field({rho * std::cos(a), rho * std::sin(a), z}).z(), bz0 * std::cos(a), 1e-12);
  EXPECT_THROW(m.field({3e-3, 0, 0}), std::exception);  // on the curved surface
}

PhysicsRig nominal(const std::string& kind) {
  PhysicsRig r;
  r.sensor = kind == "hall4" ? hall_ring(1.1e-3, 1.0) : inplane_pair(1.0);
  for (int c = 0; c < r.sensor.channels(); ++c)
    r.sensor.elements[static_cast<size_t>(c)].sensitivity = 1 / rig_amplitude(r, c);
  return r;
}

// The differential pair the estimator sees, as a complex number d24 + i d13 (sin, cos on tmr2).
std::complex<double> pair(const PhysicsRig& r, const DiametricCylinder& m, double th) {
  if (r.sensor.channels() == 2) return {rig_output(r, m, 1, th, 25), rig_output(r, m, 0, th, 25)};
  return {(rig_output(r, m, 1, th, 25) - rig_output(r, m, 3, th, 25)) / 2,
          (rig_output(r, m, 0, th, 25) - rig_output(r, m, 2, th, 25)) / 2};
}

TEST(PhysicsSensor, NominalLayoutsGiveTheDesignChannels) {
  for (const char* kind : {"hall4", "tmr2"}) {
    const PhysicsRig r = nominal(kind);
    const DiametricCylinder m = make_magnet(r.magnet);
    for (double th = 0; th < 2 * M_PI; th += 0.41) {
      EXPECT_NEAR(rig_output(r, m, 0, th, 25), std::sin(th), 1e-9) << kind;
      EXPECT_NEAR(rig_output(r, m, 1, th, 25), std::cos(th), 1e-9) << kind;
      if (r.sensor.channels() == 4) {
        EXPECT_NEAR(rig_output(r, m, 2, th, 25), -std::sin(th), 1e-9);
        EXPECT_NEAR(rig_output(r, m, 3, th, 25), -std::cos(th), 1e-9);
      }
    }
    // The remanence falls by 0.12 %/K: at 75 degC every channel is 6 % smaller.
    EXPECT_NEAR(rig_output(r, m, 0, M_PI / 2, 75), 0.94, 1e-9) << kind;
  }
}

TEST(PhysicsSensor, WhatAUniformStrayFieldLeavesInThePairs) {
  for (const char* kind : {"hall4", "tmr2"}) {
    const PhysicsRig r = nominal(kind);
    const DiametricCylinder m = make_magnet(r.magnet);
    PhysicsRig axial = r, inplane = r;
    axial.stray_T = {0, 0, 5e-3};
    inplane.stray_T = {2e-3, -1e-3, 0};
    for (double th = 0; th < 2 * M_PI; th += 0.5) {
      // Axial: the same Bz on all four plates cancels in c1 - c3; in-plane elements do not see it.
      EXPECT_NEAR(std::abs(pair(axial, m, th) - pair(r, m, th)), 0, 1e-12) << kind;
      const std::complex<double> d = pair(inplane, m, th) - pair(r, m, th);
      if (r.sensor.channels() == 4) {
        EXPECT_NEAR(std::abs(d), 0, 1e-12);  // Hall plates measure Bz only
      } else {
        // A constant offset on sin (along +x) and cos (along -y).
        const double s = r.sensor.elements[0].sensitivity;
        EXPECT_NEAR(d.imag(), s * 2e-3, 1e-12);
        EXPECT_NEAR(d.real(), s * 1e-3, 1e-12);
      }
    }
  }
}

// Angle error atan2 - theta of the pair over a turn.
std::vector<double> angle_errors(const PhysicsRig& r, int n = 72) {
  const DiametricCylinder m = make_magnet(r.magnet);
  std::vector<double> e;
  for (int k = 0; k < n; ++k) {
    const double th = 2 * M_PI * k / n;
    e.push_back(std::remainder(std::arg(pair(r, m, th)) - th, 2 * M_PI));
  }
  return e;
}

TEST(PhysicsSensor, RunoutUnderAnOnAxisInplaneSensorIsAConstantAngleShift) {
  // The sensor sits on the rotation axis: a fixed point of the magnet's frame, so the field it sees
  // turns rigidly with the shaft.
  PhysicsRig r = nominal("tmr2");
  r.runout_m = 0.5e-3;
  r.runout_angle_rad = 45 * kDeg;
  const auto e = angle_errors(r);
  for (double x : e) EXPECT_NEAR(x, e[0], 1e-9);
  EXPECT_GT(std::fabs(e[0]), 0.1 * kDeg);
  const DiametricCylinder m = make_magnet(r.magnet);
  for (double th : {0.1, 1.7, 3.9})
    EXPECT_NEAR(std::abs(pair(r, m, th)), std::abs(pair(r, m, 0)), 1e-9);
}

TEST(PhysicsSensor, PackageShiftAlongAnAxisChangesOnlyThePairAmplitudes) {
  for (const char* kind : {"hall4", "tmr2"}) {
    PhysicsRig r = nominal(kind);
    r.sensor_shift_m = {0.5e-3, 0, 0};
    const DiametricCylinder m = make_magnet(r.magnet);
    // Each pair stays a pure sine (or cosine) of theta: zero where the nominal is zero.
    EXPECT_NEAR(pair(r, m, 0).imag(), 0, 1e-12) << kind;
    EXPECT_NEAR(pair(r, m, M_PI / 2).real(), 0, 1e-12) << kind;
    const double a13 = pair(r, m, M_PI / 2).imag(), a24 = pair(r, m, 0).real();
    EXPECT_GT(std::fabs(a13 / a24 - 1), 1e-4) << kind;
  }
}

TEST(PhysicsSensor, APlateMovedOnTheRingShiftsItsPairsPhaseByHalf) {
  PhysicsRig r = nominal("hall4");
  const double d = 4 * kDeg;
  auto& p = r.sensor.elements[0].position;
  p = {p.x() * std::cos(d) - p.y() * std::sin(d), p.x() * std::sin(d) + p.y() * std::cos(d), 0};
  const DiametricCylinder m = make_magnet(r.magnet);
  // c1 now reads sin(theta - d): c1 - c3 = 2 cos(d/2) sin(theta - d/2).
  for (double th = 0; th < 2 * M_PI; th += 0.3)
    EXPECT_NEAR(pair(r, m, th).imag(), std::cos(d / 2) * std::sin(th - d / 2), 1e-9);
}

TEST(PhysicsSensor, ACubicNonlinearityIsAThirdHarmonicSeenFromEveryPosition) {
  // x - a x^3 with x = sin t: (1 - 3a/4) sin t + (a/4) sin 3t, on every element alike.
  for (const char* kind : {"hall4", "tmr2"}) {
    PhysicsRig r = nominal(kind);
    for (auto& e : r.sensor.elements) e.cubic = -0.04;
    const DiametricCylinder m = make_magnet(r.magnet);
    for (double th = 0; th < 2 * M_PI; th += 0.37) {
      EXPECT_NEAR(rig_output(r, m, 0, th, 25), 0.97 * std::sin(th) + 0.01 * std::sin(3 * th), 1e-9);
      EXPECT_NEAR(rig_output(r, m, 1, th, 25), 0.97 * std::cos(th) - 0.01 * std::cos(3 * th), 1e-9);
    }
  }
}

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

TEST(PhysicsRecording, ChannelsReferenceTemperatureAndMultiplexer) {
  PhysicsRig r = nominal("hall4");
  r.encoder_zero_rad = 30 * kDeg;
  r.mux_order = {3, 1, 0, 2};
  r.mux_slot_s = 1e-4;
  Trajectory t;
  t.kind = "constant";
  t.speed_rps = 5;
  t.sample_rate_hz = 10000;
  const Recording rec = simulate_physics(r, t, Temperature{true, 20, 60}, 500, 1);
  ASSERT_EQ(rec.channels, 4);
  ASSERT_EQ(rec.size(), 500u);
  EXPECT_DOUBLE_EQ(rec.temp.front(), 20);
  EXPECT_DOUBLE_EQ(rec.temp.back(), 60);
  const TrajectoryModel tm(t, 500);
  const DiametricCylinder m = make_magnet(r.magnet);
  for (size_t k : {0u, 17u, 499u}) {
    EXPECT_NEAR(rec.theta_ref[k], tm.theta_at(rec.t[k]) - 30 * kDeg, 1e-12);
    // c1 is converted in slot 3: it sees the shaft 0.3 ms after the frame start.
    EXPECT_NEAR(rec.ch[0][k], rig_output(r, m, 0, tm.theta_at(rec.t[k] + 3e-4), rec.temp[k]),
                1e-12);
  }
  EXPECT_EQ(rec.meta.at("sensor"), "hall_ring");
}

}  // namespace
}  // namespace acore
