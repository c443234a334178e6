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
// the shadow RAM. PSLVERR (with PRDATA = 0 and no effect) answers: an unmapped or unaligned
// address; a write with PSTRB != 4'b1111 (32-bit writes only); a write to a read-only register;
// a shadow-window access, a commit request or a CRC_EXPECTED write while a commit is busy
// (decided in the setup phase). Busy refusals are errors rather than wait states because a commit
// waits for the samples in flight, and those wait for the output's out_ready_i: a wait state could
// hold the bus for ever. A driver polls STATUS.BUSY or enables the DONE interrupt.
//
// Register map: docs/register-shell.md, generated with tb/shell/shell_regs.hpp and the localparams this
// module includes (rtl/acore_apb_regs.vh) from one description, rtl/acore_apb_regs.txt:
// identification and configuration at 0x000..0x010, CTRL, STATUS, IRQ at 0x020..0x028, MAG_LO/HI,
// the CRC registers and the scrubber's count, and the shadow coefficient words at 0x400 + 4a.
`resetall
`default_nettype none

module acore_apb #(
  // 0: rtl/acore_top.v (pipelined, one sample a clock); 1: rtl/acore_serial_top.v (one adder).
  parameter integer SERIAL = 0,
  // The datapath parameters of the top (IN_W .. FOLD, generated from the model's field table):
  // the serial core takes the modes and options the mode table and its rules give it
  // (acore_config_check with SERIAL = 1). FOLD is reported in CONFIG0; ZERO = 1 adds the ZERO
  // word (the zero position, the last register word) to WORDS.
`include "acore_datapath_params.vh"
  // $readmemh register image: power-up contents of the top's words and of the shadow ("" = none).
  parameter INIT_FILE = "",
  // CRC bits per clock: the commit's CRC pass takes WORDS 32/CRC_W clocks. 16 keeps the CRC off
  // the pipelined top's critical path (32 would shorten a commit by ~50 clocks but its fold is the
  // slowest path of the shell, ~105-111 MHz on an HX8K); 8 is smaller and hidden by the serial
  // core's drain.
  parameter integer CRC_W = (SERIAL != 0) ? 8 : 16,
  // APB byte address width (>= 11: registers below 0x100, the shadow window at 0x400).
  parameter integer APB_AW = 12,
  // 1: the drive interfaces' configuration registers (ABZ_N .. TRK_POSITION) and their outputs
  // (rtl/acore_board.v); 0: those addresses are outside the map and the outputs hold their resets.
  parameter integer IFACE = 0,
  // The tracking observer's bandwidth codes (TRK_BW accepts TRK_BW_MIN..TRK_BW_MAX; the board
  // hands rtl/acore_track.v's own range, rtl/acore_derived.vh).
  parameter integer TRK_BW_MIN = 2,
  parameter integer TRK_BW_MAX = 12,
  // Reset values of the LOS/DOS window (MAG_W bits): the default never flags.
  parameter integer MAG_LO_RESET = 0,
  parameter integer MAG_HI_RESET = -1,
  // Derived, do not override (rtl/acore_derived.vh, the tops' functions; WORDS is handed to the
  // top, whose own rule then confirms it).
  parameter integer RG_W = $clog2(REGIONS),
  parameter integer TERMS = acore_terms(CORRECTION, DEGREE),
  parameter integer WORDS = acore_words(TERMS, REGIONS, K, FOURIER_K, ZERO),
  parameter integer ADDR_W = $clog2(WORDS),
  parameter integer MAG_W = acore_mag_w(S_W),
  parameter integer TRK_LOT_W = ANGLE_W - 1
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
  // The drive interfaces' configuration (IFACE = 1; rtl/acore_abz.v, rtl/acore_uvw.v).
  output wire [12:0]        abz_n_o,
  output wire [13:0]        abz_index_o,
  output wire [15:0]        abz_spacing_o,
  output wire [4:0]         uvw_pp_o,
  output wire [ANGLE_W-1:0] uvw_offset_o,
  // The tracking observer's registers (IFACE = 1; rtl/acore_track.v) and what it reads back.
  output wire [3:0]         trk_bw_o,
  output wire [7:0]         trk_lead_o,
  output wire [TRK_LOT_W-1:0] trk_lot_o,
  input  wire [31:0]        trk_velocity_i,
  input  wire [31:0]        trk_position_i
);

`include "acore_derived.vh"

  // ---- the top's timing, by its own functions (rtl/acore_derived.vh) ----
  localparam integer LATENCY = (SERIAL != 0) ? acore_serial_latency(REG_W, S_W, DEGREE, K, ZERO) :
      acore_top_latency(REG_W, S_W, CORRECTION, DEGREE, K, FOURIER_K, FOURIER_M, FOLD);
  localparam integer CYCLES = (SERIAL != 0) ? acore_serial_cycles(REG_W, S_W, DEGREE, K, ZERO) :
      acore_top_cycles(FOLD);
  // The most samples the top holds at once (a commit waits until none is left): one per pipeline
  // stage; the folded top's output FIFO (its credit counter's bound); the serial core's one in work
  // and one result waiting. The shell's in-flight counter counts 0 .. CAPACITY.
  localparam integer CAPACITY = (SERIAL != 0) ? acore_serial_capacity() :
      acore_top_capacity(REG_W, S_W, CORRECTION, DEGREE, K, FOURIER_K, FOURIER_M, FOLD);
  localparam integer CNT_W = $clog2(CAPACITY + 1);

  // Clocks from the top's host address to its reg_rdata_o: both tops share this port timing.
  localparam integer HOST_RD_LAT = 2;

  // ---- the register map (generated: word indices R_*, field positions <REG>_<FIELD>, the
  // decode's register sets, reset values, the constant registers ID_VALUE and CONFIG*_VALUE) ----
