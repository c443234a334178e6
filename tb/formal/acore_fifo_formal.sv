// SPDX-License-Identifier: MIT
// acore_fifo_formal: the folded top's output FIFO alone (rtl/acore_fold_fifo.v, DEPTH = 4, 8-bit
// words: the order argument does not depend on the depth or the width), a tagged word: the solver
// picks any word written (a free input) with any data; the words ahead of it in the FIFO are
// counted down as they are given, and the word given when that count is zero must be the tagged
// word, unchanged (one tagged word at a time, so the check holds for every run length: an
// unbounded proof). With the counts (nothing given from an empty FIFO, every word given
// within a bounded time with ready high) this is "no word lost, duplicated or reordered". Writes
// only when the FIFO has room (the top's credits guarantee it; assumed here).
`default_nettype none

module acore_fifo_formal (
  input wire       clk_i,
  input wire       rst_i,
  input wire       wr_i,
  input wire [7:0] wdata_i,
  input wire       ready_i,
  // Tags the word written in this clock (the solver's choice).
  input wire       pick_i
);
  localparam integer DEPTH = 4;
  wire       valid_o;
  wire [7:0] data_o;
  acore_fold_fifo #(.W(8), .DEPTH(DEPTH)) dut (
    .clk_i(clk_i), .rst_i(rst_i), .wr_i(wr_i), .wdata_i(wdata_i), .valid_o(valid_o), .ready_i(ready_i),
    .data_o(data_o));

  reg init_q = 1'b1;
  always @(posedge clk_i) init_q <= 1'b0;
  always @(*) if (init_q) assume (rst_i);

  // Words written and given since reset (mod 2^5: differences stay exact, stored <= DEPTH), words
  // stored; the tagged word: written in a clock the free input pick_i is high (the first such write
  // while no word is tracked), with the number of words ahead of it still to be given.
  reg [4:0] wn_q, gn_q;
  reg [7:0] tag_q;
  reg       tagged_q;
  reg [4:0] ahead_q;
  wire      give = valid_o && ready_i;
  wire [4:0] stored = wn_q - gn_q;
  always @(*) if (!rst_i && stored >= DEPTH) assume (!wr_i);
  always @(posedge clk_i) begin
    if (rst_i) begin
      wn_q <= 0;
      gn_q <= 0;
      tagged_q <= 1'b0;
    end else begin
      wn_q <= wn_q + wr_i;
      gn_q <= gn_q + give;
      if (tagged_q && give) begin
        if (ahead_q == 0) tagged_q <= 1'b0;
        else ahead_q <= ahead_q - 1'b1;
      end else if (!tagged_q && wr_i && pick_i) begin
        tag_q <= wdata_i;
        tagged_q <= 1'b1;
        ahead_q <= stored - give;
      end
    end
  end
  // Clocks with a word stored and ready high but nothing given.
  reg [3:0] wait_q;
  always @(posedge clk_i) begin
    if (rst_i || give || stored == 0 || !ready_i) wait_q <= 0;
    else wait_q <= wait_q + 1'b1;
  end
  reg past_held_q = 1'b0;
  reg [7:0] past_data_q;
  always @(posedge clk_i) begin
    past_held_q <= valid_o && !ready_i && !rst_i;
    past_data_q <= data_o;
  end

  always @(posedge clk_i) begin
    if (!init_q && !rst_i) begin
      if (give) assert (stored != 0);                        // nothing from an empty FIFO
      assert (stored <= DEPTH);
      assert (wait_q <= 2);                                  // a stored word leaves
      if (give && tagged_q && ahead_q == 0) assert (data_o == tag_q);  // in order, unchanged
      if (tagged_q) assert (ahead_q < stored);
      if (past_held_q) assert (valid_o && data_o == past_data_q);
    end
  end
endmodule
