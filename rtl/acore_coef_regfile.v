// SPDX-License-Identifier: MIT
// acore_coef_regfile: the coefficient register file of the pipelined top (docs/contracts.md,
// register image), WORDS REG_W-bit words in flops. The map (rtl/acore_derived.vh, the same
// addresses as the model's DatapathConfig; defaults DEGREE=3, REGIONS=4, K=16 -> 52 words):
//
//   address                            content
//   0, 1                               offsets O13, O24                          signed
//   2, 3                               amplitude reciprocals 1/A13, 1/A24        unsigned, 2^(S_F+R_SHIFT)/A
//   4 + TERMS (2 r + c) + t            polynomial word t of region r, curve c    signed, COEF_F fraction bits
//                                      (1-D: t = power of x, TERMS = DEGREE+1; 2-D: acore_term2d; none: no words)
//   4 + 2 REGIONS TERMS + i            atan(2^-i), i < K, one turn = 2^Z_W         unsigned
//   then a_0, a_1, b_1 .. a_K, b_K     Fourier words (FOURIER_K > 0)              signed, FOURIER_CF fraction bits of a turn
//   WORDS - 1                          the ZERO word (ZERO = 1)                   zero position, low ANGLE_W bits
//
// Host port: one address for a write (we_i; the word changes one clock after the edge that takes
// it, the port being registered first) and a read-back pipelined over two clocks
// (rdata_o is the word at addr_i of two clocks before): the first clock picks one word of every
// group of GROUP words by the low address bits, the second picks the group. A one-clock read of
// all WORDS words was the slowest path of the top (84 MHz on an HX8K against 117 MHz for the
// datapath). Out-of-range addresses are ignored on write and read back as zero. Every
// word is also on the flat bus words_o (word a at bits [a REG_W +: REG_W]) for the datapath.
// INIT_FILE (a $readmemh image, e.g. from `anglecore calibrate`) sets the power-up contents on an
// FPGA; the words are not reset, so a host or loader writes them otherwise.
`resetall
`default_nettype none

module acore_coef_regfile #(
  parameter integer REG_W = 18,
  // Words of the map (acore_words).
  parameter integer WORDS = 52,
  // $readmemh image for the initial contents ("" = none).
  parameter INIT_FILE = "",
  // Derived, do not override.
  parameter integer ADDR_W = $clog2(WORDS),
  // Read-back: words per group of the first clock (a power of two), and the number of groups.
  parameter integer GROUP_W = (ADDR_W > 3) ? 3 : ADDR_W - 1,
  parameter integer GROUPS = (WORDS + (1 << GROUP_W) - 1) >> GROUP_W
) (
  input  wire                     clk_i,
  // Synchronous reset of the registered write enable only (the words keep their contents).
  input  wire                     rst_i,
  input  wire [ADDR_W-1:0]        addr_i,
  input  wire [REG_W-1:0]         wdata_i,
  input  wire                     we_i,
  output reg  [REG_W-1:0]         rdata_o,
  // Every word, word a at bits [a REG_W +: REG_W].
  output wire [WORDS*REG_W-1:0]   words_o
);

  reg [REG_W-1:0] mem_q [0:WORDS-1];
  // Addresses past the last word (WORDS need not be a power of two).
  localparam integer LAST_I = WORDS - 1;
  localparam [ADDR_W:0] LAST = LAST_I[ADDR_W:0];
  wire in_range = ({1'b0, addr_i} <= LAST);

  initial begin
    if (INIT_FILE != "") $readmemh(INIT_FILE, mem_q);
  end

  // Write, registered first (address, data, and the enable with its range check), so that the
  // word decode is the only logic between the host's flops and the words' enables.
  reg [ADDR_W-1:0] waddr_q;
  reg [REG_W-1:0] wdata_q;
  reg we_q;
  always @(posedge clk_i) begin
    waddr_q <= addr_i;
    wdata_q <= wdata_i;
    we_q <= we_i && in_range && !rst_i;
    if (we_q) mem_q[waddr_q] <= wdata_q;
  end

  // Read-back, clock 1: word addr_i[GROUP_W-1:0] of every group (zero past the last word), the
  // group number and the range check; clock 2: the group's word.
  localparam integer HI_W = ADDR_W - GROUP_W;
  wire [GROUP_W-1:0] lo = addr_i[GROUP_W-1:0];
  wire [REG_W-1:0] grp_w [0:GROUPS-1];
  reg [HI_W-1:0] hi_q;
  reg in_range_q;
  genvar gi;
  generate
    for (gi = 0; gi < GROUPS; gi = gi + 1) begin : g_grp
      localparam integer GI = gi;
      wire [ADDR_W-1:0] idx = {GI[HI_W-1:0], lo};
      reg [REG_W-1:0] word_q;
      always @(posedge clk_i) word_q <= ({1'b0, idx} <= LAST) ? mem_q[idx] : {REG_W{1'b0}};
      assign grp_w[gi] = word_q;
    end
  endgenerate
  always @(posedge clk_i) begin
    hi_q <= addr_i[ADDR_W-1:GROUP_W];
    in_range_q <= in_range;
    rdata_o <= in_range_q ? grp_w[hi_q] : {REG_W{1'b0}};
  end

  genvar a;
  generate
    for (a = 0; a < WORDS; a = a + 1) begin : g_word
      localparam integer OFF = a * REG_W;
      assign words_o[OFF +: REG_W] = mem_q[a];
    end
  endgenerate

endmodule

`resetall
