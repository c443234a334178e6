// SPDX-License-Identifier: MIT
// The datapath parameters passed on, each to the parameter of the same name: `include it
// first inside the parameter list of an instance that takes the whole datapath (both
// modules declare them with rtl/acore_datapath_params.vh); every item ends with a comma,
// the instance's own parameters follow.
// Written by (from the repository root)
//   acore_gen_tables rtl_datapath_pass > rtl/acore_datapath_pass.vh
// (model/cli/gen_tables.cpp, scripts/gen_tables.sh); do not edit: the CTest gen_tables_current
// compares it.
    .IN_W(IN_W), .REG_W(REG_W), .S_W(S_W), .S_F(S_F), .R_SHIFT(R_SHIFT), .SCALE_G(SCALE_G),
    .CORRECTION(CORRECTION), .DEGREE(DEGREE), .REGIONS(REGIONS), .XCENTER(XCENTER), .COEF_F(COEF_F),
    .ACC_G(ACC_G), .ACC_I(ACC_I), .K(K), .CORDIC_G(CORDIC_G), .Z_W(Z_W), .ANGLE_W(ANGLE_W),
    .FOURIER_K(FOURIER_K), .FOURIER_M(FOURIER_M), .FOURIER_CF(FOURIER_CF), .FOURIER_W(FOURIER_W),
    .FOURIER_G(FOURIER_G), .ZERO(ZERO), .FOLD(FOLD), .MULT(MULT),
