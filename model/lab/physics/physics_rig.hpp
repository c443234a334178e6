// SPDX-License-Identifier: MIT
// A magnet on a shaft end over an angle sensor, and the recording it makes (physics scenarios,
// docs/diagnosis.md "Physics benchmark"): the field of physics_magnet.hpp seen by the elements of
// physics_sensor.hpp through the chain of physics_signal_chain.hpp, on a TrajectoryModel
// (simulator.hpp) with a temperature ramp, written as a docs/contracts.md, recording file
// recording.
//
// Geometry (lab frame of physics_sensor.hpp: z = rotation axis, sensing plane z = 0):
//   the magnet's bottom face is `air_gap_m` above the sensing plane; its centre, in the shaft frame
//   (turning with the shaft angle theta), sits `runout_m` off the rotation axis at the shaft-frame
//   angle `runout_angle_rad` (dynamic eccentricity: it turns with the shaft); its magnetization
//   points at theta + magnetization_rad (90 deg nominal, so that c1 ~ sin theta);
//   the sensor package is displaced by `sensor_shift_m` (static eccentricity);
//   a uniform stray field `stray_T` adds to the magnet's;
//   the remanence follows Br(T) = Br (1 + br_per_C (T - 25)) (NdFeB about -0.12 %/K).
// Per sample k (frame start t_k = k / fs): channel c is sampled at t_k + delay_c (multiplexer), its
// element sees the field at the shaft angle of that instant, then its RC filter, noise and the ADC.
// theta_ref is the reference encoder at t_k: theta(t_k) - encoder_zero_rad (a reference whose zero
// differs from the magnet's by a constant angle).
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/recording.hpp"
#include "physics/physics_magnet.hpp"
#include "physics/physics_sensor.hpp"
#include "physics/physics_signal_chain.hpp"
#include "sim/simulator.hpp"

namespace acore {

struct MagnetSpec {
  double radius_m = 3e-3;  // a 6 mm x 2.5 mm disc, the usual size for on-axis angle sensors
  double height_m = 2.5e-3;
  double br_T = 1.25;         // sintered NdFeB (N38-class)
  double br_per_C = -0.0012;  // reversible temperature coefficient of Br, per degC
  int nodes = 96;             // quadrature angles (physics_magnet.hpp)
};

struct PhysicsRig {
  MagnetSpec magnet;
  double air_gap_m = 1.5e-3;
  double runout_m = 0, runout_angle_rad = 0;
  double magnetization_rad = 1.5707963267948966;
  Eigen::Vector3d sensor_shift_m{0, 0, 0};
  Eigen::Vector3d stray_T{0, 0, 0};
  SensorLayout sensor;
  std::vector<double> rc_tau_s;  // per channel (empty: no filter)
  Adc adc;                       // bits = 0: ideal
  std::vector<int> mux_order;    // conversion slot per channel (empty: all at once)
  double mux_slot_s = 0;
  double encoder_zero_rad = 0;
};

// The field (tesla, lab frame) at lab point p for shaft angle theta at temperature T, stray
// included. `magnet` must be built from rig.magnet (make_magnet).
DiametricCylinder make_magnet(const MagnetSpec& m);
Eigen::Vector3d rig_field(const PhysicsRig& rig, const DiametricCylinder& magnet,
                          const Eigen::Vector3d& p, double theta, double temp_C);
// Element c's clean output (no chain, no noise) at shaft angle theta and temperature T.
double rig_output(const PhysicsRig& rig, const DiametricCylinder& magnet, int c, double theta,
                  double temp_C);
// The amplitude of element c's clean output over a turn at 25 degC, stray field excluded: sets
// sensitivities so that the nominal channels swing +-1.
double rig_amplitude(const PhysicsRig& rig, int c);

// A recording of `samples` samples: columns t, theta_ref, c1..c4 or sin, cos, and temp when
// temperature.enabled (else the rig sits at start_C). Noise seeded by `seed`. Metadata: scenario
// (=physics), seed, p (=1), channels, samples, sensor.
Recording simulate_physics(const PhysicsRig& rig, const Trajectory& traj,
                           const Temperature& temperature, size_t samples, uint64_t seed);

}  // namespace acore
