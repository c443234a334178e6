// SPDX-License-Identifier: MIT
// Table 1 of Kuntz et al.: offset, amplitude and phase mismatch of the main harmonic as
// equivalent disturbance harmonics, and the second-order amplitudes of the electrical angle error
// they cause, at mechanical orders 0, p, 2p, 3p, 4p (radians).
//
// Every row was checked numerically against the second-order Taylor series (Eq. 26, evaluated by
// harmonics.hpp) and the exact DFT (tests/lab/harmonics/test_harmonics.cpp, Table1*). Two printed
// rows disagree with Eq. 26 and are implemented corrected:
//   - "Offset, amplitude", H_2p: the printed "... - A_n^2 - 2 A_n" must read "... - A_n^2 + 2 A_n";
//   - "Offset, amplitude, phase", H_0: the printed (3 - A_n + B_n) must read (3 - A_n - B_n), as in
//     the "Amplitude, phase" row (an offset does not change H_0 at second order).
// H_0 rows are printed signed; here they are magnitudes like every other entry.
#pragma once
#include <string>
#include <vector>

#include "harmonics/harmonics.hpp"

namespace acore {

enum class MismatchType {
  Offset,
  Amplitude,
  Phase,
  OffsetAmplitude,
  OffsetPhase,
  AmplitudePhase,
  OffsetAmplitudePhase
};

// The mismatch parameters of Table 1, in units of the (normalised) main-harmonic amplitude:
// offsets A0 (sine) and B0 (cosine), amplitude deviations An (sine) and Bn (cosine) from 1, phase
// mismatch delta (rad). A row uses only the parameters of its mismatch types and ignores the rest.
struct MismatchParams {
  double A0 = 0, B0 = 0, An = 0, Bn = 0, delta = 0;
};

// Electrical angle-error amplitudes (rad) at orders 0, p, 2p, 3p, 4p; zero where the row has none.
struct MismatchHarmonics {
  double H0 = 0, Hp = 0, H2p = 0, H3p = 0, H4p = 0;
  // The amplitude at multiple m (0..4) of p.
  double at_multiple(int m) const;
};

const std::vector<MismatchType>& all_mismatch_types();
std::string to_string(MismatchType t);  // "offset", "amplitude", "phase", "offset+amplitude", ...
bool has_offset(MismatchType t);
bool has_amplitude(MismatchType t);
bool has_phase(MismatchType t);

// Table 1, "Harmonic amplitudes" column (second-order approximation, corrected as above).
MismatchHarmonics table1(MismatchType t, const MismatchParams& m);

// Table 1, "Equivalent disturbance" column: B0 + i A0 (n = 0, theta = pi/2), B_n cos p phi +
// i A_n sin p phi (n = p), i 2 sin(delta/2) sin(p phi + (delta + pi)/2) (n = p, Eq. 34).
std::vector<Disturbance> mismatch_disturbances(MismatchType t, const MismatchParams& m, int p);

// Inverse of the "Phase" row's H_2p (monotone for |delta| < pi/2): the |delta| that gives h.
// Throws InputError if h exceeds the value at pi/2.
double phase_from_h2p(double h);

}  // namespace acore
