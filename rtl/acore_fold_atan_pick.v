// SPDX-License-Identifier: MIT
// acore_fold_atan_pick: the folded CORDIC's arctangent word for the iteration a phase index names,
// picked from the words on a bus (the register file's arctangent words when they are not read from
// block RAM). Iteration i0 + idx_i's word, zero-extended to Z_W bits; iterations at K and beyond
// (phases past the last iteration: read by nobody) give 0. One picker for both forms of
// acore_fold_cordic: the units' (a phase an iteration) and the split form's (two phases an
// iteration: the caller drops the index's low bit).
`resetall
`default_nettype none

module acore_fold_atan_pick #(
  // Arctangent words on the bus, AT_W bits each (word i at bits [i AT_W +: AT_W]).
  parameter integer K = 16,
  parameter integer AT_W = 18,
  // Width of the picked word (>= AT_W).
  parameter integer Z_W = 20,
  // Entries the index reaches (iterations i0 .. i0 + N - 1) and the index's width.
  parameter integer N = 16,
  parameter integer IDX_W = 4,
  // The iteration of index 0.
  parameter integer I0 = 0
) (
  input  wire [K*AT_W-1:0] atan_i,
  input  wire [IDX_W-1:0]  idx_i,
  output wire [Z_W-1:0]    at_o
);

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(Z_W >= AT_W && N >= 1 && N <= (1 << IDX_W)), .VALUE(N),
    .MSG("illegal parameter: acore_fold_atan_pick: needs Z_W >= AT_W and 1 <= N <= 2^IDX_W"))
    N_must_fit_the_index ();

  wire [Z_W-1:0] at_p [0:N-1];
  genvar p;
  generate
    for (p = 0; p < N; p = p + 1) begin : g_ph
      if (I0 + p < K) begin : g_at
        assign at_p[p] = {{(Z_W-AT_W){1'b0}}, atan_i[(I0 + p) * AT_W +: AT_W]};
      end else begin : g_noat
        assign at_p[p] = {Z_W{1'b0}};
      end
    end
  endgenerate
  assign at_o = at_p[idx_i];
  // A unit reads only its own iterations' words of the shared bus.
  wire unused_bus = ^atan_i;

endmodule

`resetall
