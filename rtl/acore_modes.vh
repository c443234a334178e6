// SPDX-License-Identifier: MIT
// The correction modes (the RTL parameter CORRECTION) for the RTL, from the model's mode
// table (model/ip/core/correction_modes.hpp): their constants, and the functions that size
// and schedule a mode. Included by rtl/acore_derived.vh into every module that uses a
// derived quantity. The functions take CORRECTION as a number (their case labels are the
// table's IDs): a module's parameter defaults call them before its body declares the
// constants. Every comparison of CORRECTION elsewhere uses the constants.
// Written by (from the repository root)
//   acore_gen_tables rtl_modes > rtl/acore_modes.vh
// (model/cli/gen_tables.cpp, scripts/gen_tables.sh); do not edit: the CTest gen_tables_current
// compares it.
//
// The rows (CORRECTION name: DEGREE, TERMS, the RTL stage; the tops that build it):
//   0 poly: DEGREE 1..7, TERMS = DEGREE + 1, acore_poly_correct; pipelined, folded, serial
//   1 poly2d: DEGREE 1..3, TERMS = ((DEGREE + 1) * (DEGREE + 2)) / 2, acore_poly2d_correct; pipelined
//   2 none: DEGREE 1..7, TERMS = 0, no stage; pipelined, folded

// The CORRECTION value of each mode.
localparam integer ACORE_CORR_POLY = 0;
localparam integer ACORE_CORR_POLY2D = 1;
localparam integer ACORE_CORR_NONE = 2;

// 1 when a row of the table has this CORRECTION.
function integer acore_mode_known(input integer f_correction);
  case (f_correction)
    0: acore_mode_known = 1;  // poly
    1: acore_mode_known = 1;  // poly2d
    2: acore_mode_known = 1;  // none
    default: acore_mode_known = 0;  // no mode
  endcase
endfunction

// Coefficients per region and curve of poly: its basis, u^j, j = 0..n (4 terms at DEGREE = 3).
function integer acore_terms_poly(input integer f_degree);
  acore_terms_poly = f_degree + 1;
endfunction

// Coefficients per region and curve of poly2d: its basis, u^i v^j, i + j <= d (10 terms at DEGREE = 3).
function integer acore_terms_poly2d(input integer f_degree);
  acore_terms_poly2d = ((f_degree + 1) * (f_degree + 2)) / 2;
endfunction

// TERMS, coefficients per region and curve, by CORRECTION: 0 for a CORRECTION no row has (no
// words and no stage; acore_config_check stops elaboration).
function integer acore_terms(input integer f_correction, input integer f_degree);
  case (f_correction)
    0: acore_terms = acore_terms_poly(f_degree);  // poly
    1: acore_terms = acore_terms_poly2d(f_degree);  // poly2d
    2: acore_terms = 0;  // none
    default: acore_terms = 0;  // no mode
  endcase
endfunction

// The correction stage's latency by CORRECTION (its function in rtl/acore_derived.vh, 0 without
// a stage).
function integer acore_correction_latency(input integer f_correction, input integer f_degree, input integer f_s_w);
  case (f_correction)
    0: acore_correction_latency = acore_poly_latency(f_degree, f_s_w);  // poly
    1: acore_correction_latency = acore_poly2d_latency(f_degree, f_s_w);  // poly2d
    2: acore_correction_latency = 0;  // none
    default: acore_correction_latency = 0;  // no mode
  endcase
endfunction

// 1 when acore_top builds the mode folded (FOLD > 1).
function integer acore_mode_on_folded(input integer f_correction);
  case (f_correction)
    0: acore_mode_on_folded = 1;  // poly
    2: acore_mode_on_folded = 1;  // none
    default: acore_mode_on_folded = 0;  // not folded, or no mode
  endcase
endfunction

// 1 when FOLD is a fold factor of acore_top (fold_values(), model/ip/core/datapath_config.hpp:
// 1, 2, 4, 8, 16, 32): 1 the pipeline, the others the folded datapath.
function integer acore_fold_legal(input integer f_fold);
  case (f_fold)
    1: acore_fold_legal = 1;
    2: acore_fold_legal = 1;
    4: acore_fold_legal = 1;
    8: acore_fold_legal = 1;
    16: acore_fold_legal = 1;
    32: acore_fold_legal = 1;
    default: acore_fold_legal = 0;
  endcase
endfunction
