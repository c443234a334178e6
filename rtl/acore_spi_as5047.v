// SPDX-License-Identifier: MIT
// acore_spi_as5047: an SPI slave that answers the AS5047P's frame, so a drive's existing AS5047P
// driver (SimpleFOC's MagneticSensorSPI, ODrive's SPI_ABS_AMS mode, ...) reads AngleCore's angle
// unchanged.
//
// The frame (AS5047P datasheet, SPI interface): mode 1 (CPOL = 0, CPHA = 1: the master changes
// MOSI on SCLK's rising edge and samples MISO on its falling edge), 16 bits MSB first, CSn low for
// the frame. A command is {PAR, R/W, ADDR[13:0]}: PAR makes the 16 bits' parity even, R/W = 1 reads.
// The answer to a read comes in the next frame, as {PAR, EF, DATA[13:0]} with even parity. A write
// is two frames (the datasheet's sequence): the command {PAR, 0, ADDR}, then the data frame
// {PAR, x, DATA}; the data frame answers the register's old content, the frame after it the new.
// The registers (their addresses, field positions, the resets of the fields the port keeps,
// ABIRES's tables and the HYS and UVWPP encodings: rtl/acore_as5047_map.txt, generated into
// rtl/acore_as5047.vh); what each does here:
//   NOP       0
//   ERRFL     PARERR, INVCOMM, FRERR; cleared by its own read
//   PROG      PROGEN, PROGVER kept and read back; OTPREF and PROGOTP read 0: there is no OTP, the
//             settings below are the datasheet's volatile path (effective at once, lost at reset),
//             and a programming "finishes" at once (PROG reads PROGEN alone, as the datasheet's
//             poll expects)
//   ZPOSM     ZPOS's upper bits   } the board's IF_ZERO.ZERO (cfg_zero)
//   ZPOSL     ZPOS's lower bits   }
//             comp_l/h_error_en (ERR_EN) kept and read back (no effect)
//   SETTINGS1 its factory bits read as the description's FIXED value (not written);
//             DIR                 the board's IF_CTRL.DIR (cfg_dir)
//             DAECDIS             the board's IF_CTRL.DAEC, inverted (cfg_daec)
//             ABIBIN              ABIRES's table: 1 binary, 0 decimal (reset 1, so that ABZ_N's
//                                 reset 1024 reads ABIRES 0)
//             Dataselect          1: ANGLECOM reads ANGLEUNC's angle
//             UVW_ABI, PWMon      kept and read back (both outputs are always on)
//   SETTINGS2 UVWPP               the board's UVW_PP = UVWPP + UVWPP_OFFSET, at most UVWPP_MAX_PP;
//                                 read: pole pairs - UVWPP_OFFSET, the last code's from
//                                 UVWPP_MAX_PP pole pairs up
//             HYS                 the board's ABZ_HYS = (HYS_MAX - HYS) LSBs of 2^-HYS_LSB_LOG2 turn
//                                 (HYS_SHIFT = ANGLE_W - HYS_LSB_LOG2 angle LSBs each);
//                                 read: HYS_MAX - ceil(ABZ_HYS / 2^HYS_SHIFT), at least 0
//             ABIRES              the board's ABZ_N from the table ABIBIN picks (ABIRES_DEC,
//                                 ABIRES_BIN; codes past a table's last take its last entry);
//                                 read: the first entry of the table not above N
//                                 (a change of ABIBIN alone rewrites N with it)
//   DIAAGC    MAGL (los_i), MAGH (dos_i), COF (ovf_i), LF (~lot_i: the angle is settled), AGC (agc_i)
//   MAG       mag_i
//   ANGLEUNC  the uncompensated angle's upper 14 bits
//   ANGLECOM  the compensated angle's upper 14 bits (ANGLEUNC's with Dataselect)
// A mapped setting is the board's register (one home: the APB reads and writes the same flop);
// the port reads it on cfg_*_i and writes it through cfg_*_we_o / cfg_*_o in the clock CSn rises
// after the data frame.
// Errors: a frame whose parity is odd sets PARERR and is ignored (a data frame's too: nothing is
// written); a frame that is not 16 clocks long, or follows a CSn gap shorter than 2 clocks
// (below), sets FRERR and is ignored; a read of another address, or a write to a register that is
// not writable (its data frame is consumed), sets INVCOMM. NOP, address 0, is no command whether
// R/W is set or not (0x0000 is the frame drivers send to collect an answer). EF, bit 14 of every
// answer, is high while ERRFL holds an error, so the answer after a refused frame carries it (its
// data is then NOP's 0), until ERRFL is read. A frame longer than 16 bits (a daisy chain's) is a
// framing error whose MISO, after the answer's 16 bits, passes on what came in on MOSI.
//
// One clock domain: SCLK, CSn and MOSI are oversampled through SYNC flops each. MOSI is taken at
// the synchronized falling edge, the same stage as SCLK's, so it is the value the master held
// across that edge. The next MISO bit is presented SYNC + 1 clocks after each falling edge (so the
// master's hold is met) and is stable until SYNC + 1 clocks after the next one: the master samples
// it right when the SCLK period is at least SYNC + 2 clocks (one clock of set-up). That is the
// port's timing rule, and SCLK_MIN, the shortest SCLK period (in clocks) the port is built for,
// must meet it: SCLK_MIN >= SYNC + 2, refused at elaboration otherwise (SYNC = 2 takes SCLK up to
// clk/4, SYNC = 3 clk/5, SYNC = 4 clk/6). The answer word follows its register while CSn is high
// and freezes when CSn falls (the angle is the one at the start of the frame that carries it);
// its parity bit, the first on MISO, is the parity of the frozen word from the clock after, SYNC + 1
// clocks after CSn falls, like every later bit after its falling edge.
// CSn timing, in clocks of clk_i: the first falling SCLK edge at least SYNC + 2 clocks after CSn
// falls (the AS5047P's own t_L, 350 ns, is longer above 12 MHz); CSn high at least 2 clocks
// between frames (the answer is loaded in the second). A frame after a shorter gap is a framing
// error, detected: its answer is {PAR, EF, 0} (0xC000), its command is ignored, FRERR is set.
`resetall
`default_nettype none

