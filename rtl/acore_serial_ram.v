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
// Arbitration (one port each way):
//   read:  dp_read_i = 1 (the core is computing a sample): the datapath's address; otherwise the
//          host's. host_rdata_o = word at the host address of the previous clock when the host had
//          the port in that clock and the address was in range, zero otherwise (so the host reads
//          back while the core is idle, i.e. in_ready_o high, exactly as from acore_coef_regfile).
//          dp_re_i = 0 holds q_o (the datapath stalls).
//   write: the host wins. A datapath write in the same clock as a host write is not done; the
//          controller sees host_we_i and stalls that clock (acore_serial_ctrl.v), so it is retried.
//          Host writes past the last word are ignored.
// INIT_FILE ($readmemh image, e.g. from `anglecore calibrate`) sets the power-up coefficients.
`resetall
`default_nettype none

module acore_serial_ram #(
  // Host word width.
  parameter integer REG_W = 18,
  // Stored word width, >= REG_W (the scratch words hold S_W-bit values).
  parameter integer MEM_W = 18,
  // Host-visible words: 4 + 2 REGIONS (DEGREE+1) + K.
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
  // Host port: synchronous write, read-back one clock after the address (while the core is idle).
  input  wire [ADDR_W-1:0] host_addr_i,
  input  wire [REG_W-1:0]  host_wdata_i,
  input  wire              host_we_i,
  output wire [REG_W-1:0]  host_rdata_o,
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

  initial begin
    if (MEM_W < REG_W) $error("acore_serial_ram: MEM_W=%0d < REG_W=%0d (instance %m)", MEM_W, REG_W);
    if (ADDR_W != $clog2(WORDS) || DA_W != $clog2(DEPTH) || DA_W < ADDR_W)
      $error("acore_serial_ram: ADDR_W/DA_W are derived (instance %m)");
  end

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

  wire             we    = host_we_i ? host_in_range : dp_we_i;
  wire [DA_W-1:0]  waddr = host_we_i ? host_addr : dp_waddr_i;
  wire [MEM_W-1:0] wdata = host_we_i ? {{(MEM_W-REG_W){1'b0}}, host_wdata_i} : dp_wdata_i;
  wire [DA_W-1:0]  raddr = dp_read_i ? dp_raddr_i : host_addr;
  wire             re    = dp_read_i ? dp_re_i : 1'b1;

  always @(posedge clk_i) begin
    if (we) mem_q[waddr] <= wdata;
    if (re) q_q <= mem_q[raddr];
  end
  assign q_o = q_q;

  // The host's read-back is valid when the host had the read port (control flop, reset).
  reg host_rd_q;
  always @(posedge clk_i) begin
    if (rst_i) host_rd_q <= 1'b0;
    else host_rd_q <= ~dp_read_i & host_in_range;
  end
  assign host_rdata_o = q_q[REG_W-1:0] & {REG_W{host_rd_q}};

endmodule

`resetall
