// SPDX-License-Identifier: MIT
// acore_delay: DEPTH-stage enable-gated delay line for data that travels beside a pipeline
// (sideband: region, flags, operands). No reset: it only carries data, the valid bit is reset.
`resetall
`default_nettype none

module acore_delay #(
  // Word width.
  parameter integer W = 1,
  // Number of register stages (0 = wire).
  parameter integer DEPTH = 1
) (
  input  wire         clk_i,
  // Pipeline advance (the whole pipeline stalls together).
  input  wire         en_i,
  input  wire [W-1:0] d_i,
  // d_i delayed by DEPTH advancing clocks.
  output wire [W-1:0] q_o
);

  generate
    if (DEPTH == 0) begin : g_wire
      assign q_o = d_i;
      wire unused_wire = ^{clk_i, en_i};  // no stage to clock
    end else begin : g_regs
      // One register per stage, generated (a for loop inside one always block would hit the
      // simulator's loop-unroll limit for the deep sideband delays of high-degree corrections).
      wire [W-1:0] q [0:DEPTH];
      assign q[0] = d_i;
      genvar i;
      for (i = 0; i < DEPTH; i = i + 1) begin : g_stage
        reg [W-1:0] q_q;
        always @(posedge clk_i) if (en_i) q_q <= q[i];
        assign q[i+1] = q_q;
      end
      assign q_o = q[DEPTH];
    end
  endgenerate

endmodule

`resetall
