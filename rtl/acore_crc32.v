// SPDX-License-Identifier: MIT
// acore_crc32: the standard CRC-32 (IEEE 802.3, zlib's crc32(): reflected polynomial 0xEDB88320,
// initial value 0xFFFFFFFF, final inversion) of a stream of 32-bit words, CRC_W bits per clock.
//
// Each word counts as its four bytes in little-endian order (bits 0..31, least significant first,
// which is the reflected CRC's bit order), so a host computes the same value with any zlib over the
// words written as 32-bit little-endian integers:
//   crc = zlib.crc32(b"".join(w.to_bytes(4, "little") for w in words))
// The coefficient image (REG_W-bit words) is fed zero-extended to 32 bits, in address order.
//
//   init_i  ‾\_______________________________   crc_o = CRC of the words taken since init_i,
//   load_i  __/‾\_______/‾\__________________   valid while idle_o is high
//   ready_o ‾‾‾‾‾\_____/‾‾‾\_____/‾‾‾‾‾‾‾‾‾‾‾   a word is taken when load_i && ready_o
//   idle_o  ‾‾‾‾‾\_____________________/‾‾‾‾‾‾   (CRC_W = 8: four clocks a word)
//
// A word taken is registered first and folded in over the next 32/CRC_W clocks, so the fold sees
// only flops. At CRC_W >= 16 the chunk's part of the fold is computed one clock ahead of the CRC
// register's (the fold is linear), so each clock's logic is half of the wide XOR network (the
// shell around acore_top then keeps the top's clock rate). A new word is taken in the clock of
// the last chunk: one word a clock at CRC_W = 32, one per four clocks at CRC_W = 8. The CRC
// register is a data flop set by init_i; only the chunk counters are reset.
`resetall
`default_nettype none

module acore_crc32 #(
  // Data bits folded into the CRC per clock: 1, 2, 4, 8, 16 or 32.
  parameter integer CRC_W = 8,
  // Derived, do not override: clocks per word, and the width of their counter.
  parameter integer STEPS = 32 / CRC_W,
  parameter integer STEP_W = (STEPS > 1) ? $clog2(STEPS) : 1
) (
  input  wire        clk_i,
  input  wire        rst_i,
  // Restart: the CRC of the empty stream (a word loaded in the same clock is dropped).
  input  wire        init_i,
  // A word to fold in, taken when load_i && ready_o.
  input  wire        load_i,
  input  wire [31:0] word_i,
  output wire        ready_o,
  // Every word taken is folded in: crc_o is their CRC-32.
  output wire        idle_o,
  output wire [31:0] crc_o
);

  // Parameter rules (rtl/acore_check.v: they stop Verilator, Icarus and Yosys).
  acore_check #(.OK(CRC_W == 1 || CRC_W == 2 || CRC_W == 4 || CRC_W == 8 || CRC_W == 16 || CRC_W == 32), .VALUE(CRC_W),
    .MSG("illegal parameter: CRC_W must be 1, 2, 4, 8, 16 or 32"))
    CRC_W_must_divide_32 ();
  acore_check #(.OK(STEPS == 32 / CRC_W), .VALUE(STEPS),
    .MSG("illegal parameter: STEPS is derived (32/CRC_W), do not override"))
    STEPS_is_derived ();

  localparam [31:0] POLY = 32'hEDB88320;

  // CRC_W bits, least significant first, through the reflected shift register.
  function [31:0] fold(input [31:0] c, input [CRC_W-1:0] d);
    integer b;
    begin
      fold = c;
      for (b = 0; b < CRC_W; b = b + 1) fold = (fold >> 1) ^ (POLY & {32{fold[0] ^ d[b]}});
    end
  endfunction

  // The word in work and how many of its chunks are still to fold (0: none).
  reg [31:0] c_q, sh_q;
  reg [STEP_W:0] left_q;
  localparam [STEP_W:0] ALL = STEPS[STEP_W:0];
  wire take = load_i & ready_o;
  wire folding = (left_q != {(STEP_W+1){1'b0}});
  assign ready_o = (left_q <= {{STEP_W{1'b0}}, 1'b1});
  always @(posedge clk_i) begin
    if (rst_i || init_i) left_q <= {(STEP_W+1){1'b0}};
    else if (take) left_q <= ALL;
    else if (folding) left_q <= left_q - 1'b1;
  end
  always @(posedge clk_i) begin
    if (take) sh_q <= word_i;
    else if (folding) sh_q <= sh_q >> CRC_W;
  end
  wire dv;
  generate
    if (CRC_W >= 16) begin : g_split
      // The fold is linear, fold(c, d) = fold(c, 0) ^ fold(0, d): the chunk's part is computed one
      // clock ahead (d_q, valid dv_q), so each clock's logic is half of a wide XOR network.
      reg [31:0] d_q;
      reg dv_q;
      always @(posedge clk_i) begin
        if (rst_i || init_i) dv_q <= 1'b0;
        else dv_q <= folding;
        d_q <= fold(32'd0, sh_q[CRC_W-1:0]);
      end
      always @(posedge clk_i) begin
        if (init_i) c_q <= 32'hFFFFFFFF;
        else if (dv_q) c_q <= fold(c_q, {CRC_W{1'b0}}) ^ d_q;
      end
      assign dv = dv_q;
    end else begin : g_direct
      // Narrow chunks: one fold a clock is shallow enough.
      always @(posedge clk_i) begin
        if (init_i) c_q <= 32'hFFFFFFFF;
        else if (folding) c_q <= fold(c_q, sh_q[CRC_W-1:0]);
      end
      assign dv = 1'b0;
    end
  endgenerate
  assign idle_o = ~folding & ~dv;
  assign crc_o = ~c_q;

endmodule

`resetall
