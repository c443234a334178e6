// SPDX-License-Identifier: MIT
// acore_fold_scaler: stage 2 for the folded top (FOLD > 1), the same contract as acore_scaler
// (model/ip/stages/scaler.cpp) on one multiplier shared by both curves. Each curve is an item: d, O and R of
// that curve at start_i; the items of a sample come FOLD/2 clocks apart, so the multiplier is
// folded F = FOLD/2 times (acore_fold_mul):
//   t = d - O                                 exact, max(D_W, REG_W) + 1 bits
//   p = 2^(SCALE_G-1) + shift_add_mul(t, R, REG_W unsigned, R_SHIFT - SCALE_G)
//   s = saturate(p >>> SCALE_G, S_W)          = saturate(round_shr(product, SCALE_G), S_W)
//                                             (sign-extended when S_W is wider than the product)
// The rounding constant is the multiplier's addend, so rounding costs no adder of its own.
//
//   clock 0: d_i, offset_i, recip_i   1: t_q   1..1+ML: product   2+ML: s_o, ovf_o
//   LATENCY = ML + 2 (ML = acore_fold_mul's LATENCY); a new item every F clocks.
// From acore_fold_lean(2 F) on (one register-file port for both words), recip_i comes one clock
// after d_i and offset_i, and everything after it one clock later: LATENCY = ML + 3. There, with the
// accumulate-in-place multiplier (acore_fold_mul_seq), t_q goes straight to the multiplier's
// operand register the clock before its start (A_PRE), instead of through a second register.
`resetall
`default_nettype none

module acore_fold_scaler #(
  // Difference width (IN_W + 1).
  parameter integer D_W = 17,
  // Register word width: offset (signed) and reciprocal (unsigned).
  parameter integer REG_W = 18,
  // Scaled curve width, signed.
  parameter integer S_W = 18,
  // Extra scale of the reciprocal R, and the guard bits kept before the final rounding.
  parameter integer R_SHIFT = 13,
  parameter integer SCALE_G = 4,
  // Clocks per item of the multiplier.
  parameter integer F = 1,
  // 0: products on adders and shifters; 1: on hardware multipliers (acore_hw_mul.v, DSP blocks).
  parameter integer MULT = 0
) (
  input  wire             clk_i,
  // d_i, offset_i, recip_i are valid (an item starts).
  input  wire             start_i,
  input  wire [D_W-1:0]   d_i,
  // Offset O, signed REG_W-bit word; reciprocal R, unsigned REG_W-bit word.
  input  wire [REG_W-1:0] offset_i,
  input  wire [REG_W-1:0] recip_i,
  // Scaled curve, signed S_W bits (S_F fraction bits), and "it was saturated".
  output wire [S_W-1:0]   s_o,
  output wire             ovf_o
);

`include "acore_derived.vh"

  // Derived, do not override: widths as in acore_scaler, plus one bit for the rounding addend.
  localparam integer T_W = acore_t_w(D_W, REG_W);
  localparam integer RS = R_SHIFT - SCALE_G;
  localparam integer P_W = T_W + ((REG_W > RS) ? (REG_W - RS) : 0) + 2;
  localparam integer LATENCY = acore_fold_scaler_latency(REG_W, F);
  localparam integer LATE_R = acore_fold_lean(2 * F);
  // 1: the multiplier is the accumulate-in-place form, whose operand register can be loaded the
  // clock before the start (acore_fold_mul's A_PRE).
  localparam integer T_PRE = (MULT == 0) ? acore_fold_mul_seq(REG_W, F) : 0;

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(SCALE_G >= 0 && SCALE_G <= R_SHIFT), .VALUE(SCALE_G),
    .MSG("illegal parameter: acore_fold_scaler: SCALE_G must be 0..R_SHIFT"))
    SCALE_G_must_be_0_to_R_SHIFT ();
  acore_check #(.OK(F >= 1 && (F & (F - 1)) == 0), .VALUE(F),
    .MSG("illegal parameter: acore_fold_scaler: F must be a power of two (FOLD/2)"))
    F_must_be_a_power_of_two ();

  reg [T_W-1:0]   t_q;
  reg [REG_W-1:0] r_q;
  reg             start_q;
  wire [T_W-1:0]  t_m;    // t (at pre_m, else at start_m) and the start at the reciprocal's clock
  wire            start_m;
  wire            pre_m;  // A_PRE: t is read the clock before the start
  always @(posedge clk_i) begin
    t_q     <= {{(T_W-D_W){d_i[D_W-1]}}, d_i} - {{(T_W-REG_W){offset_i[REG_W-1]}}, offset_i};
    r_q     <= recip_i;
    start_q <= start_i;
  end
  generate
    if (LATE_R != 0) begin : g_late
      reg start2_q;
      always @(posedge clk_i) start2_q <= start_q;
      assign start_m = start2_q;
      if (T_PRE != 0) begin : g_pre
        // The multiplier's operand register takes t at start_q and waits through the start: t
        // needs no second register of its own.
        assign t_m = t_q;
        assign pre_m = start_q;
      end else begin : g_t2
        reg [T_W-1:0] t2_q;
        always @(posedge clk_i) t2_q <= t_q;
        assign t_m = t2_q;
        assign pre_m = 1'b0;
      end
    end else begin : g_same
      assign t_m = t_q;
      assign pre_m = 1'b0;
      assign start_m = start_q;
    end
  endgenerate

  // Half an output LSB: round half up.
  localparam integer H_W = SCALE_G + 1;
  wire [H_W-1:0] half;
  generate
    if (SCALE_G > 0) begin : g_half
      assign half = {{SCALE_G{1'b0}}, 1'b1} << (SCALE_G - 1);
    end else begin : g_nohalf
      assign half = 1'b0;
    end
  endgenerate

  wire [P_W-1:0] p;
  acore_fold_mul #(
    .A_W(T_W), .B_W(REG_W), .B_SIGNED(0), .RSHIFT(RS), .INIT_W(H_W), .P_W(P_W), .F(F), .MULT(MULT),
    .A_PRE((LATE_R != 0) ? T_PRE : 0)
  ) u_mul (
    .clk_i(clk_i), .start_i(start_m), .pre_i(pre_m), .a_i(t_m), .b_i(r_q), .init_i(half), .p_o(p));

  wire [S_W-1:0] s_d;
  wire ovf_d;
  acore_saturate #(.IN_W(P_W - SCALE_G), .OUT_W(S_W)) u_sat (
    .d_i(p[P_W-1:SCALE_G]), .q_o(s_d), .ovf_o(ovf_d));
  reg [S_W-1:0] s_q;
  reg ovf_q;
  always @(posedge clk_i) begin
    s_q   <= s_d;
    ovf_q <= ovf_d;
  end
  assign s_o   = s_q;
  assign ovf_o = ovf_q;

endmodule

`resetall
