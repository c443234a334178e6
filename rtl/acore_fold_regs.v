// SPDX-License-Identifier: MIT
// acore_fold_regs: the coefficient register file of the folded top (FOLD > 1). Same map (DESIGN
// 3.2), same host port and timing as acore_coef_regfile: a write is registered first and lands
// one clock later (ignored while rst_i is high); reg_rdata is the word at the address of two
// clocks before (zero past the last word). Storage differs:
//   - every word is in a synchronous-read memory (block RAM on iCE40: 2 SB_RAM40_4K for 18-bit
//     words, one copy per read port): the host read-back reads one copy, and PORTS datapath read
//     ports (the polynomial coefficients) read theirs, each one clock after its address;
//   - the words the datapath needs all at once (offsets, reciprocals: words 0..3; the K arctangent
//     words from ATAN_BASE) are also kept in flops, on scale_o and atan_o.
// A read of a word in the clock it is written returns the old word, on every port (as the flops
// of acore_coef_regfile do).
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
  // $readmemh image for the initial contents ("" = none).
  parameter INIT_FILE = "",
  // Derived, do not override.
  parameter integer ADDR_W = $clog2(WORDS)
) (
  clk_i, rst_i, addr_i, wdata_i, we_i, rdata_o, scale_o, atan_o, raddr_i, rdata_p_o
);

  // Constant product by repeated addition, for widths and offsets at elaboration only.
  function integer fr_cmul(input integer a, input integer b);
    integer n;
    begin
      fr_cmul = 0;
      for (n = 0; n < b; n = n + 1) fr_cmul = fr_cmul + a;
    end
  endfunction

  localparam integer AT_BUS_W = fr_cmul(K, REG_W);
  localparam integer PA_W = fr_cmul(PORTS, ADDR_W);
  localparam integer PD_W = fr_cmul(PORTS, REG_W);

  input  wire                clk_i;
  // Synchronous reset of the registered write enable only (the words keep their contents).
  input  wire                rst_i;
  // Host port.
  input  wire [ADDR_W-1:0]   addr_i;
  input  wire [REG_W-1:0]    wdata_i;
  input  wire                we_i;
  output reg  [REG_W-1:0]    rdata_o;
  // Words 0..3 (offsets, reciprocals) and the arctangent words, word 0 in the low bits.
  output wire [(REG_W<<2)-1:0] scale_o;
  output wire [AT_BUS_W-1:0] atan_o;
  // Datapath read ports: address of port p at bits [p ADDR_W +: ADDR_W], its word one clock later.
  input  wire [PA_W-1:0]     raddr_i;
  output wire [PD_W-1:0]     rdata_p_o;

  initial begin
    if (ATAN_BASE < 4 || ATAN_BASE + K > WORDS)
      $error("acore_fold_regs: arctangent words %0d..%0d outside the map (instance %m)", ATAN_BASE, ATAN_BASE + K - 1);
  end

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

  // Flop copy: only the words read from scale_o and atan_o remain after synthesis.
  reg [REG_W-1:0] flop_q [0:WORDS-1];
  // Memory copies: the host read-back and the datapath ports.
  reg [REG_W-1:0] ram_q [0:WORDS-1];
  initial begin
    if (INIT_FILE != "") begin
      $readmemh(INIT_FILE, flop_q);
      $readmemh(INIT_FILE, ram_q);
    end
  end
  always @(posedge clk_i) begin
    if (we_q) begin
      flop_q[waddr_q] <= wdata_q;
      ram_q[waddr_q]  <= wdata_q;
    end
  end

  // Host read-back: the memory's registered read, then zero past the last word.
  reg [REG_W-1:0] rb_q;
  reg in_range_q;
  always @(posedge clk_i) begin
    rb_q       <= ram_q[addr_i];
    in_range_q <= in_range;
    rdata_o    <= in_range_q ? rb_q : {REG_W{1'b0}};
  end

  genvar a, p;
  generate
    for (p = 0; p < PORTS; p = p + 1) begin : g_port
      reg [REG_W-1:0] rd_q;
      always @(posedge clk_i) rd_q <= ram_q[raddr_i[fr_cmul(p, ADDR_W) +: ADDR_W]];
      assign rdata_p_o[fr_cmul(p, REG_W) +: REG_W] = rd_q;
    end
    for (a = 0; a < 4; a = a + 1) begin : g_scale
      assign scale_o[fr_cmul(a, REG_W) +: REG_W] = flop_q[a];
    end
    for (a = 0; a < K; a = a + 1) begin : g_atan
      assign atan_o[fr_cmul(a, REG_W) +: REG_W] = flop_q[ATAN_BASE + a];
    end
  endgenerate

endmodule

`resetall
