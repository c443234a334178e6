// SPDX-License-Identifier: MIT
// acore_stream_formal: the formal harness of the estimator's streaming contract (yosys-smtbmc,
// driven by tb/formal/run.py). It wraps acore_top (SERIAL = 0, pipelined or folded by FOLD) or
// acore_serial_top (SERIAL = 1) and passes them its datapath parameters (set by the driver with
// chparam), drives every
// input freely (reset high in the first clock) and checks the ports against the modules' headers:
//
//   reset     in_ready_o is low while rst_i is high; out_valid_o is low the clock after a reset.
//   count     inputs taken = outputs given + in flight: an output is given only while a sample is in
//             flight (nothing duplicated or invented) and at most CAP samples are in flight.
//   lost      a sample in flight leaves within BOUND clocks in which the output is not held
//             (out_valid_o && !out_ready_i) and (the serial core) no host write lands: nothing is
//             lost.
//   latency   a sample taken into an empty core comes out exactly LATENCY clocks later, not before.
//   hold      while out_valid_o && !out_ready_i, out_valid_o stays high and every output is stable.
//   spacing   (FOLD > 1) two samples are taken at least FOLD clocks apart.
//   pipe      (FOLD = 1) the reference pipeline: valid bits that shift on !(out_valid && !out_ready)
//             give out_valid_o and in_ready_o exactly, and the top's own valid bits equal them (the
//             tap below: the invariant that lets k-induction close).
// Order: the pipelined top moves every sample on one enable and the folded top on a fixed schedule
// into a FIFO, so with counts exact an output is the oldest sample in flight; the FIFO's order is
// proved on its own (acore_fifo_formal.sv, a tagged word).
`default_nettype none

module acore_stream_formal #(
  // The datapath parameters, passed on to the top (IN_W .. FOLD: the registry line's, set by the
  // driver; FOLD also selects the properties below).
`include "acore_datapath_params.vh"
  parameter integer SERIAL = 0,
  // 1: the top inside the APB register shell (rtl/acore_apb.v, SERIAL selects the top): the
  // stream properties at the shell's ports, and the shell's own (g_shell_ref below).
  parameter integer SHELL = 0,
  // 0 (the shell's proof): the top inside the shell is cut by the driver (its outputs free each
  // clock) and its stream constrained by what the top's own proof shows (below, g_core_free):
  // the shell's properties hold for every top. 1: the top kept.
  parameter integer CORE = 1,
  // The shell's in-flight counter width, and its APB address width.
  parameter integer CNT_W = 4,
  parameter integer APB_AW = 12,
  // The shell's image length: the words its shadow bank holds, checks and commits (the driver
  // sets the shell's own, the datapath's WORDS, or a smaller image for a short trace;
  // docs/verification.md says why a proof there is sound).
  parameter integer WORDS = 52,
  // The top's constants as it elaborates them (the driver reads them from the RTL).
  parameter integer LATENCY = 8,
  parameter integer CAP = 8,
  parameter integer BOUND = 8,
  parameter integer ADDR_W = 6,
  parameter integer RG_W = 2,
  parameter integer MAG_W = 20,
  // 1: the timer properties (lost, latency), closed by a bound of LATENCY + 8 clocks; 0: left out
  // (k-induction: there the reference invariants below imply them).
  parameter integer TIMERS = 1,
  // The shell: 1, its commit's invariants asserted (a proof: they make k-induction close); 0, left
  // out (a bounded run: a planted bug is then caught by the property it breaks, not by an
  // invariant a clock earlier).
  parameter integer INVARIANTS = 1,
  // Folded: the datapath's valid bits (acore_fold_datapath.v's v_q), LATENCY - 3 of them (the
  // output register's valid bit, the FIFO's write and read clocks follow).
  parameter integer DPV_W = 1,
  // Folded: the credit counter's width and the FIFO's pointer width.
  parameter integer OCC_W = 9
) (
  input wire               clk_i,
  input wire               rst_i,
  input wire [ADDR_W-1:0]  reg_addr_i,
  input wire [REG_W-1:0]   reg_wdata_i,
  input wire               reg_we_i,
  input wire [MAG_W-1:0]   mag_lo_i,
  input wire [MAG_W-1:0]   mag_hi_i,
  input wire               in_valid_i,
  input wire [IN_W-1:0]    c1_i,
  input wire [IN_W-1:0]    c2_i,
  input wire [IN_W-1:0]    c3_i,
  input wire [IN_W-1:0]    c4_i,
  input wire               out_ready_i,
  // APB4 master (SHELL = 1; assumed to follow the protocol, below).
  input wire               psel_i,
  input wire               penable_i,
  input wire               pwrite_i,
  input wire [APB_AW-1:0]  paddr_i,
  input wire [31:0]        pwdata_i,
  input wire [3:0]         pstrb_i
);
  wire               in_ready_o, out_valid_o, ovf_o, los_o, dos_o;
  wire [ANGLE_W-1:0] angle_o;
  wire [RG_W-1:0]    region_o;
  wire [REG_W-1:0]   reg_rdata_o;

  wire [31:0] prdata_o;
  wire        pready_o, pslverr_o, irq_o, out_tag_o;
  generate
    if (SHELL != 0) begin : g_shell
      acore_apb #(