module acore_spi_as5047 #(
  // Bits of the angle inputs (at least the 14 the frame carries: their upper 14 bits are sent).
  parameter integer ANGLE_W = 16,
  // Synchronizer flops on SCLK, CSn and MOSI.
  parameter integer SYNC = 2,
  // The shortest SCLK period the port is built for, in clocks of clk_i: at least SYNC + 2.
  parameter integer SCLK_MIN = 4,
  // Bits of the mapped settings: ABZ N (at least 12: N up to 1024), UVW pole pairs (at least 4: up
  // to 7), the ABZ hysteresis (at least ANGLE_W - 9: up to 3 2^(ANGLE_W-11)).
  parameter integer N_W = 13,
  parameter integer PP_W = 5,
  parameter integer HYS_W = 8
) (
  input  wire               clk_i,
  input  wire               rst_i,
  // The SPI pins (asynchronous to clk_i). MISO is driven while miso_oe_o (CSn low).
  input  wire               sclk_i,
  input  wire               csn_i,
  input  wire               mosi_i,
  output wire               miso_o,
  output wire               miso_oe_o,
  // What the registers read.
  input  wire [ANGLE_W-1:0] angle_unc_i,
  input  wire [ANGLE_W-1:0] angle_com_i,
  input  wire [13:0]        mag_i,
  input  wire [7:0]         agc_i,
  input  wire               los_i,
  input  wire               dos_i,
  input  wire               ovf_i,
  input  wire               lot_i,
  // The mapped settings (the board's registers): their values, and a write (one clock).
  input  wire [13:0]        cfg_zero_i,
  input  wire               cfg_dir_i,
  input  wire               cfg_daec_i,
  input  wire [N_W-1:0]     cfg_n_i,
  input  wire [PP_W-1:0]    cfg_pp_i,
  input  wire [HYS_W-1:0]   cfg_hys_i,
  output wire               cfg_zero_we_o,
  output wire [13:0]        cfg_zero_o,
  output wire               cfg_dir_we_o,
  output wire               cfg_dir_o,
  output wire               cfg_daec_we_o,
  output wire               cfg_daec_o,
  output wire               cfg_n_we_o,
  output wire [N_W-1:0]     cfg_n_o,
  output wire               cfg_pp_we_o,
  output wire [PP_W-1:0]    cfg_pp_o,
  output wire               cfg_hys_we_o,
  output wire [HYS_W-1:0]   cfg_hys_o,
  // A pulse at the end of each frame, and ERRFL (for status and tests).
  output reg                frame_o,
  output wire [2:0]         errfl_o
);

  // The AS5047P's addresses, select codes (AS5047_S_*: the register an answer or a write is
  // for), field positions, ABIRES's tables and the HYS and UVWPP encodings: generated from their
  // one description rtl/acore_as5047_map.txt.
