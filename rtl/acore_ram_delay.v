// SPDX-License-Identifier: MIT
// acore_ram_delay: a DEPTH-clock delay line in a synchronous-read memory (block RAM on iCE40: one
// SB_RAM40_4K per 16 bits of W), for long delays of wide words where a flop chain would fill logic
// cells with flops alone. A circular buffer: every clock the word is written at the write pointer
// and the word written DEPTH - 1 - OUT_REG clocks earlier is read (the memory's own output
// register), then registered once more in flops (a block RAM's clock-to-output is a quarter of a
// 100 MHz period: its word should not start a path through logic; OUT_REG = 0 leaves that register
// to a caller that registers q_o first anyway), so q_o is d_i of DEPTH clocks before. No enable
// (the folded datapath never stalls). The read address never equals the write address (DEPTH >= 3,
// the memory deeper than the read's distance), so no read-write collision can occur.
`resetall
`default_nettype none

module acore_ram_delay #(
  // Word width.
  parameter integer W = 18,
  // Delay in clocks, 3..257.
  parameter integer DEPTH = 8,
  // 1: the memory's word registered once more in flops (above); 0: q_o is the memory's own read
  // register, for a caller whose next logic is short enough to start at a block RAM's output.
  parameter integer OUT_REG = 1
) (
  input  wire         clk_i,
  // Synchronous reset of the write pointer (the only control state).
  input  wire         rst_i,
  input  wire [W-1:0] d_i,
  // d_i delayed by DEPTH clocks.
  output wire [W-1:0] q_o
);

  // Pointer width: the memory has 2^AW >= DEPTH - OUT_REG words (kept in block RAM by ram_style
  // however shallow: the block is the unit of cost).
  localparam integer AW = (DEPTH - OUT_REG > 2) ? $clog2(DEPTH - OUT_REG) : 1;
  localparam integer BACK_I = DEPTH - 1 - OUT_REG;
  localparam [AW-1:0] BACK = BACK_I[AW-1:0];

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(DEPTH >= 3 && DEPTH <= 257), .VALUE(DEPTH),
    .MSG("illegal parameter: acore_ram_delay: DEPTH must be 3..257"))
    DEPTH_must_be_3_to_257 ();
  acore_check #(.OK(OUT_REG == 1 || (OUT_REG == 0 && DEPTH <= 256)), .VALUE(OUT_REG),
    .MSG("illegal parameter: acore_ram_delay: OUT_REG must be 1, or 0 with DEPTH <= 256"))
    OUT_REG_must_be_1_or_0_with_DEPTH_to_256 ();

  (* no_rw_check, ram_style = "block" *)
  reg [W-1:0] mem_q [0:(1<<AW)-1];
  reg [AW-1:0] wp_q;
  reg [W-1:0] rd_q;
  // The read address modulo 2^AW as a net of its own: an index expression's arithmetic is not
  // wrapped to AW bits by every simulator (Icarus 11 reads out of range, X).
  wire [AW-1:0] rp = wp_q - BACK;
  always @(posedge clk_i) begin
    mem_q[wp_q] <= d_i;
    rd_q <= mem_q[rp];
    if (rst_i) wp_q <= {AW{1'b0}};
    else wp_q <= wp_q + 1'b1;
  end

  generate
    if (OUT_REG != 0) begin : g_out
      reg [W-1:0] o_q;
      always @(posedge clk_i) o_q <= rd_q;
      assign q_o = o_q;
    end else begin : g_mem
      assign q_o = rd_q;
    end
  endgenerate

endmodule

`resetall
