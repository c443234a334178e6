// SPDX-License-Identifier: MIT
// The inverse map of Kuntz's analysis: for each significant angle-error order, which signal
// imperfections can cause it and how much of its amplitude each explains.
//
// Candidates for angle-error order k (p = periodicity, first order unless noted):
//   harmonic   a signal harmonic n = k + p or n = |k - p| (n not 0 or p) (Eq. 18-21); it can
//              explain any amplitude; parameter = the least A_n + B_n that does (2 H_k).
//   offset     k = p (first order) or k = 2p (second order); parameter sqrt(A0^2 + B0^2) = H_p.
//   amplitude  k = 2p (first order) or 4p (second); parameter |A_n - B_n| = 2 H_2p.
//   phase      k = 0 or 2p (first order) or 4p (second); parameter |delta_p| from H_2p (or H_0).
// A mismatch's parameter is fitted from its first-order order; its Table 1 row then predicts the
// amplitude at k (explained = min(predicted, observed)/observed) and at its other orders
// (consistency = sum min(observed, predicted) / sum predicted over those orders: a cause whose
// other fingerprints are missing is less likely). Ranking: explained; then consistent
// (consistency >= 1/2) before inconsistent; then mismatch before harmonic, because a mismatch is
// one parameter whose other orders were checked while a harmonic n is a free fit that explains
// any amplitude; then consistency.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "harmonics/harmonic_spectrum.hpp"
#include "harmonics/harmonics.hpp"

namespace acore {

struct AttributionOptions {
  int p = 1;
  // The spectrum is of the mechanical angle error (an `estimate` run); amplitudes are multiplied by
  // p to get the electrical error that Kuntz's formulas describe. False: already electrical.
  bool mechanical = true;
  // Orders below max(min_amplitude_deg, relative_threshold x the largest non-DC order) are skipped.
  double min_amplitude_deg = 0;
  double relative_threshold = 0.05;
  // Order 0 (a constant angle offset) is usually the zero reference, not a sensor property.
  bool include_dc = false;
};

struct Cause {
  std::string kind;            // "harmonic", "offset", "amplitude", "phase"
  int signal_order = 0;        // n of the signal-domain disturbance (0 offset, p mismatch)
  int taylor_order = 1;        // 1: T^1 term, 2: T^2 term of Eq. 26
  std::string parameter_name;  // "A_n+B_n", "sqrt(A0^2+B0^2)", "|A_n-B_n|", "|delta_p|"
  double parameter = 0;        // normalised to the main-harmonic amplitude; rad for delta_p
  double predicted_deg = 0;  // predicted amplitude at this order, same units as the input spectrum
  double explained = 0;      // 0..1
  double consistency = 1;    // 0..1
  std::string text;          // one line for a report
};

struct OrderCauses {
  int order = 0;
  double amplitude_deg = 0;   // as in the input spectrum
  std::vector<Cause> causes;  // best first
};

// Significant orders of `spectrum` (largest first) with their ranked causes. Throws InputError if
// p < 1 or the spectrum orders are not 0..K in sequence.
std::vector<OrderCauses> attribute(const std::vector<OrderAmplitude>& spectrum,
                                   const AttributionOptions& opt);

// The attribution of an analysis's exact spectrum (electrical error, order 0 included, orders >= 5
// % of the largest): `anglecore harmonics --attribute` and the Python package's
// harmonics(attribute=True), one implementation for both.
std::vector<OrderCauses> attribute_exact(const HarmonicAnalysis& a);

// The attribution as `harmonics --json --attribute` writes it: [{order, amplitude_deg, causes:
// [{kind, signal_order, taylor_order, parameter_name, parameter, predicted_deg, explained,
// consistency}]}], largest order first, each order's causes best first.
nlohmann::json attribution_json(const std::vector<OrderCauses>& orders);

}  // namespace acore
