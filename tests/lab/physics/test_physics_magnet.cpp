// SPDX-License-Identifier: MIT
// The diametric cylinder magnet (physics/physics_magnet.*) against closed forms: the on-axis field,
// the far-field dipole of moment Br V, the cos(azimuth) law of Bz, the symmetries of a body
// magnetized along x (mirror in z and in y, half a turn about z), linearity in Br and the
// quadrature's convergence. The field is also checked against magpylib at 4800 points by the CTest
// physics_field_vs_magpylib.
#include <gtest/gtest.h>

#include <cmath>

#include "core/errors.hpp"
#include "physics/physics_magnet.hpp"

namespace acore {
namespace {

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

TEST(PhysicsMagnet, SymmetriesOfAMagnetizationAlongX) {
  // The surface charge M cos(phi') is even in z' and in phi' -> -phi', odd under phi' -> phi' + pi:
  //   B(x, y, -z) = (Bx, By, -Bz),  B(x, -y, z) = (Bx, -By, Bz),  B(-x, -y, z) = (Bx, By, -Bz).
  // The quadrature angles (j + 1/2) 2 pi / N share these symmetries, so they hold to rounding.
  const DiametricCylinder m(3e-3, 2.5e-3, 1.25);
  for (const Eigen::Vector3d p :
       {Eigen::Vector3d(1.1e-3, 0.4e-3, -2.75e-3), Eigen::Vector3d(-0.7e-3, 2e-3, -4e-3),
        Eigen::Vector3d(4e-3, -1e-3, 0.5e-3)}) {
    const Eigen::Vector3d b = m.field(p), scale = Eigen::Vector3d::Constant(b.norm() * 1e-12);
    const Eigen::Vector3d bz = m.field({p.x(), p.y(), -p.z()});
    const Eigen::Vector3d by = m.field({p.x(), -p.y(), p.z()});
    const Eigen::Vector3d bh = m.field({-p.x(), -p.y(), p.z()});
    EXPECT_TRUE(
        ((bz - Eigen::Vector3d(b.x(), b.y(), -b.z())).cwiseAbs().array() <= scale.array()).all());
    EXPECT_TRUE(
        ((by - Eigen::Vector3d(b.x(), -b.y(), b.z())).cwiseAbs().array() <= scale.array()).all());
    EXPECT_TRUE(
        ((bh - Eigen::Vector3d(b.x(), b.y(), -b.z())).cwiseAbs().array() <= scale.array()).all());
  }
  // The closed form on the axis is even in z.
  for (double z : {1.3e-3, 2e-3, 7e-3})
    EXPECT_DOUBLE_EQ(axial_bx_closed_form(3e-3, 2.5e-3, 1.25, z),
                     axial_bx_closed_form(3e-3, 2.5e-3, 1.25, -z));
}

TEST(PhysicsMagnet, LinearInTheRemanenceAndConvergedInTheQuadrature) {
  const DiametricCylinder a(3e-3, 2.5e-3, 1.25), b(3e-3, 2.5e-3, 2.5),
      fine(3e-3, 2.5e-3, 1.25, 512);
  // Where the Hall ring sits (1.1 mm off the axis, 1.5 mm below the face): 96 angles are as good as
  // 512 to 1e-9 (geometric convergence, physics_magnet.hpp).
  for (double az = 0; az < 2 * M_PI; az += 0.7) {
    const Eigen::Vector3d p(1.1e-3 * std::cos(az), 1.1e-3 * std::sin(az), -2.75e-3);
    EXPECT_LT((b.field(p) - 2 * a.field(p)).norm(), 1e-15 * a.field(p).norm());
    EXPECT_LT((fine.field(p) - a.field(p)).norm(), 1e-9 * fine.field(p).norm()) << az;
  }
  EXPECT_DOUBLE_EQ(a.moment_T_m3(), 1.25 * M_PI * 9e-6 * 2.5e-3);
  EXPECT_THROW(DiametricCylinder(0, 1e-3, 1), InputError);
  EXPECT_THROW(DiametricCylinder(1e-3, -1e-3, 1), InputError);
  EXPECT_THROW(DiametricCylinder(1e-3, 1e-3, 1, 4), InputError);
  EXPECT_THROW(a.field({0, 0, 0}), InputError);  // inside
}

TEST(PhysicsMagnet, DipoleFieldOnItsAxes) {
  // mu0 m / (4 pi r^3) times 2 along the moment, times -1 across it.
  const double mu = 3e-8, r = 0.02, k = mu / (4 * M_PI * r * r * r);
  const Eigen::Vector3d along = dipole_field(mu, {r, 0, 0}), across = dipole_field(mu, {0, 0, -r});
  EXPECT_NEAR(along.x(), 2 * k, 1e-15 * k);
  EXPECT_NEAR(along.y(), 0, 1e-20);
  EXPECT_NEAR(across.x(), -k, 1e-15 * k);
  EXPECT_NEAR(across.z(), 0, 1e-20);
  EXPECT_NEAR(dipole_field(mu, {-r, 0, 0}).x(), 2 * k, 1e-15 * k);
}

}  // namespace
}  // namespace acore
