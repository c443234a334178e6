// SPDX-License-Identifier: MIT
// acore_apb: the AngleCore register shell. An APB4 slave (AMBA APB protocol v2.0) around either
// top (SERIAL = 0: the pipelined rtl/acore_top.v with all its parameters; SERIAL = 1: the serial
// core rtl/acore_serial_top.v), with identification and configuration registers, a shadow
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
// Register map (byte addresses, 32-bit registers; see README "Register shell (APB)"):
//   0x000 ID            RO  0x4143_0100: "AC", version 1.0
//   0x004 CONFIG0       RO  [3:0] DEGREE [7:4] REGIONS [9:8] CORRECTION [10] XCENTER [11] ZERO
//                           [12] SERIAL [19:16] FOLD [28:24] K
//   0x008 CONFIG1       RO  [15:0] WORDS [20:16] FOURIER_K [28:24] REG_W
//   0x00C CONFIG2       RO  [15:0] LATENCY [31:16] CYCLES (clocks per sample)
//   0x010 CONFIG3       RO  [7:0] IN_W [15:8] ANGLE_W [23:16] MAG_W [31:24] CRC_W
//   0x020 CTRL          RW  [0] COMMIT (write 1: start a commit; reads 0) [1] CLEAR (write 1:
//                           clear every sticky STATUS bit; reads 0) [2] CRC_CHECK (reset 0)
//                           [3] SCRUB (reset 1) [13:8] IRQ_EN for STATUS[5:0] (reset 0)
//   0x024 STATUS        W1C [0] OVF [1] LOS [2] DOS [3] CRC_SHADOW (a commit was refused: shadow
//                           CRC != CRC_EXPECTED) [4] CRC_ACTIVE (the scrubber found the active words
//                           changed) [5] DONE (a commit ended); RO live: [16] BUSY [17] BANK
//                           [18] REF_VALID (an image was committed since reset: the scrubber checks)
//   0x028 IRQ           RO  [5:0] STATUS[5:0] & IRQ_EN; irq_o = |IRQ
//   0x030 MAG_LO        RW  [MAG_W-1:0] LOS below this magnitude (reset MAG_LO_RESET)
//   0x034 MAG_HI        RW  [MAG_W-1:0] DOS above this magnitude (reset MAG_HI_RESET)
//   0x040 CRC_EXPECTED  RW  CRC-32 the shadow must have for a checked commit (reset 0)
//   0x044 CRC_SHADOW    RO  CRC-32 of the shadow at the last commit
//   0x048 CRC_REF       RO  CRC-32 of the active image (set by each applied commit)
//   0x04C CRC_SCRUB     RO  CRC-32 of the active words at the scrubber's last pass
//   0x050 SCRUB_PASSES  RO  [15:0] completed scrubber passes (wrapping)
//   0x400 + 4a          RW  shadow coefficient word a < WORDS ([REG_W-1:0]; upper bits read 0 and
//                           are ignored on write)
`resetall
`default_nettype none