`include "acore_as5047.vh"

  acore_check #(.OK(ANGLE_W >= 14 && ANGLE_W <= 32), .VALUE(ANGLE_W),
    .MSG("illegal parameter: ANGLE_W must be 14..32 (the frame carries 14 bits)")) ANGLE_W_must_be_14_to_32 ();
  acore_check #(.OK(SYNC >= 2 && SYNC <= 4), .VALUE(SYNC),
    .MSG("illegal parameter: SYNC must be 2..4")) SYNC_must_be_2_to_4 ();
  acore_check #(.OK(SCLK_MIN >= SYNC + 2), .VALUE(SCLK_MIN),
    .MSG("illegal parameter: SCLK_MIN must be >= SYNC + 2 (MISO moves SYNC + 1 clocks after SCLK falls)"))
    SCLK_MIN_must_be_at_least_SYNC_plus_2 ();
  acore_check #(.OK(N_W >= 12 && N_W <= 16), .VALUE(N_W),
    .MSG("illegal parameter: N_W must be 12..16 (ABIRES's N up to 1024)")) N_W_must_be_12_to_16 ();
  acore_check #(.OK(PP_W >= 4 && PP_W <= 8), .VALUE(PP_W),
    .MSG("illegal parameter: PP_W must be 4..8 (UVWPP's 7 pole pairs)")) PP_W_must_be_4_to_8 ();
  acore_check #(.OK(HYS_W >= HYS_SHIFT + AS5047_SETTINGS2_HYS_W && HYS_W <= 24), .VALUE(HYS_W),
    .MSG("illegal parameter: HYS_W must be ANGLE_W-9..24 (HYS's 3 LSBs of 2^-11 turn)"))
    HYS_W_must_be_ANGLE_W_minus_9_to_24 ();

  // HYS's LSB, 2^-AS5047_HYS_LSB_LOG2 turn, in angle LSBs.
  localparam integer HYS_SHIFT = ANGLE_W - AS5047_HYS_LSB_LOG2;
  // ZPOS's bits in ZPOSL (the rest in ZPOSM).
  localparam integer ZPOS_LO_W = AS5047_ZPOSL_ZPOS_LO_W;
  // ERRFL's bits in errfl_q (the register's bits 2:0).
  localparam [2:0] E_FRERR = 3'd1 << AS5047_ERRFL_FRERR_LSB, E_INVCOMM = 3'd1 << AS5047_ERRFL_INVCOMM_LSB,
                   E_PARERR = 3'd1 << AS5047_ERRFL_PARERR_LSB;

  // ---- synchronizers (idle: SCLK low, CSn high) and edges ----
  // (CSn one stage longer: a falling edge sees whether CSn was high for two clocks before it.)
  reg [SYNC:0] sclk_s;
  reg [SYNC+1:0] csn_s;
  reg [SYNC-1:0] mosi_s;
  always @(posedge clk_i) begin
    if (rst_i) begin
      sclk_s <= {(SYNC+1){1'b0}};
      csn_s <= {(SYNC+2){1'b1}};
      mosi_s <= {SYNC{1'b0}};
    end else begin
      sclk_s <= {sclk_s[SYNC-1:0], sclk_i};
      csn_s <= {csn_s[SYNC:0], csn_i};
      mosi_s <= {mosi_s[SYNC-2:0], mosi_i};
    end
  end
  wire sel = ~csn_s[SYNC-1];
  wire fall = sel & sclk_s[SYNC] & ~sclk_s[SYNC-1];
  wire mosi = mosi_s[SYNC-1];
  wire cs_fall = csn_s[SYNC] & ~csn_s[SYNC-1];
  wire cs_rise = ~csn_s[SYNC] & csn_s[SYNC-1];
  // CSn was high for one clock only: the answer of the frame before was not loaded.
  wire cs_short = cs_fall & ~csn_s[SYNC+1];

  // ---- the settings only the port keeps (no AngleCore equivalent) ----
  reg progen_q, progver_q, abibin_q, dsel_q, uvwabi_q, pwmon_q;
  reg [AS5047_ZPOSL_ERR_EN_W-1:0] erren_q;   // ZPOSL's comp_l_error_en, comp_h_error_en

  // ABIRES's tables: N of a code, and the code read for an N (the first entry not above N).
  function integer abi_n_int(input bin, input [2:0] code);
    abi_n_int = bin ? as5047_abires_bin(code) : as5047_abires_dec(code);
  endfunction
  function [N_W-1:0] abi_n(input bin, input [2:0] code);
    /* verilator lint_off UNUSEDSIGNAL */
    reg [31:0] v;  // at most 1024: the bits above N_W are 0
    /* verilator lint_on UNUSEDSIGNAL */
    begin
      v = abi_n_int(bin, code);
      abi_n = v[N_W-1:0];
    end
  endfunction
  localparam [2:0] ABI_BIN_LAST = AS5047_ABIRES_BIN_LAST[2:0],
                   ABI_DEC_LAST = AS5047_ABIRES_DEC_LAST[2:0];
  // n >= k for a constant k (n's low w bits), as gates from the MSB down (k's 1 bits need n's, a
  // 0 bit of k under a 1 of n decides): a few LUTs, where a comparator would take a carry chain as
  // wide as n.
  function ge_w(input [31:0] n, input integer w, input integer k);
    integer b;
    reg r;
    begin
      r = 1'b1;  // the bits below: equal so far
      for (b = 0; b < w; b = b + 1)
        r = ((k >> b) & 1) != 0 ? (n[b] & r) : (n[b] | r);
      ge_w = r;
    end
  endfunction
  function ge_const(input [N_W-1:0] n, input integer k);
    ge_const = ge_w({{(32-N_W){1'b0}}, n}, N_W, k);
  endfunction
  // The code read for an N in one table: the first code (largest N first) whose N is not above n;
  // the last otherwise. Each table's comparisons are with constants; ABIBIN picks the table.
  function [2:0] abi_code_tab(input bin, input [N_W-1:0] n);
    integer c;
    begin
      abi_code_tab = bin ? ABI_BIN_LAST : ABI_DEC_LAST;
      for (c = 7; c >= 0; c = c - 1)
        if (c <= (bin ? AS5047_ABIRES_BIN_LAST : AS5047_ABIRES_DEC_LAST) &&
            ge_const(n, abi_n_int(bin, c[2:0]))) abi_code_tab = c[2:0];
    end
  endfunction
  function [2:0] abi_code(input bin, input [N_W-1:0] n);
    abi_code = bin ? abi_code_tab(1'b1, n) : abi_code_tab(1'b0, n);
  endfunction
  // The settings' encodings as look-ups of their few codes, compared with constants (a LUT or
  // two a bit, where an adder and a comparator would each take a carry chain).
  localparam integer HYS_CODE_W = AS5047_SETTINGS2_HYS_W, PP_CODE_W = AS5047_SETTINGS2_UVWPP_W,
                     HYS_HI_W = HYS_W - HYS_SHIFT;
  // HYS read back: AS5047_HYS_MAX - ceil(width / 2^HYS_SHIFT), at least 0. The ceiling is the
  // width's bits from HYS_SHIFT up (hi), plus 1 when a bit below is set (lo).
  /* verilator lint_off UNUSEDSIGNAL */
  function [HYS_CODE_W-1:0] hys_read(input [HYS_HI_W-1:0] hi, input lo);
    integer k, h;
    reg [31:0] v;  // below AS5047_HYS_MAX: fits HYS's bits
    begin
      h = {{(32-HYS_HI_W){1'b0}}, hi};
      v = 0;
      for (k = 0; k < AS5047_HYS_MAX; k = k + 1)
        if ((h == k && !lo) || (h + 1 == k && lo)) v = AS5047_HYS_MAX - k;
      hys_read = v[HYS_CODE_W-1:0];
    end
  endfunction
  /* verilator lint_on UNUSEDSIGNAL */
  wire [HYS_CODE_W-1:0] hys_code = hys_read(cfg_hys_i[HYS_W-1:HYS_SHIFT], |cfg_hys_i[HYS_SHIFT-1:0]);
  // UVWPP read back: pole pairs - AS5047_UVWPP_OFFSET, within 0 .. its code of AS5047_UVWPP_MAX_PP.
  /* verilator lint_off UNUSEDSIGNAL */
  function [PP_CODE_W-1:0] pp_read(input [PP_W-1:0] pp);
    integer p, n;
    reg [31:0] v;  // at most the code of AS5047_UVWPP_MAX_PP: fits UVWPP's bits
    begin
      n = {{(32-PP_W){1'b0}}, pp};
      v = 0;  // below AS5047_UVWPP_OFFSET
      for (p = AS5047_UVWPP_OFFSET; p < AS5047_UVWPP_MAX_PP; p = p + 1)
        if (n == p) v = p - AS5047_UVWPP_OFFSET;
      if (ge_w(n, PP_W, AS5047_UVWPP_MAX_PP)) v = AS5047_UVWPP_MAX_PP - AS5047_UVWPP_OFFSET;
      pp_read = v[PP_CODE_W-1:0];
    end
  endfunction
  /* verilator lint_on UNUSEDSIGNAL */
  wire [PP_CODE_W-1:0] uvwpp_code = pp_read(cfg_pp_i);
  // Written: pole pairs UVWPP + AS5047_UVWPP_OFFSET, at most AS5047_UVWPP_MAX_PP; the hysteresis
  // (AS5047_HYS_MAX - HYS) << HYS_SHIFT.
  /* verilator lint_off UNUSEDSIGNAL */
  function [PP_W-1:0] pp_write(input [PP_CODE_W-1:0] code);
    integer c, k;
    reg [31:0] v;  // at most AS5047_UVWPP_MAX_PP: fits PP_W
    begin
      k = {{(32-PP_CODE_W){1'b0}}, code};
      v = 0;
      for (c = 0; c < (1 << PP_CODE_W); c = c + 1)
        if (k == c)
          v = (c + AS5047_UVWPP_OFFSET >= AS5047_UVWPP_MAX_PP) ? AS5047_UVWPP_MAX_PP : c + AS5047_UVWPP_OFFSET;
      pp_write = v[PP_W-1:0];
    end
  endfunction
  function [HYS_W-1:0] hys_write(input [HYS_CODE_W-1:0] code);
    integer c, k;
    reg [31:0] v;  // at most AS5047_HYS_MAX << HYS_SHIFT: fits HYS_W
    begin
      k = {{(32-HYS_CODE_W){1'b0}}, code};
      v = 0;
      for (c = 0; c < AS5047_HYS_MAX; c = c + 1)
        if (k == c) v = (AS5047_HYS_MAX - c) << HYS_SHIFT;
      hys_write = v[HYS_W-1:0];
    end
  endfunction
  /* verilator lint_on UNUSEDSIGNAL */
  wire [AS5047_SETTINGS2_ABIRES_W-1:0] abires_code = abi_code(abibin_q, cfg_n_i);

  // ---- the answer of the next frame ----
  reg [2:0] errfl_q;   // ERRFL's bits (E_*)
  reg [AS5047_S_W-1:0] ans_q;  // which register (AS5047_S_*)
  reg [13:0] data;
  always @(*) begin
    case (ans_q)
      AS5047_S_ERRFL: data = {11'd0, errfl_q};
      AS5047_S_PROG: begin
        data = AS5047_PROG_FIXED;
        data[AS5047_PROG_PROGEN_LSB] = progen_q;
        data[AS5047_PROG_PROGVER_LSB] = progver_q;
      end
      AS5047_S_ZPOSM: begin
        data = AS5047_ZPOSM_FIXED;
        data[AS5047_ZPOSM_ZPOS_HI_MSB:AS5047_ZPOSM_ZPOS_HI_LSB] = cfg_zero_i[13:ZPOS_LO_W];
      end
      AS5047_S_ZPOSL: begin
        data = AS5047_ZPOSL_FIXED;
        data[AS5047_ZPOSL_ERR_EN_MSB:AS5047_ZPOSL_ERR_EN_LSB] = erren_q;
        data[AS5047_ZPOSL_ZPOS_LO_MSB:AS5047_ZPOSL_ZPOS_LO_LSB] = cfg_zero_i[ZPOS_LO_W-1:0];
      end
      AS5047_S_SETTINGS1: begin
        data = AS5047_SETTINGS1_FIXED;
        data[AS5047_SETTINGS1_PWMON_LSB] = pwmon_q;
        data[AS5047_SETTINGS1_DATASELECT_LSB] = dsel_q;
        data[AS5047_SETTINGS1_ABIBIN_LSB] = abibin_q;
        data[AS5047_SETTINGS1_DAECDIS_LSB] = ~cfg_daec_i;
        data[AS5047_SETTINGS1_UVW_ABI_LSB] = uvwabi_q;
        data[AS5047_SETTINGS1_DIR_LSB] = cfg_dir_i;
      end
      AS5047_S_SETTINGS2: begin
        data = AS5047_SETTINGS2_FIXED;
        data[AS5047_SETTINGS2_ABIRES_MSB:AS5047_SETTINGS2_ABIRES_LSB] = abires_code;
        data[AS5047_SETTINGS2_HYS_MSB:AS5047_SETTINGS2_HYS_LSB] = hys_code;
        data[AS5047_SETTINGS2_UVWPP_MSB:AS5047_SETTINGS2_UVWPP_LSB] = uvwpp_code;
      end
      AS5047_S_DIAAGC: begin
        data = AS5047_DIAAGC_FIXED;
        data[AS5047_DIAAGC_MAGL_LSB] = los_i;
        data[AS5047_DIAAGC_MAGH_LSB] = dos_i;
        data[AS5047_DIAAGC_COF_LSB] = ovf_i;
        data[AS5047_DIAAGC_LF_LSB] = ~lot_i;
        data[AS5047_DIAAGC_AGC_MSB:AS5047_DIAAGC_AGC_LSB] = agc_i;
      end
      AS5047_S_MAG: data = mag_i;
      AS5047_S_ANGLEUNC: data = angle_unc_i[ANGLE_W-1 -: 14];
      AS5047_S_ANGLECOM: data = angle_com_i[ANGLE_W-1 -: 14];
      default: data = 14'd0;
    endcase
  end
  wire ef = |errfl_q;

  // ---- the frame ----
  // One shift register both ways (a frame shifts its command in at the bottom while the answer
  // leaves at the top, on the same falling edges): it holds the command received when CSn rises,
  // is decoded in that clock and is loaded with the next answer in the same clock. After a
  // frame's 16th bit MISO passes on what came in on MOSI, as a daisy chain does. One parity of
  // its bits below the top serves both ways: the received frame's check, and the answer's parity
  // bit, taken while CSn is high (a clock behind the word it follows) and once more in the clock
  // CSn falls, on the frozen word.
  reg [15:0] sr_q;
  reg [4:0] bits_q;    // saturates at 17: too long
  reg wr_data_q;       // the next frame is a write's data frame
  reg [AS5047_S_W-1:0] wr_reg_q;  // the register it writes (AS5047_S_NOP: none, the data frame is consumed)
  reg short_q;         // this frame followed a CSn gap of one clock: a framing error
  wire par_lo = ^sr_q[14:0];
  wire parity_ok = ~(sr_q[15] ^ par_lo);
  wire read = sr_q[14];
  wire [13:0] addr = sr_q[13:0];
  wire [AS5047_S_W-1:0] sel_reg = as5047_sel(addr);
  // NOP (address 0) is no command either way: the frame drivers send to collect an answer is 0x0000.
  wire nop = (addr == AS5047_A_NOP);
  wire known = nop | (sel_reg != AS5047_S_NOP);
  wire writable = as5047_writable(sel_reg);
  // The register a read answers: ANGLECOM with Dataselect set answers ANGLEUNC's angle, chosen
  // here rather than in the answer (Dataselect changes only with a write's data frame, whose next
  // answer is SETTINGS1).
  wire [AS5047_S_W-1:0] sel_ans = (sel_reg == AS5047_S_ANGLECOM && dsel_q) ? AS5047_S_ANGLEUNC : sel_reg;
  wire write = ~read & ~nop;
  // Errors found at the end of this frame, as ERRFL bits.
  wire [2:0] err_new = (bits_q != 5'd16 || short_q) ? E_FRERR : ~parity_ok ? E_PARERR :
                       wr_data_q ? 3'b000 : (~known | (write & ~writable)) ? E_INVCOMM : 3'b000;
  wire frame_ok = cs_rise & (bits_q == 5'd16) & ~short_q & parity_ok;
  wire cmd_ok = frame_ok & ~wr_data_q;
  // The data frame of a write: the register written in the clock CSn rises.
  wire wr_do = frame_ok & wr_data_q;
  wire [AS5047_DATA_W-1:0] wd = sr_q[AS5047_DATA_W-1:0];  // the settings' data bits
  wire wr_set1 = (wr_reg_q == AS5047_S_SETTINGS1);
  wire wr_set2 = (wr_reg_q == AS5047_S_SETTINGS2);
  wire wd_abibin = wd[AS5047_SETTINGS1_ABIBIN_LSB];
  wire [AS5047_SETTINGS2_UVWPP_W-1:0] wd_uvwpp = wd[AS5047_SETTINGS2_UVWPP_MSB:AS5047_SETTINGS2_UVWPP_LSB];
  wire [AS5047_SETTINGS2_HYS_W-1:0] wd_hys = wd[AS5047_SETTINGS2_HYS_MSB:AS5047_SETTINGS2_HYS_LSB];
  assign cfg_zero_we_o = wr_do & ((wr_reg_q == AS5047_S_ZPOSM) | (wr_reg_q == AS5047_S_ZPOSL));
  assign cfg_zero_o = (wr_reg_q == AS5047_S_ZPOSM) ?
                      {wd[AS5047_ZPOSM_ZPOS_HI_MSB:AS5047_ZPOSM_ZPOS_HI_LSB], cfg_zero_i[ZPOS_LO_W-1:0]} :
                      {cfg_zero_i[13:ZPOS_LO_W], wd[AS5047_ZPOSL_ZPOS_LO_MSB:AS5047_ZPOSL_ZPOS_LO_LSB]};
  assign cfg_dir_we_o = wr_do & wr_set1;
  assign cfg_dir_o = wd[AS5047_SETTINGS1_DIR_LSB];
  assign cfg_daec_we_o = wr_do & wr_set1;
  assign cfg_daec_o = ~wd[AS5047_SETTINGS1_DAECDIS_LSB];
  // N: from ABIRES (SETTINGS2), or re-read through the other table when SETTINGS1 changes ABIBIN;
  // one table look-up of the table and code each write picks (a few gates of four inputs a bit).
  assign cfg_n_we_o = wr_do & (wr_set2 | (wr_set1 & (wd_abibin != abibin_q)));
  wire n_bin = wr_set2 ? abibin_q : wd_abibin;
  wire [2:0] n_code = wr_set2 ? wd[AS5047_SETTINGS2_ABIRES_MSB:AS5047_SETTINGS2_ABIRES_LSB] : abires_code;
  assign cfg_n_o = abi_n(n_bin, n_code);
  assign cfg_pp_we_o = wr_do & wr_set2;
  assign cfg_pp_o = pp_write(wd_uvwpp);
  assign cfg_hys_we_o = wr_do & wr_set2;
  assign cfg_hys_o = hys_write(wd_hys);
  // ERRFL's own answer clears it when the frame carrying it starts (not after a short gap: the
  // frame then carries 0xC000 instead).
  wire clear_errfl = cs_fall & (ans_q == AS5047_S_ERRFL) & ~cs_short;
  // (A short gap's answer, EF with even parity and data 0, is the register's synchronous reset
  // value, so its load takes no logic of each bit.)
  always @(posedge clk_i) begin
    if (rst_i || cs_short) sr_q <= 16'hC000;
    else if (!sel) sr_q <= {par_lo, ef, data};
    else if (fall) sr_q <= {sr_q[14:0], mosi};
    else if (cs_fall) sr_q[15] <= par_lo;
  end
  always @(posedge clk_i) begin
    if (rst_i) begin
      errfl_q <= 3'd0;
      ans_q <= AS5047_S_NOP;
      bits_q <= 5'd0;
      wr_data_q <= 1'b0;
      wr_reg_q <= AS5047_S_NOP;
      short_q <= 1'b0;
      frame_o <= 1'b0;
      progen_q <= AS5047_PROG_PROGEN_RESET;
      progver_q <= AS5047_PROG_PROGVER_RESET;
      abibin_q <= AS5047_SETTINGS1_ABIBIN_RESET;
      dsel_q <= AS5047_SETTINGS1_DATASELECT_RESET;
      uvwabi_q <= AS5047_SETTINGS1_UVW_ABI_RESET;
      pwmon_q <= AS5047_SETTINGS1_PWMON_RESET;
      erren_q <= AS5047_ZPOSL_ERR_EN_RESET;
    end else begin
      frame_o <= cs_rise;
      if (cs_fall) short_q <= cs_short;
      if (cs_fall) bits_q <= 5'd0;
      else if (fall && bits_q != 5'd17) bits_q <= bits_q + 5'd1;
      errfl_q <= (clear_errfl ? 3'd0 : errfl_q) | (cs_rise ? err_new : 3'd0);
      if (wr_do) begin
        case (wr_reg_q)
          AS5047_S_PROG: begin
            progen_q <= wd[AS5047_PROG_PROGEN_LSB];
            progver_q <= wd[AS5047_PROG_PROGVER_LSB];
          end
          AS5047_S_ZPOSL: erren_q <= wd[AS5047_ZPOSL_ERR_EN_MSB:AS5047_ZPOSL_ERR_EN_LSB];
          AS5047_S_SETTINGS1: begin
            uvwabi_q <= wd[AS5047_SETTINGS1_UVW_ABI_LSB];
            abibin_q <= wd_abibin;
            dsel_q <= wd[AS5047_SETTINGS1_DATASELECT_LSB];
            pwmon_q <= wd[AS5047_SETTINGS1_PWMON_LSB];
          end
          default: ;
        endcase
      end
      if (cs_rise) begin
        if (cmd_ok) begin
          // A read: its register answers next. A write: the data frame answers the old content.
          // (wr_reg_q counts only while wr_data_q is set: after a write. An unknown address
          // selects NOP, so a read needs no test of its own.)
          wr_data_q <= write;
          wr_reg_q <= writable ? sel_reg : AS5047_S_NOP;
          ans_q <= (read | writable) ? sel_ans : AS5047_S_NOP;
        end else if (wr_do) begin
          // The data frame: the next frame answers the register's new content.
          wr_data_q <= 1'b0;
          ans_q <= wr_reg_q;
        end else begin
          // A refused frame: the next answer is NOP's.
          if (bits_q == 5'd16) wr_data_q <= 1'b0;
          ans_q <= AS5047_S_NOP;
        end
      end
    end
  end
  assign miso_o = sr_q[15];
  assign miso_oe_o = ~csn_s[SYNC-1];
  assign errfl_o = errfl_q;

endmodule

`resetall
