// SPDX-License-Identifier: MIT
// acore_adder_tree: the sum of N signed W-bit terms modulo 2^W, a binary tree of adders with a
// register after every level (one carry chain per clock). Used where the sum's value is only
// needed modulo 2^W (angles: modulo one turn) or provably fits W bits.
//
//   terms_i = {t_{N-1}, ..., t_1, t_0} (t_0 in the low bits) -> sum_o = (t_0 + ... + t_{N-1}) mod 2^W
//   LATENCY = clog2(N) advancing clocks
`resetall
`default_nettype none

module acore_adder_tree #(
  // Number of terms, >= 2.
  parameter integer N = 4,
  // Width of a term and of the sum.
  parameter integer W = 16
) (
  input  wire           clk_i,
  // Pipeline advance (the whole pipeline stalls together).
  input  wire           en_i,
  input  wire [N*W-1:0] terms_i,
  output wire [W-1:0]   sum_o
);

`include "acore_derived.vh"

  // Derived, do not override.
  localparam integer LATENCY = acore_adder_tree_latency(N);
  localparam integer LEVELS = LATENCY;  // one level a clock
  localparam integer BUS_W = N * W;

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(N >= 2), .VALUE(N),
    .MSG("illegal parameter: acore_adder_tree: N must be >= 2"))
    N_must_be_at_least_2 ();

  // Level l holds ceil(N / 2^l) partial sums; unused slots are zero.
  wire [BUS_W-1:0] lvl [0:LEVELS];
  assign lvl[0] = terms_i;

  genvar l, k;
  generate
    for (l = 1; l <= LEVELS; l = l + 1) begin : g_lvl
      localparam integer N_PREV = (N + (1 << (l - 1)) - 1) >> (l - 1);
      localparam integer N_THIS = (N + (1 << l) - 1) >> l;
      for (k = 0; k < N; k = k + 1) begin : g_node
        localparam integer OFF = k * W;
        localparam integer OFF_L = 2 * k * W;
        localparam integer OFF_R = (2 * k + 1) * W;
        if (k < N_THIS) begin : g_used
          reg [W-1:0] sum_q;
          if ((k << 1) + 1 < N_PREV) begin : g_pair
            always @(posedge clk_i) if (en_i) sum_q <= lvl[l-1][OFF_L +: W] + lvl[l-1][OFF_R +: W];
          end else begin : g_single
            always @(posedge clk_i) if (en_i) sum_q <= lvl[l-1][OFF_L +: W];
          end
          assign lvl[l][OFF +: W] = sum_q;
        end else begin : g_unused
          assign lvl[l][OFF +: W] = {W{1'b0}};
        end
      end
    end
  endgenerate

  assign sum_o = lvl[LEVELS][W-1:0];

endmodule

`resetall
