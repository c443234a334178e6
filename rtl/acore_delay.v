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
    end else begin : g_regs
      // One always block per stage (a generate loop, so any DEPTH elaborates without a loop).
      reg [W-1:0] q_q [0:DEPTH-1];
      always @(posedge clk_i) if (en_i) q_q[0] <= d_i;
      genvar i;
      for (i = 1; i < DEPTH; i = i + 1) begin : g_stage
        always @(posedge clk_i) if (en_i) q_q[i] <= q_q[i-1];
      end
      assign q_o = q_q[DEPTH-1];
    end
  endgenerate

endmodule

`resetall