`include "acore_datapath_pass.vh"
        .SERIAL(SERIAL), .INIT_FILE(""), .APB_AW(APB_AW), .WORDS(WORDS)
      ) dut (
        .clk_i(clk_i), .rst_i(rst_i), .psel_i(psel_i), .penable_i(penable_i), .pwrite_i(pwrite_i),
        .paddr_i(paddr_i), .pwdata_i(pwdata_i), .pstrb_i(pstrb_i), .prdata_o(prdata_o),
        .pready_o(pready_o), .pslverr_o(pslverr_o), .irq_o(irq_o), .in_valid_i(in_valid_i),
        .in_ready_o(in_ready_o), .c1_i(c1_i), .c2_i(c2_i), .c3_i(c3_i), .c4_i(c4_i),
        .out_valid_o(out_valid_o), .out_ready_i(out_ready_i), .angle_o(angle_o),
        .region_o(region_o), .ovf_o(ovf_o), .los_o(los_o), .dos_o(dos_o), .out_tag_o(out_tag_o));
    end
    if (SHELL == 0 && SERIAL != 0) begin : g_serial
      acore_serial_top #(
`include "acore_datapath_pass.vh"
        .INIT_FILE("")
      ) dut (
        .clk_i(clk_i), .rst_i(rst_i), .reg_addr_i(reg_addr_i), .reg_wdata_i(reg_wdata_i),
        .reg_we_i(reg_we_i), .reg_rdata_o(reg_rdata_o), .mag_lo_i(mag_lo_i), .mag_hi_i(mag_hi_i),
        .in_valid_i(in_valid_i), .in_ready_o(in_ready_o), .c1_i(c1_i), .c2_i(c2_i), .c3_i(c3_i),
        .c4_i(c4_i), .out_valid_o(out_valid_o), .out_ready_i(out_ready_i), .angle_o(angle_o),
        .region_o(region_o), .ovf_o(ovf_o), .los_o(los_o), .dos_o(dos_o));
    end
    if (SHELL == 0 && SERIAL == 0) begin : g_top
      acore_top #(
