// SPDX-License-Identifier: MIT
// acore_tb_icarus: 4-state bench of rtl/acore_top.v (SERIAL=0, FOLD clocks a sample) or
// rtl/acore_serial_top.v (SERIAL=1, the first N_SERIAL samples of each frame) under Icarus Verilog. Reads model-generated
// vectors (tb/icarus/gen_vectors.cpp: regs.hex, in.hex, exp.hex, meta.txt in VEC_DIR), loads the register
// file through its write port and checks the read-back, streams the samples with random input gaps
// and output backpressure, and checks every output word against the model and that no output
// (handshake, angle, region, flags) is ever X or Z after reset (register read-back: once loaded).
// Reset and host port contract of both tops: in_ready is 0 (not X) in every reset clock; after the
// image is loaded, a reset with a sample offered and a host write in every clock takes no sample
// (no output follows) and changes no word; the read-back comes two clocks after the address.
// Nothing in the design is initialised: Icarus starts every flop (and the serial core's RAM) at X.
`timescale 1ns / 1ps
`default_nettype none

module acore_tb_icarus;
  parameter VEC_DIR = ".";
  parameter integer MAXN = 20000;
  parameter integer SERIAL = 0;
  parameter integer N_SERIAL = 400;
  // The pipelined top's fold factor (clocks per sample).
  parameter integer FOLD = 1;
  localparam integer WORDS = 52;

  reg clk = 1'b0;
  always #5 clk = ~clk;

  reg         rst;
  reg  [5:0]  reg_addr;
  reg  [17:0] reg_wdata;
  reg         reg_we;
  wire [17:0] reg_rdata;
  reg  [19:0] mag_lo, mag_hi;
  reg         in_valid;
  wire        in_ready;
  reg  [15:0] c1, c2, c3, c4;
  wire        out_valid;
  reg         out_ready;
  wire [15:0] angle;
  wire [1:0]  region;
  wire        ovf, los, dos;

  generate
    if (SERIAL != 0) begin : g_serial
      acore_serial_top dut (
        .clk_i(clk), .rst_i(rst), .reg_addr_i(reg_addr), .reg_wdata_i(reg_wdata), .reg_we_i(reg_we),
        .reg_rdata_o(reg_rdata), .mag_lo_i(mag_lo), .mag_hi_i(mag_hi), .in_valid_i(in_valid),
        .in_ready_o(in_ready), .c1_i(c1), .c2_i(c2), .c3_i(c3), .c4_i(c4), .out_valid_o(out_valid),
        .out_ready_i(out_ready), .angle_o(angle), .region_o(region), .ovf_o(ovf), .los_o(los), .dos_o(dos));
    end else begin : g_top
      acore_top #(.FOLD(FOLD)) dut (
        .clk_i(clk), .rst_i(rst), .reg_addr_i(reg_addr), .reg_wdata_i(reg_wdata), .reg_we_i(reg_we),
        .reg_rdata_o(reg_rdata), .mag_lo_i(mag_lo), .mag_hi_i(mag_hi), .in_valid_i(in_valid),
        .in_ready_o(in_ready), .c1_i(c1), .c2_i(c2), .c3_i(c3), .c4_i(c4), .out_valid_o(out_valid),
        .out_ready_i(out_ready), .angle_o(angle), .region_o(region), .ovf_o(ovf), .los_o(los), .dos_o(dos));
    end
  endgenerate

  reg [17:0] regs [0:WORDS-1];
  reg [63:0] vin  [0:MAXN-1];
  reg [20:0] vexp [0:MAXN-1];
  integer n, nin, nout, errors, xz, fd, r, a, seed, cycles, per_sample, rst_ready, rst_valid;
  reg checking, loaded;

  // In every reset clock, from the first: in_ready exactly 0 (a sample offered is not taken).
  always @(posedge clk) begin
    if (rst === 1'b1 && in_ready !== 1'b0) begin
      if (rst_ready < 5) $display("in_ready=%b while rst is high at %0t", in_ready, $time);
      rst_ready = rst_ready + 1;
    end
  end

  // Every clock after reset: no X/Z on any output; compare each delivered sample.
  always @(posedge clk) begin
    if (checking) begin
      if (^{in_ready, out_valid, angle, region, ovf, los, dos} === 1'bx) begin
        if (xz < 5) $display("X/Z on an output at cycle %0d: ready=%b valid=%b angle=%h region=%b flags=%b%b%b",
                             cycles, in_ready, out_valid, angle, region, ovf, los, dos);
        xz = xz + 1;
      end
      if (loaded && (^reg_rdata === 1'bx)) begin
        if (xz < 5) $display("X/Z on reg_rdata at cycle %0d", cycles);
        xz = xz + 1;
      end
      if (out_valid && out_ready) begin
        if ({dos, los, ovf, region, angle} !== vexp[nout]) begin
          if (errors < 5) $display("mismatch at sample %0d: rtl %h, model %h", nout, {dos, los, ovf, region, angle},
                                   vexp[nout]);
          errors = errors + 1;
        end
        nout = nout + 1;
      end
      if (in_valid && in_ready) nin = nin + 1;
      cycles = cycles + 1;
    end
  end

  initial begin
    errors = 0; xz = 0; nin = 0; nout = 0; cycles = 0; checking = 0; loaded = 0; seed = 7;
    rst_ready = 0; rst_valid = 0;
    fd = $fopen({VEC_DIR, "/meta.txt"}, "r");
    if (fd == 0) begin
      $display("FAIL");
      $fatal(1, "cannot open %s/meta.txt", VEC_DIR);
    end
    r = $fscanf(fd, "%d %d %d", n, mag_lo, mag_hi);
    $fclose(fd);
    if (n > MAXN) begin
      $display("FAIL");
      $fatal(1, "%0d samples > MAXN", n);
    end
    $readmemh({VEC_DIR, "/regs.hex"}, regs);
    $readmemh({VEC_DIR, "/in.hex"}, vin, 0, n - 1);
    $readmemh({VEC_DIR, "/exp.hex"}, vexp, 0, n - 1);
    // The serial core takes hundreds of clocks per sample: a prefix of the frame.
    if (SERIAL != 0 && n > N_SERIAL) n = N_SERIAL;
    per_sample = (SERIAL != 0) ? 600 : 20 + FOLD;

    // Reset from power-up with a sample offered.
    rst = 1'b1; reg_we = 1'b0; reg_addr = 6'd0; reg_wdata = 18'd0; in_valid = 1'b1; out_ready = 1'b1;
    {c1, c2, c3, c4} = vin[0];
    repeat (3) @(posedge clk);
    @(negedge clk) begin rst = 1'b0; in_valid = 1'b0; end
    checking = 1;
    for (a = 0; a < WORDS; a = a + 1) begin
      @(negedge clk);
      reg_addr = a; reg_wdata = regs[a]; reg_we = 1'b1;
    end
    @(negedge clk) reg_we = 1'b0;
    // Read-back, both tops: the word at the address of two clocks before.
    for (a = 0; a < WORDS; a = a + 1) begin
      reg_addr = a;
      repeat (2) @(negedge clk);
      if (reg_rdata !== regs[a]) begin
        $display("register %0d read back %h, wrote %h", a, reg_rdata, regs[a]);
        errors = errors + 1;
      end
    end
    loaded = 1;
    // Reset again with a sample offered and a host write (the word inverted) in every clock.
    rst = 1'b1; in_valid = 1'b1; reg_we = 1'b1;
    for (a = 0; a < 4; a = a + 1) begin
      reg_addr = a; reg_wdata = ~regs[a];
      @(negedge clk);
    end
    rst = 1'b0; in_valid = 1'b0; reg_we = 1'b0;
    repeat (300) begin
      @(negedge clk);
      if (out_valid !== 1'b0) rst_valid = rst_valid + 1;
    end
    for (a = 0; a < 4; a = a + 1) begin
      reg_addr = a;
      repeat (2) @(negedge clk);
      if (reg_rdata !== regs[a]) begin
        $display("register %0d changed by a write in reset: %h, was %h", a, reg_rdata, regs[a]);
        errors = errors + 1;
      end
    end
    // Stream: in_valid low 25% of clocks, out_ready low 25%.
    while (nout < n) begin
      @(negedge clk);
      in_valid = (nin < n) && ($random(seed) % 4 != 0);
      out_ready = ($random(seed) % 4 != 0);
      if (nin < n) {c1, c2, c3, c4} = vin[nin];
      if (cycles > per_sample * n + 1000) begin
        $display("FAIL");
        $fatal(1, "timeout");
      end
    end
    @(negedge clk) in_valid = 1'b0;
    repeat (300) @(negedge clk);
    if (SERIAL != 0) $write("icarus (acore_serial_top): ");
    else $write("icarus (acore_top, FOLD=%0d): ", FOLD);
    $display("%0d samples, %0d mismatches, %0d X/Z outputs, %0d cycles; in reset: in_ready high %0d clocks, outputs after it %0d",
             nout, errors, xz, cycles, rst_ready, rst_valid);
    // The exit status says it too (vvp exits 1 on $fatal): FuseSoC's sim target fails with it.
    if (errors == 0 && xz == 0 && nout == n && rst_ready == 0 && rst_valid == 0) $display("PASS");
    else begin
      $display("FAIL");
      $fatal(1, "acore_tb_icarus failed");
    end
    $finish;
  end
endmodule

`default_nettype wire
