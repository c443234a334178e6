// SPDX-License-Identifier: MIT
#include "physics/physics_rig.hpp"

#include <fmt/format.h>

#include <cmath>
#include <random>

#include "core/errors.hpp"

namespace acore {

namespace {

Eigen::Vector3d rotate_z(const Eigen::Vector3d& v, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y(), v.z()};
}

}  // namespace

DiametricCylinder make_magnet(const MagnetSpec& m) {
  return DiametricCylinder(m.radius_m, m.height_m, m.br_T, m.nodes);
}

Eigen::Vector3d rig_field(const PhysicsRig& rig, const DiametricCylinder& magnet,
                          const Eigen::Vector3d& p, double theta, double temp_C) {
  // The magnet's centre turns with the shaft; its frame is turned by psi from the lab's.
  const Eigen::Vector3d centre = rotate_z({rig.runout_m * std::cos(rig.runout_angle_rad),
                                           rig.runout_m * std::sin(rig.runout_angle_rad), 0},
                                          theta) +
                                 Eigen::Vector3d(0, 0, rig.air_gap_m + magnet.height() / 2);
  const double psi = theta + rig.magnetization_rad;
  const Eigen::Vector3d b = rotate_z(magnet.field(rotate_z(p - centre, -psi)), psi);
  const double remanence = 1 + rig.magnet.br_per_C * (temp_C - 25);
  return remanence * b + rig.stray_T;
}

double rig_output(const PhysicsRig& rig, const DiametricCylinder& magnet, int c, double theta,
                  double temp_C) {
  const SensingElement& e = rig.sensor.elements[static_cast<size_t>(c)];
  return element_output(e, rig_field(rig, magnet, e.position + rig.sensor_shift_m, theta, temp_C),
                        temp_C);
}

double rig_amplitude(const PhysicsRig& rig, int c) {
  PhysicsRig r = rig;
  r.stray_T.setZero();
  const DiametricCylinder magnet = make_magnet(r.magnet);
  // The first Fourier coefficient of the output over a turn (exact for a linear field map).
  constexpr int kN = 64;
  double a = 0, b = 0;
  for (int k = 0; k < kN; ++k) {
    const double th = 2 * M_PI * k / kN;
    const double v = rig_output(r, magnet, c, th, 25);
    a += v * std::cos(th);
    b += v * std::sin(th);
  }
  return 2.0 / kN * std::hypot(a, b);
}

Recording simulate_physics(const PhysicsRig& rig, const Trajectory& traj,
                           const Temperature& temperature, size_t samples, uint64_t seed) {
  const int nch = rig.sensor.channels();
  if (nch != 2 && nch != 4) throw InputError("physics rig: the sensor needs 2 or 4 elements");
  if (!rig.rc_tau_s.empty() && static_cast<int>(rig.rc_tau_s.size()) != nch)
    throw InputError("physics rig: one RC time constant per channel");
  if (!rig.mux_order.empty() && static_cast<int>(rig.mux_order.size()) != nch)
    throw InputError("physics rig: one multiplexer slot per channel");
  const TrajectoryModel tm(traj, samples);
  const DiametricCylinder magnet = make_magnet(rig.magnet);
  const double h = 1.0 / tm.sample_rate();
  const std::vector<double> delay = rig.mux_order.empty()
                                        ? std::vector<double>(static_cast<size_t>(nch), 0.0)
                                        : multiplex_delays(rig.mux_order, rig.mux_slot_s);
  std::vector<RcFilter> rc;
  for (int c = 0; c < nch; ++c)
    rc.emplace_back(rig.rc_tau_s.empty() ? 0.0 : rig.rc_tau_s[static_cast<size_t>(c)], h);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);

  Recording rec;
  rec.channels = nch;
  rec.t.resize(samples);
  rec.theta_ref.resize(samples);
  for (int c = 0; c < nch; ++c) rec.ch[static_cast<size_t>(c)].resize(samples);
  if (temperature.enabled) rec.temp.resize(samples);
  const double span = samples > 1 ? static_cast<double>(samples - 1) : 1.0;
  for (size_t k = 0; k < samples; ++k) {
    const double tk = tm.time(k);
    const double temp = temperature.start_C +
                        (temperature.end_C - temperature.start_C) * static_cast<double>(k) / span;
    rec.t[k] = tk;
    rec.theta_ref[k] = tm.theta_at(tk) - rig.encoder_zero_rad;
    if (temperature.enabled) rec.temp[k] = temp;
    for (int c = 0; c < nch; ++c) {
      const size_t ci = static_cast<size_t>(c);
      const double x = rig_output(rig, magnet, c, tm.theta_at(tk + delay[ci]), temp);
      const double y = rc[ci].step(x) + rig.sensor.elements[ci].noise * gauss(rng);
      rec.ch[ci][k] = rig.adc.convert(y);
    }
  }
  rec.meta["scenario"] = "physics";
  rec.meta["seed"] = std::to_string(seed);
  rec.meta["p"] = "1";
  rec.meta["channels"] = std::to_string(nch);
  rec.meta["samples"] = std::to_string(samples);
  rec.meta["sensor"] = rig.sensor.kind;
  return rec;
}

}  // namespace acore
