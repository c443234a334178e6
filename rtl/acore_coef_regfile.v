// SPDX-License-Identifier: MIT
// acore_coef_regfile: the coefficient register file (DESIGN 3.2), WORDS REG_W-bit words.
//
//   address              content (defaults: DEGREE=3, REGIONS=4, K=16 -> 52 words)
//   0, 1                 offsets O13, O24                       signed
//   2, 3                 amplitude reciprocals 1/A13, 1/A24     unsigned, 2^(S_F+R_SHIFT)/A
//   4 + 2(n+1)r + (n+1)c + j   coefficient of x^j, region r, curve c   signed, COEF_F fraction bits
//   4 + 2 REGIONS (n+1) + i    atan(2^-i), one turn = 2^Z_W             unsigned
//
// Host port: one address for a synchronous write (we_i) and a registered read-back (rdata_o, one
// clock after addr_i). Out-of-range addresses are ignored on write and read back as zero. Every
// word is also on the flat bus words_o (word a at bits [a REG_W +: REG_W]) for the datapath.
// INIT_FILE (a $readmemh image, e.g. from `anglecore calibrate`) sets the power-up contents on an
// FPGA; the words are not reset, so a host or loader writes them otherwise.
`resetall
`default_nettype none

module acore_coef_regfile #(
  parameter integer REG_W = 18,
  // 4 + 2 REGIONS (DEGREE+1) + K.
  parameter integer WORDS = 52,
  // $readmemh image for the initial contents ("" = none).
  parameter INIT_FILE = "",
  // Derived, do not override.
  parameter integer ADDR_W = $clog2(WORDS)
) (
  clk_i, addr_i, wdata_i, we_i, rdata_o, words_o
);

  // Constant product by repeated addition, for widths and offsets at elaboration only: the RTL
  // has no multiplication operator at all (the datapath multiplies on adders and shifters).
  function integer rf_cmul(input integer a, input integer b);
    integer n;
    begin
      rf_cmul = 0;
      for (n = 0; n < b; n = n + 1) rf_cmul = rf_cmul + a;
    end
  endfunction

  // Derived, do not override: width of the flat word bus.
  localparam integer BUS_W = rf_cmul(WORDS, REG_W);

  input  wire               clk_i;
  input  wire [ADDR_W-1:0]  addr_i;
  input  wire [REG_W-1:0]   wdata_i;
  input  wire               we_i;
  output reg  [REG_W-1:0]   rdata_o;
  output wire [BUS_W-1:0]   words_o;

  reg [REG_W-1:0] mem_q [0:WORDS-1];
  // Addresses past the last word (WORDS need not be a power of two).
  localparam integer LAST_I = WORDS - 1;
  localparam [ADDR_W:0] LAST = LAST_I[ADDR_W:0];
  wire in_range = ({1'b0, addr_i} <= LAST);

  initial begin
    if (INIT_FILE != "") $readmemh(INIT_FILE, mem_q);
  end

  always @(posedge clk_i) begin
    if (we_i && in_range) mem_q[addr_i] <= wdata_i;
    rdata_o <= in_range ? mem_q[addr_i] : {REG_W{1'b0}};
  end

  genvar a;
  generate
    for (a = 0; a < WORDS; a = a + 1) begin : g_word
      localparam integer OFF = rf_cmul(a, REG_W);
      assign words_o[OFF +: REG_W] = mem_q[a];
    end
  endgenerate

endmodule

`resetall
