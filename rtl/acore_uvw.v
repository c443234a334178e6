// SPDX-License-Identifier: MIT
// acore_uvw: UVW (six-step, Hall-style) commutation signals from the angle stream, for a motor
// with PP = 1 .. 2^(PP_W-1) pole pairs and a programmable offset (the rotor's electrical zero on
// the angle scale), as a drive's block commutation or Hall input expects them.
//
//   e = ((angle - OFFSET) PP) mod 2^ANGLE_W        the electrical angle (shift-add over PP's bits)
//   sector = floor(6 e / 2^ANGLE_W)                five constant thresholds
//   U = sector in {0,1,2}, V = sector in {2,3,4}, W = sector in {4,5,0}
//
// Each signal is high for half an electrical turn, V lags U and W lags V by a third of one, so a
// forward turn gives UVW = 101 100 110 010 011 001 (one signal changes per sector boundary, as
// three Hall sensors 120 degrees apart). Three clocks of latency, one sample a clock.
`resetall
`default_nettype none

module acore_uvw #(
  // Bits of the angle: one turn = 2^ANGLE_W.
  parameter integer ANGLE_W = 16,
  // Bits of the pole-pair input: PP = 1 .. 2^(PP_W-1) (5: up to 16).
  parameter integer PP_W = 5,
  // 1: pp_i is always 1 .. 2^(PP_W-1) (a register that refuses other values feeds it, as the
  // board's UVW_PP): no clamp. 0: PP outside that range is clamped.
  parameter integer PP_IN_RANGE = 0
) (
  input  wire               clk_i,
  input  wire               rst_i,
  input  wire               angle_valid_i,
  input  wire [ANGLE_W-1:0] angle_i,
  // Pole pairs (1 .. 2^(PP_W-1), clamped; the register shell refuses other values) and offset.
  input  wire [PP_W-1:0]    pp_i,
  input  wire [ANGLE_W-1:0] offset_i,
  // Registered outputs; valid_o pulses with each converted sample (the outputs hold between).
  output reg                u_o,
  output reg                v_o,
  output reg                w_o,
  output reg  [2:0]         sector_o,
  output reg                valid_o
);

  localparam integer LATENCY = 3;
  localparam integer PPMAX = 1 << (PP_W - 1);

  acore_check #(.OK(ANGLE_W >= 3 && ANGLE_W <= 32), .VALUE(ANGLE_W),
    .MSG("illegal parameter: ANGLE_W must be 3..32")) ANGLE_W_must_be_3_to_32 ();
  acore_check #(.OK(PP_IN_RANGE == 0 || PP_IN_RANGE == 1), .VALUE(PP_IN_RANGE),
    .MSG("illegal parameter: PP_IN_RANGE must be 0 or 1")) PP_IN_RANGE_must_be_0_or_1 ();
  acore_check #(.OK(PP_W >= 1 && PP_W <= 8), .VALUE(PP_W),
    .MSG("illegal parameter: PP_W must be 1..8 (up to 2^(PP_W-1) pole pairs)")) PP_W_must_be_1_to_8 ();

  // The sector thresholds ceil(k 2^ANGLE_W / 6), k = 1..5: e >= T_k iff 6 e >= k 2^ANGLE_W.
  // (Constants, evaluated at elaboration; 40 bits hold 5 2^32.)
  function [39:0] thr(input integer k);
    thr = ((40'd1 << ANGLE_W) * k + 40'd5) / 40'd6;
  endfunction
  localparam [39:0] T1 = thr(1), T2 = thr(2), T3 = thr(3), T4 = thr(4), T5 = thr(5);

  localparam [PP_W-1:0] PPMAX_V = PPMAX[PP_W-1:0];
  localparam [PP_W-1:0] ONE_PP = {{(PP_W-1){1'b0}}, 1'b1};
  wire [PP_W-1:0] pp = (PP_IN_RANGE != 0) ? pp_i :
                       (pp_i == {PP_W{1'b0}}) ? ONE_PP : (pp_i > PPMAX_V) ? PPMAX_V : pp_i;

  // Stage 1: the offset; stage 2: the electrical angle; stage 3: the sector and the signals.
  reg [ANGLE_W-1:0] d_q, e_q;
  reg [PP_W-1:0] pp_q;
  reg v1_q, v2_q;
  reg [ANGLE_W-1:0] e_d;
  integer i;
  // PP's top bit is set only for PP = 2^(PP_W-1) alone (PP is clamped to at most that): a shift,
  // one adder fewer than a product over all of PP's bits.
  always @(*) begin
    e_d = {ANGLE_W{1'b0}};
    for (i = 0; i < PP_W - 1; i = i + 1)
      if (pp_q[i]) e_d = e_d + (d_q << i);
    if (pp_q[PP_W-1]) e_d = d_q << (PP_W - 1);
  end
  wire [39:0] e40 = {{(40-ANGLE_W){1'b0}}, e_q};
  wire [2:0] sector = (e40 >= T5) ? 3'd5 : (e40 >= T4) ? 3'd4 : (e40 >= T3) ? 3'd3 :
                      (e40 >= T2) ? 3'd2 : (e40 >= T1) ? 3'd1 : 3'd0;
  always @(posedge clk_i) begin
    if (rst_i) begin
      v1_q <= 1'b0;
      v2_q <= 1'b0;
      valid_o <= 1'b0;
      u_o <= 1'b0;
      v_o <= 1'b0;
      w_o <= 1'b0;
      sector_o <= 3'd0;
    end else begin
      v1_q <= angle_valid_i;
      v2_q <= v1_q;
      valid_o <= v2_q;
      if (v2_q) begin
        sector_o <= sector;
        u_o <= (sector <= 3'd2);
        v_o <= (sector >= 3'd2) && (sector <= 3'd4);
        w_o <= (sector >= 3'd4) || (sector == 3'd0);
      end
    end
    if (angle_valid_i) begin
      d_q <= angle_i - offset_i;
      pp_q <= pp;
    end
    if (v1_q) e_q <= e_d;
  end

endmodule

`resetall