`include "acore_datapath_pass.vh"
        .INIT_FILE("")
      ) dut (
        .clk_i(clk_i), .rst_i(rst_i), .reg_addr_i(reg_addr_i), .reg_wdata_i(reg_wdata_i),
        .reg_we_i(reg_we_i), .reg_rdata_o(reg_rdata_o), .mag_lo_i(mag_lo_i), .mag_hi_i(mag_hi_i),
        .in_valid_i(in_valid_i), .in_ready_o(in_ready_o), .c1_i(c1_i), .c2_i(c2_i), .c3_i(c3_i),
        .c4_i(c4_i), .out_valid_o(out_valid_o), .out_ready_i(out_ready_i), .angle_o(angle_o),
        .region_o(region_o), .ovf_o(ovf_o), .los_o(los_o), .dos_o(dos_o));
    end
  endgenerate

  // Reset in the first clock (the flops' power-up values are free).
  reg init_q = 1'b1;
  always @(posedge clk_i) init_q <= 1'b0;
  always @(*) if (init_q) assume (rst_i);

  wire accept  = in_valid_i && in_ready_o;
  wire deliver = out_valid_o && out_ready_i;
  wire held    = out_valid_o && !out_ready_i;

  // ---- count: inputs taken and outputs given since the last reset ----
  localparam integer CW = 12;
  reg [CW-1:0] taken_q, given_q;
  wire [CW-1:0] inflight = taken_q - given_q;
  always @(posedge clk_i) begin
    if (rst_i) begin
      taken_q <= 0;
      given_q <= 0;
    end else begin
      taken_q <= taken_q + accept;
      given_q <= given_q + deliver;
    end
  end

  // The top's host port writes: the harness's, or (SHELL = 1) the shell's commit (a tap).
  // The shell's gate: no sample taken while a commit is busy (a tap; 0 without the shell).
  wire host_we, shell_busy;
  generate
    if (SHELL != 0) begin : g_host_we
      wire tap_top_we, tap_busy;
      assign host_we = tap_top_we;
      assign shell_busy = tap_busy;
    end else begin : g_host_we_port
      assign host_we = reg_we_i;
      assign shell_busy = 1'b0;
    end
  endgenerate

  // ---- lost: clocks a sample has been in flight with the output free and nothing given ----
  // (the serial core: not counting the clocks in which a host write lands, the clock after the
  // harness gives it: each stalls a scratch-word write by one clock, so a host writing every
  // clock holds the sample for as long; acore_serial_top.v's header)
  reg [CW-1:0] wait_q;
  reg          we_land_q = 1'b0;
  always @(posedge clk_i) begin
    we_land_q <= host_we && !rst_i;
    if (rst_i || deliver || inflight == 0 || held) wait_q <= 0;
    else if (!(SERIAL != 0 && we_land_q)) wait_q <= wait_q + 1'b1;
  end

  // ---- latency: a sample taken into an empty core; host writes may delay the serial core's ----
  reg [CW-1:0] lat_q;      // clocks since that sample was taken (0: none watched)
  reg          lat_we_q;   // a host write since
  always @(posedge clk_i) begin
    if (rst_i) begin
      lat_q <= 0;
      lat_we_q <= 1'b0;
    end else if (lat_q == 0) begin
      if (accept && inflight == 0) lat_q <= 1;
      lat_we_q <= 1'b0;
    end else begin
      lat_q <= (lat_q == LATENCY || deliver) ? 0 : lat_q + 1'b1;
      lat_we_q <= lat_we_q | host_we;
    end
  end

  // ---- spacing (FOLD > 1): clocks since the last sample taken ----
  reg [CW-1:0] since_q;
  always @(posedge clk_i) begin
    if (rst_i) since_q <= FOLD;
    else if (accept) since_q <= 1;
    else if (since_q < FOLD) since_q <= since_q + 1'b1;
  end

  // ---- hold: the outputs of the clock before ----
  reg               past_held_q = 1'b0;
  reg               past_rst_q = 1'b0;
  reg [ANGLE_W-1:0] past_angle_q;
  reg [RG_W-1:0]    past_region_q;
  reg [2:0]         past_flags_q;
  always @(posedge clk_i) begin
    past_held_q   <= held && !rst_i;
    past_rst_q    <= rst_i;
    past_angle_q  <= angle_o;
    past_region_q <= region_o;
    past_flags_q  <= {ovf_o, los_o, dos_o};
  end

  always @(posedge clk_i) begin
    if (!init_q) begin
      // reset
      if (rst_i) assert (!in_ready_o);
      if (past_rst_q) assert (!out_valid_o);
      // count
      if (!rst_i && deliver) assert (inflight != 0);
      if (!rst_i) assert (inflight <= CAP);
      if (TIMERS != 0) begin
        // lost
        if (!rst_i) assert (wait_q <= BOUND);
        // latency
        if (!rst_i && lat_q != 0 && lat_q < LATENCY) assert (!out_valid_o);
        if (!rst_i && lat_q == LATENCY && !(SERIAL != 0 && lat_we_q)) assert (out_valid_o);
      end
      // hold
      if (past_held_q && !rst_i) begin
        assert (out_valid_o);
        assert (angle_o == past_angle_q && region_o == past_region_q &&
                {ovf_o, los_o, dos_o} == past_flags_q);
      end
      // spacing
      if (FOLD > 1 && accept) assert (since_q >= FOLD);
    end
  end

  // ---- the top cut (CORE = 0): its stream as its proof (this harness around the top alone) shows
  // it, assumed: nothing given from an empty core, at most CAP samples taken, the output valid low
  // the clock after a reset and held (with its data) while not taken. The stream properties above
  // then restate these; the shell's below are what this harness proves. ----
  generate
    if (CORE == 0) begin : g_core_free
      always @(*) begin
        if (!init_q) begin
          if (inflight == 0) assume (!out_valid_o);
          if (inflight >= CAP) assume (!in_ready_o);
          if (past_rst_q) assume (!out_valid_o);
          if (past_held_q && !rst_i) assume (out_valid_o && angle_o == past_angle_q &&
                                             region_o == past_region_q &&
                                             {ovf_o, los_o, dos_o} == past_flags_q);
        end
      end
    end
  endgenerate

  // ---- pipe (FOLD = 1): the reference pipeline and the top's valid bits (tap_vld, connected to
  // the top's vld_q by the driver after flattening) ----
  generate
    if (CORE != 0 && SERIAL == 0 && FOLD == 1) begin : g_ref
      reg  [LATENCY-1:0] ref_q;
      wire [LATENCY-1:0] tap_vld;
      wire ref_en = !(ref_q[LATENCY-1] && !out_ready_i);
      always @(posedge clk_i) begin
        if (rst_i) ref_q <= 0;
        else if (ref_en) ref_q <= {ref_q[LATENCY-2:0], accept};
      end
      integer i;
      reg [CW-1:0] ones;
      always @(*) begin
        ones = 0;
        for (i = 0; i < LATENCY; i = i + 1) ones = ones + ref_q[i];
      end
      always @(posedge clk_i) begin
        if (!init_q) begin
          assert (out_valid_o == ref_q[LATENCY-1]);
          assert (in_ready_o == (!rst_i && ref_en && !shell_busy));
          assert (tap_vld == ref_q);
          if (!rst_i) assert (inflight == ones);
        end
      end
    end
  endgenerate

  // ---- folded (FOLD > 1): where every sample in flight is (taps, connected by the driver to the
  // top's credit counter and ready flop, the datapath's valid bits, the output register's valid bit
  // and the FIFO's pointers): in flight = in the datapath + in the output register + stored in the
  // FIFO + on the output port; the credit counter counts them; in_ready_o only when FOLD clocks
  // have passed. These make k-induction close. ----
  generate
    if (CORE != 0 && SERIAL == 0 && FOLD > 1) begin : g_fold_ref
      wire [DPV_W-1:0] tap_v;
      wire             tap_out_vld, tap_rdy;
      wire [OCC_W-1:0] tap_occ, tap_wptr, tap_rptr;
      wire [$clog2(FOLD)-1:0] tap_cnt;
      integer i;
      reg [CW-1:0] ones;
      always @(*) begin
        ones = 0;
        for (i = 0; i < DPV_W; i = i + 1) ones = ones + tap_v[i];
      end
      wire [OCC_W-1:0] stored = tap_wptr - tap_rptr;
      always @(*) begin
        if (!init_q && !rst_i) begin
          assert (inflight == ones + tap_out_vld + stored + out_valid_o);
          assert (tap_occ == inflight);
          assert (tap_cnt == ((since_q >= FOLD) ? FOLD - 1 : since_q - 1));
          if (tap_rdy) assert (tap_cnt == FOLD - 1);
          if (tap_rdy) assert (inflight < CAP);
          if (tap_rdy) assert (in_ready_o == !shell_busy);
        end
      end
    end
  endgenerate
  // ---- serial (SERIAL = 1): where the sample in flight is (taps, connected by the driver to the
  // sequencer's idle state and the stage-2 flag of its OUT operation): being computed (not idle),
  // its result being written to the output registers (OUT's stage 2), or on the output port. These
  // make k-induction close. ----
  generate
    if (CORE != 0 && SERIAL != 0) begin : g_serial_ref
      wire tap_idle, tap_out_we;
      always @(*) begin
        if (!init_q && !rst_i) begin
          assert (inflight == !tap_idle + tap_out_we + out_valid_o);
          if (!tap_idle) assert (!in_ready_o);
        end
      end
    end
  endgenerate
  // ---- shell (SHELL = 1): the APB4 rules, the commit, the CRC, the scrubber ----
  //   apb       PREADY high; PSLVERR only in an access phase (PSEL && PENABLE); no side effect
  //             outside an error-free write access: a register value (CTRL's fields, MAG_LO/HI)
  //             changes, a shadow word is written, a commit is requested or a sticky STATUS bit
  //             falls only the clock after one (or in reset); CRC_EXPECTED's word of the shadow
  //             RAM is written exactly in reset (its reset value) and in an error-free write
  //             access of CRC_EXPECTED (PWDATA), and never read in the clock it is written.
  //   atomic    the top's host port writes (the commit's stream) only while a commit is busy, with
  //             no sample in flight, none taken in that clock or the next (the write lands the
  //             clock after it is registered): every output is computed with one image; the
  //             shadow is not written while a commit is busy (the image checked is the one
  //             streamed), nor read and written in one clock (its block RAM leaves that
  //             undefined: rtl/acore_sync_ram.v).
  //   crc       with CRC_CHECK set when the commit decides, a commit whose shadow CRC (the
  //             engine's, CRC_SHADOW) differs from CRC_EXPECTED (the harness's copy of the last
  //             write, exp_q) writes nothing and keeps the bank.
  //   The shadow RAM's read is cut (a free value each clock); the harness assumes only that a
  //   read of CRC_EXPECTED's word returns exp_q, which the write rule above makes the RAM's.
  //   scrub     the scrubber never writes the top's words: every write is a commit's.
  //   count     the shell's in-flight counter equals the harness's (the invariant for induction).
  generate
    if (SHELL != 0) begin : g_shell_ref
      // APB4 master rules: PENABLE only in the clock after a setup phase (PSEL && !PENABLE),
      // whose address, direction, data and strobes it keeps; PREADY is high, so an access phase
      // lasts one clock. No transfer in reset.
      reg past_setup_q = 1'b0;
      reg [APB_AW-1:0] past_addr_q;
      reg past_write_q;
      reg [31:0] past_wdata_q;
      reg [3:0] past_strb_q;
      always @(posedge clk_i) begin
        past_setup_q <= psel_i && !penable_i && !rst_i;
        past_addr_q <= paddr_i;
        past_write_q <= pwrite_i;
        past_wdata_q <= pwdata_i;
        past_strb_q <= pstrb_i;
      end
      always @(*) begin
        if (rst_i) assume (!psel_i);
        if (penable_i) assume (psel_i && past_setup_q);
        if (past_setup_q) assume (psel_i && penable_i && paddr_i == past_addr_q &&
                                  pwrite_i == past_write_q && pwdata_i == past_wdata_q &&
                                  pstrb_i == past_strb_q);
      end
      wire access = psel_i && penable_i;
      // (taps, connected by the driver to the shell's wires)
      wire tap_top_we, tap_busy, tap_coef_we, tap_sh_re, tap_commit, tap_decide, tap_check;
      wire [31:0] tap_crc;
      wire [CNT_W-1:0] tap_inflight;
      wire tap_bank;
      wire tap_scrub;
      wire [5:0] tap_irq_en;
      wire [MAG_W-1:0] tap_mag_lo, tap_mag_hi;
      wire tap_ovf, tap_los, tap_dos, tap_crc_shadow_err, tap_crc_active_err, tap_done;
      wire [5:0] tap_sticky = {tap_ovf, tap_los, tap_dos, tap_crc_shadow_err, tap_crc_active_err,
                               tap_done};
      wire [2+6+2*MAG_W-1:0] regs = {tap_check, tap_scrub, tap_irq_en, tap_mag_lo, tap_mag_hi};
      reg [2+6+2*MAG_W-1:0] past_regs_q;
      // CRC_EXPECTED in the shadow RAM (rtl/acore_coef_bank.v: the word after CRC_REF's): the
      // RAM's ports, the harness's copy of the register (reset value 0, the register table's)
      // and whether the RAM's output holds a read of its word.
      localparam integer RAM_AW = $clog2(WORDS + 4);
      localparam integer A_EXP_I = WORDS + 3;
      localparam [RAM_AW-1:0] A_EXP = A_EXP_I[RAM_AW-1:0];
      wire tap_ram_we;
      wire [RAM_AW-1:0] tap_ram_waddr, tap_ram_raddr;
      wire [31:0] tap_ram_wdata, tap_q;
      wire exp_wr = access && pwrite_i && !pslverr_o && paddr_i == 32'h40;
      wire exp_we = tap_ram_we && tap_ram_waddr == A_EXP;
      reg [31:0] exp_q;
      reg exp_rd_q = 1'b0;
      always @(posedge clk_i) begin
        if (rst_i) exp_q <= 32'd0;
        else if (exp_wr) exp_q <= pwdata_i;
        exp_rd_q <= !rst_i && tap_sh_re && tap_ram_raddr == A_EXP;
      end
      always @(*) begin
        if (!init_q && exp_rd_q) assume (tap_q == exp_q);
      end
      reg [5:0] past_sticky_q;
      reg past_wr_q = 1'b0, past_top_we_q = 1'b0, past_bank_q, ok_q, past_shell_rst_q = 1'b1;
      always @(posedge clk_i) begin
        past_regs_q <= regs;
        past_sticky_q <= tap_sticky;
        past_wr_q <= access && pwrite_i && !pslverr_o;
        past_top_we_q <= tap_top_we && !rst_i;
        past_bank_q <= tap_bank;
        past_shell_rst_q <= rst_i;
        // the commit's verdict, when it decides: may it write? (the CRC engine holds the shadow's
        // CRC, which CRC_SHADOW's word took, from the CHECK pass's end: the invariants below)
        if (tap_decide) ok_q <= !tap_check || tap_crc == exp_q;
      end
      always @(posedge clk_i) begin
        if (!init_q && !rst_i) begin
          // apb
          assert (pready_o);
          if (pslverr_o) assert (access);
          if (!past_shell_rst_q && !past_wr_q) begin
            assert (regs == past_regs_q);
            assert ((past_sticky_q & ~tap_sticky) == 6'd0);
          end
          if (tap_coef_we || tap_commit) assert (access && pwrite_i && !pslverr_o);
          // atomic, scrub
          if (tap_top_we) assert (tap_busy && inflight == 0 && !accept);
          if (past_top_we_q) assert (!accept);
          if (tap_coef_we) assert (!tap_busy && !tap_sh_re);
          // crc: a write follows a decision that allowed it; the bank flips only after writes
          if (tap_top_we) assert (ok_q);
          if (!past_shell_rst_q && tap_bank != past_bank_q) assert (ok_q);
          // count
          assert (tap_inflight == inflight);
        end
        // CRC_EXPECTED's word
        if (!init_q) begin
          assert (exp_we == (rst_i || exp_wr));
          if (exp_we) assert (tap_ram_wdata == (rst_i ? 32'd0 : pwdata_i));
          // (in reset a read of it may meet reset's write: nothing takes that read's output)
          if (exp_we && !rst_i) assert (!(tap_sh_re && tap_ram_raddr == A_EXP));
        end
      end

      // The commit's invariants (what makes the proof unbounded: the bank's state, its comparator
      // pipeline and CRC_SHADOW tied to the harness's verdict ok_q and counters). Taps, connected
      // by the driver to the bank (rtl/acore_coef_bank.v): its state, busy flop and registered
      // request; the CHECK pass's flags (the last word fed to the CRC engine, its CRC taken into
      // CRC_SHADOW, the comparison ready), words left and CRC load; STREAM's pending word; SETTLE's
      // counter; the comparator (CRC != reference, registered, and the reference it used); the CRC
      // engine's value and idle flag.
      localparam [2:0] C_IDLE = 3'd0, C_INIT = 3'd1, C_CHECK = 3'd2, C_STREAM = 3'd3,
                       C_SETTLE = 3'd4;
      // (keep: with INVARIANTS = 0 nothing reads them, and the driver still connects them)
      (* keep *) wire [2:0] tap_state;
      // (SETTLE's counter: clog2(SETTLE) bits, one at the shell's SETTLE = 2)
      (* keep *) wire tap_settle;
      (* keep *) wire tap_busy_q, tap_req, tap_fed, tap_crc_done, tap_cmp, tap_neq, tap_sel;
      (* keep *) wire tap_more, tap_ld, tap_pend, tap_crc_idle, tap_exp_ld;
      wire streaming = tap_state == C_STREAM || tap_state == C_SETTLE;
      wire checked = tap_state == C_CHECK && tap_crc_done;
      always @(posedge clk_i) begin
        if (INVARIANTS != 0 && !init_q && !rst_i) begin
          assert (tap_state <= C_SETTLE);
          assert (tap_busy_q == (tap_state != C_IDLE));
          assert (tap_busy == (tap_busy_q || tap_req));
          if (tap_req) assert (tap_state == C_IDLE);
          // STREAM and SETTLE: decided to write, nothing in flight; the top's port written only
          // there, and not in SETTLE's last clock (the samples flow again the clock after it).
          if (streaming) assert (ok_q && tap_inflight == 0);
          if (tap_pend) assert (tap_state == C_STREAM);
          if (tap_top_we) assert (streaming);
          if (tap_top_we && tap_state == C_SETTLE) assert (tap_settle != 0);
          // CHECK: once the last word is fed, no more loads; once its CRC is taken (into
          // CRC_SHADOW's word, with a read of CRC_EXPECTED's), the engine is idle (its CRC still);
          // the clock after, the RAM's output holds CRC_EXPECTED's word (exp_ld); from the next,
          // the comparator holds CRC != CRC_EXPECTED (locked while busy).
          if (tap_state == C_CHECK && tap_fed) assert (!tap_more);
          if (checked) begin
            assert (tap_fed && !tap_more && !tap_ld && tap_crc_idle && tap_sel);
            if (tap_cmp) assert (tap_neq == (tap_crc != exp_q));
            else assert (tap_exp_ld);
          end
          if (tap_exp_ld) assert (checked && !tap_cmp && exp_rd_q);
          if (tap_state == C_CHECK && tap_cmp) assert (tap_crc_done);
        end
      end
    end
  endgenerate

endmodule
