// SPDX-License-Identifier: MIT
// acore_pulse_delay: a one-bit delay line of DEPTH clocks for pulses at least GAP clocks apart
// (q_o is d_i of DEPTH clocks before). A chunk of GAP clocks or less holds one pulse at most, so
// it is a down-counter and a busy bit (clog2 of its length + 1 flops) instead of a flop a clock;
// chunks of 4 clocks or less stay flop chains. Only the busy bits and the chains are reset.
`resetall
`default_nettype none

module acore_pulse_delay #(
  // Clocks of delay, >= 1.
  parameter integer DEPTH = 16,
  // Pulses on d_i come at least GAP clocks apart (>= 1).
  parameter integer GAP = 16
) (
  input  wire clk_i,
  input  wire rst_i,
  input  wire d_i,
  output wire q_o
);

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(DEPTH >= 1 && GAP >= 1), .VALUE(DEPTH),
    .MSG("illegal parameter: acore_pulse_delay: DEPTH and GAP must be >= 1"))
    DEPTH_and_GAP_must_be_at_least_1 ();

  localparam integer CHUNKS = (DEPTH + GAP - 1) / GAP;
  localparam integer LAST = DEPTH - (CHUNKS - 1) * GAP;

  wire [CHUNKS:0] p;
  assign p[0] = d_i;
  genvar c;
  generate
    for (c = 0; c < CHUNKS; c = c + 1) begin : g_chunk
      localparam integer L = (c == CHUNKS - 1) ? LAST : GAP;
      if (L == 1) begin : g_flop
        reg sh_q;
        always @(posedge clk_i) begin
          if (rst_i) sh_q <= 1'b0;
          else sh_q <= p[c];
        end
        assign p[c+1] = sh_q;
      end else if (L <= 4) begin : g_flops
        reg [L-1:0] sh_q;
        always @(posedge clk_i) begin
          if (rst_i) sh_q <= {L{1'b0}};
          else sh_q <= {sh_q[L-2:0], p[c]};
        end
        assign p[c+1] = sh_q[L-1];
      end else begin : g_count
        // A pulse loads L - 1; the pulse leaves the clock the count is 0 (L clocks later).
        localparam integer CW = $clog2(L);
        localparam integer LOAD_I = L - 1;
        localparam [CW-1:0] LOAD = LOAD_I[CW-1:0];
        reg [CW-1:0] cnt_q;
        reg          busy_q;
        wire         zero = (cnt_q == {CW{1'b0}});
        always @(posedge clk_i) begin
          cnt_q <= p[c] ? LOAD : cnt_q - 1'b1;
          if (rst_i) busy_q <= 1'b0;
          else if (p[c]) busy_q <= 1'b1;
          else if (zero) busy_q <= 1'b0;
        end
        assign p[c+1] = busy_q & zero;
      end
    end
  endgenerate
  assign q_o = p[CHUNKS];

endmodule

`resetall
