// SPDX-License-Identifier: MIT
// Configurations of every register-map shape, as RTL parameter overrides: the correction modes,
// 8 (centred) regions, the Fourier stage with and without polynomials, the ZERO word, the wide
// CORDIC presets. The codec and register-image tests run over all of them.
#pragma once

namespace acore::test {

inline const char* const kMapShapes[] = {
    "",
    "DEGREE=5 REGIONS=8 COEF_F=12 ACC_G=7 ACC_I=7",
    "CORRECTION=1",
    "CORRECTION=1 DEGREE=1 REGIONS=8 XCENTER=1",
    "CORRECTION=2",
    "DEGREE=7 REGIONS=8 XCENTER=1",
    "FOURIER_K=5",
    "CORRECTION=2 FOURIER_K=21 ZERO=1",
    "ZERO=1",
    "CORRECTION=1 IN_W=18 REG_W=20 COEF_F=17 K=18 CORDIC_G=4 Z_W=22 ANGLE_W=18",
    "REG_W=22 COEF_F=19 K=20 CORDIC_G=5 Z_W=24 ANGLE_W=20 ZERO=1 FOURIER_K=3"};

}  // namespace acore::test
