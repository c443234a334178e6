// SPDX-License-Identifier: MIT
// acore_apb: the AngleCore register shell. An APB4 slave (AMBA APB protocol v2.0) around either
// top (SERIAL = 0: rtl/acore_top.v with all its parameters, pipelined or folded by FOLD; SERIAL = 1:
// the serial core rtl/acore_serial_top.v), with identification and configuration registers, a shadow
// coefficient bank committed between samples under a CRC-32 check (rtl/acore_coef_bank.v), a
// background scrubber of the active words, sticky status, an interrupt, and the LOS/DOS window as
// registers. The tops are used as they are: their raw host port belongs to the shell, their
// valid/ready streams pass through (gated during a commit), and every output carries out_tag_o,
// the generation bit of the coefficient image it was computed with.
//
//   APB --> register block --> shadow bank (RAM) --commit--> top host port <-- scrubber (CRC)
//   c1..c4, in_valid --[gate while committing]--> acore_top | acore_serial_top --> angle, flags, tag
//
// Why APB: the shell has a dozen 32-bit registers and a coefficient window written once in a
// while; APB4 is the standard bus for such peripherals (every SoC interconnect has an AXI/AHB to
// APB bridge), and its two-phase transfer costs a handful of flops where AXI4-Lite needs five
// channels with independent handshakes and a write-address/write-data join.
//
// APB timing: zero wait states (PREADY is always high). The shell decodes the address and reads
// in the setup phase (PSEL && !PENABLE), so the access phase returns registered data, also from
// the shadow RAM, which holds CRC_EXPECTED, CRC_SHADOW, CRC_REF and CRC_SCRUB too (rtl/acore_coef_bank.v).
// PSLVERR (with PRDATA = 0 and no effect) answers: an unmapped or unaligned address; a write with PSTRB != 4'b1111 (32-bit writes only); a write to a read-only register;
// a shadow-window access, a commit request or a CRC_EXPECTED write while a commit is busy
// (decided in the setup phase). Busy refusals are errors rather than wait states because a commit
// waits for the samples in flight, and those wait for the output's out_ready_i: a wait state could
// hold the bus for ever. A driver polls STATUS.BUSY or enables the DONE interrupt.
//
// Register map: docs/register-shell.md: identification and configuration at 0x000..0x010, CTRL,
// STATUS, IRQ at 0x020..0x028, MAG_LO/HI, the CRC registers and the scrubber's count, and the shadow
// coefficient words at 0x400 + 4a. The registers themselves (the APB decode, the flops, the read
// mux, the refusals) are the register block rtl/acore_apb_regblock.v, generated with the
// localparams, wires and instance this module includes (rtl/acore_apb_regs.vh), tb/shell/shell_regs.hpp
// and the table from one description, rtl/acore_apb_regs.txt; this module keeps the behaviour:
// the commit, the CRC and the scrubber (rtl/acore_coef_bank.v), the busy refusals, the bank, the
// sticky events and the interrupt.
`resetall
`default_nettype none

module acore_apb #(
  // 0: rtl/acore_top.v (pipelined, one sample a clock); 1: rtl/acore_serial_top.v (one adder).
  parameter integer SERIAL = 0,
  // The datapath parameters of the top (IN_W .. MULT, generated from the model's field table):
  // the serial core takes the modes and options the mode table and its rules give it
  // (acore_config_check with SERIAL = 1). FOLD is reported in CONFIG0; ZERO = 1 adds the ZERO
  // word (the zero position, the last register word) to WORDS.
