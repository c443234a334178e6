// SPDX-License-Identifier: MIT
// acore_coef_scrub: the background scrubber of the active coefficient words. It reads every word
// of the top's register file through the top's own host read-back port, in address order, folds
// it into the shared CRC-32 engine (rtl/acore_crc32.v) and signals the end of each pass; the bank
// (rtl/acore_coef_bank.v) compares the pass's CRC with the CRC of the committed image, so a bit
// that flips in the active words after a commit (a single-event upset) shows within two passes.
//
// The read port is the top's: acore_top answers every clock (reg_rdata_o = the word at the address
// of RD_LAT clocks before); the serial core answers only for an address given while it is idle
// (in_ready_o high: its RAM's one read port belongs to the datapath otherwise), so rd_ok_i says
// whether a read given in this clock will be served and the scrubber waits until one is. The bank
// registers addr_o before the top's port, so a word arrives RD_LAT + 1 clocks after addr_o changes:
//
//   addr_o       =X A ===========================X A+1
//   top address   ==X A =========================X
//   rd_ok_i (k-RD_LAT)              ‾‾‾‾‾            served?
//   state        START/LOAD| READ  READ  READ |LOAD| READ ...
//   crc_load_o   __________________________/‾‾‾‾\____   HOLD = 0: the copy, when the engine is ready
//
// The engine takes a word in the clock of its load: with HOLD = 0 (the serial core, whose
// read-back is valid only in the clock it is served) the scrubber copies the word into word_q when
// the engine is ready and hands it over in LOAD; with HOLD = 1 (acore_top, whose read-back stays
// while its address does) the engine takes the read-back in the clock it is served, and LOAD keeps
// the address until the engine is ready again. A pass's end waits while hold_i is high (the bank's
// block RAM, where the pass's CRC goes, is the APB's in that clock). A pass takes at the least
// WORDS max(RD_LAT + 3, 32/CRC_W + 1) clocks with HOLD = 0, WORDS (RD_LAT + 2 + 32/CRC_W) with
// HOLD = 1 (6 x 52 = 312 for the pipelined top at CRC_W = 16); on the streaming serial core, one
// word per sample (the core idles one clock a sample).
// run_i low (the bank commits, or the host disabled scrubbing) abandons the pass; it starts again
// from word 0 when run_i returns. Meanwhile the address counter is the commit's (clr_i, inc_i: it
// reads the shadow and writes the top in address order too), so the bank needs no counter and no
// address multiplexer of its own.
`resetall
`default_nettype none

