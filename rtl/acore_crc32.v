// SPDX-License-Identifier: MIT
// acore_crc32: the standard CRC-32 (IEEE 802.3, zlib's crc32(): reflected polynomial 0xEDB88320,
// initial value 0xFFFFFFFF, final inversion) of a stream of 32-bit words, CRC_W bits per clock.
//
// Each word counts as its four bytes in little-endian order (bits 0..31, least significant first,
// which is the reflected CRC's bit order), so a host computes the same value with any zlib over the
// words written as 32-bit little-endian integers:
//   crc = zlib.crc32(b"".join(w.to_bytes(4, "little") for w in words))
// The coefficient image (DATA_W-bit words) is fed zero-extended to 32 bits, in address order.
//
//   init_i  ‾\_______________________________   crc_o = CRC of the words taken before this clock,
//   load_i  __/‾\_______/‾\__________________   valid while idle_o is high
//   ready_o ‾‾‾‾‾\___/‾‾‾‾‾\___/‾‾‾‾‾‾‾‾‾‾‾‾‾   a word is taken when load_i && ready_o
//   idle_o  ‾‾‾‾‾\___/‾‾‾‾‾\___/‾‾‾‾‾‾‾‾‾‾‾‾‾   (CRC_W = 8: four clocks a word)
//
// Below CRC_W = 16 the engine folds chunk 0 of word_i in the clock of the take and keeps the
// word's other chunks in a shift register, one chunk a clock after it (word_i need not stay: the
// shadow RAM's read port is free for the register block's reads of the CRC registers the clock
// after the take). At CRC_W >= 16 (the fast tops' shells) the word is registered at the take
// and its chunk's part of the fold is registered next, so the CRC register takes each chunk two
// clocks later than the narrow form, and each clock's logic is half of the wide XOR network. A new
// word is taken once the last chunk of the word before is under way: one word a clock at CRC_W = 32,
// one per four clocks at CRC_W = 8. The CRC register is a data flop cleared by init_i (it holds
// the CRC's complement); only the run flags are reset.
`resetall
`default_nettype none

