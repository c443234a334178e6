// SPDX-License-Identifier: MIT
// acore_hw_mul: the hardware multiplier of MULT = 1 (model/ip/core/fixed_point.hpp hw_mul()):
//   p = (a * b) >>> RSHIFT      the exact product, floored once
// a signed, b signed (B_SIGNED) or unsigned. The one `*` of the datapath: synthesis maps it onto
// DSP blocks (DSP48E1 on Xilinx 7, SB_MAC16 on the iCE40 UP5K, several for wide operands) and the
// first register into them. Every stage instantiates it only in its MULT = 1 generate branch
// (tb/lint/no_multiplier.py proves that a MULT = 0 build holds no multiplier cell, and that a
// MULT = 1 build holds them in this module only).
//
//   cycle 0: a_i, b_i -> product -> reg | DEPTH - 1 more registers | p_o, DEPTH advancing clocks later
`resetall
`default_nettype none

module acore_hw_mul #(
  // Width of a, signed.
  parameter integer A_W = 18,
  // Width of b.
  parameter integer B_W = 18,
  // 1: b is two's complement; 0: b is unsigned.
  parameter integer B_SIGNED = 0,
  // Right shift (floor) of the product, >= 0.
  parameter integer RSHIFT = 9,
  // Width of the result, signed; must hold the floored product (wrapped modulo 2^P_W otherwise).
  parameter integer P_W = 30,
  // Registers after the product, >= 1 (the latency).
  parameter integer DEPTH = 1
) (
  input  wire           clk_i,
  input  wire           en_i,
  input  wire [A_W-1:0] a_i,
  input  wire [B_W-1:0] b_i,
  output wire [P_W-1:0] p_o
);

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(RSHIFT >= 0), .VALUE(RSHIFT),
    .MSG("illegal parameter: acore_hw_mul: RSHIFT must be >= 0"))
    RSHIFT_must_be_at_least_0 ();
  acore_check #(.OK(DEPTH >= 1), .VALUE(DEPTH),
    .MSG("illegal parameter: acore_hw_mul: DEPTH must be >= 1"))
    DEPTH_must_be_at_least_1 ();

  // Derived, do not override: the exact product's width (b read with a sign bit).
  localparam integer PR_W = A_W + B_W + 1;

  wire signed [A_W-1:0]  a_s = a_i;
  wire signed [B_W:0]    b_s = {(B_SIGNED != 0) & b_i[B_W-1], b_i};
  wire signed [PR_W-1:0] prod = a_s * b_s;
  wire signed [PR_W-1:0] prod_sh = prod >>> RSHIFT;
  // Sign-extended, or cut, to P_W bits.
  wire [P_W-1:0] p_d;
  generate
    if (P_W > PR_W) begin : g_ext
      assign p_d = {{(P_W-PR_W){prod_sh[PR_W-1]}}, prod_sh};
    end else begin : g_cut
      assign p_d = prod_sh[P_W-1:0];
      if (P_W < PR_W) begin : g_unused
        // The sign bits above P_W (the caller's P_W holds the result).
        wire unused_hi = ^prod_sh[PR_W-1:P_W];
      end
    end
  endgenerate

  reg [P_W-1:0] p_q;
  always @(posedge clk_i) if (en_i) p_q <= p_d;
  // The remaining DEPTH - 1 registers (none: the product register is the output).
  generate
    if (DEPTH > 1) begin : g_dp
      acore_delay #(.W(P_W), .DEPTH(DEPTH - 1)) u_dp (
        .clk_i(clk_i), .en_i(en_i), .d_i(p_q), .q_o(p_o));
    end else begin : g_out
      assign p_o = p_q;
    end
  endgenerate

endmodule

`resetall
