// SPDX-License-Identifier: MIT
// Magnetic sensing elements and the two layouts of the physics scenarios (docs/diagnosis.md
// "Physics benchmark"): four Hall plates on a ring measuring the axial field (the paper's c1..c4),
// and a two-channel in-plane sensor (TMR/AMR-like) at the axis measuring (Bx, By) as sin, cos.
//
// The lab frame: z is the rotation axis, pointing from the sensor to the magnet; the sensing plane
// is z = 0. Each element measures the field along its own unit direction n at its own position:
//   x = S (1 + kS (T - 25)) (B . n),   out = x + a3 x^3 + O + kO (T - 25)
// (S sensitivity per tesla, a3 a cubic nonlinearity of the element and its amplifier, O offset, kS
// and kO temperature coefficients, T in degC), plus
// white noise of sigma `noise` at the ADC input (the chain's noise, referred there).
//
// Layouts (nominal; the magnetization points at theta + 90 deg, physics_rig.hpp, so that c1 = sin):
//   hall_ring    c1..c4 at azimuths 0, -90, 180, 90 deg (lab, seen from the magnet), i.e. 0, 90,
//                180, 270 deg counter-clockwise in the chip's own top view, which faces the magnet
//                and so mirrors the lab's turning sense; n = +z. c1 ~ sin, c2 ~ cos, c3 ~ -sin,
//                c4 ~ -cos, as docs/contracts.md, recording file.
//   inplane_pair sin along +x, cos along -y, both at the axis: on the axis below a diametric magnet
//                the in-plane field is antiparallel to M.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

namespace acore {

struct SensingElement {
  std::string name;                    // c1..c4, or sin, cos
  Eigen::Vector3d position{0, 0, 0};   // lab frame, m
  Eigen::Vector3d direction{0, 0, 1};  // unit vector: the field component measured
  double sensitivity = 1;              // output units per tesla
  double offset = 0;                   // output units
  double sensitivity_per_C = 0;        // relative change of the sensitivity per degC from 25 degC
  double offset_per_C = 0;             // output units per degC from 25 degC
  double cubic = 0;                    // a3, per output unit squared (negative: soft saturation)
  double noise = 0;                    // white noise sigma at the ADC input, output units
};

struct SensorLayout {
  std::string kind;                      // "hall_ring" or "inplane_pair"
  std::vector<SensingElement> elements;  // 4 (c1..c4) or 2 (sin, cos)
  int channels() const { return static_cast<int>(elements.size()); }
};

// Four Hall plates on a ring of `radius_m`, sensitivity `sensitivity` per tesla.
SensorLayout hall_ring(double radius_m, double sensitivity);
// Two in-plane elements at the axis.
SensorLayout inplane_pair(double sensitivity);

// The element's output for the field B (tesla) at temperature T (degC), noise excluded.
double element_output(const SensingElement& e, const Eigen::Vector3d& b, double temp_C);

}  // namespace acore
