// SPDX-License-Identifier: MIT
// acore_sync_ram: a DEPTH x W memory with one write port and one registered read port, written so
// that Yosys maps it to block RAM (iCE40 SB_RAM40_4K: 256 x 16 each, so two for 18-bit words;
// xc7 distributed RAM or RAMB18). The shell's shadow coefficient bank (rtl/acore_coef_bank.v).
//
//   we_i, waddr_i, wdata_i  the word changes at the clock edge
//   re_i, raddr_i           q_o = the word at raddr_i one clock later (held while re_i is low);
//                           a read and a write of the same address in one clock: undefined (the
//                           users never read and write in one clock: the register block reads in
//                           the APB setup phase and writes in the access phase, the commit reads
//                           while writes are refused)
// INIT_FILE ($readmemh image) sets the power-up contents of words 0..INIT_WORDS-1 (the image's
// length: the shadow's words beyond it hold the shell's CRC registers); the words are not reset.
`resetall
`default_nettype none

module acore_sync_ram #(
  parameter integer W = 18,
  parameter integer DEPTH = 52,
  parameter INIT_FILE = "",
  // Words the image holds (1..DEPTH).
  parameter integer INIT_WORDS = DEPTH,
  // Derived, do not override.
  parameter integer ADDR_W = $clog2(DEPTH)
) (
  input  wire              clk_i,
  input  wire              we_i,
  input  wire [ADDR_W-1:0] waddr_i,
  input  wire [W-1:0]      wdata_i,
  input  wire              re_i,
  input  wire [ADDR_W-1:0] raddr_i,
  output reg  [W-1:0]      q_o
);

  // Parameter rules (rtl/acore_check.v: they stop Verilator, Icarus and Yosys).
  acore_check #(.OK(DEPTH >= 2), .VALUE(DEPTH),
    .MSG("illegal parameter: DEPTH must be at least 2"))
    DEPTH_must_be_at_least_2 ();
  acore_check #(.OK(ADDR_W == $clog2(DEPTH)), .VALUE(ADDR_W),
    .MSG("illegal parameter: ADDR_W is derived (clog2(DEPTH)), do not override"))
    ADDR_W_is_derived ();
  acore_check #(.OK(INIT_WORDS >= 1 && INIT_WORDS <= DEPTH), .VALUE(INIT_WORDS),
    .MSG("illegal parameter: INIT_WORDS must be 1..DEPTH"))
    INIT_WORDS_must_be_1_to_DEPTH ();

  // no_rw_check: Yosys need not keep the old word on a read and write of one address in one
  // clock (the block RAM leaves it undefined): without it the emulation costs a register of the
  // write data and address and a bypass multiplexer (44 flops and 23 LUT4s at 18 x 52).
  (* no_rw_check *)
  reg [W-1:0] mem_q [0:DEPTH-1];

  initial begin
    if (INIT_FILE != "") $readmemh(INIT_FILE, mem_q, 0, INIT_WORDS - 1);
  end

  always @(posedge clk_i) begin
    if (we_i) mem_q[waddr_i] <= wdata_i;
    if (re_i) q_o <= mem_q[raddr_i];
  end

endmodule

`resetall
