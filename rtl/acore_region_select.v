// SPDX-License-Identifier: MIT
// acore_region_select: stage 3, domain selection (model/ip/stages/region_select.hpp). The most linear curve
// is the one nearer its zero crossing (smaller magnitude); it becomes the polynomial argument x:
//
//   |s13| <= |s24|, s24 >= 0 -> region 0 (around   0 deg), x = s13
//   |s13| >  |s24|, s13 >= 0 -> region 1 (around  90 deg), x = s24
//   |s13| <= |s24|, s24 <  0 -> region 2 (around 180 deg), x = s13
//   |s13| >  |s24|, s13 <  0 -> region 3 (around 270 deg), x = s24
//
// Ties go to the sine curve. REGIONS = 8 halves each region at its zero crossing:
// region8 = 2 region4 + (x >= 0), i.e. {region4, x >= 0}. The scaled curves pass through for the correction.
// Latency LATENCY = 2 clocks (magnitudes, then compare and select).
// HELD13 = 1 (the folded datapath): s13_i is held by the caller through clock 2, so clock 2 reads it
// there and no register of this stage copies it; en_i marks clock 1 of a sample alone, and clock 2's
// registers take the clock after it, so the outputs hold until the next sample's clock 2.
`resetall
`default_nettype none

module acore_region_select #(
  // Curve width, signed.
  parameter integer S_W = 18,
  // 4 or 8 regions.
  parameter integer REGIONS = 4,
  // 1: s13_i is held through clock 2 (see above): no copy of it in clock 1.
  parameter integer HELD13 = 0,
  // Derived, do not override: region index width.
  parameter integer RG_W = $clog2(REGIONS)
) (
  input  wire            clk_i,
  input  wire            en_i,
  input  wire [S_W-1:0]  s13_i,
  input  wire [S_W-1:0]  s24_i,
  output reg  [RG_W-1:0] region_o,
  // Polynomial argument.
  output reg  [S_W-1:0]  x_o,
  output reg  [S_W-1:0]  s13_o,
  output reg  [S_W-1:0]  s24_o
);

`include "acore_derived.vh"

  localparam integer LATENCY = acore_region_select_latency();

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(REGIONS == 4 || REGIONS == 8), .VALUE(REGIONS),
    .MSG("illegal parameter: acore_region_select: REGIONS must be 4 or 8"))
    REGIONS_must_be_4_or_8 ();
  acore_check #(.OK(RG_W == $clog2(REGIONS)), .VALUE(RG_W),
    .MSG("illegal parameter: acore_region_select: RG_W is derived (clog2(REGIONS)), do not override"))
    RG_W_is_derived ();
  acore_check #(.OK(HELD13 == 0 || HELD13 == 1), .VALUE(HELD13),
    .MSG("illegal parameter: acore_region_select: HELD13 must be 0 or 1"))
    HELD13_must_be_0_or_1 ();

  // Clock 1: magnitudes as unsigned S_W-bit numbers (|-2^(S_W-1)| = 2^(S_W-1) still fits), each
  // -v as ~(v - 1): one carry chain (v plus the sign in every bit) and an exclusive or, where
  // sign ? 0 - v : v costs a subtractor and a choice.
  // Clock 2: compare and select. One carry chain per clock.
  wire [S_W-1:0] s13_dec = s13_i + {S_W{s13_i[S_W-1]}};
  wire [S_W-1:0] s24_dec = s24_i + {S_W{s24_i[S_W-1]}};
  reg [S_W-1:0] a13_q, a24_q, s24_q;
  always @(posedge clk_i) begin
    if (en_i) begin
      a13_q <= s13_dec ^ {S_W{s13_i[S_W-1]}};
      a24_q <= s24_dec ^ {S_W{s24_i[S_W-1]}};
      s24_q <= s24_i;
    end
  end
  // s13 in clock 2: the caller's held word (HELD13) or this stage's copy; clock 2's enable.
  wire [S_W-1:0] s13_2;
  wire           en2;
  generate
    if (HELD13 != 0) begin : g_held13
      // (No reset: until its first clock it holds the outputs, which no sample needs yet.)
      reg en2_q;
      always @(posedge clk_i) en2_q <= en_i;
      assign en2 = en2_q;
      assign s13_2 = s13_i;
    end else begin : g_copy13
      assign en2 = en_i;
      reg [S_W-1:0] s13_c_q;
      always @(posedge clk_i) if (en_i) s13_c_q <= s13_i;
      assign s13_2 = s13_c_q;
    end
  endgenerate
  wire use13 = (a13_q <= a24_q);
  wire [1:0] r4 = use13 ? {s24_q[S_W-1], 1'b0} : {s13_2[S_W-1], 1'b1};
  wire [S_W-1:0] x = use13 ? s13_2 : s24_q;

  wire [RG_W-1:0] region;
  generate
    if (REGIONS == 8) begin : g_r8
      assign region = {r4, ~x[S_W-1]};
    end else begin : g_r4
      assign region = r4;
    end
  endgenerate

  always @(posedge clk_i) begin
    if (en2) begin
      region_o <= region;
      x_o      <= x;
      s13_o    <= s13_2;
      s24_o    <= s24_q;
    end
  end

endmodule

`resetall