`include "acore_apb_regs.vh"
  // The coefficient window: address bits [WIN_AW-1:2] index a word, the bits above select it.
  localparam integer WIN_AW = $clog2(COEF_WORDS) + 2;
  // (The width is kept positive for an illegal APB_AW, so that its rule, below, reports it.)
  localparam integer WIN_SEL_W = (APB_AW > WIN_AW) ? APB_AW - WIN_AW : 1;
  localparam integer WIN_SEL_I = COEF_BASE >> WIN_AW;
  localparam [WIN_SEL_W-1:0] WIN_SEL = WIN_SEL_I[WIN_SEL_W-1:0];

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
  acore_check #(.OK(APB_AW >= 11 && APB_AW <= 32), .VALUE(APB_AW),
    .MSG("illegal parameter: APB_AW must be 11..32 (registers at 0x000, the shadow window at 0x400)"))
    APB_AW_must_be_11_to_32 ();
  acore_check #(.OK(IFACE == 0 || IFACE == 1), .VALUE(IFACE),
    .MSG("illegal parameter: IFACE must be 0 or 1")) IFACE_must_be_0_or_1 ();
  acore_check #(.OK(TRK_BW_MIN >= 0 && TRK_BW_MIN <= TRK_BW_MAX && TRK_BW_MAX <= 15),
    .VALUE(TRK_BW_MAX), .MSG("illegal parameter: TRK_BW_MIN..TRK_BW_MAX must lie in 0..15"))
    TRK_BW_range_must_lie_in_0_to_15 ();
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
  wire [ADDR_W-1:0] top_addr;
  wire [REG_W-1:0] top_wdata, top_rdata;
  wire top_we;
  reg [MAG_W-1:0] mag_lo_q, mag_hi_q;
  generate
    if (SERIAL != 0) begin : g_serial
      acore_serial_top #(
`include "acore_datapath_pass.vh"
        .INIT_FILE(INIT_FILE), .WORDS(WORDS)
      ) u_top (
        .clk_i(clk_i), .rst_i(rst_i), .reg_addr_i(top_addr), .reg_wdata_i(top_wdata), .reg_we_i(top_we),
        .reg_rdata_o(top_rdata), .mag_lo_i(mag_lo_q), .mag_hi_i(mag_hi_q),
        .in_valid_i(top_in_valid), .in_ready_o(top_in_ready), .c1_i(c1_i), .c2_i(c2_i), .c3_i(c3_i),
        .c4_i(c4_i), .out_valid_o(top_out_valid), .out_ready_i(out_ready_i), .angle_o(top_angle),
        .region_o(top_region), .ovf_o(top_ovf), .los_o(top_los), .dos_o(top_dos));
    end else begin : g_pipe
      acore_top #(