module acore_apb #(
  // 0: rtl/acore_top.v (pipelined, one sample a clock); 1: rtl/acore_serial_top.v (one adder).
  parameter integer SERIAL = 0,
  // The tops' parameters (rtl/acore_top.v documents each). The serial core has no CORRECTION,
  // XCENTER or Fourier stage: with SERIAL = 1 they must keep their defaults.
  parameter integer IN_W = 16,
  parameter integer REG_W = 18,
  parameter integer S_W = 18,
  parameter integer S_F = 16,
  parameter integer R_SHIFT = 13,
  parameter integer SCALE_G = 4,
  parameter integer CORRECTION = 0,
  parameter integer DEGREE = 3,
  parameter integer REGIONS = 4,
  parameter integer XCENTER = 0,
  parameter integer COEF_F = 15,
  parameter integer ACC_G = 4,
  parameter integer ACC_I = 6,
  parameter integer K = 16,
  parameter integer CORDIC_G = 3,
  parameter integer Z_W = 20,
  parameter integer ANGLE_W = 16,
  parameter integer FOURIER_K = 0,
  parameter integer FOURIER_M = 12,
  parameter integer FOURIER_CF = 22,
  parameter integer FOURIER_W = 16,
  parameter integer FOURIER_G = 2,
  // 1: the ZERO word (the zero position, last register word; both tops): WORDS counts it.
  parameter integer ZERO = 0,
  // Fold factor of acore_top, reported in CONFIG0 (the shell wraps FOLD = 1 only, see its rule).
  parameter integer FOLD = 1,
  // $readmemh register image: power-up contents of the top's words and of the shadow ("" = none).
  parameter INIT_FILE = "",
  // CRC bits per clock: the commit's CRC pass takes WORDS 32/CRC_W clocks. 16 keeps the CRC off
  // the pipelined top's critical path (32 would shorten a commit by ~50 clocks but its fold is the
  // slowest path of the shell, ~105-111 MHz on an HX8K); 8 is smaller and hidden by the serial
  // core's drain.
  parameter integer CRC_W = (SERIAL != 0) ? 8 : 16,
  // APB byte address width (>= 11: registers below 0x100, the shadow window at 0x400).
  parameter integer APB_AW = 12,
  // Reset values of the LOS/DOS window (MAG_W bits): the default never flags.
  parameter integer MAG_LO_RESET = 0,
  parameter integer MAG_HI_RESET = -1,
  // Derived, do not override (the tops' formulas; WORDS is handed to the top, whose own rule
  // then confirms it).
  parameter integer RG_W = $clog2(REGIONS),
  parameter integer TERMS = (CORRECTION == 2) ? 0 :
                            (CORRECTION == 1) ? ((DEGREE == 1) ? 3 : (DEGREE == 2) ? 6 : 10) : DEGREE + 1,
  parameter integer WORDS = 4 + (TERMS << ($clog2(REGIONS) + 1)) + K +
                            ((FOURIER_K > 0) ? (FOURIER_K << 1) + 1 : 0) + ((ZERO != 0) ? 1 : 0),
  parameter integer ADDR_W = $clog2(WORDS),
  parameter integer MAG_W = S_W + 2
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
  output wire               out_tag_o
);

  function integer apb_cmul(input integer a, input integer b);
    integer n;
    begin
      apb_cmul = 0;
      for (n = 0; n < b; n = n + 1) apb_cmul = apb_cmul + a;
    end
  endfunction

  // ---- the top's timing, by its own formulas (README "RTL", "Serial core") ----
  localparam integer FOURIER_KB = ($clog2(FOURIER_K + 1) > 2) ? $clog2(FOURIER_K + 1) : 2;
  localparam integer TOP_LATENCY = 1 + ($clog2(REG_W) + 3) + 2 +
      ((CORRECTION == 2) ? 0 : (CORRECTION == 1) ? 6 + apb_cmul(DEGREE, $clog2(S_W) + 2) :
                                                   4 + apb_cmul(DEGREE, $clog2(S_W) + 2)) +
      (K + 2) + ((FOURIER_K > 0) ? $clog2(FOURIER_KB) + 1 + FOURIER_M + $clog2(FOURIER_K + 1) + 1 : 0) + 1;
  localparam integer SERIAL_CYCLES = 22 + ((ZERO != 0) ? 1 : 0) + (REG_W << 1) + apb_cmul(DEGREE << 1, S_W + 2) +
                                     apb_cmul(3, K);
  localparam integer LATENCY = (SERIAL != 0) ? SERIAL_CYCLES + 1 : TOP_LATENCY;
  localparam integer CYCLES = (SERIAL != 0) ? SERIAL_CYCLES : FOLD;
  // Samples the top can hold at once: one per pipeline stage, or the serial core's one in work
  // and one result waiting.
  localparam integer CNT_W = $clog2(LATENCY + 2);

  // Clocks from the top's host address to its reg_rdata_o: both tops share this port timing.
  localparam integer HOST_RD_LAT = 2;

  // Parameter rules of the shell (rtl/acore_check.v: they stop Verilator, Icarus and Yosys); the
  // datapath's own rules are the top's (acore_config_check), applied when it is built below.
  acore_check #(.OK(SERIAL == 0 || SERIAL == 1), .VALUE(SERIAL),
    .MSG("illegal parameter: SERIAL must be 0 (acore_top) or 1 (acore_serial_top)"))
    SERIAL_must_be_0_or_1 ();
  acore_check #(.OK(SERIAL == 0 || CORRECTION == 0), .VALUE(CORRECTION),
    .MSG("illegal parameter: CORRECTION must be 0 with SERIAL=1 (the serial core is the 1-D polynomial)"))
    CORRECTION_must_be_0_with_SERIAL ();
  acore_check #(.OK(SERIAL == 0 || XCENTER == 0), .VALUE(XCENTER),
    .MSG("illegal parameter: XCENTER must be 0 with SERIAL=1 (the serial core is the 1-D polynomial)"))
    XCENTER_must_be_0_with_SERIAL ();
  acore_check #(.OK(SERIAL == 0 || FOURIER_K == 0), .VALUE(FOURIER_K),
    .MSG("illegal parameter: FOURIER_K must be 0 with SERIAL=1 (the serial core has no Fourier stage)"))
    FOURIER_K_must_be_0_with_SERIAL ();
  acore_check #(.OK(FOLD == 1), .VALUE(FOLD),
    .MSG("illegal parameter: FOLD must be 1 (acore_top has no fold factor in this build)"))
    FOLD_must_be_1 ();
  acore_check #(.OK(WORDS <= 256), .VALUE(WORDS),
    .MSG("illegal parameter: WORDS must be at most 256 (the shadow window)"))
    WORDS_must_fit_the_shadow_window ();
  acore_check #(.OK(APB_AW >= 11 && APB_AW <= 32), .VALUE(APB_AW),
    .MSG("illegal parameter: APB_AW must be 11..32 (registers at 0x000, the shadow window at 0x400)"))
    APB_AW_must_be_11_to_32 ();
  acore_check #(.OK(CRC_W == 1 || CRC_W == 2 || CRC_W == 4 || CRC_W == 8 || CRC_W == 16 || CRC_W == 32),
    .VALUE(CRC_W), .MSG("illegal parameter: CRC_W must be 1, 2, 4, 8, 16 or 32"))
    CRC_W_must_divide_32 ();
  acore_check #(.OK(RG_W == $clog2(REGIONS)), .VALUE(RG_W),
    .MSG("illegal parameter: RG_W is derived (clog2(REGIONS)), do not override"))
    RG_W_is_derived ();
  acore_check #(
    .OK(TERMS == ((CORRECTION == 2) ? 0 : (CORRECTION == 1) ?
                  ((DEGREE == 1) ? 3 : (DEGREE == 2) ? 6 : 10) : DEGREE + 1)),
    .VALUE(TERMS),
    .MSG("illegal parameter: TERMS is derived (coefficients per region and curve), do not override"))
    TERMS_is_derived ();
  acore_check #(.OK(ADDR_W == $clog2(WORDS)), .VALUE(ADDR_W),
    .MSG("illegal parameter: ADDR_W is derived (clog2(WORDS)), do not override"))
    ADDR_W_is_derived ();
  acore_check #(.OK(MAG_W == S_W + 2), .VALUE(MAG_W),
    .MSG("illegal parameter: MAG_W is derived (S_W+2), do not override"))
    MAG_W_is_derived ();

  // ---- identification and configuration (constants) ----
  localparam [31:0] ID = 32'h4143_0100;
  localparam [31:0] CONFIG0 = {3'd0, K[4:0], 4'd0, FOLD[3:0], 3'd0, SERIAL[0], ZERO[0], XCENTER[0],
                               CORRECTION[1:0], REGIONS[3:0], DEGREE[3:0]};
  localparam [31:0] CONFIG1 = {3'd0, REG_W[4:0], 3'd0, FOURIER_K[4:0], WORDS[15:0]};
  localparam [31:0] CONFIG2 = {CYCLES[15:0], LATENCY[15:0]};
  localparam [31:0] CONFIG3 = {CRC_W[7:0], MAG_W[7:0], ANGLE_W[7:0], IN_W[7:0]};

  // Register word addresses (byte address / 4).
  localparam [5:0] R_ID = 6'h00, R_CONFIG0 = 6'h01, R_CONFIG1 = 6'h02, R_CONFIG2 = 6'h03,
                   R_CONFIG3 = 6'h04, R_CTRL = 6'h08, R_STATUS = 6'h09, R_IRQ = 6'h0A,
                   R_MAG_LO = 6'h0C, R_MAG_HI = 6'h0D, R_CRC_EXP = 6'h10, R_CRC_SHADOW = 6'h11,
                   R_CRC_REF = 6'h12, R_CRC_SCRUB = 6'h13, R_SCRUB_PASSES = 6'h14;

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
        .IN_W(IN_W), .REG_W(REG_W), .S_W(S_W), .S_F(S_F), .R_SHIFT(R_SHIFT), .SCALE_G(SCALE_G),
        .DEGREE(DEGREE), .REGIONS(REGIONS), .COEF_F(COEF_F), .ACC_G(ACC_G), .ACC_I(ACC_I), .K(K),
        .CORDIC_G(CORDIC_G), .Z_W(Z_W), .ANGLE_W(ANGLE_W), .ZERO(ZERO), .INIT_FILE(INIT_FILE),
        .WORDS(WORDS)
      ) u_top (
        .clk_i(clk_i), .rst_i(rst_i), .reg_addr_i(top_addr), .reg_wdata_i(top_wdata), .reg_we_i(top_we),
        .reg_rdata_o(top_rdata), .mag_lo_i(mag_lo_q), .mag_hi_i(mag_hi_q),
        .in_valid_i(top_in_valid), .in_ready_o(top_in_ready), .c1_i(c1_i), .c2_i(c2_i), .c3_i(c3_i),
        .c4_i(c4_i), .out_valid_o(top_out_valid), .out_ready_i(out_ready_i), .angle_o(top_angle),
        .region_o(top_region), .ovf_o(top_ovf), .los_o(top_los), .dos_o(top_dos));
    end else begin : g_pipe
      acore_top #(
        .IN_W(IN_W), .REG_W(REG_W), .S_W(S_W), .S_F(S_F), .R_SHIFT(R_SHIFT), .SCALE_G(SCALE_G),
        .CORRECTION(CORRECTION), .DEGREE(DEGREE), .REGIONS(REGIONS), .XCENTER(XCENTER), .COEF_F(COEF_F),
        .ACC_G(ACC_G), .ACC_I(ACC_I), .K(K), .CORDIC_G(CORDIC_G), .Z_W(Z_W), .ANGLE_W(ANGLE_W),
        .FOURIER_K(FOURIER_K), .FOURIER_M(FOURIER_M), .FOURIER_CF(FOURIER_CF), .FOURIER_W(FOURIER_W),
        .FOURIER_G(FOURIER_G), .ZERO(ZERO), .INIT_FILE(INIT_FILE), .WORDS(WORDS)
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
  wire [7:0] widx = paddr_i[9:2];
  wire in_regs = (paddr_i[APB_AW-1:8] == {(APB_AW-8){1'b0}});
  wire in_win = (paddr_i[APB_AW-1:10] == {{(APB_AW-11){1'b0}}, 1'b1}) && ({1'b0, widx} < WORDS[8:0]);
  wire is_ro = (ridx == R_ID) | (ridx == R_CONFIG0) | (ridx == R_CONFIG1) | (ridx == R_CONFIG2) |
               (ridx == R_CONFIG3) | (ridx == R_IRQ) | (ridx == R_CRC_SHADOW) | (ridx == R_CRC_REF) |
               (ridx == R_CRC_SCRUB) | (ridx == R_SCRUB_PASSES);
  wire is_rw = (ridx == R_CTRL) | (ridx == R_STATUS) | (ridx == R_MAG_LO) | (ridx == R_MAG_HI) |
               (ridx == R_CRC_EXP);
  wire reg_ok = in_regs & (is_rw | (is_ro & ~pwrite_i));
  wire busy_err = busy & (in_win | (in_regs & pwrite_i & ((ridx == R_CRC_EXP) | ((ridx == R_CTRL) & pwdata_i[0]))));
  wire err_d = (paddr_i[1:0] != 2'b00) | (pwrite_i & (pstrb_i != 4'hF)) | ~(reg_ok | in_win) | busy_err;

  // Control and status registers.
  reg check_q, scrub_q;
  reg [5:0] irq_en_q, sticky_q;
  reg [31:0] crc_exp_q;
  wire [31:0] crc_shadow, crc_ref, crc_scrub;
  wire [15:0] scrub_passes;
  wire ref_valid, done, refused, scrub_err;
  wire [5:0] irq_pend = sticky_q & irq_en_q;
  assign irq_o = |irq_pend;

  reg [31:0] rd_d;
  always @(*) begin
    rd_d = 32'd0;
    case (ridx)
      R_ID: rd_d = ID;
      R_CONFIG0: rd_d = CONFIG0;
      R_CONFIG1: rd_d = CONFIG1;
      R_CONFIG2: rd_d = CONFIG2;
      R_CONFIG3: rd_d = CONFIG3;
      R_CTRL: rd_d = {18'd0, irq_en_q, 4'd0, scrub_q, check_q, 2'b00};
      R_STATUS: rd_d = {13'd0, ref_valid, bank, busy, 10'd0, sticky_q};
      R_IRQ: rd_d = {26'd0, irq_pend};
      R_MAG_LO: rd_d[MAG_W-1:0] = mag_lo_q;
      R_MAG_HI: rd_d[MAG_W-1:0] = mag_hi_q;
      R_CRC_EXP: rd_d = crc_exp_q;
      R_CRC_SHADOW: rd_d = crc_shadow;
      R_CRC_REF: rd_d = crc_ref;
      R_CRC_SCRUB: rd_d = crc_scrub;
      R_SCRUB_PASSES: rd_d = {16'd0, scrub_passes};
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
  reg [31:0] rdata_q;
  always @(posedge clk_i) begin
    if (setup) begin
      err_q <= err_d;
      win_q <= in_win;
      rdata_q <= rd_d;
      w_ctrl_q <= ok_reg_wr & (ridx == R_CTRL) & ~(busy & pwdata_i[0]);
      w_status_q <= ok_reg_wr & (ridx == R_STATUS);
      w_mag_lo_q <= ok_reg_wr & (ridx == R_MAG_LO);
      w_mag_hi_q <= ok_reg_wr & (ridx == R_MAG_HI);
      w_crc_q <= ok_reg_wr & (ridx == R_CRC_EXP) & ~busy;
      w_win_q <= ok_wr & in_win & ~busy;
    end
  end
  wire [REG_W-1:0] sh_rdata;
  wire rd_access = access & ~pwrite_i & ~err_q;
  assign prdata_o = ~rd_access ? 32'd0 : win_q ? {{(32-REG_W){1'b0}}, sh_rdata} : rdata_q;
  assign pready_o = 1'b1;
  assign pslverr_o = access & err_q;

  // Access phase: the write.
  wire wr_ctrl = access & w_ctrl_q;
  wire commit = wr_ctrl & pwdata_i[0];
  wire clear = wr_ctrl & pwdata_i[1];
  wire [5:0] w1c = (access && w_status_q) ? pwdata_i[5:0] : 6'd0;
  localparam [MAG_W-1:0] MAG_LO_R = MAG_LO_RESET[MAG_W-1:0];
  localparam [MAG_W-1:0] MAG_HI_R = MAG_HI_RESET[MAG_W-1:0];
  // Events of this clock (set wins over a clear in the same clock: no event is lost).
  wire [5:0] events = {done, scrub_err, refused, emit & top_dos, emit & top_los, emit & top_ovf};
  always @(posedge clk_i) begin
    if (rst_i) begin
      check_q <= 1'b0;
      scrub_q <= 1'b1;
      irq_en_q <= 6'd0;
      sticky_q <= 6'd0;
      mag_lo_q <= MAG_LO_R;
      mag_hi_q <= MAG_HI_R;
      crc_exp_q <= 32'd0;
    end else begin
      if (wr_ctrl) begin
        check_q <= pwdata_i[2];
        scrub_q <= pwdata_i[3];
        irq_en_q <= pwdata_i[13:8];
      end
      if (access && w_mag_lo_q) mag_lo_q <= pwdata_i[MAG_W-1:0];
      if (access && w_mag_hi_q) mag_hi_q <= pwdata_i[MAG_W-1:0];
      if (access && w_crc_q) crc_exp_q <= pwdata_i;
      sticky_q <= (sticky_q & ~(w1c | {6{clear}})) | events;
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
