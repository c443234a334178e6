// SPDX-License-Identifier: MIT
// The sensing elements and layouts (physics/physics_sensor.*) against their closed forms: an
// element reads only the field along its direction, linearly without a cubic term and oddly with
// one, its sensitivity and offset drift linearly from 25 degC; the Hall ring's plates sit at
// azimuths 0, -90, 180, 90 deg on its radius (opposite plates antipodal), the in-plane pair at the
// axis along +x and -y. (How the layouts see the magnet, through the rig, is in
// test_physics_rig.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "physics/physics_sensor.hpp"

namespace acore {
namespace {

TEST(PhysicsSensor, ElementReadsTheFieldAlongItsDirectionOnly) {
  SensingElement e;
  e.direction = Eigen::Vector3d(1, 2, 2) / 3;  // a unit vector
  e.sensitivity = 40;
  e.offset = 0.3;
  std::mt19937_64 rng(111);
  std::normal_distribution<double> g(0, 0.02);
  for (int k = 0; k < 1000; ++k) {
    const Eigen::Vector3d b1(g(rng), g(rng), g(rng)), b2(g(rng), g(rng), g(rng));
    // Linear: superposition of the field parts (the offset counted once).
    EXPECT_NEAR(element_output(e, b1 + b2, 25) - e.offset,
                (element_output(e, b1, 25) - e.offset) + (element_output(e, b2, 25) - e.offset),
                1e-12);
    // Blind across its direction: a field perpendicular to n gives the offset alone.
    const Eigen::Vector3d perp = b1 - b1.dot(e.direction) * e.direction;
    EXPECT_NEAR(element_output(e, perp, 25), e.offset, 1e-12);
    EXPECT_NEAR(element_output(e, b1, 25), e.offset + 40 * b1.dot(e.direction), 1e-12);
  }
}

TEST(PhysicsSensor, CubicIsOddAndDriftIsLinearInTemperature) {
  SensingElement e;
  e.direction = {0, 0, 1};
  e.sensitivity = 10;
  e.cubic = -0.04;
  e.offset = 0.05;
  e.sensitivity_per_C = -0.001;
  e.offset_per_C = 2e-4;
  for (double bz : {0.01, 0.05, 0.1})
    for (double t : {-40.0, 25.0, 125.0}) {
      const double dt = t - 25, o = 0.05 + 2e-4 * dt;
      const double x = 10 * (1 - 0.001 * dt) * bz;
      const double up = element_output(e, {0, 0, bz}, t), down = element_output(e, {0, 0, -bz}, t);
      EXPECT_NEAR(up - o, -(down - o), 1e-14) << bz << " " << t;  // odd about the offset
      EXPECT_NEAR(up, x - 0.04 * x * x * x + o, 1e-14);
    }
  // At zero field only the offset and its drift remain.
  EXPECT_NEAR(element_output(e, {0, 0, 0}, 75), 0.05 + 2e-4 * 50, 1e-15);
}

TEST(PhysicsSensor, LayoutsPlaceAndOrientTheirElements) {
  const double r = 1.1e-3;
  const SensorLayout ring = hall_ring(r, 3.0);
  ASSERT_EQ(ring.channels(), 4);
  EXPECT_EQ(ring.kind, "hall_ring");
  const double az[4] = {0, -90, 180, 90};
  for (int c = 0; c < 4; ++c) {
    const SensingElement& e = ring.elements[static_cast<size_t>(c)];
    EXPECT_EQ(e.name, "c" + std::to_string(c + 1));
    const double a = az[c] * M_PI / 180;
    EXPECT_NEAR(e.position.x(), r * std::cos(a), 1e-18);
    EXPECT_NEAR(e.position.y(), r * std::sin(a), 1e-18);
    EXPECT_EQ(e.position.z(), 0.0);
    EXPECT_EQ(e.direction, Eigen::Vector3d(0, 0, 1));
    EXPECT_EQ(e.sensitivity, 3.0);
  }
  // Opposite plates are antipodal: c1 - c3 and c2 - c4 cancel any field even in the position.
  EXPECT_LT((ring.elements[0].position + ring.elements[2].position).norm(), 1e-18);
  EXPECT_LT((ring.elements[1].position + ring.elements[3].position).norm(), 1e-18);
  const SensorLayout pair = inplane_pair(2.0);
  ASSERT_EQ(pair.channels(), 2);
  EXPECT_EQ(pair.kind, "inplane_pair");
  EXPECT_EQ(pair.elements[0].name, "sin");
  EXPECT_EQ(pair.elements[1].name, "cos");
  EXPECT_EQ(pair.elements[0].direction, Eigen::Vector3d(1, 0, 0));
  EXPECT_EQ(pair.elements[1].direction, Eigen::Vector3d(0, -1, 0));
  for (const auto& e : pair.elements) {
    EXPECT_EQ(e.position, Eigen::Vector3d::Zero());
    EXPECT_EQ(e.sensitivity, 2.0);
  }
}

}  // namespace
}  // namespace acore