module acore_crc32 #(
  // Data bits folded into the CRC per clock: 1, 2, 4, 8, 16 or 32.
  parameter integer CRC_W = 8,
  // Bits of word_i (1..32); the word's upper 32 - DATA_W bits are zero.
  parameter integer DATA_W = 32,
  // Derived, do not override: clocks per word, and the width of their counter.
  parameter integer STEPS = 32 / CRC_W,
  parameter integer STEP_W = (STEPS > 1) ? $clog2(STEPS) : 1
) (
  input  wire              clk_i,
  input  wire              rst_i,
  // Restart: the CRC of the empty stream (a word loaded in the same clock is dropped).
  input  wire              init_i,
  // A word to fold in, taken when load_i && ready_o; below CRC_W = 16 the source holds it for
  // STEPS clocks (the take's and the STEPS - 1 after it).
  input  wire              load_i,
  input  wire [DATA_W-1:0] word_i,
  output wire              ready_o,
  // Every word taken before this clock is folded in: crc_o is their CRC-32.
  output wire              idle_o,
  output wire [31:0]       crc_o
);

  // Parameter rules (rtl/acore_check.v: they stop Verilator, Icarus and Yosys).
  acore_check #(.OK(CRC_W == 1 || CRC_W == 2 || CRC_W == 4 || CRC_W == 8 || CRC_W == 16 || CRC_W == 32), .VALUE(CRC_W),
    .MSG("illegal parameter: CRC_W must be 1, 2, 4, 8, 16 or 32"))
    CRC_W_must_divide_32 ();
  acore_check #(.OK(DATA_W >= 1 && DATA_W <= 32), .VALUE(DATA_W),
    .MSG("illegal parameter: DATA_W must be 1..32"))
    DATA_W_must_be_1_to_32 ();
  acore_check #(.OK(STEPS == 32 / CRC_W), .VALUE(STEPS),
    .MSG("illegal parameter: STEPS is derived (32/CRC_W), do not override"))
    STEPS_is_derived ();

  localparam [31:0] POLY = 32'hEDB88320;
  localparam integer LAST_I = STEPS - 1;
  localparam [STEP_W-1:0] LAST = LAST_I[STEP_W-1:0];
  localparam [STEP_W-1:0] SECOND = 1;

  // CRC_W bits, least significant first, through the reflected shift register.
  function [31:0] fold(input [31:0] c, input [CRC_W-1:0] d);
    integer b;
    begin
      fold = c;
      for (b = 0; b < CRC_W; b = b + 1) fold = (fold >> 1) ^ (POLY & {32{fold[0] ^ d[b]}});
    end
  endfunction

  // n_q: the CRC register, kept inverted (the final inversion is then no logic of its own; the
  // fold's inversions merge into its XORs). run_q: chunks 1..STEPS-1 of the word taken are being
  // folded, chunk idx_q in this clock.
  reg [31:0] n_q;
  reg run_q;
  // (read by the narrow form only: the wide one shifts its registered word)
  /* verilator lint_off UNUSEDSIGNAL */
  wire [STEP_W-1:0] idx;
  /* verilator lint_on UNUSEDSIGNAL */
  wire take = load_i & ready_o;
  wire step = take | run_q;
  assign ready_o = ~run_q;
  generate
    if (STEPS > 1) begin : g_count
      reg [STEP_W-1:0] idx_q;
      assign idx = idx_q;
      always @(posedge clk_i) begin
        if (rst_i || init_i) run_q <= 1'b0;
        else if (take) run_q <= 1'b1;
        else if (idx_q == LAST) run_q <= 1'b0;
        idx_q <= take ? SECOND : idx_q + 1'b1;
      end
    end else begin : g_one
      always @(posedge clk_i) run_q <= 1'b0;
      assign idx = 1'b0;
    end
  endgenerate
  wire busy;
  generate
    if (CRC_W >= 16) begin : g_split
      // Wide chunks, on the fast tops' clock: the word is registered at the take (w_q, the
      // source's read data off the path) and shifted a chunk a clock, its chunk's part of the fold
      // registered next (d_q; the fold is linear, fold(c, d) = fold(c, 0) ^ fold(0, d)), so each
      // clock's logic is half of a wide XOR network with no multiplexer before it; the word's
      // chunks reach the CRC register two clocks after the direct form's.
      reg [DATA_W-1:0] w_q;
      reg [31:0] d_q;
      reg sv_q, dv_q;
      // (its chunk: the low CRC_W bits, all 32 only at CRC_W = 32)
      /* verilator lint_off UNUSEDSIGNAL */
      wire [31:0] w_wide = {{(32-DATA_W){1'b0}}, w_q};
      /* verilator lint_on UNUSEDSIGNAL */
      always @(posedge clk_i) begin
        if (rst_i || init_i) begin
          sv_q <= 1'b0;
          dv_q <= 1'b0;
        end else begin
          sv_q <= step;
          dv_q <= sv_q;
        end
        if (take) w_q <= word_i;
        else if (sv_q) w_q <= w_q >> CRC_W;
        d_q <= fold(32'd0, w_wide[CRC_W-1:0]);
      end
      always @(posedge clk_i) begin
        if (init_i) n_q <= 32'd0;
        else if (dv_q) n_q <= ~(fold(~n_q, {CRC_W{1'b0}}) ^ d_q);
      end
      assign busy = sv_q | dv_q;
    end else begin : g_direct
      // Narrow chunks: one fold a clock is shallow enough, chunk 0 straight from the source's
      // word, the others from the shift register (the word zero-extended: the bits above DATA_W
      // shift in as zeros).
      localparam integer R_W = (DATA_W > CRC_W) ? DATA_W - CRC_W : 1;
      wire [31:0] wide = {{(32-DATA_W){1'b0}}, word_i};
      /* verilator lint_off UNUSEDSIGNAL */
      wire [31:0] wide_rest = wide >> CRC_W;
      reg [R_W-1:0] rest_q;
      wire [R_W+31:0] rest_x = {32'd0, rest_q};
      /* verilator lint_on UNUSEDSIGNAL */
      always @(posedge clk_i) rest_q <= run_q ? rest_x[CRC_W +: R_W] : wide_rest[R_W-1:0];
      wire [CRC_W-1:0] chunk = run_q ? rest_x[CRC_W-1:0] : wide[CRC_W-1:0];
      always @(posedge clk_i) begin
        if (init_i) n_q <= 32'd0;
        else if (step) n_q <= ~fold(~n_q, chunk);
      end
      assign busy = 1'b0;
    end
  endgenerate
  assign idle_o = ~run_q & ~busy;
  assign crc_o = n_q;

endmodule

`resetall
