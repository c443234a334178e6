// SPDX-License-Identifier: MIT
// acore_serial_ram: the serial core's memory: the WORDS-word coefficient register file (same map
// and host port as rtl/acore_coef_regfile.v) plus SCRATCH words where the datapath parks the
// sample's variables (s13, s24, y13). Written as one synchronous-read memory (one write port, one
// read port) so synthesis maps it to block RAM (iCE40 SB_RAM40_4K, two of them for 18-bit words).
//
//   addresses 0 .. WORDS-1             coefficient words, host-visible (REG_W bits, zero-padded)
//   addresses WORDS .. WORDS+SCRATCH-1 scratch, datapath only (MEM_W bits, signed values stored
//                                      sign-extended)
//
// Host port: the timing of rtl/acore_coef_regfile.v (and so of acore_top). A write is registered
// first (address, data, enable; ignored while rst_i is high or past the last word) and lands one
// clock after the edge that takes it; host_rdata_o is the word at host_addr_i of two clocks before
// (the RAM's output register, then a host read-back register).
// Arbitration (one port each way):
//   read:  dp_read_i = 1 (the core is computing a sample): the datapath's address; otherwise the
//          host's. host_rdata_o = the word at the host address of two clocks before when the host
//          had the port in that clock and the address was in range, zero otherwise (so the host
//          reads back while the core is idle, i.e. in_ready_o high). dp_re_i = 0 holds q_o (the
//          datapath stalls).
//   write: the host's registered write wins. A datapath write in the same clock is not done; the
//          controller sees host_wr_o and stalls that clock (acore_serial_ctrl.v), so it is retried.
// INIT_FILE ($readmemh image, e.g. from `anglecore calibrate`) sets the power-up coefficients.
`resetall
`default_nettype none

module acore_serial_ram #(
  // Host word width.
  parameter integer REG_W = 18,
  // Stored word width, >= REG_W (the scratch words hold S_W-bit values).
  parameter integer MEM_W = 18,
  // Host-visible words: the map (acore_words: 4 + 2 REGIONS (DEGREE+1) + K, + 1 with ZERO).
  parameter integer WORDS = 52,
  // Datapath-only words after them.
  parameter integer SCRATCH = 3,
  // $readmemh image for the initial coefficient words ("" = none).
  parameter INIT_FILE = "",
  // Derived, do not override: host and datapath address widths.
  parameter integer ADDR_W = $clog2(WORDS),
  parameter integer DA_W = $clog2(WORDS + SCRATCH)
) (
  input  wire              clk_i,
  input  wire              rst_i,
  // Host port: write lands one clock after the edge that takes it (ignored in reset); read-back
  // two clocks after the address (while the core is idle).
  input  wire [ADDR_W-1:0] host_addr_i,
  input  wire [REG_W-1:0]  host_wdata_i,
  input  wire              host_we_i,
  output reg  [REG_W-1:0]  host_rdata_o,
  // The registered host write takes the write port this clock (the datapath's write waits).
  output wire              host_wr_o,
  // Datapath port.
  // 1: the datapath owns the read port this clock.
  input  wire              dp_read_i,
  // Read enable of the datapath (0: q_o holds, the core stalls).
  input  wire              dp_re_i,
  input  wire [DA_W-1:0]   dp_raddr_i,
  input  wire              dp_we_i,
  input  wire [DA_W-1:0]   dp_waddr_i,
  input  wire [MEM_W-1:0]  dp_wdata_i,
  // Registered read data (one clock after the address).
  output wire [MEM_W-1:0]  q_o
);

  localparam integer DEPTH = WORDS + SCRATCH;

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(MEM_W >= REG_W), .VALUE(MEM_W),
    .MSG("illegal parameter: acore_serial_ram: MEM_W must be >= REG_W"))
    MEM_W_must_be_at_least_REG_W ();
  acore_check #(.OK(ADDR_W == $clog2(WORDS)), .VALUE(ADDR_W),
    .MSG("illegal parameter: acore_serial_ram: ADDR_W is derived (clog2(WORDS)), do not override"))
    ADDR_W_is_derived ();
  acore_check #(.OK(DA_W == $clog2(DEPTH) && DA_W >= ADDR_W), .VALUE(DA_W),
    .MSG("illegal parameter: acore_serial_ram: DA_W is derived (clog2(WORDS+SCRATCH)), do not override"))
    DA_W_is_derived ();

  reg [MEM_W-1:0] mem_q [0:DEPTH-1];
  reg [MEM_W-1:0] q_q;

  initial begin
    if (INIT_FILE != "") $readmemh(INIT_FILE, mem_q, 0, WORDS - 1);
  end

  // Host addresses past the last coefficient word (WORDS need not be a power of two).
  localparam integer LAST_I = WORDS - 1;
  localparam [ADDR_W:0] LAST = LAST_I[ADDR_W:0];
  wire host_in_range = ({1'b0, host_addr_i} <= LAST);
  wire [DA_W-1:0] host_addr = {{(DA_W-ADDR_W){1'b0}}, host_addr_i};

  // Host write, registered first (as in acore_coef_regfile.v): address, data, and the enable with
  // its range check and the reset.
  reg [DA_W-1:0] host_waddr_q;
  reg [REG_W-1:0] host_wdata_q;
  reg host_we_q;
  always @(posedge clk_i) begin
    host_waddr_q <= host_addr;
    host_wdata_q <= host_wdata_i;
    host_we_q <= host_we_i && host_in_range && !rst_i;
  end
  assign host_wr_o = host_we_q;

  wire             we    = host_we_q | dp_we_i;
  wire [DA_W-1:0]  waddr = host_we_q ? host_waddr_q : dp_waddr_i;
  wire [MEM_W-1:0] wdata = host_we_q ? {{(MEM_W-REG_W){1'b0}}, host_wdata_q} : dp_wdata_i;
  wire [DA_W-1:0]  raddr = dp_read_i ? dp_raddr_i : host_addr;
  wire             re    = dp_read_i ? dp_re_i : 1'b1;

  always @(posedge clk_i) begin
    if (we) mem_q[waddr] <= wdata;
    if (re) q_q <= mem_q[raddr];
  end
  assign q_o = q_q;

  // The host's read-back is valid when the host had the read port (control flop, reset); the
  // second clock registers it (the host port's two-clock read-back).
  reg host_rd_q;
  always @(posedge clk_i) begin
    if (rst_i) host_rd_q <= 1'b0;
    else host_rd_q <= ~dp_read_i & host_in_range;
  end
  always @(posedge clk_i) host_rdata_o <= q_q[REG_W-1:0] & {REG_W{host_rd_q}};

endmodule

`resetall
