// SPDX-License-Identifier: MIT
// acore_config_check: the datapath configuration's rules at elaboration, the same rules and limits
// as the bit-accurate model's DatapathConfig::validate() (model/ip/core/datapath_config.cpp), one
// acore_check per rule, named after it. Both tops instantiate it with their parameters and say
// which top they are (SERIAL), so an illegal configuration stops Verilator, Icarus and Yosys with
// the rule's message before any stage is built, and the RTL accepts exactly what the model accepts
// (tb/lint/param_checks.py checks both ways on random configurations). The correction modes' rules
// (a known mode, its DEGREE, the tops that build it) are generated from the model's mode table
// (rtl/acore_mode_checks.vh).
`resetall
`default_nettype none

module acore_config_check #(
`include "acore_datapath_params.vh"
  // The top the parameters are for: 0 = acore_top (pipelined, or folded by FOLD), 1 = the serial
  // core acore_serial_top (the 1-D polynomial only, without XCENTER, Fourier stage or FOLD).
  parameter integer SERIAL = 0
) ();

`include "acore_derived.vh"

  // In the order of DatapathConfig::validate().
  acore_check #(.OK(IN_W >= 8 && IN_W <= 24), .VALUE(IN_W),
    .MSG("illegal parameter: IN_W must be 8..24"))
    IN_W_must_be_8_to_24 ();
  acore_check #(.OK(REG_W >= IN_W + 2 && REG_W <= 30), .VALUE(REG_W),
    .MSG("illegal parameter: REG_W must be IN_W+2..30 (an offset needs IN_W+2 bits)"))
    REG_W_must_be_IN_W_plus_2_to_30 ();
  acore_check #(.OK(S_W >= S_F + 2 && S_W <= 30), .VALUE(S_W),
    .MSG("illegal parameter: S_W must be S_F+2..30"))
    S_W_must_be_S_F_plus_2_to_30 ();
  acore_check #(.OK(R_SHIFT >= 0 && R_SHIFT <= 30), .VALUE(R_SHIFT),
    .MSG("illegal parameter: R_SHIFT must be 0..30"))
    R_SHIFT_must_be_0_to_30 ();
  acore_check #(.OK(SCALE_G >= 0 && SCALE_G <= R_SHIFT), .VALUE(SCALE_G),
    .MSG("illegal parameter: SCALE_G must be 0..R_SHIFT"))
    SCALE_G_must_be_0_to_R_SHIFT ();
  // The correction mode: a row of the table, its DEGREE, the tops that build it.
