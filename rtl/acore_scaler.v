// SPDX-License-Identifier: MIT
// acore_scaler: stage 2, scaling of one curve (paper Eq. 5 read as (c - O) / A; model/ip/stages/scaler.cpp):
//   t = d - O                                     exact, max(D_W, REG_W) + 1 bits
//   p = shift_add_mul(t, R, REG_W unsigned, R_SHIFT - SCALE_G)     S_F + SCALE_G fraction bits
//   s = saturate(round_shr(p, SCALE_G), S_W)      round half up, Q2.16 by default
// R = round(2^(S_F + R_SHIFT) / A) is the amplitude reciprocal from the register file.
// Example (defaults): d = 8192, O = 0, R = 2^29 / 8192 = 65536 -> s = 65536 (1.0).
//
//   clk 0: t_q   1..L: adder tree (L = clog2(REG_W))   L+1: rounded   L+2: saturated s_o, ovf_o
// (LATENCY = L + 3; one carry chain per clock)
`resetall
`default_nettype none

module acore_scaler #(
  // Difference width (IN_W + 1).
  parameter integer D_W = 17,
  // Register word width: offset (signed) and reciprocal (unsigned).
  parameter integer REG_W = 18,
  // Scaled curve width, signed.
  parameter integer S_W = 18,
  // Extra scale of the reciprocal R.
  parameter integer R_SHIFT = 13,
  // Guard fraction bits kept in the product before the final rounding.
  parameter integer SCALE_G = 4,
  // 0: products on adders and shifters; 1: on hardware multipliers (acore_hw_mul.v, DSP blocks).
  parameter integer MULT = 0
) (
  input  wire             clk_i,
  input  wire             en_i,
  input  wire [D_W-1:0]   d_i,
  // Offset O, signed REG_W-bit word.
  input  wire [REG_W-1:0] offset_i,
  // Reciprocal R, unsigned REG_W-bit word.
  input  wire [REG_W-1:0] recip_i,
  // Scaled curve, signed S_W bits (S_F fraction bits).
  output wire [S_W-1:0]   s_o,
  // The result was saturated.
  output wire             ovf_o
);

`include "acore_derived.vh"

  // Derived, do not override.
  localparam integer T_W = acore_t_w(D_W, REG_W);
  localparam integer RS = R_SHIFT - SCALE_G;
  localparam integer P_W = T_W + ((REG_W > RS) ? (REG_W - RS) : 0) + 1;
  localparam integer LATENCY = acore_scaler_latency(REG_W);

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(SCALE_G >= 0 && SCALE_G <= R_SHIFT), .VALUE(SCALE_G),
    .MSG("illegal parameter: acore_scaler: SCALE_G must be 0..R_SHIFT"))
    SCALE_G_must_be_0_to_R_SHIFT ();

  reg [T_W-1:0] t_q;
  always @(posedge clk_i) begin
    if (en_i) t_q <= {{(T_W-D_W){d_i[D_W-1]}}, d_i} - {{(T_W-REG_W){offset_i[REG_W-1]}}, offset_i};
  end

  wire [P_W-1:0] p;
  acore_shift_add_mul #(
    .A_W(T_W), .B_W(REG_W), .B_SIGNED(0), .RSHIFT(RS), .P_W(P_W), .MULT(MULT)
  ) u_mul (
    .clk_i(clk_i), .en_i(en_i), .a_i(t_q), .b_i(recip_i), .p_o(p)
  );

  // Round half up: add half an LSB of the kept part, then drop SCALE_G bits (one adder, its own
  // clock), then saturate (its own clock).
  wire [P_W:0] p_ext = {p[P_W-1], p};
  wire [P_W:0] p_rnd;
  generate
    if (SCALE_G > 0) begin : g_rnd
      assign p_rnd = p_ext + ({{P_W{1'b0}}, 1'b1} << (SCALE_G - 1));
    end else begin : g_nornd
      assign p_rnd = p_ext;
    end
  endgenerate
  reg [P_W-SCALE_G:0] p_sh_q;
  always @(posedge clk_i) if (en_i) p_sh_q <= p_rnd[P_W:SCALE_G];

  wire [S_W-1:0] s_d;
  wire ovf_d;
  acore_saturate #(.IN_W(P_W + 1 - SCALE_G), .OUT_W(S_W)) u_sat (.d_i(p_sh_q), .q_o(s_d), .ovf_o(ovf_d));

  reg [S_W-1:0] s_q;
  reg ovf_q;
  always @(posedge clk_i) begin
    if (en_i) begin
      s_q   <= s_d;
      ovf_q <= ovf_d;
    end
  end
  assign s_o   = s_q;
  assign ovf_o = ovf_q;

endmodule

`resetall
