// SPDX-License-Identifier: MIT
// The register map's content in real numbers: offsets and amplitudes in recording units,
// polynomial coefficients, Fourier coefficients in radians, the zero offset. What the calibration
// fits, what quantize() turns into register words and dequantize() recovers, and what the float
// model runs (docs/register-map.md for the words).
#pragma once
#include <vector>

#include "core/datapath_config.hpp"

namespace acore {

// The calibrated estimator in real numbers: what the float model runs.
struct FloatCoefficients {
  int correction = kPoly;  // a mode of core/correction_modes.hpp
  int degree = 3;
  int regions = 4;
  int xcenter = 0;
  double offset[2] = {0, 0};  // O13, O24 in recording units
  double amp[2] = {1, 1};     // A13, A24 in recording units
  std::vector<double> poly;   // [region][curve][term], curve 0 = c13, 1 = c24 (terms as in the map)
  // The correction's shape (correction, degree, regions, xcenter) as a datapath configuration.
  DatapathConfig shape() const {
    DatapathConfig c;
    c.correction = correction;
    c.degree = degree;
    c.regions = regions;
    c.xcenter = xcenter;
    return c;
  }
  int terms() const { return shape().coef_per_curve(); }
  double& coef(int r, int c, int t) { return poly[(r * 2 + c) * terms() + t]; }
  double coef(int r, int c, int t) const { return poly[(r * 2 + c) * terms() + t]; }
  // Angle-domain Fourier correction after the CORDIC: [a_0, a_1, b_1, ..., a_K, b_K] in radians of
  // electrical angle, in the estimated angle (model/ip/stages/fourier_correct.hpp); empty = off.
  std::vector<double> fourier;
  int fourier_k() const { return fourier.empty() ? 0 : static_cast<int>(fourier.size() / 2); }
  // Zero offset: sensor angle - p theta_ref (electrical, rad, [-pi, pi)). The corrected curves
  // follow p theta_ref + zero_offset; the chain subtracts it at its output when zero_word = 1 (the
  // ZERO word, float_estimate() mirrors it), otherwise run_float() subtracts it in software.
  double zero_offset = 0;
  int zero_word = 0;
  double software_zero_offset() const { return zero_word ? 0.0 : zero_offset; }
};

}  // namespace acore
