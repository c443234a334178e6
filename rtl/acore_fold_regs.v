// SPDX-License-Identifier: MIT
// acore_fold_regs: the coefficient register file of the folded top (FOLD > 1). Same map (docs/contracts.md,
// register image), same host port and timing as acore_coef_regfile: a write is registered first and lands
// one clock later (ignored while rst_i is high); reg_rdata is the word at the address of two
// clocks before (zero past the last word). Storage differs:
//   - every word is in a synchronous-read memory (block RAM on iCE40: 2 SB_RAM40_4K for 18-bit
//     words, one copy per read port): the host read-back reads one copy, and PORTS datapath read
//     ports read theirs, each one clock after its address;
//   - with ATAN_FLOPS, the K arctangent words (from ATAN_BASE) are also kept in flops, on atan_o,
//     for a datapath that needs them all at once; with LAST_FLOP, the last word (the ZERO word) on
//     last_o, for the top's output register;
//   - with FLOP_PORT >= 0, that datapath port reads the flop copy of words 0..FLOP_WORDS-1 (its
//     address modulo FLOP_WORDS), with the same one clock of read (its address registered): a port
//     that reads a few words costs a few words of flops instead of a block RAM copy of the map.
// The host read-back of a word in the clock it is written returns the old word, as the flops of
// acore_coef_regfile do. A datapath port reading a word in the very clock the host writes it may
// see the old or the new word (iCE40 block RAM leaves a read-write collision undefined; checking
// for it would cost logic on every port): write coefficients between samples.
`resetall
`default_nettype none