`include "acore_datapath_params.vh"
  // $readmemh register image: power-up contents of the top's words and of the shadow ("" = none).
  parameter INIT_FILE = "",
  // CRC bits per clock: the commit's CRC pass takes WORDS 32/CRC_W clocks. 16 keeps the CRC off
  // the pipelined top's critical path (32 would shorten a commit by ~50 clocks but its fold is the
  // slowest path of the shell, ~105-111 MHz on an HX8K); 8 is smaller and hidden by the serial
  // core's drain; 4 around a folded top, whose small area is the point (the engine 88 LUT4s
  // instead of 212 at 16; a commit of 52 words is busy ~470 clocks instead of ~170).
  parameter integer CRC_W = (SERIAL != 0) ? 8 : (FOLD > 1) ? 4 : 16,
  // APB byte address width (>= 11: registers below 0x100, the shadow window at 0x400).
  parameter integer APB_AW = 12,
  // Reset values of the LOS/DOS window (MAG_W bits): the default never flags.
  parameter integer MAG_LO_RESET = 0,
  parameter integer MAG_HI_RESET = -1,
  // Derived, do not override (rtl/acore_derived.vh, the tops' functions; WORDS is handed to the
  // top, whose own rule then confirms it).
  parameter integer RG_W = $clog2(REGIONS),
  parameter integer TERMS = acore_terms(CORRECTION, DEGREE),
  parameter integer WORDS = acore_words(TERMS, REGIONS, K, FOURIER_K, ZERO),
  parameter integer ADDR_W = $clog2(WORDS),
  parameter integer MAG_W = acore_mag_w(S_W)
) (
  input  wire               clk_i,
  // Synchronous, active high: the shell's control state and the top's (in_ready_o is low).
  input  wire               rst_i,
  // APB4 slave.
  input  wire               psel_i,
  input  wire               penable_i,
  input  wire               pwrite_i,
  input  wire [APB_AW-1:0]  paddr_i,
  input  wire [31:0]        pwdata_i,
  input  wire [3:0]         pstrb_i,
  output wire [31:0]        prdata_o,
  output wire               pready_o,
  output wire               pslverr_o,
  // Interrupt, level, high while any enabled sticky STATUS bit is set.
  output wire               irq_o,
  // Input stream (low in_ready_o in reset and while a commit is busy).
  input  wire               in_valid_i,
  output wire               in_ready_o,
  input  wire [IN_W-1:0]    c1_i,
  input  wire [IN_W-1:0]    c2_i,
  input  wire [IN_W-1:0]    c3_i,
  input  wire [IN_W-1:0]    c4_i,
  // Output stream: the top's, plus the image's generation bit (STATUS.BANK when it was computed).
  output wire               out_valid_o,
  input  wire               out_ready_i,
  output wire [ANGLE_W-1:0] angle_o,
  output wire [RG_W-1:0]    region_o,
  output wire               ovf_o,
  output wire               los_o,
  output wire               dos_o,
  output wire               out_tag_o,
  // The top's magnitude with the angle (rtl/acore_top.v's mag_o).
  output wire [MAG_W-1:0]   mag_o
);

`include "acore_derived.vh"

  // ---- the top's timing, by its own functions (rtl/acore_derived.vh) ----
  localparam integer LATENCY = (SERIAL != 0) ? acore_serial_latency(REG_W, S_W, DEGREE, K, ZERO, MULT) :
      acore_top_latency(REG_W, S_W, CORRECTION, DEGREE, K, FOURIER_K, FOURIER_M, FOLD, MULT);
  localparam integer CYCLES = (SERIAL != 0) ? acore_serial_cycles(REG_W, S_W, DEGREE, K, ZERO, MULT) :
      acore_top_cycles(FOLD);
  // The most samples the top holds at once (a commit waits until none is left): one per pipeline
  // stage; the folded top's output FIFO (its credit counter's bound); the serial core's one in work
  // and one result waiting. The shell's in-flight counter counts 0 .. CAPACITY.
  localparam integer CAPACITY = (SERIAL != 0) ? acore_serial_capacity() :
      acore_top_capacity(REG_W, S_W, CORRECTION, DEGREE, K, FOURIER_K, FOURIER_M, FOLD);
  localparam integer CNT_W = $clog2(CAPACITY + 1);

  // Clocks from the top's host address to its reg_rdata_o: both tops share this port timing.
  localparam integer HOST_RD_LAT = 2;

  // ---- the registers (generated: field positions <REG>_<FIELD>, the constant registers'
  // CONFIG*_VALUE, a wire rg_<reg>_<field> per port of the register block and its instance u_regs,
  // which answers every address of the shell: the APB slave is the block) ----
