// SPDX-License-Identifier: MIT
// acore_shift_add_mul: the adder/shifter multiplier of model/ip/core/fixed_point.hpp shift_add_mul():
//   p = sum over bits j of b of  b[j] ? (a >>> (RSHIFT - j)) : 0      (a << (j - RSHIFT) if j > RSHIFT)
// every partial product truncated (floor) on its own; with B_SIGNED the top bit of b weighs
// -2^(B_W-1), so its partial product is subtracted. No multiplier: B_W partial products (AND
// gates) summed by a binary adder tree with a register after every level.
//
//   cycle 0: a_i, b_i -> partial products -> level-1 adders -> reg
//   cycle 1..LATENCY-1: one tree level per clock; p_o valid LATENCY advancing clocks after a_i/b_i
//
// Sums are computed modulo 2^P_W: intermediate wrap-around is harmless as long as the exact result
// fits P_W bits, which the elaboration check enforces.
//
// MULT = 1 (hardware multipliers, fixed_point.hpp hw_mul()): p = (a * b) >>> RSHIFT, the exact
// product floored once, on acore_hw_mul with the same LATENCY, so the stage around it keeps its
// schedule (the DSP's own pipeline registers absorb the first of them where the device has them).
`resetall
`default_nettype none

module acore_shift_add_mul #(
  // Width of a, signed.
  parameter integer A_W = 18,
  // Width of b.
  parameter integer B_W = 18,
  // 1: b is two's complement; 0: b is unsigned.
  parameter integer B_SIGNED = 0,
  // Right shift of the product (fraction bits of b).
  parameter integer RSHIFT = 9,
  // Width of the product, signed; must hold the exact result.
  parameter integer P_W = 30,
  // 0: adders and shifters (every partial product floored); 1: the multiply operator (DSP blocks;
  // the full product floored once).
  parameter integer MULT = 0
) (
  input  wire           clk_i,
  input  wire           en_i,
  input  wire [A_W-1:0] a_i,
  input  wire [B_W-1:0] b_i,
  output wire [P_W-1:0] p_o
);

`include "acore_derived.vh"

  // Derived, do not override: tree levels = pipeline latency.
  localparam integer LATENCY = acore_shift_add_mul_latency(B_W);
  localparam integer LEVELS = LATENCY;
  // Bits the exact product can need: |a| 2^(B_W - RSHIFT) plus floor slack, plus sign.
  localparam integer NEED_W = A_W + ((B_W > RSHIFT) ? (B_W - RSHIFT) : 0) + 1;

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(P_W >= NEED_W), .VALUE(P_W),
    .MSG("illegal parameter: acore_shift_add_mul: P_W cannot hold the product"))
    P_W_must_hold_the_product ();
  acore_check #(.OK(B_W >= 2), .VALUE(B_W),
    .MSG("illegal parameter: acore_shift_add_mul: B_W must be >= 2"))
    B_W_must_be_at_least_2 ();
  acore_check #(.OK(MULT == 0 || MULT == 1), .VALUE(MULT),
    .MSG("illegal parameter: acore_shift_add_mul: MULT must be 0 or 1"))
    MULT_must_be_0_or_1 ();

  genvar l, k;
  generate
    if (MULT != 0) begin : g_hw
      acore_hw_mul #(
        .A_W(A_W), .B_W(B_W), .B_SIGNED(B_SIGNED), .RSHIFT(RSHIFT), .P_W(P_W), .DEPTH(LATENCY)
      ) u_hw (
        .clk_i(clk_i), .en_i(en_i), .a_i(a_i), .b_i(b_i), .p_o(p_o));
    end else begin : g_tree
      // Entries per level: level l holds ceil(B_W / 2^l) partial sums; unused slots are zero.
      localparam integer LVL_W = B_W * P_W;
      wire [LVL_W-1:0] lvl [0:LEVELS];
      // Level 0: partial products, each a floor-shifted copy of a, gated by one bit of b.
      for (k = 0; k < B_W; k = k + 1) begin : g_pp
        wire [P_W-1:0] shifted;
        if (k > RSHIFT) begin : g_left
          wire [P_W-1:0] ext = {{(P_W-A_W){a_i[A_W-1]}}, a_i};
          assign shifted = ext << (k - RSHIFT);
        end else if (RSHIFT - k < A_W) begin : g_right
          assign shifted = {{(P_W-A_W+RSHIFT-k){a_i[A_W-1]}}, a_i[A_W-1:RSHIFT-k]};
        end else begin : g_sign
          assign shifted = {P_W{a_i[A_W-1]}};
        end
        localparam integer OFF = k * P_W;
        assign lvl[0][OFF +: P_W] = shifted & {P_W{b_i[k]}};
      end

      for (l = 1; l <= LEVELS; l = l + 1) begin : g_lvl
        localparam integer N_PREV = (B_W + (1 << (l - 1)) - 1) >> (l - 1);
        localparam integer N_THIS = (B_W + (1 << l) - 1) >> l;
        for (k = 0; k < B_W; k = k + 1) begin : g_node
          localparam integer OFF = k * P_W;
          localparam integer OFF_L = 2 * k * P_W;
          localparam integer OFF_R = (2 * k + 1) * P_W;
          if (k < N_THIS) begin : g_used
            reg [P_W-1:0] sum_q;
            wire [P_W-1:0] lhs = lvl[l-1][OFF_L +: P_W];
            if ((k << 1) + 1 < N_PREV) begin : g_pair
              wire [P_W-1:0] rhs = lvl[l-1][OFF_R +: P_W];
              // The signed top bit of b sits at index B_W-1 of level 0: subtract it.
              if (l == 1 && B_SIGNED != 0 && (k << 1) + 1 == B_W - 1) begin : g_sub
                always @(posedge clk_i) if (en_i) sum_q <= lhs - rhs;
              end else begin : g_add
                always @(posedge clk_i) if (en_i) sum_q <= lhs + rhs;
              end
            end else begin : g_single
              if (l == 1 && B_SIGNED != 0 && (k << 1) == B_W - 1) begin : g_neg
                always @(posedge clk_i) if (en_i) sum_q <= {P_W{1'b0}} - lhs;
              end else begin : g_pass
                always @(posedge clk_i) if (en_i) sum_q <= lhs;
              end
            end
            assign lvl[l][OFF +: P_W] = sum_q;
          end else begin : g_unused
            assign lvl[l][OFF +: P_W] = {P_W{1'b0}};
          end
        end
      end
      assign p_o = lvl[LEVELS][P_W-1:0];
    end
  endgenerate

endmodule

`resetall