`include "acore_mode_checks.vh"

  acore_check #(.OK(REGIONS == 4 || REGIONS == 8), .VALUE(REGIONS),
    .MSG("illegal parameter: REGIONS must be 4 or 8"))
    REGIONS_must_be_4_or_8 ();
  acore_check #(.OK(XCENTER == 0 || (XCENTER == 1 && REGIONS == 8)), .VALUE(XCENTER),
    .MSG("illegal parameter: XCENTER must be 0, or 1 with REGIONS=8"))
    XCENTER_must_be_0_or_1_with_8_regions ();
  acore_check #(.OK(S_F >= 3), .VALUE(S_F),
    .MSG("illegal parameter: S_F must be >= 3 (poly2d reads v as 4v)"))
    S_F_must_be_at_least_3 ();
  acore_check #(.OK(COEF_F >= 1 && COEF_F < REG_W), .VALUE(COEF_F),
    .MSG("illegal parameter: COEF_F must be 1..REG_W-1"))
    COEF_F_must_be_1_to_REG_W_minus_1 ();
  acore_check #(.OK(COEF_F + ACC_G >= S_F), .VALUE(COEF_F + ACC_G),
    .MSG("illegal parameter: COEF_F+ACC_G must be >= S_F"))
    COEF_F_plus_ACC_G_must_be_at_least_S_F ();
  acore_check #(.OK(ACC_G >= 0), .VALUE(ACC_G),
    .MSG("illegal parameter: ACC_G must be >= 0 (a coefficient is shifted left by ACC_G)"))
    ACC_G_must_be_at_least_0 ();
  acore_check #(.OK(ACC_I >= REG_W - COEF_F + 1), .VALUE(ACC_I),
    .MSG("illegal parameter: ACC_I must be >= REG_W-COEF_F+1 (a coefficient's integer bits and a sign)"))
    ACC_I_must_be_at_least_REG_W_minus_COEF_F_plus_1 ();
  acore_check #(.OK(COEF_F + ACC_G + ACC_I <= 40), .VALUE(COEF_F + ACC_G + ACC_I),
    .MSG("illegal parameter: COEF_F+ACC_G+ACC_I (the Horner accumulator) must be <= 40"))
    ACC_W_must_be_at_most_40 ();
  acore_check #(.OK(K >= 4 && K <= 24), .VALUE(K),
    .MSG("illegal parameter: K must be 4..24"))
    K_must_be_4_to_24 ();
  acore_check #(.OK(CORDIC_G >= 0 && CORDIC_G <= 8), .VALUE(CORDIC_G),
    .MSG("illegal parameter: CORDIC_G must be 0..8"))
    CORDIC_G_must_be_0_to_8 ();
  acore_check #(.OK(K < S_W + 2 + CORDIC_G), .VALUE(K),
    .MSG("illegal parameter: K must be < S_W+2+CORDIC_G (the CORDIC's X/Y width: stage i shifts by i)"))
    K_must_be_below_S_W_plus_2_plus_CORDIC_G ();
  acore_check #(.OK(Z_W >= ANGLE_W && Z_W <= REG_W + 2), .VALUE(Z_W),
    .MSG("illegal parameter: Z_W must be ANGLE_W..REG_W+2 (atan(1) must fit a word)"))
    Z_W_must_be_ANGLE_W_to_REG_W_plus_2 ();
  acore_check #(.OK(ANGLE_W >= 8 && ANGLE_W <= 24), .VALUE(ANGLE_W),
    .MSG("illegal parameter: ANGLE_W must be 8..24"))
    ANGLE_W_must_be_8_to_24 ();
  acore_check #(.OK(FOURIER_K >= 0 && FOURIER_K <= 31), .VALUE(FOURIER_K),
    .MSG("illegal parameter: FOURIER_K must be 0..31"))
    FOURIER_K_must_be_0_to_31 ();

  // Only with the Fourier correction (FOURIER_K > 0); its parameters are unused otherwise.
  acore_check #(.OK(FOURIER_K == 0 || (FOURIER_M >= 4 && FOURIER_M <= K)), .VALUE(FOURIER_M),
    .MSG("illegal parameter: FOURIER_M must be 4..K (it uses the CORDIC's atan words)"))
    FOURIER_M_must_be_4_to_K ();
  acore_check #(.OK(FOURIER_K == 0 || (Z_W > ANGLE_W)), .VALUE(Z_W),
    .MSG("illegal parameter: Z_W must be > ANGLE_W with FOURIER_K > 0"))
    Z_W_must_exceed_ANGLE_W_with_Fourier ();
  // The Fourier stage's rotation CORDIC (acore_cordic_rotate: M stages on W+2+G-bit vectors).
  acore_check #(.OK(FOURIER_K == 0 || (FOURIER_M < FOURIER_W + 2 + FOURIER_G)), .VALUE(FOURIER_M),
    .MSG("illegal parameter: FOURIER_M must be below FOURIER_W+2+FOURIER_G"))
    FOURIER_M_must_be_below_FOURIER_W_plus_2_plus_FOURIER_G ();
  acore_check #(.OK(FOURIER_K == 0 || (FOURIER_M <= Z_W - 4)), .VALUE(FOURIER_M),
    .MSG("illegal parameter: FOURIER_M must be at most Z_W-4"))
    FOURIER_M_must_be_at_most_Z_W_minus_4 ();
  acore_check #(.OK(FOURIER_K == 0 || (FOURIER_W >= 8 && FOURIER_W <= REG_W)), .VALUE(FOURIER_W),
    .MSG("illegal parameter: FOURIER_W must be 8..REG_W"))
    FOURIER_W_must_be_8_to_REG_W ();
  acore_check #(.OK(FOURIER_K == 0 || (FOURIER_G >= 0 && FOURIER_G <= 8)), .VALUE(FOURIER_G),
    .MSG("illegal parameter: FOURIER_G must be 0..8"))
    FOURIER_G_must_be_0_to_8 ();
  acore_check #(.OK(FOURIER_K == 0 || (FOURIER_CF + FOURIER_G > ANGLE_W && FOURIER_CF + FOURIER_G <= 40)),
    .VALUE(FOURIER_CF + FOURIER_G),
    .MSG("illegal parameter: FOURIER_CF+FOURIER_G must be ANGLE_W+1..40"))
    FOURIER_CF_plus_FOURIER_G_must_be_ANGLE_W_plus_1_to_40 ();
  acore_check #(.OK(FOURIER_K == 0 || (FOURIER_CF >= REG_W - 1)), .VALUE(FOURIER_CF),
    .MSG("illegal parameter: FOURIER_CF must be >= REG_W-1 (a coefficient is less than half a turn)"))
    FOURIER_CF_must_be_at_least_REG_W_minus_1 ();

  // The ZERO word: the zero position is an angle code in one register word.
  acore_check #(.OK(ZERO == 0 || ZERO == 1), .VALUE(ZERO),
    .MSG("illegal parameter: ZERO must be 0 or 1"))
    ZERO_must_be_0_or_1 ();
  acore_check #(.OK(ZERO == 0 || ANGLE_W <= REG_W), .VALUE(ANGLE_W),
    .MSG("illegal parameter: ANGLE_W must be <= REG_W with ZERO = 1 (the zero position is one word)"))
    ANGLE_W_must_fit_a_word_with_ZERO ();

  // The fold factor (acore_top): its values and the modes that fold are the table's, above.
  acore_check #(.OK(FOLD == 1 || FOURIER_K == 0), .VALUE(FOLD),
    .MSG("illegal parameter: FOLD must be 1 with FOURIER_K > 0: the Fourier correction is not folded"))
    FOLD_must_be_1_with_Fourier ();

  // The products: adders and shifters, or hardware multipliers (acore_hw_mul.v).
  acore_check #(.OK(MULT == 0 || MULT == 1), .VALUE(MULT),
    .MSG("illegal parameter: MULT must be 0 or 1"))
    MULT_must_be_0_or_1 ();

  // The serial core (SERIAL = 1): the 1-D polynomial on raw x (its modes are the table's, above),
  // no Fourier stage, not folded.
  acore_check #(.OK(SERIAL == 0 || SERIAL == 1), .VALUE(SERIAL),
    .MSG("illegal parameter: acore_config_check: SERIAL must be 0 (acore_top) or 1 (acore_serial_top)"))
    SERIAL_must_be_0_or_1 ();
`include "acore_serial_checks.vh"

endmodule

`resetall
