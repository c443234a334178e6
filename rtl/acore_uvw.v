// SPDX-License-Identifier: MIT
// acore_uvw: UVW (six-step, Hall-style) commutation signals from the angle stream, for a motor
// with PP = 1 .. 2^(PP_W-1) pole pairs and a programmable offset (the rotor's electrical zero on
// the angle scale), as a drive's block commutation or Hall input expects them.
//
//   e = ((angle - OFFSET) PP) mod 2^ANGLE_W        the electrical angle (Horner over PP's bits,
//                                                   one bit a clock, on one adder)
//   sector = floor(6 e / 2^ANGLE_W) = 3e >> (ANGLE_W - 1)   (3e on the same adder, one clock more)
//   U = sector in {0,1,2}, V = sector in {2,3,4}, W = sector in {4,5,0}
//
// Each signal is high for half an electrical turn, V lags U and W lags V by a third of one, so a
// forward turn gives UVW = 101 100 110 010 011 001 (one signal changes per sector boundary, as
// three Hall sensors 120 degrees apart).
//
// Timing: the latest angle wins. An accepted angle is held, its conversion starts in the next
// clock the adder is free and takes PP_W + 2 clocks (the offset, PP_W Horner steps, then 3e and
// the signals): valid_o pulses LATENCY = PP_W + 3 clocks after angle_valid_i when the adder is
// idle; an angle arriving during a conversion waits, and a newer one replaces it. A stream of a
// sample every PP_W + 2 clocks or more (7 at the board's PP_W = 5: the board's at FOLD 8 and
// above) is converted sample by sample; a faster one at one sample every PP_W + 2 clocks, always
// the latest. One adder instead of a product over PP's bits and five threshold comparators: the
// board is area-bound.
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

  localparam integer LATENCY = PP_W + 3;
  localparam integer PPMAX = 1 << (PP_W - 1);

  acore_check #(.OK(ANGLE_W >= 3 && ANGLE_W <= 32), .VALUE(ANGLE_W),
    .MSG("illegal parameter: ANGLE_W must be 3..32")) ANGLE_W_must_be_3_to_32 ();
  acore_check #(.OK(PP_IN_RANGE == 0 || PP_IN_RANGE == 1), .VALUE(PP_IN_RANGE),
    .MSG("illegal parameter: PP_IN_RANGE must be 0 or 1")) PP_IN_RANGE_must_be_0_or_1 ();
  acore_check #(.OK(PP_W >= 1 && PP_W <= 8), .VALUE(PP_W),
    .MSG("illegal parameter: PP_W must be 1..8 (up to 2^(PP_W-1) pole pairs)")) PP_W_must_be_1_to_8 ();

  localparam [PP_W-1:0] PPMAX_V = PPMAX[PP_W-1:0];
  localparam [PP_W-1:0] ONE_PP = {{(PP_W-1){1'b0}}, 1'b1};
  wire [PP_W-1:0] pp = (PP_IN_RANGE != 0) ? pp_i :
                       (pp_i == {PP_W{1'b0}}) ? ONE_PP : (pp_i > PPMAX_V) ? PPMAX_V : pp_i;

  // The latest angle (held until its conversion starts) and whether one waits.
  reg [ANGLE_W-1:0] ang_q;
  reg pend_q, run_q;
  // PP, MSB first, above a marker 1 that reaches the top after the PP_W Horner steps (the bits
  // below it 0: the 3e step), in place of a step counter.
  reg [PP_W:0] ppsh_q;
  reg [ANGLE_W-1:0] d_q, acc_q;
  // One adder: Horner's acc 2 + (d or 0) modulo a turn, then acc 2 + acc = 3e (ANGLE_W + 2 bits).
  wire last = (ppsh_q[PP_W-1:0] == {PP_W{1'b0}});
  wire [ANGLE_W-1:0] addend = last ? acc_q : (ppsh_q[PP_W] ? d_q : {ANGLE_W{1'b0}});
  wire [ANGLE_W+1:0] sum = {1'b0, acc_q, 1'b0} + {2'b00, addend};
  wire [2:0] sector = sum[ANGLE_W+1:ANGLE_W-1];
  wire start = pend_q & (~run_q | last);
  always @(posedge clk_i) begin
    if (rst_i) begin
      pend_q <= 1'b0;
      run_q <= 1'b0;
      valid_o <= 1'b0;
      u_o <= 1'b0;
      v_o <= 1'b0;
      w_o <= 1'b0;
      sector_o <= 3'd0;
    end else begin
      valid_o <= run_q & last;
      if (run_q && last) begin
        sector_o <= sector;
        u_o <= (sector <= 3'd2);
        v_o <= (sector >= 3'd2) && (sector <= 3'd4);
        w_o <= (sector >= 3'd4) || (sector == 3'd0);
      end
      if (start) run_q <= 1'b1;
      else if (last) run_q <= 1'b0;
      if (angle_valid_i) pend_q <= 1'b1;
      else if (start) pend_q <= 1'b0;
    end
    if (angle_valid_i) ang_q <= angle_i;
    // The datapath needs no reset: run_q says when it holds a conversion.
    if (start) begin
      d_q <= ang_q - offset_i;
      ppsh_q <= {pp, 1'b1};
      acc_q <= {ANGLE_W{1'b0}};
    end else if (run_q && !last) begin
      acc_q <= sum[ANGLE_W-1:0];
      ppsh_q <= ppsh_q << 1;
    end
  end

endmodule

`resetall
