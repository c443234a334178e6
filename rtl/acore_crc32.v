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
//   init_i  ‾\___________________________     crc_o = CRC of the words loaded since init_i
//   load_i  __/‾\_______/‾\______________     a word is taken when load_i && ready_o
//   ready_o ‾‾‾‾‾\_____/‾‾‾\_____/‾‾‾‾‾‾‾     low for 32/CRC_W - 1 clocks after a load
//
// One clock per word at CRC_W = 32 (a 32-input XOR network per CRC bit, ~6 LUT4 each), four at
// CRC_W = 8 (a few LUT4 per bit). The register is a data flop initialised by init_i; only the
// chunk counter is reset.
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
  // CRC-32 of every word taken since init_i (valid while ready_o is high).
  output wire [31:0] crc_o
);

  initial begin
    if (CRC_W != 1 && CRC_W != 2 && CRC_W != 4 && CRC_W != 8 && CRC_W != 16 && CRC_W != 32)
      $error("acore_crc32: CRC_W=%0d must be 1, 2, 4, 8, 16 or 32 (instance %m)", CRC_W);
    if (STEPS != 32 / CRC_W) $error("acore_crc32: STEPS is derived (instance %m)");
  end

  localparam [31:0] POLY = 32'hEDB88320;

  // CRC_W bits, least significant first, through the reflected shift register.
  function [31:0] fold(input [31:0] c, input [CRC_W-1:0] d);
    integer b;
    begin
      fold = c;
      for (b = 0; b < CRC_W; b = b + 1) fold = (fold >> 1) ^ (POLY & {32{fold[0] ^ d[b]}});
    end
  endfunction

  reg [31:0] c_q;
  wire busy;
  generate
    if (STEPS == 1) begin : g_word
      assign busy = 1'b0;
      wire unused_rst = rst_i;
      always @(posedge clk_i) begin
        if (init_i) c_q <= 32'hFFFFFFFF;
        else if (load_i) c_q <= fold(c_q, word_i);
      end
    end else begin : g_chunks
      // The loaded word's bits not yet folded in, and how many chunks remain.
      reg [31:0] sh_q;
      reg [STEP_W-1:0] left_q;
      localparam [STEP_W-1:0] LAST = STEPS[STEP_W-1:0] - 1'b1;
      assign busy = (left_q != {STEP_W{1'b0}});
      always @(posedge clk_i) begin
        if (rst_i || init_i) left_q <= {STEP_W{1'b0}};
        else if (load_i && !busy) left_q <= LAST;
        else if (busy) left_q <= left_q - 1'b1;
      end
      always @(posedge clk_i) begin
        if (init_i) c_q <= 32'hFFFFFFFF;
        else if (load_i && !busy) c_q <= fold(c_q, word_i[CRC_W-1:0]);
        else if (busy) c_q <= fold(c_q, sh_q[CRC_W-1:0]);
        if (load_i && !busy) sh_q <= word_i >> CRC_W;
        else sh_q <= sh_q >> CRC_W;
      end
    end
  endgenerate

  assign ready_o = ~busy;
  assign crc_o = ~c_q;

endmodule

`resetall
