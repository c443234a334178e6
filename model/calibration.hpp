// SPDX-License-Identifier: MIT
// Calibration (paper section II.B): pre-filter, scaling (offset = mean, amplitude per Eq. 4),
// domain selection (region_select.hpp), the zero offset z (the constant electrical angle between
// the sensor and the reference: circular mean of wrap(atan2(s13, s24) - p theta_ref)), and a
// least-squares fit per region of the differences of Eq. 6 against the aligned reference:
// d13 = s13 - sin(p theta_ref + z) and d24 = s24 - cos(p theta_ref + z) against powers of x.
// Then quantization of everything into the register image (DESIGN 3.2).
#pragma once
#include <string>
#include <vector>

#include "datapath_config.hpp"
#include "recording.hpp"
#include "regimage.hpp"

namespace acore {

// The calibrated estimator in real numbers: what the float model runs.
struct FloatCoefficients {
  int correction = kPoly;  // kPoly, kPoly2d, kNone (datapath_config.hpp)
  int degree = 3;
  int regions = 4;
  int xcenter = 0;
  double offset[2] = {0, 0};  // O13, O24 in recording units
  double amp[2] = {1, 1};     // A13, A24 in recording units
  std::vector<double> poly;   // [region][curve][term], curve 0 = c13, 1 = c24 (terms as in the map)
  // The correction's shape (correction, degree, regions, xcenter) as a datapath configuration.
  DatapathConfig shape() const;
  int terms() const { return shape().coef_per_curve(); }
  double& coef(int r, int c, int t) { return poly[(r * 2 + c) * terms() + t]; }
  double coef(int r, int c, int t) const { return poly[(r * 2 + c) * terms() + t]; }
  // Angle-domain Fourier correction after the CORDIC: [a_0, a_1, b_1, ..., a_K, b_K] in radians of
  // electrical angle, in the estimated angle (model/fourier_correct.hpp); empty = off.
  std::vector<double> fourier;
  int fourier_k() const { return fourier.empty() ? 0 : static_cast<int>(fourier.size() / 2); }
  // Zero offset: sensor angle - p theta_ref (electrical, rad, [-pi, pi)). The corrected curves
  // follow p theta_ref + zero_offset; the chain subtracts it at its output when zero_word = 1 (the
  // ZERO word, float_estimate() mirrors it), otherwise run_float() subtracts it in software.
  double zero_offset = 0;
  int zero_word = 0;
  double software_zero_offset() const { return zero_word ? 0.0 : zero_offset; }
};

struct CalOptions {
  int correction = kPoly;
  int degree = 3;
  int regions = 4;
  int xcenter = 0;      // 8 regions: fit in u = 2 (x -+ 3/8) (poly_correct.hpp)
  int periodicity = 1;  // electrical periods per turn: the reference is sin/cos(p theta_ref)
  int fourier_k = 0;    // harmonics of the Fourier correction fitted after the correction; 0 = none
  // Zero offset: estimate it from the calibration recording (circular mean of the uncorrected angle
  // error) and fit against the aligned reference; or, false, take `zero_offset` as given (rad; 0 =
  // fit against theta_ref itself, Eq. 6 as printed: the polynomials absorb any constant offset).
  bool estimate_zero = true;
  double zero_offset = 0;
};

// The zero offset of scaled curves against a reference: the circular mean of
// wrap(atan2(s13, s24) - p theta_ref), rad in [-pi, pi). Throws InputError when the errors have no
// mean direction (resultant length below 1e-9: no constant offset to speak of).
double zero_offset_estimate(const std::vector<double>& s13, const std::vector<double>& s24,
                            const std::vector<double>& theta_ref, int periodicity);

// The real-valued arguments of the correction polynomials, as the datapath forms them:
// u = x, or 2 (x -+ 3/8) with xcenter; v = 2^kVShift (y_other - sign(y_other)) (poly2d).
double correction_u(double x, int xcenter);
double correction_v(double y_other);
// Every term's basis value at (x, y_other) in the register map's order (1-D: u^j; 2-D: u^i v^j).
void correction_basis(const DatapathConfig& shape, double x, double y_other, double* out);
// P_region,curve(x, y_other) in double, by (nested) Horner like the datapath.
double correction_poly(const FloatCoefficients& fc, int region, int curve, double x,
                       double y_other);

// The calibration options a datapath configuration asks for (its correction mode, degree, regions).
CalOptions cal_options_for(const DatapathConfig& cfg, int periodicity);

// Throws InputError when the recording has no theta_ref or too few samples in a region.
// With opt.fourier_k > 0, after the polynomial: least squares of the remaining angle error
// (float estimate - p theta_ref - zero offset, wrapped) against 1, cos k theta, sin k theta
// (k = 1..K) of the float estimate theta.
FloatCoefficients calibrate(const Recording& rec, const CalOptions& opt);

// The "ADC" gain: the largest power of two that maps the recording's largest |channel| to at most
// a quarter of the IN_W-bit full scale (headroom for samples the calibration never saw).
double choose_in_scale(const Recording& rec, int in_w);

// Quantizes into a register image of configuration cfg (degree and regions taken from coef; the
// ZERO word from cfg.zero_word, holding coef.zero_offset as an angle code; the header records
// coef.zero_offset). Throws InputError naming the register when a value does not fit its field.
RegImage quantize(const FloatCoefficients& coef, DatapathConfig cfg, double in_scale);

// quantize(), but when a coefficient does not fit, trade coefficient fraction bits for range (down
// to 8) while the Horner accumulator keeps its fraction bits; likewise a Fourier coefficient lowers
// fourier_coef_f (down to reg_w - 1). The image header records the result.
RegImage quantize_auto_range(const FloatCoefficients& coef, DatapathConfig cfg, double in_scale);

// calibrate() with cal_options_for(cfg), then quantize_auto_range() at the automatic in_scale: the
// one-call path of the sweep and the co-sim tests. *fc (optional) receives the float coefficients.
RegImage calibrate_image(const Recording& rec, const DatapathConfig& cfg, int periodicity,
                         FloatCoefficients* fc = nullptr);

// The real values a register image stands for (so the float engine can run from an image).
FloatCoefficients dequantize(const RegImage& img);

}  // namespace acore