`include "acore_datapath_pass.vh"
        .INIT_FILE(INIT_FILE), .WORDS(WORDS)
      ) u_top (
        .clk_i(clk_i), .rst_i(rst_i), .reg_addr_i(top_addr), .reg_wdata_i(top_wdata), .reg_we_i(top_we),
        .reg_rdata_o(top_rdata), .mag_lo_i(mag_lo_q), .mag_hi_i(mag_hi_q),
        .in_valid_i(top_in_valid), .in_ready_o(top_in_ready), .c1_i(c1_i), .c2_i(c2_i), .c3_i(c3_i),
        .c4_i(c4_i), .out_valid_o(top_out_valid), .out_ready_i(out_ready_i), .angle_o(top_angle),
        .region_o(top_region), .ovf_o(top_ovf), .los_o(top_los), .dos_o(top_dos));
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
  assign out_tag_o = bank & top_out_valid;

  // ---- APB: decode and read in the setup phase, write in the access phase ----
  wire setup = psel_i & ~penable_i;
  wire access = psel_i & penable_i;
  wire [5:0] ridx = paddr_i[7:2];
  wire [WIN_AW-3:0] widx = paddr_i[WIN_AW-1:2];
  wire in_regs = (paddr_i[APB_AW-1:8] == {(APB_AW-8){1'b0}});
  wire in_win = (paddr_i[APB_AW-1:WIN_AW] == WIN_SEL) && ({1'b0, widx} < WORDS[WIN_AW-2:0]);
  wire is_ro = REGS_RO[ridx];
  wire is_rw = REGS_WR[ridx];
  wire reg_ok = in_regs & (is_rw | (is_ro & ~pwrite_i));
  wire busy_err = busy & (in_win | (in_regs & pwrite_i & ((ridx == R_CRC_EXPECTED) |
                                                          ((ridx == R_CTRL) & pwdata_i[CTRL_COMMIT]))));
  // Interface values out of range: N 1..2^(N_W-1), pole pairs 1..2^(PP_W-1) (the field widths).
  localparam integer ABZ_N_MAX = 1 << (ABZ_N_N_W - 1);
  localparam integer UVW_PP_MAX = 1 << (UVW_PP_POLE_PAIRS_W - 1);
  wire [ABZ_N_N_W-1:0] wr_n = pwdata_i[ABZ_N_N +: ABZ_N_N_W];
  wire [UVW_PP_POLE_PAIRS_W-1:0] wr_pp = pwdata_i[UVW_PP_POLE_PAIRS +: UVW_PP_POLE_PAIRS_W];
  // The tracker's bandwidth code: TRK_BW_MIN..TRK_BW_MAX (the upper bits of the word must be 0 too:
  // a code of 16 or more is not read as its low bits).
  localparam [31:0] TRK_BW_LO = TRK_BW_MIN;
  localparam [31:0] TRK_BW_HI = TRK_BW_MAX;
  wire range_err = (IFACE != 0) & in_regs & pwrite_i &
      (((ridx == R_ABZ_N) & ((wr_n == 0) | ({19'd0, wr_n} > ABZ_N_MAX))) |
       ((ridx == R_UVW_PP) & ((wr_pp == 0) | ({27'd0, wr_pp} > UVW_PP_MAX))) |
       ((ridx == R_TRK_BW) & ((pwdata_i < TRK_BW_LO) | (pwdata_i > TRK_BW_HI))));
  wire err_d = (paddr_i[1:0] != 2'b00) | (pwrite_i & (pstrb_i != 4'hF)) | ~(reg_ok | in_win) | busy_err |
               range_err;

  // Control and status registers. The sticky STATUS bits are STATUS[STICKY_W-1:0] (the map's W1C
  // bits, scripts/gen_apb_regs.py checks it); their interrupt enables and pending bits have the same
  // positions in CTRL.IRQ_EN and IRQ.PENDING.
  localparam integer STICKY_W = CTRL_IRQ_EN_W;
  reg check_q, scrub_q;
  reg [STICKY_W-1:0] irq_en_q, sticky_q;
  reg [31:0] crc_exp_q;
  wire [31:0] crc_shadow, crc_ref, crc_scrub;
  wire [15:0] scrub_passes;
  wire ref_valid, done, refused, scrub_err;
  wire [STICKY_W-1:0] irq_pend = sticky_q & irq_en_q;
  assign irq_o = |irq_pend;

  // Each register's fields at their positions, zero elsewhere.
  reg [31:0] rd_d;
  always @(*) begin
    rd_d = 32'd0;
    case (ridx)
      R_ID: rd_d = ID_VALUE;
      R_CONFIG0: rd_d = CONFIG0_VALUE;
      R_CONFIG1: rd_d = CONFIG1_VALUE;
      R_CONFIG2: rd_d = CONFIG2_VALUE;
      R_CONFIG3: rd_d = CONFIG3_VALUE;
      R_CTRL: begin
        rd_d[CTRL_CRC_CHECK] = check_q;
        rd_d[CTRL_SCRUB] = scrub_q;
        rd_d[CTRL_IRQ_EN +: CTRL_IRQ_EN_W] = irq_en_q;
      end
      R_STATUS: begin
        rd_d[STICKY_W-1:0] = sticky_q;
        rd_d[STATUS_BUSY] = busy;
        rd_d[STATUS_BANK] = bank;
        rd_d[STATUS_REF_VALID] = ref_valid;
      end
      R_IRQ: rd_d[IRQ_PENDING +: IRQ_PENDING_W] = irq_pend;
      R_MAG_LO: rd_d[MAG_LO_MAG_LO +: MAG_LO_MAG_LO_W] = mag_lo_q;
      R_MAG_HI: rd_d[MAG_HI_MAG_HI +: MAG_HI_MAG_HI_W] = mag_hi_q;
      R_CRC_EXPECTED: rd_d[CRC_EXPECTED_CRC_EXPECTED +: CRC_EXPECTED_CRC_EXPECTED_W] = crc_exp_q;
      R_CRC_SHADOW: rd_d[CRC_SHADOW_CRC_SHADOW +: CRC_SHADOW_CRC_SHADOW_W] = crc_shadow;
      R_CRC_REF: rd_d[CRC_REF_CRC_REF +: CRC_REF_CRC_REF_W] = crc_ref;
      R_CRC_SCRUB: rd_d[CRC_SCRUB_CRC_SCRUB +: CRC_SCRUB_CRC_SCRUB_W] = crc_scrub;
      R_SCRUB_PASSES: rd_d[SCRUB_PASSES_PASSES +: SCRUB_PASSES_PASSES_W] = scrub_passes;
      R_ABZ_N: rd_d[ABZ_N_N +: ABZ_N_N_W] = abz_n_q;
      R_ABZ_INDEX: rd_d[ABZ_INDEX_POS +: ABZ_INDEX_POS_W] = abz_index_q;
      R_ABZ_SPACING: rd_d[ABZ_SPACING_SPACING +: ABZ_SPACING_SPACING_W] = abz_spacing_q;
      R_UVW_PP: rd_d[UVW_PP_POLE_PAIRS +: UVW_PP_POLE_PAIRS_W] = uvw_pp_q;
      R_UVW_OFFSET: rd_d[UVW_OFFSET_OFFSET +: UVW_OFFSET_OFFSET_W] = uvw_offset_q;
      R_TRK_BW: rd_d[TRK_BW_BW +: TRK_BW_BW_W] = trk_bw_q;
      R_TRK_LEAD: rd_d[TRK_LEAD_LEAD +: TRK_LEAD_LEAD_W] = trk_lead_q;
      R_TRK_LOT: rd_d[TRK_LOT_THRESHOLD +: TRK_LOT_THRESHOLD_W] = trk_lot_q;
      R_TRK_VELOCITY: rd_d[TRK_VELOCITY_VELOCITY +: TRK_VELOCITY_VELOCITY_W] =
          (IFACE != 0) ? trk_velocity_i : 32'd0;
      R_TRK_POSITION: rd_d = (IFACE != 0) ? trk_position_i : 32'd0;
      default: rd_d = 32'd0;
    endcase
  end

  // Setup phase: the answer (error, register data, or the shadow word from the RAM next clock) and
  // which register an error-free write will change. rdata_q depends on the register index alone
  // (PRDATA is gated below), and the access phase's write enables are one gate from these flops,
  // so the address decode stays off the data registers' enables.
  // A write without error, by the conditions that apply to each target (no window compare on the
  // register paths).
  wire ok_wr = pwrite_i & (paddr_i[1:0] == 2'b00) & (pstrb_i == 4'hF);
  wire ok_reg_wr = ok_wr & in_regs;
  reg err_q, win_q, w_ctrl_q, w_status_q, w_mag_lo_q, w_mag_hi_q, w_crc_q, w_win_q;
  reg w_abz_n_q, w_abz_index_q, w_abz_spacing_q, w_uvw_pp_q, w_uvw_offset_q;
  reg w_trk_bw_q, w_trk_lead_q, w_trk_lot_q;
  reg [31:0] rdata_q;
  always @(posedge clk_i) begin
    if (setup) begin
      err_q <= err_d;
      win_q <= in_win;
      rdata_q <= rd_d;
      w_ctrl_q <= ok_reg_wr & (ridx == R_CTRL) & ~(busy & pwdata_i[CTRL_COMMIT]);
      w_status_q <= ok_reg_wr & (ridx == R_STATUS);
      w_mag_lo_q <= ok_reg_wr & (ridx == R_MAG_LO);
      w_mag_hi_q <= ok_reg_wr & (ridx == R_MAG_HI);
      w_crc_q <= ok_reg_wr & (ridx == R_CRC_EXPECTED) & ~busy;
      w_win_q <= ok_wr & in_win & ~busy;
      w_abz_n_q <= (IFACE != 0) & ok_reg_wr & (ridx == R_ABZ_N) & ~range_err;
      w_abz_index_q <= (IFACE != 0) & ok_reg_wr & (ridx == R_ABZ_INDEX);
      w_abz_spacing_q <= (IFACE != 0) & ok_reg_wr & (ridx == R_ABZ_SPACING);
      w_uvw_pp_q <= (IFACE != 0) & ok_reg_wr & (ridx == R_UVW_PP) & ~range_err;
      w_uvw_offset_q <= (IFACE != 0) & ok_reg_wr & (ridx == R_UVW_OFFSET);
      w_trk_bw_q <= (IFACE != 0) & ok_reg_wr & (ridx == R_TRK_BW) & ~range_err;
      w_trk_lead_q <= (IFACE != 0) & ok_reg_wr & (ridx == R_TRK_LEAD);
      w_trk_lot_q <= (IFACE != 0) & ok_reg_wr & (ridx == R_TRK_LOT);
    end
  end
  wire [REG_W-1:0] sh_rdata;
  wire rd_access = access & ~pwrite_i & ~err_q;
  assign prdata_o = ~rd_access ? 32'd0 : win_q ? {{(32-REG_W){1'b0}}, sh_rdata} : rdata_q;
  assign pready_o = 1'b1;
  assign pslverr_o = access & err_q;

  // Access phase: the write.
  wire wr_ctrl = access & w_ctrl_q;
  wire commit = wr_ctrl & pwdata_i[CTRL_COMMIT];
  wire clear = wr_ctrl & pwdata_i[CTRL_CLEAR];
  wire [STICKY_W-1:0] w1c = (access && w_status_q) ? pwdata_i[STICKY_W-1:0] : {STICKY_W{1'b0}};
  // The interface registers (IFACE = 1).
  reg [ABZ_N_N_W-1:0] abz_n_q;
  reg [ABZ_INDEX_POS_W-1:0] abz_index_q;
  reg [ABZ_SPACING_SPACING_W-1:0] abz_spacing_q;
  reg [UVW_PP_POLE_PAIRS_W-1:0] uvw_pp_q;
  reg [UVW_OFFSET_OFFSET_W-1:0] uvw_offset_q;
  reg [TRK_BW_BW_W-1:0] trk_bw_q;
  reg [TRK_LEAD_LEAD_W-1:0] trk_lead_q;
  reg [TRK_LOT_THRESHOLD_W-1:0] trk_lot_q;
  always @(posedge clk_i) begin
    if (rst_i) begin
      abz_n_q <= ABZ_N_RESET[ABZ_N_N +: ABZ_N_N_W];
      abz_index_q <= ABZ_INDEX_RESET[ABZ_INDEX_POS +: ABZ_INDEX_POS_W];
      abz_spacing_q <= ABZ_SPACING_RESET[ABZ_SPACING_SPACING +: ABZ_SPACING_SPACING_W];
      uvw_pp_q <= UVW_PP_RESET[UVW_PP_POLE_PAIRS +: UVW_PP_POLE_PAIRS_W];
      uvw_offset_q <= {UVW_OFFSET_OFFSET_W{1'b0}};
      trk_bw_q <= TRK_BW_RESET[TRK_BW_BW +: TRK_BW_BW_W];
      trk_lead_q <= TRK_LEAD_RESET[TRK_LEAD_LEAD +: TRK_LEAD_LEAD_W];
      trk_lot_q <= TRK_LOT_RESET[TRK_LOT_THRESHOLD +: TRK_LOT_THRESHOLD_W];
    end else if (access) begin
      if (w_abz_n_q) abz_n_q <= wr_n;
      if (w_abz_index_q) abz_index_q <= pwdata_i[ABZ_INDEX_POS +: ABZ_INDEX_POS_W];
      if (w_abz_spacing_q) abz_spacing_q <= pwdata_i[ABZ_SPACING_SPACING +: ABZ_SPACING_SPACING_W];
      if (w_uvw_pp_q) uvw_pp_q <= wr_pp;
      if (w_uvw_offset_q) uvw_offset_q <= pwdata_i[UVW_OFFSET_OFFSET +: UVW_OFFSET_OFFSET_W];
      if (w_trk_bw_q) trk_bw_q <= pwdata_i[TRK_BW_BW +: TRK_BW_BW_W];
      if (w_trk_lead_q) trk_lead_q <= pwdata_i[TRK_LEAD_LEAD +: TRK_LEAD_LEAD_W];
      if (w_trk_lot_q) trk_lot_q <= pwdata_i[TRK_LOT_THRESHOLD +: TRK_LOT_THRESHOLD_W];
    end
  end
  assign abz_n_o = abz_n_q;
  assign abz_index_o = abz_index_q;
  assign abz_spacing_o = abz_spacing_q;
  assign uvw_pp_o = uvw_pp_q;
  assign uvw_offset_o = uvw_offset_q;
  assign trk_bw_o = trk_bw_q;
  assign trk_lead_o = trk_lead_q;
  assign trk_lot_o = trk_lot_q;

  localparam [MAG_W-1:0] MAG_LO_R = MAG_LO_RESET[MAG_W-1:0];
  localparam [MAG_W-1:0] MAG_HI_R = MAG_HI_RESET[MAG_W-1:0];
  // Events of this clock at their STATUS positions (set wins over a clear in the same clock: no
  // event is lost).
  reg [STICKY_W-1:0] events;
  always @(*) begin
    events = {STICKY_W{1'b0}};
    events[STATUS_OVF] = emit & top_ovf;
    events[STATUS_LOS] = emit & top_los;
    events[STATUS_DOS] = emit & top_dos;
    events[STATUS_CRC_SHADOW] = refused;
    events[STATUS_CRC_ACTIVE] = scrub_err;
    events[STATUS_DONE] = done;
  end
  always @(posedge clk_i) begin
    if (rst_i) begin
      check_q <= CTRL_RESET[CTRL_CRC_CHECK];
      scrub_q <= CTRL_RESET[CTRL_SCRUB];
      irq_en_q <= CTRL_RESET[CTRL_IRQ_EN +: CTRL_IRQ_EN_W];
      sticky_q <= {STICKY_W{1'b0}};
      mag_lo_q <= MAG_LO_R;
      mag_hi_q <= MAG_HI_R;
      crc_exp_q <= CRC_EXPECTED_RESET;
    end else begin
      if (wr_ctrl) begin
        check_q <= pwdata_i[CTRL_CRC_CHECK];
        scrub_q <= pwdata_i[CTRL_SCRUB];
        irq_en_q <= pwdata_i[CTRL_IRQ_EN +: CTRL_IRQ_EN_W];
      end
      if (access && w_mag_lo_q) mag_lo_q <= pwdata_i[MAG_LO_MAG_LO +: MAG_LO_MAG_LO_W];
      if (access && w_mag_hi_q) mag_hi_q <= pwdata_i[MAG_HI_MAG_HI +: MAG_HI_MAG_HI_W];
      if (access && w_crc_q) crc_exp_q <= pwdata_i[CRC_EXPECTED_CRC_EXPECTED +: CRC_EXPECTED_CRC_EXPECTED_W];
      sticky_q <= (sticky_q & ~(w1c | {STICKY_W{clear}})) | events;
    end
  end

  // ---- the coefficient bank: shadow, commit, CRC, scrubber ----
  acore_coef_bank #(
    .REG_W(REG_W), .WORDS(WORDS), .RD_LAT(HOST_RD_LAT), .CRC_W(CRC_W), .CNT_W(CNT_W), .SETTLE(2),
    .INIT_FILE(INIT_FILE)
  ) u_bank (
    .clk_i(clk_i), .rst_i(rst_i),
    .sh_we_i(access & w_win_q), .sh_waddr_i(widx[ADDR_W-1:0]), .sh_wdata_i(pwdata_i[REG_W-1:0]),
    // Every setup phase reads the shadow (used only for a window read): the address decode stays
    // off the RAM's read enable.
    .sh_re_i(setup), .sh_raddr_i(widx[ADDR_W-1:0]), .sh_rdata_o(sh_rdata),
    .commit_i(commit), .check_i(check_q), .scrub_i(scrub_q), .crc_expected_i(crc_exp_q),
    .accept_i(accept), .emit_i(emit),
    .busy_o(busy), .bank_o(bank), .ref_valid_o(ref_valid),
    .crc_shadow_o(crc_shadow), .crc_ref_o(crc_ref), .crc_scrub_o(crc_scrub), .scrub_passes_o(scrub_passes),
    .done_o(done), .refused_o(refused), .scrub_err_o(scrub_err),
    .top_addr_o(top_addr), .top_wdata_o(top_wdata), .top_we_o(top_we), .top_rdata_i(top_rdata),
    .top_rd_ok_i((SERIAL != 0) ? top_in_ready : 1'b1));

endmodule

`resetall
