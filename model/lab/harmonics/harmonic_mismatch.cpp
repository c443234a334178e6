// SPDX-License-Identifier: MIT
// Table 1 of Kuntz et al. as functions; see harmonic_mismatch.hpp for the two corrected rows.
#include "harmonics/harmonic_mismatch.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/angle.hpp"
#include "core/errors.hpp"

namespace acore {

namespace {}

double MismatchHarmonics::at_multiple(int m) const {
  switch (m) {
    case 0:
      return H0;
    case 1:
      return Hp;
    case 2:
      return H2p;
    case 3:
      return H3p;
    case 4:
      return H4p;
    default:
      return 0;
  }
}

const std::vector<MismatchType>& all_mismatch_types() {
  static const std::vector<MismatchType> all = {MismatchType::Offset,
                                                MismatchType::Amplitude,
                                                MismatchType::Phase,
                                                MismatchType::OffsetAmplitude,
                                                MismatchType::OffsetPhase,
                                                MismatchType::AmplitudePhase,
                                                MismatchType::OffsetAmplitudePhase};
  return all;
}

bool has_offset(MismatchType t) {
  return t == MismatchType::Offset || t == MismatchType::OffsetAmplitude ||
         t == MismatchType::OffsetPhase || t == MismatchType::OffsetAmplitudePhase;
}
bool has_amplitude(MismatchType t) {
  return t == MismatchType::Amplitude || t == MismatchType::OffsetAmplitude ||
         t == MismatchType::AmplitudePhase || t == MismatchType::OffsetAmplitudePhase;
}
bool has_phase(MismatchType t) {
  return t == MismatchType::Phase || t == MismatchType::OffsetPhase ||
         t == MismatchType::AmplitudePhase || t == MismatchType::OffsetAmplitudePhase;
}

std::string to_string(MismatchType t) {
  std::string s;
  if (has_offset(t)) s += "offset";
  if (has_amplitude(t)) s += s.empty() ? "amplitude" : "+amplitude";
  if (has_phase(t)) s += s.empty() ? "phase" : "+phase";
  return s;
}

MismatchHarmonics table1(MismatchType t, const MismatchParams& m) {
  using std::cos;
  using std::fabs;
  using std::sin;
  using std::sqrt;
  const double A0 = m.A0, B0 = m.B0, An = m.An, Bn = m.Bn, d = m.delta;
  const double r2 = A0 * A0 + B0 * B0;
  const double dab = An - Bn;
  // Shared by the rows with amplitude and phase mismatch.
  const double h4p_amp_phase =
      0.125 * sqrt(std::pow(sin(2 * d) + 2 * sin(d) * (dab - 1), 2) +
                   std::pow(dab * dab - 2 * dab + 2 * cos(d) * (dab - 1) + cos(2 * d) + 1, 2));
  MismatchHarmonics h;
  switch (t) {
    case MismatchType::Offset:
      h.Hp = sqrt(r2);
      h.H2p = sqrt(std::pow(A0, 4) / 4 + A0 * A0 * B0 * B0 / 2 + std::pow(B0, 4) / 4);
      break;
    case MismatchType::Amplitude:
      h.H2p = fabs(0.5 * dab + 0.25 * (Bn * Bn - An * An));
      h.H4p = dab * dab / 8;
      break;
    case MismatchType::Phase:
      h.H0 = fabs(0.75 * sin(d) - 0.125 * sin(2 * d));
      h.H2p = sqrt(0.25 * sin(d) * sin(d) + std::pow(cos(d) - 1, 2));
      h.H4p = 0.25 * (1 - cos(d));
      break;
    case MismatchType::OffsetAmplitude:
      h.Hp = fabs(0.5 * (Bn + An - 2)) * sqrt(r2);
      // Corrected: the paper prints "- 2 A_n" for the last term; Eq. 26 gives "+ 2 A_n".
      h.H2p =
          sqrt(B0 * B0 * A0 * A0 +
               std::pow(2 * B0 * B0 + Bn * Bn - 2 * Bn - 2 * A0 * A0 - An * An + 2 * An, 2) / 16);
      h.H3p = fabs(0.5 * dab) * sqrt(r2);
      h.H4p = dab * dab / 8;
      break;
    case MismatchType::OffsetPhase:
      h.H0 = fabs(0.75 * sin(d) - 0.125 * sin(2 * d));
      h.Hp = sqrt(2.0) / 2 * sqrt((5 - 3 * cos(d)) * r2);
      h.H2p = 0.5 * sqrt(std::pow(sin(d) - 2 * A0 * B0, 2) +
                         std::pow(2 * cos(d) - A0 * A0 + B0 * B0 - 2, 2));
      h.H3p = sqrt(2.0) / 2 * sqrt((1 - cos(d)) * r2);
      h.H4p = 0.25 * (1 - cos(d));
      break;
    case MismatchType::AmplitudePhase:
      h.H0 = fabs(0.25 * (3 - An - Bn) * sin(d) - 0.125 * sin(2 * d));
      h.H2p =
          0.25 *
          sqrt(std::pow(An * An - Bn * Bn - 4 * An + 2 * Bn + 2 * An * cos(d) - 4 * cos(d) + 4, 2) +
               4 * sin(d) * sin(d) * std::pow(Bn - 1, 2));
      h.H4p = h4p_amp_phase;
      break;
    case MismatchType::OffsetAmplitudePhase:
      // Corrected: the paper prints (3 - A_n + B_n); Eq. 26 gives (3 - A_n - B_n).
      h.H0 = fabs(0.25 * (3 - An - Bn) * sin(d) - 0.125 * sin(2 * d));
      h.Hp = 0.5 * sqrt(r2 * (std::pow(An + Bn, 2) - 6 * (An + Bn) + 2 * cos(d) * (An + Bn) -
                              6 * cos(d) + 10));
      h.H2p = 0.5 * sqrt(std::pow(sin(d) * (Bn - 1) + 2 * A0 * B0, 2) +
                         std::pow(0.5 * (An * An - Bn * Bn) + A0 * A0 - B0 * B0 - 2 * An + Bn +
                                      cos(d) * (An - 2) + 2,
                                  2));
      h.H3p = 0.5 * sqrt(r2 * (dab * dab - 2 * dab + 2 * cos(d) * (dab - 1) + 2));
      h.H4p = h4p_amp_phase;
      break;
  }
  return h;
}

std::vector<Disturbance> mismatch_disturbances(MismatchType t, const MismatchParams& m, int p) {
  std::vector<Disturbance> d;
  if (has_offset(t)) d.push_back({0, m.A0, kPi / 2, m.B0, 0, "offset"});
  if (has_amplitude(t)) d.push_back({p, m.An, 0, m.Bn, 0, "amplitude"});
  if (has_phase(t)) d.push_back({p, 2 * std::sin(m.delta / 2), (m.delta + kPi) / 2, 0, 0, "phase"});
  return d;
}

double phase_from_h2p(double h) {
  auto f = [](double d) { return table1(MismatchType::Phase, {0, 0, 0, 0, d}).H2p; };
  double lo = 0, hi = kPi / 2;
  if (!(h >= 0) || h > f(hi))
    throw InputError(
        fmt::format("phase mismatch: H_2p = {} rad is out of the range of Table 1's phase row", h));
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < h ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace acore
