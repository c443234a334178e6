// SPDX-License-Identifier: MIT
// acore_apb_tb_icarus: 4-state bench of the APB register shell (rtl/acore_apb.v) around the
// pipelined top (SERIAL=0) or the serial core (SERIAL=1, the first N_SERIAL samples) under Icarus
// Verilog, on the model-generated vectors of tb/icarus/gen_vectors.cpp (regs.hex, in.hex, exp.hex,
// meta.txt: samples, mag_lo, mag_hi, the image's CRC-32). Through APB only: writes the image into
// the shadow window and reads it back, sets the LOS/DOS window, commits under the CRC check,
// streams with random gaps and backpressure, compares every output with the model and its tag
// with the committed generation, and checks that no shell output (APB, interrupt, streams) is
// ever X or Z after reset. At the end the scrubber's CRC must equal the image's.
`timescale 1ns / 1ps
`default_nettype none

module acore_apb_tb_icarus;
  parameter VEC_DIR = ".";
  parameter integer MAXN = 20000;
  parameter integer SERIAL = 0;
  parameter integer N_SERIAL = 200;
  localparam integer WORDS = 52;

  reg clk = 1'b0;
  always #5 clk = ~clk;

  reg         rst;
  reg         psel, penable, pwrite;
  reg  [11:0] paddr;
  reg  [31:0] pwdata;
  reg  [3:0]  pstrb;
  wire [31:0] prdata;
  wire        pready, pslverr, irq;
  reg         in_valid;
  wire        in_ready;
  reg  [15:0] c1, c2, c3, c4;
  wire        out_valid;
  reg         out_ready;
  wire [15:0] angle;
  wire [1:0]  region;
  wire        ovf, los, dos, tag;

  acore_apb #(.SERIAL(SERIAL)) dut (
    .clk_i(clk), .rst_i(rst), .psel_i(psel), .penable_i(penable), .pwrite_i(pwrite), .paddr_i(paddr),
    .pwdata_i(pwdata), .pstrb_i(pstrb), .prdata_o(prdata), .pready_o(pready), .pslverr_o(pslverr),
    .irq_o(irq), .in_valid_i(in_valid), .in_ready_o(in_ready), .c1_i(c1), .c2_i(c2), .c3_i(c3),
    .c4_i(c4), .out_valid_o(out_valid), .out_ready_i(out_ready), .angle_o(angle), .region_o(region),
    .ovf_o(ovf), .los_o(los), .dos_o(dos), .out_tag_o(tag));

  reg [17:0] regs [0:WORDS-1];
  reg [63:0] vin  [0:MAXN-1];
  reg [20:0] vexp [0:MAXN-1];
  reg [31:0] crc, rd, mag_lo, mag_hi;
  reg err;
  integer n, nin, nout, errors, xz, fd, r, a, seed, cycles, per_sample;
  reg checking;

  // APB master: setup phase, access phase; the data and PSLVERR are sampled at the access edge.
  task apb(input wr, input [11:0] addr, input [31:0] data, output [31:0] q, output e);
    begin
      @(negedge clk);
      psel = 1'b1; penable = 1'b0; pwrite = wr; paddr = addr; pwdata = wr ? data : 32'd0; pstrb = 4'hf;
      @(negedge clk);
      penable = 1'b1;
      while (pready !== 1'b1) @(negedge clk);
      @(posedge clk);
      q = prdata; e = pslverr;
      #1 psel = 1'b0; penable = 1'b0; pwrite = 1'b0;
    end
  endtask

  // Every clock after reset: no X/Z on any shell output; compare each delivered sample.
  always @(posedge clk) begin
    if (checking) begin
      if (^{prdata, pready, pslverr, irq, in_ready, out_valid, angle, region, ovf, los, dos, tag} === 1'bx) begin
        if (xz < 5) $display("X/Z on an output at cycle %0d: prdata=%h ready=%b slverr=%b irq=%b in_ready=%b valid=%b angle=%h tag=%b",
                             cycles, prdata, pready, pslverr, irq, in_ready, out_valid, angle, tag);
        xz = xz + 1;
      end
      if (out_valid && out_ready) begin
        if ({dos, los, ovf, region, angle} !== vexp[nout] || tag !== 1'b1) begin
          if (errors < 5) $display("mismatch at sample %0d: rtl %h tag %b, model %h tag 1", nout,
                                   {dos, los, ovf, region, angle}, tag, vexp[nout]);
          errors = errors + 1;
        end
        nout = nout + 1;
      end
      if (in_valid && in_ready) nin = nin + 1;
      cycles = cycles + 1;
    end
  end

  initial begin
    errors = 0; xz = 0; nin = 0; nout = 0; cycles = 0; checking = 0; seed = 11;
    fd = $fopen({VEC_DIR, "/meta.txt"}, "r");
    if (fd == 0) begin
      $fatal(1, "cannot open %s/meta.txt", VEC_DIR);
    end
    r = $fscanf(fd, "%d %d %d %h", n, mag_lo, mag_hi, crc);
    $fclose(fd);
    if (r != 4 || n > MAXN) begin
      $fatal(1, "meta.txt (%0d fields, %0d samples)", r, n);
    end
    $readmemh({VEC_DIR, "/regs.hex"}, regs);
    $readmemh({VEC_DIR, "/in.hex"}, vin, 0, n - 1);
    $readmemh({VEC_DIR, "/exp.hex"}, vexp, 0, n - 1);
    if (SERIAL != 0 && n > N_SERIAL) n = N_SERIAL;
    per_sample = (SERIAL != 0) ? 600 : 20;

    rst = 1'b1; psel = 1'b0; penable = 1'b0; pwrite = 1'b0; paddr = 12'd0; pwdata = 32'd0; pstrb = 4'd0;
    in_valid = 1'b0; out_ready = 1'b1; c1 = 16'd0; c2 = 16'd0; c3 = 16'd0; c4 = 16'd0;
    repeat (3) @(posedge clk);
    @(negedge clk) rst = 1'b0;
    checking = 1;
    // The image into the shadow, read back.
    for (a = 0; a < WORDS; a = a + 1) begin
      apb(1'b1, 12'h400 + 4 * a, {14'd0, regs[a]}, rd, err);
      if (err) errors = errors + 1;
    end
    for (a = 0; a < WORDS; a = a + 1) begin
      apb(1'b0, 12'h400 + 4 * a, 32'd0, rd, err);
      if (err || rd !== {14'd0, regs[a]}) begin
        $display("shadow word %0d read back %h, wrote %h", a, rd, regs[a]);
        errors = errors + 1;
      end
    end
    apb(1'b1, 12'h030, mag_lo, rd, err);
    apb(1'b1, 12'h034, mag_hi, rd, err);
    apb(1'b1, 12'h040, crc, rd, err);
    // CTRL: COMMIT | CRC_CHECK | SCRUB; then STATUS until BUSY falls.
    apb(1'b1, 12'h020, 32'h0000000d, rd, err);
    rd = 32'h00010000;
    while (rd[16]) apb(1'b0, 12'h024, 32'd0, rd, err);
    if (rd[3] || !rd[17] || !rd[5]) begin
      $display("commit: STATUS %h (expected DONE, BANK, no CRC error)", rd);
      errors = errors + 1;
    end
    // Stream: in_valid low 25 % of the clocks, out_ready low 25 %.
    while (nout < n) begin
      @(negedge clk);
      in_valid = (nin < n) && ($random(seed) % 4 != 0);
      out_ready = ($random(seed) % 4 != 0);
      if (nin < n) {c1, c2, c3, c4} = vin[nin];
      if (cycles > per_sample * n + 5000) begin
        $fatal(1, "timeout");
      end
    end
    @(negedge clk) in_valid = 1'b0;
    // One more scrubber pass at least, then its CRC is the image's and no CRC error is flagged.
    repeat (2 * WORDS * 8) @(negedge clk);
    apb(1'b0, 12'h04c, 32'd0, rd, err);
    if (rd !== crc) begin
      $display("CRC_SCRUB %h, image CRC-32 %h", rd, crc);
      errors = errors + 1;
    end
    apb(1'b0, 12'h024, 32'd0, rd, err);
    if (rd[4:3] != 2'b00) begin
      $display("STATUS %h: CRC error flagged", rd);
      errors = errors + 1;
    end
    if (SERIAL != 0) $write("icarus (acore_apb, serial core): ");
    else $write("icarus (acore_apb, acore_top): ");
    $display("%0d samples, %0d mismatches, %0d X/Z outputs, %0d cycles", nout, errors, xz, cycles);
    // The exit status says it too (vvp exits 1 on $fatal): FuseSoC's sim_apb target fails with it.
    if (errors == 0 && xz == 0 && nout == n) $display("PASS");
    else begin
      $display("FAIL");
      $fatal(1, "acore_apb_tb_icarus failed");
    end
    $finish;
  end
endmodule

`default_nettype wire
