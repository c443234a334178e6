// SPDX-License-Identifier: MIT
#include "physics/physics_sensor.hpp"

#include <cmath>

#include "core/angle.hpp"

namespace acore {

namespace {}

SensorLayout hall_ring(double radius_m, double sensitivity) {
  SensorLayout s;
  s.kind = "hall_ring";
  const double azimuth_deg[4] = {0, -90, 180, 90};
  for (int c = 0; c < 4; ++c) {
    SensingElement e;
    e.name = "c" + std::to_string(c + 1);
    const double a = azimuth_deg[c] * kPi / 180;
    e.position = {radius_m * std::cos(a), radius_m * std::sin(a), 0};
    e.direction = {0, 0, 1};
    e.sensitivity = sensitivity;
    s.elements.push_back(e);
  }
  return s;
}

SensorLayout inplane_pair(double sensitivity) {
  SensorLayout s;
  s.kind = "inplane_pair";
  SensingElement sn, cs;
  sn.name = "sin";
  sn.direction = {1, 0, 0};
  cs.name = "cos";
  cs.direction = {0, -1, 0};
  sn.sensitivity = cs.sensitivity = sensitivity;
  s.elements = {sn, cs};
  return s;
}

double element_output(const SensingElement& e, const Eigen::Vector3d& b, double temp_C) {
  const double dt = temp_C - 25;
  const double x = e.sensitivity * (1 + e.sensitivity_per_C * dt) * b.dot(e.direction);
  return x + e.cubic * x * x * x + e.offset + e.offset_per_C * dt;
}

}  // namespace acore
