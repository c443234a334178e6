// SPDX-License-Identifier: MIT
// The field of a diametrically magnetized cylinder magnet (physics scenarios, docs/diagnosis.md
// "Physics benchmark"): the equivalent surface-charge model.
//
// A uniformly magnetized body with no free currents has H = -grad(phi), phi the potential of the
// magnetic "charges" rho = -div M (0 inside a uniform magnet) and sigma = M . n on its surface. For
// a cylinder of radius R and height h magnetized across its axis (M along +x), sigma = M cos(phi')
// on the curved surface and 0 on the end faces, so outside the magnet
//
//   B(p) = mu0 H(p) = Br / (4 pi) * integral over phi' in [0, 2pi), z' in [-h/2, h/2] of
//          cos(phi') (p - s) / |p - s|^3  R dphi' dz',       s = (R cos phi', R sin phi', z')
//
// with Br = mu0 M the remanence. The z' integral has a closed form (see field()); the phi' integral
// is periodic and analytic in phi' for every observer off the surface, so the trapezoidal rule on
// `nodes` equally spaced angles converges geometrically (error ~ exp(-nodes * d / R) for an
// observer at distance d from the rim): it is the Gauss rule for periodic integrands. Units:
// metres, tesla.
//
// The magnet frame: axis z, centre at the origin, magnetization along +x. The field is linear in M,
// so the field of the magnet turned by psi about z at p is R(psi) field(R(-psi) p).
#pragma once
#include <Eigen/Core>
#include <vector>

namespace acore {

class DiametricCylinder {
 public:
  // Throws InputError for a non-positive radius, height or node count.
  DiametricCylinder(double radius_m, double height_m, double br_T, int nodes = 96);
  double radius() const { return r_; }
  double height() const { return h_; }
  double remanence() const { return br_; }
  // B at p (magnet frame), M along +x. Throws InputError for a point inside or on the magnet
  // (inside, the charge integral gives H, not B; on the curved surface it is singular).
  Eigen::Vector3d field(const Eigen::Vector3d& p) const;
  // The magnetic moment |m| = M V = Br pi R^2 h / mu0 times mu0: Br * volume (T m^3).
  double moment_T_m3() const;

 private:
  double r_, h_, br_;
  std::vector<double> cos_, sin_;  // the quadrature angles
};

// The field of a point dipole of moment mu0*m = `moment_T_m3` along +x at the origin, at p
// (far-field limit of any magnet of that moment): B = mu0/(4 pi) (3 (m . u) u - m) / |p|^3, u = p /
// |p|.
Eigen::Vector3d dipole_field(double moment_T_m3, const Eigen::Vector3d& p);

// The in-plane field on the axis (p = (0, 0, z), |z| > h/2) in closed form: on the axis every
// surface element is at distance R from it, so the z' integral alone remains:
//   Bx = -(Br / 4) * [u1 / sqrt(R^2 + u1^2) - u2 / sqrt(R^2 + u2^2)],  u1 = z + h/2, u2 = z - h/2
// (By = Bz = 0 by symmetry).
double axial_bx_closed_form(double radius_m, double height_m, double br_T, double z_m);

}  // namespace acore
