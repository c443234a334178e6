// SPDX-License-Identifier: MIT
// Harmonic analysis of the arctangent angle error (Kuntz et al., "Harmonic analysis of the
// arctangent function ...", docs/harmonics.md).
//
// Signals (Eq. 1 and 11, docs/contracts.md, command line `harmonics` input), mechanical angle phi,
// periodicity p:
//   a(phi) = A0 + Ap sin(p phi + delta_p) + sum_n A_n sin(n phi + theta_n)
//   b(phi) = B0 + Bp cos(p phi)           + sum_n B_n cos(n phi + psi_n)
// Electrical angular error (Eq. 9): dphi_p = unwrap(atan2(a, b)) - p phi, in radians.
//
// After normalisation by g = (Ap + Bp) / 2 (section 4.1) the signal is z = b + i a =
// e^{i p phi} + sum of "disturbances" (n, A, theta, B, psi): the terms, the offset (n = 0,
// Eq. 37), the amplitude mismatch (n = p, Eq. 38) and the phase mismatch (n = p, Eq. 34).
// Everything below (predictions, bounds) works on that disturbance list.
//
// Worked example (the paper's Eq. 33, tests/data/kuntz_eq33.json): p = 2, terms
// (3, 0.05, pi/8, 0.02, pi/7) and (9, 0.075, 0, 0.09, pi/4): max |dphi_p| = 7.755 deg, dominant
// error orders 1, 5, 7, 11 (= n -+ p), minor orders 2, 4, 8, 10, 14, 16 (= 2p +- n +- m).
#pragma once
#include <complex>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace acore {

// One disturbance harmonic of Eq. 1: A sin(n phi + theta) in a, B cos(n phi + psi) in b.
// Amplitudes of user terms are >= 0 (the paper's convention); equivalent disturbances of an offset
// or an amplitude mismatch may be negative (section 4: "negative amplitudes can be allowed").
struct Disturbance {
  int n = 1;
  double A = 0, theta = 0, B = 0, psi = 0;
  std::string source = "term";  // "term", "offset", "amplitude", "phase"
};

// The docs/contracts.md, command line input, un-normalised (volts or any unit; angles in radians).
struct SignalSpec {
  int p = 1;
  double A0 = 0, B0 = 0, Ap = 1, Bp = 1, delta_p = 0;
  std::vector<Disturbance> terms;  // n >= 1, n != p, A, B >= 0
};

// Parses and validates a spec; throws InputError naming the offending field ("terms[1].A ...").
SignalSpec parse_signal_spec(const nlohmann::json& j);
SignalSpec load_signal_spec(const std::string& path);
// The highest periodicity and term order a spec may name: the analysis grid grows with 32 x the
// highest predicted order (2 p + 2 n) and the spectrum costs grid x orders: 256 keeps an analysis
// under a second (p = 1000 took 8 s of CPU, a fuzzer's timeout). Sensor periodicities and
// harmonic orders in practice are far below (the recordings' p is 1..64).
constexpr int kMaxOrder = 256;
// Throws InputError for: p or a term's n outside 1..kMaxOrder, non-finite values, Ap or Bp <= 0,
// |delta_p| >= pi/2, a term with n = p (a main-harmonic mismatch must be given as Ap, Bp, delta_p),
// negative term amplitudes, and a normalised spectrum outside the convergence domain (sum_amplitude
// >= 1).
void validate(const SignalSpec& spec);

// Normalisation (section 4.1): all disturbances of the spec divided by g = (Ap + Bp) / 2, with the
// offset as n = 0 (theta = pi/2, psi = 0), the amplitude mismatch as n = p (A = Ap/g - 1,
// B = Bp/g - 1), and the phase mismatch as n = p with A = (Ap/g) 2 sin(delta_p/2),
// theta = (delta_p + pi)/2 (Eq. 34). The factor Ap/g on the phase term keeps the representation
// exact ((Ap/g) sin(p phi + delta_p) = (Ap/g) sin p phi + that term); the paper drops it, which
// changes the result only at second order. Zero-amplitude entries are omitted.
std::vector<Disturbance> equivalent_disturbances(const SignalSpec& spec);

// Geometric sum (Eq. 28): sum sqrt(A^2 + B^2). Taylor sum (Eq. 31): sum |A| + |B|.
double geometric_amplitude_sum(const std::vector<Disturbance>& d);
double taylor_amplitude_sum(const std::vector<Disturbance>& d);