`include "acore_apb_regs.vh"
  assign rg_psel = psel_i;
  assign prdata_o = rg_prdata;
  assign pready_o = 1'b1;
  assign pslverr_o = rg_pslverr;

  // Parameter rules of the shell (rtl/acore_check.v: they stop Verilator, Icarus and Yosys); the
  // datapath's own rules are the top's (acore_config_check), applied when it is built below.
  acore_check #(.OK(SERIAL == 0 || SERIAL == 1), .VALUE(SERIAL),
    .MSG("illegal parameter: SERIAL must be 0 (acore_top) or 1 (acore_serial_top)"))
    SERIAL_must_be_0_or_1 ();
  // The correction mode (the mode table's rules: a known mode, its DEGREE, the tops that build
  // it) and the serial core's options, also at the shell's own level (rtl/acore_serial_checks.vh
  // says why); the top checks them again (acore_config_check).
`include "acore_mode_checks.vh"
`include "acore_serial_checks.vh"
  acore_check #(.OK(WORDS <= COEF_WORDS), .VALUE(WORDS),
    .MSG("illegal parameter: WORDS must be at most 256 (the shadow window)"))
    WORDS_must_fit_the_shadow_window ();
  acore_check #(.OK(CRC_W == 1 || CRC_W == 2 || CRC_W == 4 || CRC_W == 8 || CRC_W == 16 || CRC_W == 32),
    .VALUE(CRC_W), .MSG("illegal parameter: CRC_W must be 1, 2, 4, 8, 16 or 32"))
    CRC_W_must_divide_32 ();
  acore_check #(.OK(RG_W == $clog2(REGIONS)), .VALUE(RG_W),
    .MSG("illegal parameter: RG_W is derived (clog2(REGIONS)), do not override"))
    RG_W_is_derived ();
  acore_check #(.OK(TERMS == acore_terms(CORRECTION, DEGREE)), .VALUE(TERMS),
    .MSG("illegal parameter: TERMS is derived (coefficients per region and curve), do not override"))
    TERMS_is_derived ();
  acore_check #(.OK(ADDR_W == $clog2(WORDS)), .VALUE(ADDR_W),
    .MSG("illegal parameter: ADDR_W is derived (clog2(WORDS)), do not override"))
    ADDR_W_is_derived ();
  acore_check #(.OK(MAG_W == acore_mag_w(S_W)), .VALUE(MAG_W),
    .MSG("illegal parameter: MAG_W is derived (S_W+2), do not override"))
    MAG_W_is_derived ();

  // ---- the top ----
  wire top_in_valid, top_in_ready, top_out_valid;
  wire [ANGLE_W-1:0] top_angle;
  wire [RG_W-1:0] top_region;
  wire top_ovf, top_los, top_dos;
  wire [MAG_W-1:0] top_mag;
  wire [ADDR_W-1:0] top_addr;
  wire [REG_W-1:0] top_wdata, top_rdata;
  wire top_we;
  generate
    if (SERIAL != 0) begin : g_serial
      acore_serial_top #(
`include "acore_datapath_pass.vh"
        .INIT_FILE(INIT_FILE), .WORDS(WORDS)
      ) u_top (
        .clk_i(clk_i), .rst_i(rst_i), .reg_addr_i(top_addr), .reg_wdata_i(top_wdata), .reg_we_i(top_we),
        .reg_rdata_o(top_rdata), .mag_lo_i(rg_mag_lo), .mag_hi_i(rg_mag_hi),
        .in_valid_i(top_in_valid), .in_ready_o(top_in_ready), .c1_i(c1_i), .c2_i(c2_i), .c3_i(c3_i),
        .c4_i(c4_i), .out_valid_o(top_out_valid), .out_ready_i(out_ready_i), .angle_o(top_angle),
        .region_o(top_region), .ovf_o(top_ovf), .los_o(top_los), .dos_o(top_dos),
        .mag_o(top_mag));
    end else begin : g_pipe
      acore_top #(
