// SPDX-License-Identifier: MIT
// acore_derived.vh: every quantity the RTL derives from the datapath parameters, defined once as
// constant functions (evaluated at elaboration: no hardware), `include`d inside each module that
// needs one, after its port list. The register map (model/ip/core/datapath_config.hpp, the same
// addresses), the widths the stages share, each stage's LATENCY (the pipelined and the folded
// schedules) and each top's LATENCY, CYCLES and the samples it can hold. A module that declares a
// LATENCY takes it from here, and a schedule adds the same functions: no figure is computed twice.
// Arguments are named f_<parameter>: no module names a signal or genvar f_*.
//
// Constant products are written with `*` (and ceilings with `/`): they are evaluated at
// elaboration. The datapath itself multiplies on adders and shifters only; tb/lint/no_multiplier.py
// proves it on every registered build's netlist (no $mul, $macc, $div, $mod or $pow cell).

// The correction modes (CORRECTION): their constants ACORE_CORR_*, TERMS (acore_terms), the
// correction stage's latency (acore_correction_latency) and the tops that build each, generated
// from the model's mode table.
`include "acore_modes.vh"

// ---- widths ----

// D_W: c1 - c3 (pre-filter difference).
function integer acore_d_w(input integer f_in_w);
  acore_d_w = f_in_w + 1;
endfunction

// T_W: d - O, exact (scaler).
function integer acore_t_w(input integer f_d_w, input integer f_reg_w);
  acore_t_w = ((f_d_w > f_reg_w) ? f_d_w : f_reg_w) + 1;
endfunction

// MAG_W: the CORDIC's magnitude X_K >>> G for IN_W-bit inputs (the status window's width).
function integer acore_mag_w(input integer f_in_w);
  acore_mag_w = f_in_w + 2;
endfunction

// XY_W: the CORDIC's X/Y registers (|(x, y)| grows by the gain 1.65 and sqrt 2, plus G guard bits).
function integer acore_xy_w(input integer f_in_w, input integer f_g);
  acore_xy_w = f_in_w + 2 + f_g;
endfunction

// ACC_F, ACC_W: the Horner accumulator's fraction bits and width.
function integer acore_acc_f(input integer f_coef_f, input integer f_acc_g);
  acore_acc_f = f_coef_f + f_acc_g;
endfunction
function integer acore_acc_w(input integer f_coef_f, input integer f_acc_g, input integer f_acc_i);
  acore_acc_w = f_coef_f + f_acc_g + f_acc_i;
endfunction

// ---- the register map (docs/contracts.md, register image) ----
//   0, 1                        offsets O13, O24
//   2, 3                        amplitude reciprocals 1/A13, 1/A24
//   4 + TERMS (2 r + c) + t     polynomial word t of region r, curve c (none without correction)
//   then K words                atan(2^-i), i = 0..K-1
//   then 2 FOURIER_K + 1 words  Fourier a_0, a_1, b_1, .., a_K, b_K (FOURIER_K > 0)
//   then the ZERO word          the zero position (ZERO = 1), the last word

// Words per region and curve: acore_terms(CORRECTION, DEGREE) (rtl/acore_modes.vh).

// poly2d: the term of u^i v^j (i + j <= DEGREE), grouped by the power of u: (0,0), (0,1) .. (0,d),
// (1,0) .., (d,0).
function integer acore_term2d(input integer f_degree, input integer f_i, input integer f_j);
  acore_term2d = f_i * (f_degree + 1) - (f_i * (f_i - 1)) / 2 + f_j;
endfunction

function integer acore_poly_words(input integer f_terms, input integer f_regions);
  acore_poly_words = 2 * f_regions * f_terms;
endfunction

function integer acore_fourier_words(input integer f_fourier_k);
  acore_fourier_words = (f_fourier_k > 0) ? 2 * f_fourier_k + 1 : 0;
endfunction

// WORDS: every word of the map.
function integer acore_words(input integer f_terms, input integer f_regions, input integer f_k,
                             input integer f_fourier_k, input integer f_zero);
  acore_words = 4 + acore_poly_words(f_terms, f_regions) + f_k + acore_fourier_words(f_fourier_k) +
                ((f_zero != 0) ? 1 : 0);
endfunction

// Curve 0 = the sine curve c13, 1 = the cosine curve c24.
function integer acore_addr_offset(input integer f_curve);
  acore_addr_offset = f_curve;
endfunction

function integer acore_addr_recip(input integer f_curve);
  acore_addr_recip = 2 + f_curve;
endfunction

function integer acore_addr_poly(input integer f_terms, input integer f_region,
                                 input integer f_curve, input integer f_term);
  acore_addr_poly = 4 + f_terms * (2 * f_region + f_curve) + f_term;
endfunction

function integer acore_addr_atan(input integer f_terms, input integer f_regions, input integer f_i);
  acore_addr_atan = 4 + acore_poly_words(f_terms, f_regions) + f_i;
endfunction

// Fourier word j: 0 = a_0, acore_fourier_a(k) = a_k, acore_fourier_b(k) = b_k (k = 1..FOURIER_K).
function integer acore_addr_fourier(input integer f_terms, input integer f_regions,
                                    input integer f_k, input integer f_j);
  acore_addr_fourier = acore_addr_atan(f_terms, f_regions, f_k) + f_j;
endfunction
function integer acore_fourier_a(input integer f_harmonic);
  acore_fourier_a = 2 * f_harmonic - 1;
endfunction
function integer acore_fourier_b(input integer f_harmonic);
  acore_fourier_b = 2 * f_harmonic;
endfunction

function integer acore_addr_zero(input integer f_terms, input integer f_regions, input integer f_k,
                                 input integer f_fourier_k);
  acore_addr_zero = acore_addr_fourier(f_terms, f_regions, f_k, acore_fourier_words(f_fourier_k));
endfunction

// ---- stage latencies (advancing clocks from a stage's input to its output) ----

// acore_prefilter: one register.
function integer acore_prefilter_latency();
  acore_prefilter_latency = 1;
endfunction

// acore_shift_add_mul: one adder-tree level a clock over the B_W partial products.
function integer acore_shift_add_mul_latency(input integer f_b_w);
  acore_shift_add_mul_latency = (f_b_w > 1) ? $clog2(f_b_w) : 1;
endfunction

// acore_adder_tree: one level a clock over N terms.
function integer acore_adder_tree_latency(input integer f_n);
  acore_adder_tree_latency = $clog2(f_n);
endfunction

// acore_scaler: t = d - O, the multiplier, round, saturate.
function integer acore_scaler_latency(input integer f_reg_w);
  acore_scaler_latency = 1 + acore_shift_add_mul_latency(f_reg_w) + 2;
endfunction

// acore_region_select: magnitudes, then compare and select.
function integer acore_region_select_latency();
  acore_region_select_latency = 2;
endfunction

// acore_round_sub_sat: round, subtract, saturate.
function integer acore_round_sub_sat_latency();
  acore_round_sub_sat_latency = 3;
endfunction

// acore_poly_correct: the leading coefficient, DEGREE Horner steps (multiplier, add, saturate),
// then round, subtract, saturate.
function integer acore_poly_latency(input integer f_degree, input integer f_s_w);
  acore_poly_latency = 1 + f_degree * (acore_shift_add_mul_latency(f_s_w) + 2) +
                       acore_round_sub_sat_latency();
endfunction

// acore_poly2d_correct: u, v and the leading coefficients, two clocks to the outer chain's first
// step, DEGREE outer steps (the inner chains run beside them), round, subtract, saturate.
function integer acore_poly2d_latency(input integer f_degree, input integer f_s_w);
  acore_poly2d_latency = 3 + f_degree * (acore_shift_add_mul_latency(f_s_w) + 2) +
                         acore_round_sub_sat_latency();
endfunction

// Stage 4 by CORRECTION: acore_correction_latency (rtl/acore_modes.vh), each mode's function above.

// acore_cordic: normalization and pre-rotation (5 clocks with NORM, else 1), K stages (two clocks
// each with SPLIT), the output rounding. acore_fold_cordic: acore_fold_cordic_latency.
function integer acore_cordic_latency(input integer f_k, input integer f_norm,
                                      input integer f_split);
  acore_cordic_latency = ((f_norm != 0) ? 5 : 1) + f_k * ((f_split != 0) ? 2 : 1) + 1;
endfunction
// acore_fold_cordic: the split form (two clocks an iteration, one barrel shifter) where a vector's
// N clocks hold 2K, and its latency (acore_cordic's, with SPLIT in that form).
function integer acore_fold_cordic_split(input integer f_k, input integer f_n);
  acore_fold_cordic_split = (f_n >= 2 * f_k) ? 1 : 0;
endfunction
function integer acore_fold_cordic_latency(input integer f_k, input integer f_n);
  acore_fold_cordic_latency = acore_cordic_latency(f_k, 0, acore_fold_cordic_split(f_k, f_n));
endfunction
// acore_fold_datapath: 1 when its angle, magnitude, region and overflow hold from valid_o until the
// next sample's (the split CORDIC's output registers, the sparse region and overflow lines of
// acore_fold_lean), so the top may take them a clock later with no register of its own.
function integer acore_fold_out_held(input integer f_k, input integer f_fold);
  acore_fold_out_held = (acore_fold_cordic_split(f_k, f_fold) != 0 &&
                         acore_fold_lean(f_fold) != 0) ? 1 : 0;
endfunction

// acore_cordic_rotate: one clock a stage.
function integer acore_cordic_rotate_latency(input integer f_m);
  acore_cordic_rotate_latency = f_m;
endfunction

// acore_fourier_correct: bits of the constant k of k theta (>= 2).
function integer acore_fourier_kb(input integer f_fourier_k);
  acore_fourier_kb = ($clog2(f_fourier_k + 1) > 2) ? $clog2(f_fourier_k + 1) : 2;
endfunction

// acore_fourier_correct (0 without it): k theta, quadrant and start vector, the rotations, the
// sum of the FOURIER_K + 1 terms, round and subtract.
function integer acore_fourier_latency(input integer f_fourier_k, input integer f_fourier_m);
  acore_fourier_latency = (f_fourier_k > 0) ?
      acore_shift_add_mul_latency(acore_fourier_kb(f_fourier_k)) + 1 +
      acore_cordic_rotate_latency(f_fourier_m) + acore_adder_tree_latency(f_fourier_k + 1) + 1 : 0;
endfunction

// The top's output register (zero position, status window).
function integer acore_out_latency();
  acore_out_latency = 1;
endfunction

// ---- the folded schedule (FOLD > 1: acore_fold_*.v) ----

// From this FOLD on, the folded datapath trades a few flops for block RAMs (an item every FOLD/2
// clocks leaves time for it): its long delay lines (each curve to the Horner chain's subtraction,
// the region to the output, the Horner steps' argument) are acore_sparse_delay, a few words of
// flops instead of a block RAM each, and the scaler reads a curve's offset and reciprocal on one
// port, one clock apart (one clock more of latency). Below it, block RAM where it fits, as
// acore_fold_datapath.v gives the blocks out.
function integer acore_fold_lean(input integer f_fold);
  acore_fold_lean = (f_fold >= 16) ? 1 : 0;
endfunction

// acore_fold_mul: bits of b a clock (B_W over F clocks), the form, the latency from start_i to p_o
// and the clock init_i is read.
function integer acore_fold_mul_b(input integer f_b_w, input integer f_f);
  acore_fold_mul_b = (f_b_w + f_f - 1) / f_f;
endfunction
// 1: two bits of b a clock accumulated in place (the addend one clock before the first group),
// done in time for the next product: the accumulator is cleared at start_i, takes the addend on
// clock 1 and the ceil(B_W / 2) groups on clocks 2 on, and holds the result until the next start.
function integer acore_fold_mul_seq(input integer f_b_w, input integer f_f);
  acore_fold_mul_seq = (f_f > 1 && acore_fold_mul_b(f_b_w, f_f) == 2 &&
                        (f_b_w + 1) / 2 + 2 <= f_f) ? 1 : 0;
endfunction
function integer acore_fold_mul_latency(input integer f_b_w, input integer f_f);
  acore_fold_mul_latency = (f_f == 1) ? acore_shift_add_mul_latency(f_b_w) + 1 :
                           (acore_fold_mul_seq(f_b_w, f_f) != 0) ? f_f :
                                        $clog2(acore_fold_mul_b(f_b_w, f_f)) + 1 + f_f;
endfunction
function integer acore_fold_mul_init_at(input integer f_b_w, input integer f_f);
  acore_fold_mul_init_at = (acore_fold_mul_seq(f_b_w, f_f) != 0) ? 1 :
                           acore_fold_mul_latency(f_b_w, f_f) - f_f;
endfunction
// The in-place form with LOAD (the addend loaded into the accumulator at start_i, the groups on
// the clocks after): clocks from start_i until the result is in the accumulator, ceil(B_W / 2) + 1
// (a Horner chain's step on one multiplier: acore_fold_poly_chain).
function integer acore_fold_mul_load_step(input integer f_b_w);
  acore_fold_mul_load_step = (f_b_w + 1) / 2 + 1;
endfunction

// acore_fold_scaler: t = d - O, the folded multiplier (rounding constant as its addend), saturate.
// (acore_fold_lean: the reciprocal one clock after the offset, the product one clock later.)
function integer acore_fold_scaler_latency(input integer f_reg_w, input integer f_f);
  acore_fold_scaler_latency = 1 + acore_fold_mul_latency(f_reg_w, f_f) + 1 +
                              acore_fold_lean(2 * f_f);
endfunction

// acore_fold_poly: 1 when a_n and the first Horner step's word share one read port. An item reads
// a_n at its start and the first step's word INIT_AT + 1 clocks later (INIT_AT: when the
// multiplier adds the word), and items come F clocks apart at least, so no two of these reads ever
// fall on one clock when INIT_AT + 1 < F (from F = 8 on at S_W = 18).
function integer acore_fold_poly_share(input integer f_s_w, input integer f_f);
  acore_fold_poly_share = (acore_fold_mul_init_at(f_s_w, f_f) + 1 < f_f) ? 1 : 0;
endfunction
// acore_fold_poly: its coefficient read ports (a_n, then one per Horner step; a_n and the first
// step's on one with acore_fold_poly_share).
function integer acore_fold_poly_ports(input integer f_degree, input integer f_s_w, input integer f_f);
  acore_fold_poly_ports = f_degree + 1 - acore_fold_poly_share(f_s_w, f_f);
endfunction

// acore_fold_poly with PAIRED (the folded datapath's items: a sample's two items F clocks apart,
// samples 2F clocks apart at least, at arbitrary gaps): a static schedule of its reads over fewer
// ports. Read i = 2 k + c is read k (0: a_n at the item's start; m + 1: step m's word, INIT_AT - 1
// clocks into step m, which starts 2 + m (ML + 1) clocks after its item; INIT_AT =
// acore_fold_mul_init_at) of item c (0 the first),
// at acore_fold_poly_pair_at(i) clocks after the pair's first item starts.
function integer acore_fold_poly_pair_t(input integer f_i, input integer f_ml, input integer f_ia,
                                        input integer f_f);
  acore_fold_poly_pair_t = (f_i % 2) * f_f + ((f_i < 2) ? 0 : 2 + (f_i / 2 - 1) * (f_ml + 1) + f_ia - 1);
endfunction
function integer acore_fold_poly_pair_at(input integer f_i, input integer f_s_w, input integer f_f);
  acore_fold_poly_pair_at = acore_fold_poly_pair_t(f_i, acore_fold_mul_latency(f_s_w, f_f),
                                                   acore_fold_mul_init_at(f_s_w, f_f), f_f);
endfunction
// Read f_i's port: the window of 2F clocks (from the pair's first read) it falls in. Reads of two
// samples are 2F clocks apart or more plus their offsets' difference, so two reads of one window
// (offsets less than 2F apart, and distinct: acore_fold_poly_pair_ok) never meet on a clock,
// whatever the gaps between the samples. f_i = -1: the number of ports (the last read is the
// second item's last step).
function integer acore_fold_poly_pair_port(input integer f_i, input integer f_degree,
                                           input integer f_s_w, input integer f_f);
  acore_fold_poly_pair_port = (f_i < 0) ?
    acore_fold_poly_pair_at(2 * f_degree + 1, f_s_w, f_f) / (2 * f_f) + 1 :
    acore_fold_poly_pair_at(f_i, f_s_w, f_f) / (2 * f_f);
endfunction
// 1 when the windowed schedule holds: no two reads at one clock, and no window (port) without a
// read. (The multiplier's latency computed once: Yosys evaluates constant functions slowly.)
function integer acore_fold_poly_pair_ok(input integer f_degree, input integer f_s_w,
                                         input integer f_f);
  integer f_a, f_b, f_p, f_any, f_ml, f_ia, f_np;
  begin
    acore_fold_poly_pair_ok = 1;
    f_ml = acore_fold_mul_latency(f_s_w, f_f);
    f_ia = acore_fold_mul_init_at(f_s_w, f_f);
    f_np = acore_fold_poly_pair_t(2 * f_degree + 1, f_ml, f_ia, f_f) / (2 * f_f) + 1;
    for (f_a = 0; f_a < 2 * (f_degree + 1); f_a = f_a + 1)
      for (f_b = f_a + 1; f_b < 2 * (f_degree + 1); f_b = f_b + 1)
        if (acore_fold_poly_pair_t(f_a, f_ml, f_ia, f_f) == acore_fold_poly_pair_t(f_b, f_ml, f_ia, f_f))
          acore_fold_poly_pair_ok = 0;
    for (f_p = 0; f_p < f_np; f_p = f_p + 1) begin
      f_any = 0;
      for (f_a = 0; f_a < 2 * (f_degree + 1); f_a = f_a + 1)
        if (acore_fold_poly_pair_t(f_a, f_ml, f_ia, f_f) / (2 * f_f) == f_p) f_any = 1;
      if (f_any == 0) acore_fold_poly_pair_ok = 0;
    end
  end
endfunction
// 1 when acore_fold_poly with PAIRED uses the windowed schedule: paired items from
// acore_fold_lean() on (F >= 8), the schedule holds and it needs fewer ports than one port a read
// (acore_fold_poly_ports; at S_W = 18: 2 instead of 3 at F = 16, none fewer at F = 8).
function integer acore_fold_poly_paired(input integer f_paired, input integer f_degree,
                                        input integer f_s_w, input integer f_f);
  begin
    acore_fold_poly_paired = 0;
    if (f_paired != 0 && acore_fold_lean(2 * f_f) != 0 && acore_fold_poly_share(f_s_w, f_f) != 0)
      if (acore_fold_poly_pair_port(-1, f_degree, f_s_w, f_f) <
          acore_fold_poly_ports(f_degree, f_s_w, f_f))
        acore_fold_poly_paired = acore_fold_poly_pair_ok(f_degree, f_s_w, f_f);
  end
endfunction
// acore_fold_poly with PAIRED: 1 when each item's whole Horner chain runs on one multiplier of
// its own (item c of a sample on multiplier c), its steps one after another on the same
// accumulator (acore_fold_mul's LOAD form: the addend loaded at a step's start, the groups right
// after, the next step's operand the saturated result). An item loads a_n into the accumulator one
// clock after its start and starts its DEGREE steps the clock after; its result is final
// 2 + DEGREE * acore_fold_mul_load_step clocks after its start, and must be read before the next
// item on that multiplier (2F clocks after this one at the earliest) loads its a_n, at its clock
// 1: DEGREE steps in 2F - 1 clocks (F = 16 at S_W = 18 and DEGREE <= 3). Adders and shifters only
// (MULT = 0), two bits of the argument a clock (acore_fold_mul_seq).
function integer acore_fold_poly_chain(input integer f_paired, input integer f_degree,
                                       input integer f_s_w, input integer f_f, input integer f_mult);
  acore_fold_poly_chain = (f_paired != 0 && f_mult == 0 && acore_fold_mul_seq(f_s_w, f_f) != 0 &&
                           f_degree * acore_fold_mul_load_step(f_s_w) <= 2 * f_f - 1) ? 1 : 0;
endfunction
// Its read ports with PAIRED: with acore_fold_poly_chain one a multiplier (an item's reads are
// less than 2F clocks apart, the next item on the multiplier 2F clocks later at the earliest).
function integer acore_fold_poly_ports_paired(input integer f_paired, input integer f_degree,
                                              input integer f_s_w, input integer f_f,
                                              input integer f_mult);
  acore_fold_poly_ports_paired =
    (acore_fold_poly_chain(f_paired, f_degree, f_s_w, f_f, f_mult) != 0) ? 2 :
    (acore_fold_poly_paired(f_paired, f_degree, f_s_w, f_f) != 0) ?
    acore_fold_poly_pair_port(-1, f_degree, f_s_w, f_f) : acore_fold_poly_ports(f_degree, f_s_w, f_f);
endfunction

// acore_fold_poly: a_n addressed and read, DEGREE steps (folded multiplier with a_j as addend,
// saturate), round, subtract, saturate; with acore_fold_poly_chain, a_n read and loaded, DEGREE
// chained steps of acore_fold_mul_load_step clocks, then round, subtract, saturate.
function integer acore_fold_poly_latency(input integer f_paired, input integer f_degree,
                                         input integer f_s_w, input integer f_f,
                                         input integer f_mult);
  acore_fold_poly_latency = (acore_fold_poly_chain(f_paired, f_degree, f_s_w, f_f, f_mult) != 0) ?
    2 + f_degree * acore_fold_mul_load_step(f_s_w) + acore_round_sub_sat_latency() :
    2 + f_degree * (acore_fold_mul_latency(f_s_w, f_f) + 1) + acore_round_sub_sat_latency();
endfunction

// The folded datapath's schedule (acore_fold_datapath.v), in clocks after the accepting edge: the
// c24 item follows the c13 item by H = FOLD/2 clocks; R: the region select's output (c13 item into
// the correction); C: both corrected curves into the CORDIC (R without correction).
function integer acore_fold_r(input integer f_reg_w, input integer f_fold);
  acore_fold_r = (f_fold / 2) + acore_fold_scaler_latency(f_reg_w, f_fold / 2) +
                 acore_region_select_latency();
endfunction
function integer acore_fold_c(input integer f_reg_w, input integer f_s_w,
                              input integer f_correction, input integer f_degree,
                              input integer f_fold, input integer f_mult);
  acore_fold_c = acore_fold_r(f_reg_w, f_fold) + ((f_correction == ACORE_CORR_NONE) ? 0 :
                 (f_fold / 2) + acore_fold_poly_latency(1, f_degree, f_s_w, f_fold / 2, f_mult));
endfunction
// The accepting edge to valid_o, in clocks after it, minus one (v_q[LATENCY]).
function integer acore_fold_datapath_latency(input integer f_reg_w, input integer f_s_w,
                                             input integer f_correction, input integer f_degree,
                                             input integer f_k, input integer f_fold,
                                             input integer f_mult);
  acore_fold_datapath_latency = acore_fold_c(f_reg_w, f_s_w, f_correction, f_degree, f_fold, f_mult) +
                                acore_fold_cordic_latency(f_k, f_fold);
endfunction

// acore_fold_cordic: stage units (N iterations each), and the width of an iteration index.
function integer acore_fold_cordic_units(input integer f_k, input integer f_n);
  acore_fold_cordic_units = (f_k + f_n - 1) / f_n;
endfunction
function integer acore_fold_cordic_idx_w(input integer f_k, input integer f_n);
  acore_fold_cordic_idx_w = $clog2(acore_fold_cordic_units(f_k, f_n) * f_n);
endfunction

// acore_fold_fifo: a word is on its output two clocks after the clock it is written in (empty
// FIFO); it holds FIFO_DEPTH words (one block RAM deep).
function integer acore_fold_fifo_latency();
  acore_fold_fifo_latency = 2;
endfunction
function integer acore_fold_fifo_depth();
  acore_fold_fifo_depth = 256;
endfunction

// acore_sparse_delay: its buffer words, ceil((DEPTH - 1) / GAP), at least 2 (its pointers wrap
// at that count: a power of two costs no compare, any other count one per pointer, against a
// word of flops per bit a power of two could waste).
function integer acore_sparse_slots(input integer f_depth, input integer f_gap);
  begin
    acore_sparse_slots = (f_depth - 1 + f_gap - 1) / f_gap;
    if (acore_sparse_slots < 2) acore_sparse_slots = 2;
  end
endfunction

// An HX8K's iCE40 block RAMs (SB_RAM40_4K), the folded datapath's budget.
function integer acore_hx8k_blocks();
  acore_hx8k_blocks = 32;
endfunction

// ---- the tops ----

// acore_top builds the folded datapath for a legal folded configuration only (FOLD > 1 and a
// value of acore_fold_legal(), a mode the table folds, no Fourier stage); otherwise the pipeline,
// and acore_config_check stops an illegal one.
function integer acore_folded(input integer f_fold, input integer f_correction,
                              input integer f_fourier_k);
  acore_folded = ((f_fold != 1 && acore_fold_legal(f_fold) != 0) &&
                  acore_mode_on_folded(f_correction) != 0 && f_fourier_k == 0) ? 1 : 0;
endfunction

// acore_top's LATENCY: pipelined, the stages in a row; folded, the accepting edge to out_valid_o
// with the output FIFO empty (the accepting clock, the datapath, the output register, the FIFO).
function integer acore_top_latency(input integer f_reg_w, input integer f_s_w,
                                   input integer f_correction, input integer f_degree,
                                   input integer f_k, input integer f_fourier_k,
                                   input integer f_fourier_m, input integer f_fold,
                                   input integer f_mult);
  acore_top_latency = (acore_folded(f_fold, f_correction, f_fourier_k) != 0) ?
      1 + acore_fold_datapath_latency(f_reg_w, f_s_w, f_correction, f_degree, f_k, f_fold, f_mult) +
      acore_out_latency() + acore_fold_fifo_latency() :
      acore_prefilter_latency() + acore_scaler_latency(f_reg_w) + acore_region_select_latency() +
      acore_correction_latency(f_correction, f_degree, f_s_w) + acore_cordic_latency(f_k, 0, 0) +
      acore_fourier_latency(f_fourier_k, f_fourier_m) + acore_out_latency();
endfunction

// acore_top's clocks per sample at full rate.
function integer acore_top_cycles(input integer f_fold);
  acore_top_cycles = f_fold;
endfunction

// The most samples acore_top holds at once (accepted, not yet delivered): one per pipeline stage;
// folded, its credit counter admits a sample only while the output FIFO can take every one.
function integer acore_top_capacity(input integer f_reg_w, input integer f_s_w,
                                    input integer f_correction, input integer f_degree,
                                    input integer f_k, input integer f_fourier_k,
                                    input integer f_fourier_m, input integer f_fold);
  acore_top_capacity = (acore_folded(f_fold, f_correction, f_fourier_k) != 0) ?
      acore_fold_fifo_depth() :
      acore_top_latency(f_reg_w, f_s_w, f_correction, f_degree, f_k, f_fourier_k, f_fourier_m,
                        f_fold, 0);  // (pipelined: MULT leaves the latency as it is)
endfunction

// acore_serial_top: clocks per sample (the schedule in acore_serial_ctrl.v: 22 single operations,
// the ZR operation with ZERO, 3 per CORDIC iteration; with MULT = 0 REG_W scaling bits per curve and
// S_W + 2 per Horner step and curve, with MULT = 1 one scaling product per curve (2 clocks) and per
// curve a load, 2 clocks per Horner step and the bubble after the last, less one: 4 + 4 DEGREE),
// and from the accepting clock to out_valid_o.
function integer acore_serial_cycles(input integer f_reg_w, input integer f_s_w,
                                     input integer f_degree, input integer f_k,
                                     input integer f_zero, input integer f_mult);
  acore_serial_cycles = 22 + ((f_zero != 0) ? 1 : 0) + 3 * f_k +
                        ((f_mult != 0) ? 4 + 4 * f_degree
                                       : 2 * f_reg_w + 2 * f_degree * (f_s_w + 2));
endfunction
function integer acore_serial_latency(input integer f_reg_w, input integer f_s_w,
                                      input integer f_degree, input integer f_k,
                                      input integer f_zero, input integer f_mult);
  acore_serial_latency = acore_serial_cycles(f_reg_w, f_s_w, f_degree, f_k, f_zero, f_mult) + 1;
endfunction

// The serial core holds one sample in work and one result waiting for out_ready_i.
function integer acore_serial_capacity();
  acore_serial_capacity = 2;
endfunction

// ---- the tracking observer (rtl/acore_track.v) ----

// Its bandwidth codes: gains 2^-k and 2^-(2k+1) of an error with FRAC_W fraction bits; the
// integral gain's shift 2k + 1 stays below FRAC_W, so the slowest code still moves the velocity.
function integer acore_track_k_min();
  acore_track_k_min = 2;
endfunction
function integer acore_track_k_max(input integer f_frac_w);
  acore_track_k_max = (f_frac_w - 1) / 2;
endfunction
// Clocks from a sample taken to its result (the loop, the v * D partial sums, the output register).
function integer acore_track_latency(input integer f_loop_clocks);
  acore_track_latency = 2 + f_loop_clocks;
endfunction
// The time-shared observer (SERIAL = 1: one adder, the shifts one bit a clock): clocks from a sample
// taken to its result, which are also its clocks per sample (it takes the next sample in the clock
// its result appears). Its fixed schedule (rtl/acore_track.v): 4 clocks to the prediction and the
// error; the loop, P_W - 1 shifts of the error (its bits leave one a clock for the loss-of-tracking
// comparison) and two pauses for the updates; one clearing the accumulator; v * D over the
// D_W = LEAD_W + 10 bits of D with the compensated angle added in two more steps; three for the
// rounding; the output register.
function integer acore_track_serial_cycles(input integer f_angle_w, input integer f_frac_w,
                                           input integer f_lead_w);
  acore_track_serial_cycles = 4 + (f_angle_w + f_frac_w + 1) + 1 + (f_lead_w + 10 + 2) + 3 + 1;
endfunction
// The word-serial observer (SERIAL = 2): the bits of D = COMP_LATENCY + LEAD / 2^LEAD_F (LEAD_F
// fraction bits) that can be nonzero, and its clocks from a sample taken to its result, which are
// also its clocks per sample. Its fixed schedule (rtl/acore_track.v): five clocks of the loop (the
// prediction, the error, two shifts with phi's update between, v's update), the product v * D
// PROD_BITS bits of D a clock, the compensated angle, the output register.
function integer acore_track_word_d_w(input integer f_comp_latency, input integer f_lead_w,
                                      input integer f_lead_f);
  acore_track_word_d_w = $clog2(f_comp_latency * (2 ** f_lead_f) + (2 ** f_lead_w));
endfunction
function integer acore_track_word_cycles(input integer f_comp_latency, input integer f_lead_w,
                                         input integer f_lead_f, input integer f_prod_bits);
  acore_track_word_cycles = 5 + (acore_track_word_d_w(f_comp_latency, f_lead_w, f_lead_f) +
                                 f_prod_bits - 1) / f_prod_bits + 1 + 1;
endfunction
// The fewest bits of D a clock (PROD_BITS, 1..4) with which the word-serial observer takes a sample
// every f_cycles clocks; 0 when none does.
function integer acore_track_word_prod_bits(input integer f_cycles, input integer f_comp_latency,
                                            input integer f_lead_w, input integer f_lead_f);
  integer r;
  begin
    acore_track_word_prod_bits = 0;
    for (r = 4; r >= 1; r = r - 1)
      if (acore_track_word_cycles(f_comp_latency, f_lead_w, f_lead_f, r) <= f_cycles)
        acore_track_word_prod_bits = r;
  end
endfunction
// The time-shared observer with coarse shifts (SERIAL = 3: one adder, the error shifted by
// SHIFT_BITS or by one bit a clock, loss of tracking from one sum on the adder): shifting by n
// bits takes n / SHIFT_BITS + n % SHIFT_BITS clocks.
function integer acore_track_shift_steps(input integer f_n, input integer f_b);
  acore_track_shift_steps = f_n / f_b + f_n % f_b;
endfunction
// Its loop's clocks: the error shifted by k, phi's update, by k + 1 more, v's update, for the
// slowest bandwidth code (the first sample after reset shifts by 0 and k + 1: never more).
function integer acore_track_shift_loop(input integer f_frac_w, input integer f_b);
  integer k, n;
  begin
    acore_track_shift_loop = 0;
    for (k = acore_track_k_min(); k <= acore_track_k_max(f_frac_w); k = k + 1) begin
      n = acore_track_shift_steps(k, f_b) + acore_track_shift_steps(k + 1, f_b) + 2;
      if (n > acore_track_shift_loop) acore_track_shift_loop = n;
    end
  end
endfunction
// Its clocks from a sample taken to its result, which are also its clocks per sample. Its fixed
// schedule (rtl/acore_track.v, g_shf): 3 clocks to the error (one idle); one to the loss of
// tracking; the loop; 2 to the next sample's prediction; v * (D - 1) over D's DE_W nonzero bits
// with the phi register added in two more steps (one without an addition); the compensated angle
// with the output's valid; the output register.
function integer acore_track_shift_cycles(input integer f_frac_w, input integer f_comp_latency,
                                          input integer f_lead_w, input integer f_lead_f,
                                          input integer f_b);
  acore_track_shift_cycles = 4 + acore_track_shift_loop(f_frac_w, f_b) + 2 +
                             (acore_track_word_d_w(f_comp_latency, f_lead_w, f_lead_f) + 2) + 1 + 1;
endfunction
// The fewest bits a coarse shift takes (SHIFT_BITS, 2..8) with which SERIAL = 3 takes a sample
// every f_cycles clocks; 0 when none does.
function integer acore_track_shift_bits(input integer f_cycles, input integer f_frac_w,
                                        input integer f_comp_latency, input integer f_lead_w,
                                        input integer f_lead_f);
  integer b;
  begin
    acore_track_shift_bits = 0;
    for (b = 8; b >= 2; b = b - 1)
      if (acore_track_shift_cycles(f_frac_w, f_comp_latency, f_lead_w, f_lead_f, b) <= f_cycles)
        acore_track_shift_bits = b;
  end
endfunction
// The latency the observer compensates (COMP_LATENCY), in whole samples: a top's LATENCY in clocks
// over its clocks per sample at full rate, rounded down (the rest of a sample, and the observer's
// own clocks, are the LEAD register's: LEAD is unsigned, so the whole part must not overshoot).
function integer acore_comp_latency(input integer f_latency, input integer f_cycles);
  acore_comp_latency = f_latency / f_cycles;
endfunction