// Bounds on the electrical error, radians. Eq. 29: max |dphi_p| <= atan(A sqrt(1-A^2)/(1-A^2));
// Eq. 30: <= pi/3 A for A < 1/2; Eq. 32: |dphi_p - T_k| <= -log(1 - At) - sum_{q<=k} At^q / q.
// Each throws InputError outside its domain (A >= 1, A >= 1/2, At >= 1 respectively) instead of
// returning a number that means nothing.
double geometric_bound(double sum_amplitude);
double geometric_bound_linear(double sum_amplitude);
double taylor_remainder_bound(double taylor_sum, int k);

// Mechanical angles of a uniform grid of n points over one turn: 2 pi j / n.
std::vector<double> turn_grid(int n);

// Exact electrical error at each phi: unwrapped atan2 of z = e^{i p phi} + disturbances, minus
// p phi, shifted by a multiple of 2 pi so that its mean lies in (-pi, pi].
std::vector<double> exact_error(const std::vector<Disturbance>& d, int p,
                                const std::vector<double>& phi);
// The same from the raw (un-normalised) signals of Eq. 1 / 11.
std::vector<double> exact_error(const SignalSpec& spec, const std::vector<double>& phi);

// Time-domain Taylor terms: T^1 of Eq. 18 (summed over the disturbances) and T^2 of Eq. 26.
std::vector<double> first_order_term(const std::vector<Disturbance>& d, int p,
                                     const std::vector<double>& phi);
std::vector<double> second_order_term(const std::vector<Disturbance>& d, int p,
                                      const std::vector<double>& phi);

// A real trigonometric series sum_k c_k e^{i k phi}, two-sided (c_{-k} = conj c_k).
class TrigSeries {
 public:
  void add_sin(int k, double phase, double amplitude);  // amplitude sin(k phi + phase)
  void add_cos(int k, double phase, double amplitude);  // amplitude cos(k phi + phase)
  TrigSeries operator*(const TrigSeries& o) const;
  TrigSeries& operator+=(const TrigSeries& o);
  TrigSeries scaled(double s) const;
  // One-sided amplitude of mechanical order k >= 0: 2 |c_k| for k > 0, |c_0| for k = 0.
  double amplitude(int k) const;
  double value(double phi) const;
  int max_order() const;

 private:
  std::map<int, std::complex<double>> c_;
};

// Per-order amplitudes from the formulas (not from a DFT of the prediction): T^1 contributes at
// |n -+ p| (Eq. 19-21), T^2 at |2p +- n +- m| (Eq. 26 expanded into exponentials).
TrigSeries first_order_series(const std::vector<Disturbance>& d, int p);
TrigSeries second_order_series(const std::vector<Disturbance>& d, int p);

// One-sided DFT amplitude of mechanical orders 0..max_order of samples on turn_grid(size).
std::vector<double> dft_amplitudes(const std::vector<double>& samples, int max_order);

// One row of the harmonics table, radians of electrical error.
struct HarmonicRow {
  int order = 0;
  double exact = 0, first = 0, second = 0;
};

// The full analysis of a spec (what `anglecore harmonics` reports). Angles in radians.
struct HarmonicAnalysis {
  SignalSpec spec;
  std::vector<Disturbance> disturbances;
  double sum_amplitude = 0;                       // Eq. 28
  double taylor_sum = 0;                          // Eq. 31
  std::vector<double> phi, exact, first, second;  // one turn, electrical error
  double max_error = 0, residual_first = 0, residual_second = 0;
  double bound_geometric = 0;                    // Eq. 29
  std::optional<double> bound_geometric_linear;  // Eq. 30, when sum_amplitude < 1/2
  std::optional<double> bound_taylor_first;      // Eq. 32, k = 1, when taylor_sum < 1
  std::optional<double> bound_taylor_second;     // Eq. 32, k = 2
  std::vector<HarmonicRow> harmonics;            // orders 0..max order of T^2
  std::vector<std::string> notes;                // e.g. why a Taylor bound is absent

  // docs/contracts.md, command line output (degrees); an absent bound is null. Extra fields: p,
  // grid, sums, notes.
  nlohmann::json to_json() const;
};

// grid = 0 picks a power of two >= 4096 and >= 32 x the highest predicted order.
HarmonicAnalysis analyze(const SignalSpec& spec, int grid = 0);

}  // namespace acore
