// SPDX-License-Identifier: MIT
// acore_fold_fifo: the folded top's output FIFO (FOLD > 1). The datapath never stalls; the top's
// credit counter admits a sample only while the FIFO can take every sample in flight, so a write
// always finds room. Storage is a synchronous-read memory (one SB_RAM40_4K per 16 bits of W on
// iCE40); its read register is the output register (first word fall-through):
//
//   clk      _/~\_/~\_/~\_/~\_
//   wr_i     _/~~~\___________       word written at edge 1
//   valid_o  _________/~~~~~~~       edge 2: read issued (not empty), edge 3: word on data_o
//
// so a word appears on data_o two clocks after the clock it is written in (the FIFO was empty),
// and one word can leave per clock while ready_i is high. Only the pointers and valid_o are reset.
`resetall
`default_nettype none

module acore_fold_fifo #(
  // Word width.
  parameter integer W = 21,
  // Depth, a power of two (256: one block RAM deep).
  parameter integer DEPTH = 256
) (
  input  wire         clk_i,
  input  wire         rst_i,
  // Write a word (never when DEPTH words are stored: the caller's credits guarantee it).
  input  wire         wr_i,
  input  wire [W-1:0] wdata_i,
  // Output stream.
  output reg          valid_o,
  input  wire         ready_i,
  output reg  [W-1:0] data_o
);

  localparam integer AW = $clog2(DEPTH);

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(AW >= 1 && (1 << AW) == DEPTH), .VALUE(DEPTH),
    .MSG("illegal parameter: acore_fold_fifo: DEPTH must be a power of two >= 2"))
    DEPTH_must_be_a_power_of_two ();

  // A read never meets a write of the same word (the read word is stored, the written one free).
  (* no_rw_check, ram_style = "block" *)
  reg [W-1:0] mem_q [0:DEPTH-1];
  // Pointers one bit wider than the address: equal = empty.
  reg [AW:0] wptr_q, rptr_q;
  wire empty = (wptr_q == rptr_q);
  // Load the output register when it is free or being emptied.
  wire load = !empty && (!valid_o || ready_i);
  always @(posedge clk_i) begin
    if (wr_i) mem_q[wptr_q[AW-1:0]] <= wdata_i;
    if (load) data_o <= mem_q[rptr_q[AW-1:0]];
  end
  always @(posedge clk_i) begin
    if (rst_i) begin
      wptr_q  <= {(AW+1){1'b0}};
      rptr_q  <= {(AW+1){1'b0}};
      valid_o <= 1'b0;
    end else begin
      if (wr_i) wptr_q <= wptr_q + 1'b1;
      if (load) rptr_q <= rptr_q + 1'b1;
      if (load) valid_o <= 1'b1;
      else if (ready_i) valid_o <= 1'b0;
    end
  end

endmodule

`resetall
