// SPDX-License-Identifier: MIT
// acore_prefilter: stage 1 (paper Eq. 3, model/ip/stages/prefilter.hpp). Opposite sensors are subtracted,
// which cancels the common-mode "temporal variation":
//   d13 = c1 - c3,  d24 = c2 - c4        D_W = IN_W + 1 bits, exact (no rounding, no overflow)
// Two-channel sensors feed c1 = sin, c2 = cos, c3 = c4 = 0. Latency LATENCY = 1 clock.
`resetall
`default_nettype none

module acore_prefilter #(
  // Channel code width, signed two's complement.
  parameter integer IN_W = 16,
  // Derived, do not override: difference width.
  parameter integer D_W = acore_d_w(IN_W)
) (
  input  wire            clk_i,
  // Pipeline advance.
  input  wire            en_i,
  input  wire [IN_W-1:0] c1_i,
  input  wire [IN_W-1:0] c2_i,
  input  wire [IN_W-1:0] c3_i,
  input  wire [IN_W-1:0] c4_i,
  // c1 - c3, the sine curve.
  output reg  [D_W-1:0]  d13_o,
  // c2 - c4, the cosine curve.
  output reg  [D_W-1:0]  d24_o
);

`include "acore_derived.vh"

  localparam integer LATENCY = acore_prefilter_latency();

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(D_W == acore_d_w(IN_W)), .VALUE(D_W),
    .MSG("illegal parameter: acore_prefilter: D_W is derived (IN_W+1), do not override"))
    D_W_is_derived ();

  always @(posedge clk_i) begin
    if (en_i) begin
      d13_o <= {c1_i[IN_W-1], c1_i} - {c3_i[IN_W-1], c3_i};
      d24_o <= {c2_i[IN_W-1], c2_i} - {c4_i[IN_W-1], c4_i};
    end
  end

endmodule

`resetall
