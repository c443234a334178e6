// SPDX-License-Identifier: MIT
// The correction modes' parameter rules, from the model's mode table
// (model/ip/core/correction_modes.hpp), included in rtl/acore_config_check.v: the same
// rules as DatapathConfig::validate() (a known mode, its DEGREE, FOLD's values, the tops that
// build it).
// Written by (from the repository root)
//   acore_gen_tables rtl_mode_checks > rtl/acore_mode_checks.vh
// (model/cli/gen_tables.cpp, scripts/gen_tables.sh); do not edit: the CTest gen_tables_current
// compares it.

  // CORRECTION is a row of the table.
  acore_check #(.OK(acore_mode_known(CORRECTION) != 0), .VALUE(CORRECTION),
    .MSG("illegal parameter: CORRECTION must be 0 (poly), 1 (poly2d) or 2 (none)"))
    CORRECTION_must_be_0_1_or_2 ();

  // Each mode's DEGREE.
  acore_check #(.OK(CORRECTION != ACORE_CORR_POLY || (DEGREE >= 1 && DEGREE <= 7)), .VALUE(DEGREE),
    .MSG("illegal parameter: DEGREE must be 1..7 for poly (CORRECTION=0)"))
    DEGREE_must_be_1_to_7_for_poly ();
  acore_check #(.OK(CORRECTION != ACORE_CORR_POLY2D || (DEGREE >= 1 && DEGREE <= 3)), .VALUE(DEGREE),
    .MSG("illegal parameter: DEGREE must be 1..3 for poly2d (CORRECTION=1)"))
    DEGREE_must_be_1_to_3_for_poly2d ();
  acore_check #(.OK(CORRECTION != ACORE_CORR_NONE || (DEGREE >= 1 && DEGREE <= 7)), .VALUE(DEGREE),
    .MSG("illegal parameter: DEGREE must be 1..7 for none (CORRECTION=2)"))
    DEGREE_must_be_1_to_7_for_none ();

  // FOLD is a fold factor of acore_top (fold_values()).
  acore_check #(.OK(acore_fold_legal(FOLD) != 0), .VALUE(FOLD),
    .MSG("illegal parameter: FOLD must be 1, 2, 4, 8, 16 or 32"))
    FOLD_must_be_1_2_4_8_16_or_32 ();

  // The modes a top does not build: acore_top pipelined (FOLD = 1) or folded (FOLD > 1),
  // the serial core (SERIAL = 1).
  acore_check #(.OK(FOLD == 1 || CORRECTION != ACORE_CORR_POLY2D), .VALUE(FOLD),
    .MSG("illegal parameter: FOLD must be 1 with poly2d (CORRECTION=1): poly2d is not folded"))
    FOLD_must_be_1_with_poly2d ();
  acore_check #(.OK(SERIAL == 0 || CORRECTION != ACORE_CORR_POLY2D), .VALUE(CORRECTION),
    .MSG("illegal parameter: CORRECTION must not be 1 (poly2d) on the serial core: it builds 0 (poly)"))
    CORRECTION_must_not_be_poly2d_on_the_serial_core ();
  acore_check #(.OK(SERIAL == 0 || CORRECTION != ACORE_CORR_NONE), .VALUE(CORRECTION),
    .MSG("illegal parameter: CORRECTION must not be 2 (none) on the serial core: it builds 0 (poly)"))
    CORRECTION_must_not_be_none_on_the_serial_core ();
