// SPDX-License-Identifier: MIT
// The datapath parameters, declared alike in every module that takes the whole datapath
// (acore_top, acore_serial_top, acore_apb, acore_board, acore_config_check, the pin wrappers
// of synth/, the formal harness tb/formal/acore_stream_formal.sv), from the model's field
// table config_fields() (model/ip/core/datapath_config.cpp): name, default (a default
// DatapathConfig's) and meaning. `include it first inside the module's ANSI parameter list:
// every declaration ends with a comma, the module's own parameters follow.
// Written by (from the repository root)
//   acore_gen_tables rtl_datapath_params > rtl/acore_datapath_params.vh
// (model/cli/gen_tables.cpp, scripts/gen_tables.sh); do not edit: the CTest gen_tables_current
// compares it.
  // Channel code width, signed.
  parameter integer IN_W = 16,
  // Register word width.
  parameter integer REG_W = 18,
  // Scaled and corrected curve width, signed.
  parameter integer S_W = 18,
  // Fraction bits of the scaled curves (1.0 = 2^S_F).
  parameter integer S_F = 16,
  // Extra scale of the amplitude reciprocal, R = round(2^(S_F + R_SHIFT) / A).
  parameter integer R_SHIFT = 13,
  // Guard fraction bits of the scaling product.
  parameter integer SCALE_G = 4,
  // Correction mode, a row of the mode table (rtl/acore_modes.vh): 0 poly, 1 poly2d, 2 none.
  parameter integer CORRECTION = 0,
  // Polynomial degree of the correction (the total degree for two arguments).
  parameter integer DEGREE = 3,
  // Regions of the domain selection, 4 or 8.
  parameter integer REGIONS = 4,
  // 1 (8 regions only): the polynomials are in u = 2 (x -+ 3/8), centred in their half region.
  parameter integer XCENTER = 0,
  // Fraction bits of a polynomial coefficient (a signed REG_W-bit word).
  parameter integer COEF_F = 15,
  // Guard fraction bits of the Horner accumulator.
  parameter integer ACC_G = 4,
  // Integer bits (with the sign) of the Horner accumulator.
  parameter integer ACC_I = 6,
  // CORDIC iterations (= stages).
  parameter integer K = 16,
  // Guard fraction bits of the CORDIC's X/Y registers.
  parameter integer CORDIC_G = 3,
  // CORDIC angle accumulator width, one turn = 2^Z_W.
  parameter integer Z_W = 20,
  // Output angle width, unsigned, one turn = 2^ANGLE_W.
  parameter integer ANGLE_W = 16,
  // Harmonics of the Fourier correction after the CORDIC (0 = no stage, no words).
  parameter integer FOURIER_K = 0,
  // Rotation-CORDIC stages per harmonic (<= K).
  parameter integer FOURIER_M = 12,
  // Fraction bits of a Fourier coefficient, in turns.
  parameter integer FOURIER_CF = 22,
  // Significant bits of a harmonic's word, signed.
  parameter integer FOURIER_W = 16,
  // Guard fraction bits of the Fourier rotations.
  parameter integer FOURIER_G = 2,
  // 1: one more register word (the last), the zero position, subtracted from the angle.
  parameter integer ZERO = 0,
  // Clocks per sample of acore_top: 1 pipelined, more folded (fold_values(); serial core: 1).
  parameter integer FOLD = 1,
  // Products: 0 adders and shifters (each partial product floored), 1 the multiply operator (DSP blocks; the full product floored once).
  parameter integer MULT = 0,