module acore_fold_regs #(
  parameter integer REG_W = 18,
  // Words in the map.
  parameter integer WORDS = 52,
  // Address of the first arctangent word, and their number.
  parameter integer ATAN_BASE = 36,
  parameter integer K = 16,
  // Datapath read ports.
  parameter integer PORTS = 4,
  // 1: the arctangent words also in flops, on atan_o (else atan_o is zero).
  parameter integer ATAN_FLOPS = 1,
  // 1: the last word also in flops, on last_o (else last_o is zero).
  parameter integer LAST_FLOP = 0,
  // A datapath port that reads words 0..FLOP_WORDS-1 (a power of two) from flops, or -1 (none).
  parameter integer FLOP_PORT = -1,
  parameter integer FLOP_WORDS = 4,
  // $readmemh image for the initial contents ("" = none).
  parameter INIT_FILE = "",
  // Derived, do not override.
  parameter integer ADDR_W = $clog2(WORDS)
) (
  input  wire                     clk_i,
  // Synchronous reset of the registered write enable only (the words keep their contents).
  input  wire                     rst_i,
  // Host port.
  input  wire [ADDR_W-1:0]        addr_i,
  input  wire [REG_W-1:0]         wdata_i,
  input  wire                     we_i,
  output reg  [REG_W-1:0]         rdata_o,
  // The arctangent words (ATAN_FLOPS), word 0 in the low bits.
  output wire [K*REG_W-1:0]       atan_o,
  // The last word (LAST_FLOP).
  output wire [REG_W-1:0]         last_o,
  // Datapath read ports: address of port p at bits [p ADDR_W +: ADDR_W], its word one clock later.
  input  wire [PORTS*ADDR_W-1:0]  raddr_i,
  output wire [PORTS*REG_W-1:0]   rdata_p_o
);

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(ATAN_BASE >= 4 && ATAN_BASE + K <= WORDS), .VALUE(ATAN_BASE),
    .MSG("illegal parameter: acore_fold_regs: the arctangent words ATAN_BASE..ATAN_BASE+K-1 must be inside the map"))
    ATAN_words_must_be_inside_the_map ();

  acore_check #(.OK(FLOP_PORT < PORTS && FLOP_WORDS >= 2 && FLOP_WORDS <= WORDS &&
                   (FLOP_WORDS & (FLOP_WORDS - 1)) == 0), .VALUE(FLOP_WORDS),
    .MSG("illegal parameter: acore_fold_regs: FLOP_PORT must be a port (or -1) and FLOP_WORDS a power of two >= 2 inside the map"))
    FLOP_PORT_must_read_a_power_of_two_of_words ();

  localparam integer FP = (FLOP_PORT >= 0) ? FLOP_PORT : 0;
  localparam integer FW_W = $clog2(FLOP_WORDS);
  localparam integer LAST_I = WORDS - 1;
  localparam [ADDR_W:0] LAST = LAST_I[ADDR_W:0];
  wire in_range = ({1'b0, addr_i} <= LAST);

  // Write, registered first (as acore_coef_regfile).
  reg [ADDR_W-1:0] waddr_q;
  reg [REG_W-1:0]  wdata_q;
  reg              we_q;
  always @(posedge clk_i) begin
    waddr_q <= addr_i;
    wdata_q <= wdata_i;
    we_q    <= we_i && in_range && !rst_i;
  end

  // Memory copies: the host read-back (read-write collisions resolved to the old word) and the
  // datapath ports (collisions left undefined, see above).
  (* ram_style = "block" *)
  reg [REG_W-1:0] rb_mem_q [0:WORDS-1];
  (* no_rw_check, ram_style = "block" *)
  reg [REG_W-1:0] dp_mem_q [0:WORDS-1];
  initial begin
    if (INIT_FILE != "") begin
      $readmemh(INIT_FILE, rb_mem_q);
      $readmemh(INIT_FILE, dp_mem_q);
    end
  end
  always @(posedge clk_i) begin
    if (we_q) begin
      rb_mem_q[waddr_q] <= wdata_q;
      dp_mem_q[waddr_q] <= wdata_q;
    end
  end

  // Host read-back: the memory's registered read, then zero past the last word.
  reg [REG_W-1:0] rb_q;
  reg in_range_q;
  always @(posedge clk_i) begin
    rb_q       <= rb_mem_q[addr_i];
    in_range_q <= in_range;
    rdata_o    <= in_range_q ? rb_q : {REG_W{1'b0}};
  end

  // The flop port's word (FLOP_PORT), from the flop copy.
  wire [REG_W-1:0] flop_word;
  genvar a, p;
  generate
    for (p = 0; p < PORTS; p = p + 1) begin : g_port
      if (p == FLOP_PORT) begin : g_flop
        // The address registered (FW_W flops, not REG_W), the word chosen after it: the same
        // clock of read (a word written in between may show: see the collision rule above).
        assign rdata_p_o[p * REG_W +: REG_W] = flop_word;
      end else begin : g_ram
        reg [REG_W-1:0] rd_q;
        always @(posedge clk_i) rd_q <= dp_mem_q[raddr_i[p * ADDR_W +: ADDR_W]];
        assign rdata_p_o[p * REG_W +: REG_W] = rd_q;
      end
    end
    if (FLOP_PORT < 0) begin : g_no_flop_port
      wire unused_flop_word = ^flop_word;
    end
    if (ATAN_FLOPS != 0 || LAST_FLOP != 0 || FLOP_PORT >= 0) begin : g_flops
      // A flop copy of every word, written with the memories; only the arctangent words, the
      // last word and the flop port's words are read (synthesis keeps those alone).
      reg [REG_W-1:0] flop_q [0:WORDS-1];
      initial begin
        if (INIT_FILE != "") $readmemh(INIT_FILE, flop_q);
      end
      always @(posedge clk_i) if (we_q) flop_q[waddr_q] <= wdata_q;
      for (a = 0; a < K; a = a + 1) begin : g_atan
        assign atan_o[a * REG_W +: REG_W] = (ATAN_FLOPS != 0) ? flop_q[ATAN_BASE + a] : {REG_W{1'b0}};
      end
      assign last_o = (LAST_FLOP != 0) ? flop_q[WORDS - 1] : {REG_W{1'b0}};
      // The flop port: words 0..FLOP_WORDS-1, chosen by its address's low bits.
      wire [REG_W-1:0] fw [0:FLOP_WORDS-1];
      for (a = 0; a < FLOP_WORDS; a = a + 1) begin : g_fw
        assign fw[a] = flop_q[a];
      end
      reg [FW_W-1:0] fa_q;
      always @(posedge clk_i) fa_q <= raddr_i[FP * ADDR_W +: FW_W];
      assign flop_word = (FLOP_PORT >= 0) ? fw[fa_q] : {REG_W{1'b0}};
      if (FLOP_PORT >= 0 && FW_W < ADDR_W) begin : g_fp_hi
        wire unused_fp_hi = ^raddr_i[FP * ADDR_W + FW_W +: ADDR_W - FW_W];
      end
    end else begin : g_no_flops
      assign atan_o = {(K*REG_W){1'b0}};
      assign last_o = {REG_W{1'b0}};
      assign flop_word = {REG_W{1'b0}};
    end
  endgenerate

endmodule

`resetall
