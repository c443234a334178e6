// SPDX-License-Identifier: MIT
// CTest `physics_field_vs_magpylib`: the surface-charge field of
// model/lab/physics/physics_magnet.cpp against magpylib's cylinder (an independent implementation:
// an analytic solution in elliptic integrals), through scripts/magpylib_field.py in the virtual
// environment scripts/setup.sh makes.
//
// 40 random magnets (radius 2..5 mm, height 1.5..4 mm, Br 1.0..1.4 T), 100 observers each where the
// scenarios put sensing elements: below the magnet at an air gap of 0.5..2.5 mm, up to 2 mm off
// the axis (ring radius + package shift + run-out), plus 20 beside and above it (distance from the
// surface >= 1 mm). Tolerance: |B_cpp - B_magpylib| <= 1e-6 |B_magpylib| + 1e-9 T at every point
// (the quadrature converges geometrically; 1e-6 is far below the 0.05 % noise of the scenarios).
//
// usage: physics_field_vs_magpylib PYTHON SOURCE_DIR WORK_DIR
#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <random>

#include "physics/physics_magnet.hpp"

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: physics_field_vs_magpylib PYTHON SOURCE_DIR WORK_DIR\n";
    return 2;
  }
  const std::string python = argv[1], src = argv[2], work = argv[3];
  std::mt19937_64 rng(20261124);
  auto u = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  struct Case {
    double r, h, br;
    std::vector<Eigen::Vector3d> points;
  };
  std::vector<Case> cases;
  nlohmann::json in;
  in["cases"] = nlohmann::json::array();
  for (int k = 0; k < 40; ++k) {
    Case c{u(2e-3, 5e-3), u(1.5e-3, 4e-3), u(1.0, 1.4), {}};
    for (int j = 0; j < 100; ++j) {
      const double rho = u(0, 2e-3), a = u(0, 2 * M_PI);
      c.points.emplace_back(rho * std::cos(a), rho * std::sin(a), -c.h / 2 - u(0.5e-3, 2.5e-3));
    }
    for (int j = 0; j < 20; ++j) {
      const double rho = c.r + u(1e-3, 3e-3), a = u(0, 2 * M_PI);
      c.points.emplace_back(rho * std::cos(a), rho * std::sin(a), u(-c.h, c.h + 2e-3));
    }
    nlohmann::json pts = nlohmann::json::array();
    for (const auto& p : c.points) pts.push_back({p.x(), p.y(), p.z()});
    in["cases"].push_back({{"radius_m", c.r}, {"height_m", c.h}, {"br_T", c.br}, {"points", pts}});
    cases.push_back(c);
  }
  const std::string in_path = work + "/magpylib_in.json", out_path = work + "/magpylib_out.json";
  std::ofstream(in_path) << in.dump();
  const std::string cmd = fmt::format("\"{}\" \"{}/scripts/magpylib_field.py\" \"{}\" \"{}\"",
                                      python, src, in_path, out_path);
  if (std::system(cmd.c_str()) != 0) {
    std::cerr << "physics_field_vs_magpylib: '" << cmd
              << "' failed: run ./scripts/setup.sh (it makes .venv with magpylib)\n";
    return 1;
  }
  nlohmann::json out;
  std::ifstream(out_path) >> out;
  double worst = 0;
  int bad = 0, n = 0;
  for (size_t k = 0; k < cases.size(); ++k) {
    const acore::DiametricCylinder magnet(cases[k].r, cases[k].h, cases[k].br);
    for (size_t j = 0; j < cases[k].points.size(); ++j) {
      const auto& b = out["cases"][k]["B_T"][j];
      const Eigen::Vector3d ref(b[0].get<double>(), b[1].get<double>(), b[2].get<double>());
      const Eigen::Vector3d ours = magnet.field(cases[k].points[j]);
      const double err = (ours - ref).norm(), tol = 1e-6 * ref.norm() + 1e-9;
      worst = std::max(worst, err / ref.norm());
      ++n;
      if (err > tol) {
        if (++bad <= 5)
          std::cerr << fmt::format(
              "magnet {} point {}: ours ({:.9g}, {:.9g}, {:.9g}) T, magpylib "
              "({:.9g}, {:.9g}, {:.9g}) T\n",
              k, j, ours.x(), ours.y(), ours.z(), ref.x(), ref.y(), ref.z());
      }
    }
  }
  std::cout << fmt::format(
      "{} points, magpylib {}: worst relative difference {:.2e} (tolerance 1e-6), {} beyond\n", n,
      out["magpylib"].get<std::string>(), worst, bad);
  return bad == 0 ? 0 : 1;
}
