// SPDX-License-Identifier: MIT
// The physics rig (physics/physics_rig.*): magnet on a shaft over a sensor layout, through the
// analog chain, against closed forms and the physics the scenario truths rest on (the layouts'
// design channels, what stray fields, run-out and package shifts leave in the pairs), the rig's
// covariance under a turn of the whole set-up, the remanence's temperature law, and the recording
// it writes (reference, temperature ramp, multiplexer, noise, ADC).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>

#include "core/errors.hpp"
#include "physics/physics_rig.hpp"

namespace acore {
namespace {

constexpr double kDeg = M_PI / 180;

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

Eigen::Vector3d turned(const Eigen::Vector3d& v, double a) {
  return {std::cos(a) * v.x() - std::sin(a) * v.y(), std::sin(a) * v.x() + std::cos(a) * v.y(),
          v.z()};
}

TEST(PhysicsRig, TurningShaftAndObserverTogetherTurnsTheField) {
  // Magnet, run-out and magnetization all turn with the shaft: the field at the point turned by d,
  // for the shaft turned by d, is the field turned by d (no stray field, which does not turn).
  PhysicsRig r = nominal("hall4");
  r.runout_m = 0.2e-3;
  r.runout_angle_rad = 0.7;
  const DiametricCylinder m = make_magnet(r.magnet);
  const Eigen::Vector3d p(0.9e-3, -0.3e-3, 0.1e-3);
  for (double th : {0.0, 1.3, 4.0})
    for (double d : {0.25, -2.0, M_PI}) {
      const Eigen::Vector3d a = turned(rig_field(r, m, p, th, 25), d);
      const Eigen::Vector3d b = rig_field(r, m, turned(p, d), th + d, 25);
      EXPECT_LT((a - b).norm(), 1e-12 * a.norm()) << th << " " << d;
    }
}

TEST(PhysicsRig, RemanenceFollowsTemperatureAndStrayFieldAdds) {
  PhysicsRig r = nominal("tmr2");
  const DiametricCylinder m = make_magnet(r.magnet);
  const Eigen::Vector3d p(0.2e-3, 0.1e-3, 0);
  const Eigen::Vector3d b25 = rig_field(r, m, p, 0.8, 25);
  for (double t : {-40.0, 0.0, 85.0, 150.0}) {
    const double k = 1 + r.magnet.br_per_C * (t - 25);
    EXPECT_LT((rig_field(r, m, p, 0.8, t) - k * b25).norm(), 1e-15 * b25.norm()) << t;
  }
  r.stray_T = {1e-3, -2e-3, 3e-3};
  EXPECT_LT((rig_field(r, m, p, 0.8, 25) - b25 - r.stray_T).norm(), 1e-15);
  // The amplitude that sets the sensitivities ignores the stray field.
  EXPECT_NEAR(rig_amplitude(r, 0), 1.0, 1e-12);
}

TEST(PhysicsRecording, NoiseIsSeededAdcQuantizesAndBadRigsAreRejected) {
  PhysicsRig r = nominal("tmr2");
  for (auto& e : r.sensor.elements) e.noise = 0.01;
  Trajectory t;
  t.kind = "constant";
  t.speed_rps = 1;
  t.sample_rate_hz = 2000;
  const size_t n = 4000;
  const Recording a = simulate_physics(r, t, Temperature{}, n, 5);
  const Recording b = simulate_physics(r, t, Temperature{}, n, 5);
  const Recording c = simulate_physics(r, t, Temperature{}, n, 6);
  EXPECT_EQ(a.ch[0], b.ch[0]);
  EXPECT_NE(a.ch[0], c.ch[0]);
  EXPECT_FALSE(a.has_temp());
  // The noise around the clean output has the element's sigma.
  const DiametricCylinder m = make_magnet(r.magnet);
  double ss = 0;
  for (size_t k = 0; k < n; ++k) {
    const double e = a.ch[1][k] - rig_output(r, m, 1, a.theta_ref[k], 25);
    ss += e * e;
  }
  EXPECT_NEAR(std::sqrt(ss / n), 0.01, 0.0005);
  // A 10-bit ADC over +-2: every value on its lattice.
  r.adc = Adc{10, 2.0, 0.0};
  const Recording q = simulate_physics(r, t, Temperature{}, 500, 5);
  for (double v : q.ch[0]) EXPECT_EQ(v / r.adc.step(), std::nearbyint(v / r.adc.step()));
  EXPECT_EQ(q.meta.at("sensor"), "inplane_pair");
  EXPECT_EQ(q.meta.at("samples"), "500");
  // Bad rigs: 3 elements, a filter or a slot per channel missing.
  PhysicsRig three = r;
  three.sensor.elements.push_back(three.sensor.elements[0]);
  EXPECT_THROW(simulate_physics(three, t, Temperature{}, 10, 1), InputError);
  PhysicsRig rc = r;
  rc.rc_tau_s = {1e-4};
  EXPECT_THROW(simulate_physics(rc, t, Temperature{}, 10, 1), InputError);
  PhysicsRig mux = r;
  mux.mux_order = {0, 1, 2};
  EXPECT_THROW(simulate_physics(mux, t, Temperature{}, 10, 1), InputError);
}

}  // namespace
}  // namespace acore
