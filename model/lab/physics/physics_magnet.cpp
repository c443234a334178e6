// SPDX-License-Identifier: MIT
#include "physics/physics_magnet.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/angle.hpp"
#include "core/errors.hpp"

namespace acore {

namespace {

// [F(u1) - F(u2)] / rho^2 with F(u) = u / sqrt(rho^2 + u^2), s = sqrt(rho^2 + u^2). When u1 and
// u2 have one sign (the observer above or below the magnet), 1 - |u| / s = rho^2 / (s (s + |u|))
// removes the cancellation that the direct form suffers as rho -> 0.
double z_integral_a(double rho2, double u1, double s1, double u2, double s2) {
  if (u1 * u2 >= 0) {
    const double sign = u1 + u2 >= 0 ? 1.0 : -1.0;
    return sign * (1.0 / (s2 * (s2 + std::fabs(u2))) - 1.0 / (s1 * (s1 + std::fabs(u1))));
  }
  return (u1 / s1 - u2 / s2) / rho2;
}

}  // namespace

DiametricCylinder::DiametricCylinder(double radius_m, double height_m, double br_T, int nodes)
    : r_(radius_m), h_(height_m), br_(br_T) {
  if (!(radius_m > 0) || !(height_m > 0) || nodes < 8)
    throw InputError(
        fmt::format("magnet: radius {} m, height {} m and nodes {} must be > 0 (nodes >= 8)",
                    radius_m, height_m, nodes));
  cos_.resize(static_cast<size_t>(nodes));
  sin_.resize(static_cast<size_t>(nodes));
  for (int j = 0; j < nodes; ++j) {
    const double a = 2 * kPi * (j + 0.5) / nodes;
    cos_[static_cast<size_t>(j)] = std::cos(a);
    sin_[static_cast<size_t>(j)] = std::sin(a);
  }
}

double DiametricCylinder::moment_T_m3() const { return br_ * kPi * r_ * r_ * h_; }

Eigen::Vector3d DiametricCylinder::field(const Eigen::Vector3d& p) const {
  if (std::hypot(p.x(), p.y()) <= r_ * (1 + 1e-9) && std::fabs(p.z()) <= h_ / 2 * (1 + 1e-9))
    throw InputError(fmt::format("magnet: the point ({}, {}, {}) m is not outside the magnet",
                                 p.x(), p.y(), p.z()));
  const double u1 = p.z() + h_ / 2, u2 = p.z() - h_ / 2;
  const double u1s = u1 * u1, u2s = u2 * u2;
  double bx = 0, by = 0, bz = 0;
  for (size_t j = 0; j < cos_.size(); ++j) {
    const double dx = p.x() - r_ * cos_[j], dy = p.y() - r_ * sin_[j];
    const double rho2 = dx * dx + dy * dy;
    const double s1 = std::sqrt(rho2 + u1s), s2 = std::sqrt(rho2 + u2s);
    // Integrals over z' of 1 / |p - s|^3 and (p_z - z') / |p - s|^3.
    const double ia = z_integral_a(rho2, u1, s1, u2, s2);
    const double ib = 1.0 / s2 - 1.0 / s1;
    const double w = cos_[j];  // sigma / M at this angle
    bx += w * dx * ia;
    by += w * dy * ia;
    bz += w * ib;
  }
  const double k = br_ / (4 * kPi) * r_ * (2 * kPi / static_cast<double>(cos_.size()));
  return {k * bx, k * by, k * bz};
}

Eigen::Vector3d dipole_field(double moment_T_m3, const Eigen::Vector3d& p) {
  const double r = p.norm();
  const Eigen::Vector3d u = p / r;
  const Eigen::Vector3d m(moment_T_m3, 0, 0);
  return (3 * m.dot(u) * u - m) / (4 * kPi * r * r * r);
}

double axial_bx_closed_form(double radius_m, double height_m, double br_T, double z_m) {
  const double u1 = z_m + height_m / 2, u2 = z_m - height_m / 2, r2 = radius_m * radius_m;
  return -br_T / 4 * (u1 / std::sqrt(r2 + u1 * u1) - u2 / std::sqrt(r2 + u2 * u2));
}

}  // namespace acore
