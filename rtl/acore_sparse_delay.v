// SPDX-License-Identifier: MIT
// acore_sparse_delay: a DEPTH-clock delay line for a stream whose words are valid only now and
// then (push_i, at least GAP clocks apart), in a small circular buffer of flops: the word pushed
// at clock t is on q_o at clock t + DEPTH (and held until the next word's turn). At a large fold a
// delay line of the folded datapath carries one item every FOLD/2 clocks at most, so it holds a
// few words however long it is: SLOTS = ceil((DEPTH - 1) / GAP) flops per bit (at least 2; the
// pointers wrap at SLOTS, free when it is a power of two) and an SLOTS:1 read choice, instead of DEPTH flops per bit or a block RAM
// (acore_delay, acore_ram_delay). The caller gives pop_i = push_i delayed DEPTH - 1 clocks (the
// folded datapath has it in its valid bits: no chain of its own). Words leave in the order they
// came; push k + SLOTS comes SLOTS GAP >= DEPTH - 1 clocks after push k, not before push k's word
// is read (the clock DEPTH - 1 after it), so no word is overwritten while it waits.
`resetall
`default_nettype none

module acore_sparse_delay #(
  // Word width.
  parameter integer W = 18,
  // Delay in clocks, >= 2.
  parameter integer DEPTH = 8,
  // Clocks between two pushes, at least.
  parameter integer GAP = 8,
  // Derived, do not override: buffer words.
  parameter integer SLOTS = acore_sparse_slots(DEPTH, GAP)
) (
  input  wire         clk_i,
  // Synchronous reset of the pointers (the only control state).
  input  wire         rst_i,
  // d_i is a word to delay.
  input  wire         push_i,
  input  wire [W-1:0] d_i,
  // The word pushed DEPTH - 1 clocks ago is due next clock.
  input  wire         pop_i,
  // The word pushed DEPTH clocks ago (the clock after pop_i; held until the next pop).
  output reg  [W-1:0] q_o
);

`include "acore_derived.vh"

  localparam integer PW = $clog2(SLOTS);

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(DEPTH >= 2), .VALUE(DEPTH),
    .MSG("illegal parameter: acore_sparse_delay: DEPTH must be >= 2"))
    DEPTH_must_be_at_least_2 ();
  acore_check #(.OK(GAP >= 1), .VALUE(GAP),
    .MSG("illegal parameter: acore_sparse_delay: GAP must be >= 1"))
    GAP_must_be_at_least_1 ();
  acore_check #(.OK(SLOTS == acore_sparse_slots(DEPTH, GAP)), .VALUE(SLOTS),
    .MSG("illegal parameter: acore_sparse_delay: SLOTS is derived, do not override"))
    SLOTS_is_derived ();

  // Flops, not a block RAM: the buffer is a few words (and its point is to free the blocks).
  (* ram_style = "logic" *)
  reg [W-1:0]  mem_q [0:SLOTS-1];
  reg [PW-1:0] wp_q, rp_q;
  // The pointers' next values: + 1, wrapping at SLOTS (by themselves at a power of two).
  wire [PW-1:0] wp_inc, rp_inc;
  generate
    if ((1 << PW) == SLOTS) begin : g_wrap2
      assign wp_inc = wp_q + 1'b1;
      assign rp_inc = rp_q + 1'b1;
    end else begin : g_wrapn
      localparam integer LAST_I = SLOTS - 1;
      localparam [PW-1:0] LAST = LAST_I[PW-1:0];
      assign wp_inc = (wp_q == LAST) ? {PW{1'b0}} : wp_q + 1'b1;
      assign rp_inc = (rp_q == LAST) ? {PW{1'b0}} : rp_q + 1'b1;
    end
  endgenerate
  always @(posedge clk_i) begin
    if (push_i) mem_q[wp_q] <= d_i;
    if (pop_i) q_o <= mem_q[rp_q];
    if (rst_i) begin
      wp_q <= {PW{1'b0}};
      rp_q <= {PW{1'b0}};
    end else begin
      if (push_i) wp_q <= wp_inc;
      if (pop_i) rp_q <= rp_inc;
    end
  end

endmodule

`resetall