module acore_coef_scrub #(
  parameter integer REG_W = 18,
  // Coefficient words of the top.
  parameter integer WORDS = 52,
  // Clocks from the top's host address to its reg_rdata_o.
  parameter integer RD_LAT = 2,
  // 1: the top's read-back keeps the word while the address stays (acore_top): the engine reads
  // it there; 0: it is valid only in the clock it is served (the serial core): a copy (word_q).
  parameter integer HOLD = 0,
  // Derived, do not override.
  parameter integer ADDR_W = $clog2(WORDS)
) (
  input  wire              clk_i,
  input  wire              rst_i,
  // 1: scrub; 0: stop (the bank owns the top's port and the CRC engine).
  input  wire              run_i,
  // While run_i is low the bank's commit steps the address counter (one counter for both: they
  // never run at once): clear it, or count on; last_o: it holds the last word.
  input  wire              clr_i,
  input  wire              inc_i,
  output wire              last_o,
  // Address wanted on the top's host port (registered by the bank), and the top's read-back.
  output reg  [ADDR_W-1:0] addr_o,
  input  wire [REG_W-1:0]  rdata_i,
  // The top serves a host read whose address it sees in this clock.
  input  wire              rd_ok_i,
  // The shared CRC engine (acore_crc32).
  output wire              crc_init_o,
  output wire              crc_load_o,
  output wire [REG_W-1:0]  crc_word_o,
  // The engine folds no word (a word taken into word_q now would change the one it folds).
  input  wire              crc_ready_i,
  input  wire              crc_idle_i,
  // The pass may not end in this clock (the bank's memory, where CRC_SCRUB goes, is busy): END
  // waits (the engine holds the CRC).
  input  wire              hold_i,
  // A pass over all WORDS words ends in this clock: the engine's crc_o is its CRC.
  output wire              pass_o
);

  // Parameter rules (rtl/acore_check.v: they stop Verilator, Icarus and Yosys).
  acore_check #(.OK(RD_LAT >= 1 && RD_LAT <= 4), .VALUE(RD_LAT),
    .MSG("illegal parameter: RD_LAT must be 1..4"))
    RD_LAT_must_be_1_to_4 ();
  acore_check #(.OK(WORDS >= 2), .VALUE(WORDS),
    .MSG("illegal parameter: WORDS must be at least 2"))
    WORDS_must_be_at_least_2 ();
  acore_check #(.OK(ADDR_W == $clog2(WORDS)), .VALUE(ADDR_W),
    .MSG("illegal parameter: ADDR_W is derived (clog2(WORDS)), do not override"))
    ADDR_W_is_derived ();

  localparam [1:0] ST_START = 2'd0, ST_READ = 2'd1, ST_LOAD = 2'd2, ST_END = 2'd3;
  localparam integer WAIT_W = $clog2(RD_LAT + 2);
  localparam integer DUE_I = RD_LAT + 1;
  localparam [WAIT_W-1:0] DUE = DUE_I[WAIT_W-1:0];
  localparam integer LAST_I = WORDS - 1;
  localparam [ADDR_W-1:0] LAST = LAST_I[ADDR_W-1:0];

  reg [1:0] state_q;
  // Clocks since addr_o changed (saturating at DUE), and rd_ok_i of the last RD_LAT clocks.
  reg [WAIT_W-1:0] wait_q;
  reg [RD_LAT-1:0] ok_q;
  // addr_o is the last word (a flop, so the state's next value is a few gates from flops).
  reg last_q;

  // The read-back now is the word at addr_o, read in a clock the top served.
  wire served = (wait_q == DUE) && ok_q[RD_LAT-1];

  generate
    if (RD_LAT > 1) begin : g_ok_sr
      always @(posedge clk_i) ok_q <= {ok_q[RD_LAT-2:0], rd_ok_i};
    end else begin : g_ok_one
      always @(posedge clk_i) ok_q <= rd_ok_i;
    end
  endgenerate

  always @(posedge clk_i) begin
    if (rst_i || !run_i) begin
      state_q <= ST_START;
      wait_q <= {WAIT_W{1'b0}};
    end else begin
      case (state_q)
        ST_START: begin
          wait_q <= {WAIT_W{1'b0}};
          state_q <= ST_READ;
        end
        ST_READ: begin
          if (served && crc_ready_i) begin
            // HOLD: the engine takes the read-back itself in this clock.
            state_q <= (HOLD != 0 && last_q) ? ST_END : ST_LOAD;
          end else if (wait_q != DUE) begin
            wait_q <= wait_q + 1'b1;
          end
        end
        ST_LOAD: begin
          // HOLD: the address stays until the engine has folded the word (it reads the read-back).
          if (crc_ready_i) begin
            wait_q <= {WAIT_W{1'b0}};
            state_q <= (HOLD == 0 && last_q) ? ST_END : ST_READ;
          end
        end
        default: begin  // ST_END: until the last word is folded in (and no hold)
          if (crc_idle_i && !hold_i) state_q <= ST_START;
        end
      endcase
    end
  end

  // The address counter: cleared in START, counted on in LOAD (but after the last word); the
  // commit's steps while run_i is low (the state is START then, and nothing else moves it).
  wire a_clr = clr_i | (run_i & (state_q == ST_START));
  wire a_inc = inc_i | (run_i & (state_q == ST_LOAD) & crc_ready_i & ~((HOLD == 0) & last_q));
  always @(posedge clk_i) begin
    if (a_clr) begin
      addr_o <= {ADDR_W{1'b0}};
      last_q <= 1'b0;
    end else if (a_inc) begin
      addr_o <= addr_o + 1'b1;
      last_q <= (addr_o == LAST - 1'b1);
    end
  end
  assign last_o = last_q;

  generate
    if (HOLD != 0) begin : g_hold
      assign crc_word_o = rdata_i;
    end else begin : g_copy
      // The serial core's read-back is valid only in the clock it is served: a copy.
      reg [REG_W-1:0] word_q;
      always @(posedge clk_i) if (state_q == ST_READ && served && crc_ready_i) word_q <= rdata_i;
      assign crc_word_o = word_q;
        end
  endgenerate
  assign crc_init_o = (state_q == ST_START);
  assign crc_load_o = (HOLD != 0) ? (state_q == ST_READ) && served : (state_q == ST_LOAD);
  assign pass_o = (state_q == ST_END) && crc_idle_i && !hold_i;

endmodule

`resetall