`include "acore_datapath_pass.vh"
        .INIT_FILE(INIT_FILE), .WORDS(WORDS)
      ) u_top (
        .clk_i(clk_i), .rst_i(rst_i), .reg_addr_i(top_addr), .reg_wdata_i(top_wdata), .reg_we_i(top_we),
        .reg_rdata_o(top_rdata), .mag_lo_i(rg_mag_lo), .mag_hi_i(rg_mag_hi),
        .in_valid_i(top_in_valid), .in_ready_o(top_in_ready), .c1_i(c1_i), .c2_i(c2_i), .c3_i(c3_i),
        .c4_i(c4_i), .out_valid_o(top_out_valid), .out_ready_i(out_ready_i), .angle_o(top_angle),
        .region_o(top_region), .ovf_o(top_ovf), .los_o(top_los), .dos_o(top_dos),
        .mag_o(top_mag));
    end
  endgenerate

  // ---- streams: no sample enters in reset or while a commit is busy ----
  wire busy, bank;
  wire gate = busy | rst_i;
  assign top_in_valid = in_valid_i & ~gate;
  assign in_ready_o = top_in_ready & ~gate;
  wire accept = top_in_valid & top_in_ready;
  wire emit = top_out_valid & out_ready_i;
  assign out_valid_o = top_out_valid;
  assign angle_o = top_angle;
  assign region_o = top_region;
  assign ovf_o = top_ovf;
  assign los_o = top_los;
  assign dos_o = top_dos;
  assign mag_o = top_mag;
  assign out_tag_o = bank & top_out_valid;

  // ---- status and interrupt ----
  // The sticky STATUS events of this clock (the register block lets a set win over a clear in the
  // same clock: no event is lost), and the live state.
  wire done, refused, scrub_err, ref_valid;
  assign rg_status_ovf_set = emit & top_ovf;
  assign rg_status_los_set = emit & top_los;
  assign rg_status_dos_set = emit & top_dos;
  assign rg_status_crc_shadow_set = refused;
  assign rg_status_crc_active_set = scrub_err;
  assign rg_status_done_set = done;
  assign rg_status_busy = busy;
  assign rg_status_bank = bank;
  assign rg_status_ref_valid = ref_valid;
  // The sticky bits at their STATUS positions: their interrupt enables and pending bits have the
  // same positions in CTRL.IRQ_EN and IRQ.PENDING (the description's `irq` line, checked by
  // scripts/gen_apb_regs.py).
  localparam integer STICKY_W = CTRL_IRQ_EN_W;
  reg [STICKY_W-1:0] sticky;
  always @(*) begin
    sticky = {STICKY_W{1'b0}};
    sticky[STATUS_OVF] = rg_status_ovf;
    sticky[STATUS_LOS] = rg_status_los;
    sticky[STATUS_DOS] = rg_status_dos;
    sticky[STATUS_CRC_SHADOW] = rg_status_crc_shadow;
    sticky[STATUS_CRC_ACTIVE] = rg_status_crc_active;
    sticky[STATUS_DONE] = rg_status_done;
  end
  assign rg_irq_pending = sticky & rg_ctrl_irq_en;
  assign irq_o = |rg_irq_pending;

  // Busy refusals (errors, not wait states: a commit waits for the samples in flight, and those
  // wait for out_ready_i, so a wait state could hold the bus for ever): while a commit is busy,
  // a shadow access, a commit request and a CRC_EXPECTED write.
  assign rg_coef_lock = busy;
  assign rg_ctrl_commit_lock = busy;
  assign rg_crc_expected_lock = busy;

  // The shadow's write data is PWDATA whole (CRC_EXPECTED's word), whose REG_W low bits the
  // COEF window's write data repeats: that copy goes unused.
  wire coef_wdata_unused = ^rg_coef_wdata;

  // ---- the coefficient bank: shadow, commit, CRC, scrubber ----
  acore_coef_bank #(
    .REG_W(REG_W), .WORDS(WORDS), .RD_LAT(HOST_RD_LAT), .RD_HOLD((SERIAL == 0) ? 1 : 0), .CRC_W(CRC_W),
    .CNT_W(CNT_W), .SETTLE(2),
    .INIT_FILE(INIT_FILE), .EXP_RESET(CRC_EXPECTED_RESET)
  ) u_bank (
    .clk_i(clk_i), .rst_i(rst_i),
    // The shadow is the COEF window's memory (the block reads it in every setup phase).
    // (its write data PWDATA: CRC_EXPECTED's word, whose REG_W low bits are a COEF word's)
    .sh_we_i(rg_coef_we), .sh_waddr_i(rg_coef_addr), .sh_wdata_i(rg_crc_expected_wdata),
    .sh_re_i(rg_coef_re), .sh_raddr_i(rg_coef_addr), .crc_shadow_re_i(rg_crc_shadow_re),
    .crc_scrub_re_i(rg_crc_scrub_re), .crc_ref_re_i(rg_crc_ref_re),
    .exp_re_i(rg_crc_expected_re), .exp_we_i(rg_crc_expected_we), .sh_rdata_o(rg_coef_rdata),
    .crc_shadow_zero_o(rg_crc_shadow_zero), .crc_scrub_zero_o(rg_crc_scrub_zero),
    .crc_ref_zero_o(rg_crc_ref_zero),
    .commit_i(rg_ctrl_commit), .check_i(rg_ctrl_crc_check), .scrub_i(rg_ctrl_scrub),
    .accept_i(accept), .emit_i(emit),
    .busy_o(busy), .bank_o(bank), .ref_valid_o(ref_valid),
    .scrub_passes_o(rg_scrub_passes_passes),
    .done_o(done), .refused_o(refused), .scrub_err_o(scrub_err),
    .top_addr_o(top_addr), .top_wdata_o(top_wdata), .top_we_o(top_we), .top_rdata_i(top_rdata),
    .top_rd_ok_i((SERIAL != 0) ? top_in_ready : 1'b1));

endmodule

`resetall
