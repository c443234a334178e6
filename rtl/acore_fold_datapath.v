// SPDX-License-Identifier: MIT
// acore_fold_datapath: the estimator of acore_top folded N = FOLD times (FOLD > 1, acore_fold_legal()): a sample
// every N clocks or more, each piece of hardware used N times per sample, the same contract bit
// for bit (model/ip/engine/fixed_model.cpp). The two curves share one scaler and one Horner chain: each
// sample becomes two items (c13, then c24 N/2 clocks later), and the multipliers are folded
// F = N/2 times (acore_fold_mul). The CORDIC has K/N stage units (acore_fold_cordic).
//
//   accept -> prefilter -> [c13 | c24] scaler -> pair -> region select -> [c13 | c24] Horner
//          -> pair -> CORDIC -> angle, magnitude, region, overflow (to the top's output register)
//
// Schedule, in clocks after the accepting edge (H = N/2; SL, PL, CL the scaler's, the Horner
// chain's and the CORDIC's latencies):
//   0       d13, d24 (held until the next sample); c13 item into the scaler
//   H       c24 item into the scaler
//   SL      s13 out (held);   H + SL: s24 out -> region select (2 clocks)
//   R = H + SL + 2: region, x (held until the next sample's); c13 item into the Horner chain;
//           R + H: c24 (each item's curve goes from the scaler to the chain's subtraction through
//           a delay line)
//   R + PL  y13 out (held);   C = R + H + PL: y24 out -> CORDIC
//   C + CL  angle, magnitude, and the region and overflow of the sample beside them (valid_o)
// A sample is a valid bit that travels with it (valid_o); nothing stalls: the top's credit counter
// never lets more samples in than its output FIFO can hold. No reset but of the valid bits (and
// of the block RAM delay lines' pointers). CORRECTION = ACORE_CORR_NONE: no Horner chain, C = R.
`resetall
`default_nettype none

module acore_fold_datapath #(
  parameter integer IN_W = 16,
  parameter integer REG_W = 18,
  parameter integer S_W = 18,
  parameter integer S_F = 16,
  parameter integer R_SHIFT = 13,
  parameter integer SCALE_G = 4,
  // 0 = poly, 2 = none (poly2d is not folded).
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
  // Clocks per sample (a value of acore_fold_legal() above 1: 2, 4, 8, 16, 32).
  parameter integer FOLD = 2,
  // 1: the register file's last word is the ZERO word (after the arctangent words), on last_o.
  parameter integer ZERO = 0,
  // 0: products on adders and shifters; 1: on hardware multipliers (acore_hw_mul.v, DSP blocks).
  parameter integer MULT = 0,
  // Register file: words (acore_words: no Fourier words, the ZERO word with ZERO) and the power-up
  // image.
  parameter integer WORDS = 52,
  parameter INIT_FILE = "",
  // Derived, do not override.
  parameter integer ADDR_W = $clog2(WORDS),
  parameter integer RG_W = $clog2(REGIONS),
  parameter integer MAG_W = acore_mag_w(S_W)
) (
  input  wire                  clk_i,
  // Synchronous reset of the valid bits (and of the register file's write enable).
  input  wire                  rst_i,
  // Register file host port (acore_coef_regfile's timing: write lands one clock later, read-back
  // two clocks after the address).
  input  wire [ADDR_W-1:0]     reg_addr_i,
  input  wire [REG_W-1:0]      reg_wdata_i,
  input  wire                  reg_we_i,
  output wire [REG_W-1:0]      reg_rdata_o,
  // A sample is taken (at least FOLD clocks after the previous one): c1..c4 are valid.
  input  wire                  accept_i,
  input  wire [IN_W-1:0]       c1_i,
  input  wire [IN_W-1:0]       c2_i,
  input  wire [IN_W-1:0]       c3_i,
  input  wire [IN_W-1:0]       c4_i,
  // A sample's results (valid for one clock).
  output wire                  valid_o,
  output wire [ANGLE_W-1:0]    angle_o,
  output wire [MAG_W-1:0]      mag_o,
  output wire [RG_W-1:0]       region_o,
  output wire                  ovf_o,
  // The register file's last word (ZERO = 1: the ZERO word, from flops; else zero), for the top's
  // output register.
  output wire [REG_W-1:0]      last_o
);

`include "acore_derived.vh"

  // The valid bits read below (acore_fold_lean: v_q[t] for these t only), i = 0 .. NVTAP - 1 (-1
  // past).
  localparam integer NVTAP = 13;
  // C and LATENCY from R, PL and CL (as acore_fold_c; PL = 0 without correction): fewer arguments,
  // since Yosys's time at elaboration grows with them (checked against C and LATENCY below).
  function integer vtap(input integer i, input integer h, input integer sl, input integer r,
                        input integer pl, input integer cl, input integer sp);
    integer c;
    begin
      c = r + ((pl == 0) ? 0 : h + pl);
      case (i)
        0: vtap = 0;
        1: vtap = h - 1;
        2: vtap = h;
        3: vtap = sl;
        4: vtap = sl + h;
        5: vtap = r;
        6: vtap = r + h;
        7: vtap = r + pl;
        8: vtap = c;
        // (the curve's sparse line's pops; sp = S_PAIR_RAM, the line in block RAM: none, tap 0 again)
        9: vtap = (sp != 0) ? 0 : sl + h + pl - 2;
        10: vtap = (sp != 0) ? 0 : sl + 2 * h + pl - 2;
        11: vtap = c + cl - 1;
        12: vtap = c + cl;
        default: vtap = -1;
      endcase
    end
  endfunction
  // The smallest one above p (2^30 when none). The two functions below walk the distinct values
  // in order through this one: a few hundred calls at elaboration, where comparing every pair
  // for every bit took Yosys 26 s.
  function integer vtap_next(input integer p, input integer h, input integer sl, input integer r,
                             input integer pl, input integer cl, input integer sp);
    integer i, v;
    begin
      vtap_next = 1 << 30;
      for (i = 0; i < NVTAP; i = i + 1) begin
        v = vtap(i, h, sl, r, pl, cl, sp);
        if (v > p && v < vtap_next) vtap_next = v;
      end
    end
  endfunction
  // How many distinct ones are below t.
  function integer vtap_rank(input integer t, input integer h, input integer sl, input integer r,
                             input integer pl, input integer cl, input integer sp);
    integer i, p;
    begin
      vtap_rank = 0;
      p = -(1 << 30);
      for (i = 0; i < NVTAP; i = i + 1) begin
        p = vtap_next(p, h, sl, r, pl, cl, sp);
        if (p < t) vtap_rank = vtap_rank + 1;
      end
    end
  endfunction
  // The k-th smallest distinct one (k = 0: the smallest).
  function integer vtap_kth(input integer k, input integer h, input integer sl, input integer r,
                            input integer pl, input integer cl, input integer sp);
    integer i;
    begin
      vtap_kth = -(1 << 30);
      for (i = 0; i <= k; i = i + 1) vtap_kth = vtap_next(vtap_kth, h, sl, r, pl, cl, sp);
    end
  endfunction

  // Derived, do not override: the map, the register file's read ports and the block RAM budget
  // (iCE40 SB_RAM40_4K, 256 x 16: an HX8K's 32, acore_hx8k_blocks). Fixed: the Horner chain's PP
  // ports (a_n, then one per step; a_n and the first step on one with acore_fold_poly_share), the
  // scaler's 2 (offset, reciprocal; from acore_fold_lean() on one port that reads the four words
  // from flops, no block), the host read-back copy (BPW blocks each) and the output FIFO. Then, while they fit, in
  // this order (flops saved per block): the curves' and the region's delay lines (S_RAM; from
  // acore_fold_lean() on they are acore_sparse_delay, no block), the Horner steps' argument lines
  // (U_RAM), and for as many CORDIC units as fit a port of their own for the arctangent words
  // (AT_UNITS; the other units take their words from flops, with an N:1 choice that shares the
  // negation's LUT at N = 2 only).
  localparam integer TERMS = acore_terms(CORRECTION, DEGREE);
  localparam integer ATAN_BASE = acore_addr_atan(TERMS, REGIONS, 0);
  localparam integer H = FOLD / 2;
  localparam integer U = acore_fold_cordic_units(K, FOLD);
  localparam integer PP = (CORRECTION == ACORE_CORR_NONE) ? 0 :
                          acore_fold_poly_ports_paired(1, DEGREE, S_W, FOLD / 2, MULT);
  localparam integer BPW = (REG_W > 16) ? 2 : 1;
  localparam integer FIFO_B = (ANGLE_W + RG_W + 3 > 16) ? 2 : 1;
  // The scaler's ports: offset and reciprocal, or both on one (acore_fold_lean).
  localparam integer SC_P = (acore_fold_lean(FOLD) != 0) ? 1 : 2;
  // The scaler's ports in block RAM (acore_fold_lean: its one port on the flop copy).
  localparam integer SC_B = (SC_P == 2) ? 2 : 0;
  localparam integer BLOCKS = FIFO_B + (PP + SC_B + 1) * BPW;
  localparam integer SR_B = ((CORRECTION == ACORE_CORR_NONE) ? 0 : (S_W > 16) ? 2 : 1) + 1;   // s line, region line
  localparam integer U_B = (DEGREE - 1) * ((S_W + ADDR_W > 16) ? 2 : 1);        // argument lines
  localparam integer RAM_BLOCKS = acore_hx8k_blocks();
  // From acore_fold_lean() on, the lines are in flops (acore_sparse_delay) and take no block.
  localparam integer SPARSE = acore_fold_lean(FOLD);
  localparam integer S_RAM = (SPARSE == 0 && BLOCKS + SR_B <= RAM_BLOCKS) ? 1 : 0;
  localparam integer U_RAM = (S_RAM != 0 && CORRECTION != ACORE_CORR_NONE && BLOCKS + SR_B + U_B <= RAM_BLOCKS) ? 1 : 0;
  localparam integer FREE_B = RAM_BLOCKS - BLOCKS - ((S_RAM != 0) ? SR_B : 0) - ((U_RAM != 0) ? U_B : 0);
  localparam integer AT_FIT = (FREE_B > 0) ? (FREE_B >> (BPW - 1)) : 0;
  localparam integer AT_UNITS = (AT_FIT >= U) ? U : AT_FIT;
  localparam integer AT_P = PP + SC_P;  // the first CORDIC unit's port
  localparam integer PORTS = AT_P + AT_UNITS;
  localparam integer PA_W = PORTS * ADDR_W;
  localparam integer PD_W = PORTS * REG_W;
  localparam integer AT_BUS_W = K * REG_W;

  // Derived, do not override: stage latencies and the schedule (rtl/acore_derived.vh).
  localparam integer D_W = acore_d_w(IN_W);
  localparam integer F = H;
  localparam integer SL = acore_fold_scaler_latency(REG_W, F);
  localparam integer PL = (CORRECTION == ACORE_CORR_NONE) ? 0 : acore_fold_poly_latency(1, DEGREE, S_W, F, MULT);
  localparam integer CL = acore_fold_cordic_latency(K, FOLD);
  localparam integer R = acore_fold_r(REG_W, FOLD);
  localparam integer C = acore_fold_c(REG_W, S_W, CORRECTION, DEGREE, FOLD, MULT);
  // From acore_fold_lean() on, the blocks the Horner chain's paired schedule frees (fewer copies of
  // the map: acore_fold_poly_paired) hold the curve's delay line instead of its flops.
  localparam integer PP_FREED = (CORRECTION == ACORE_CORR_NONE) ? 0 :
                                (acore_fold_poly_ports(DEGREE, S_W, FOLD / 2) - PP) * BPW;
  localparam integer S_LINE_B = (S_W > 16) ? 2 : 1;
  localparam integer S_PAIR_RAM = (SPARSE != 0 && PP_FREED >= S_LINE_B &&
                                   H + PL - 1 <= 257) ? 1 : 0;
  // The accepting edge to valid_o, in clocks after it, minus one.
  localparam integer LATENCY = acore_fold_datapath_latency(REG_W, S_W, CORRECTION, DEGREE, K, FOLD, MULT);
  acore_check #(.OK(vtap(8, H, SL, R, PL, CL, 0) == C && vtap(12, H, SL, R, PL, CL, 0) == LATENCY),
    .VALUE(LATENCY), .MSG("illegal parameter: acore_fold_datapath: vtap's C and LATENCY must be the schedule's"))
    vtap_must_follow_the_schedule ();

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(FOLD != 1 && acore_fold_legal(FOLD) != 0), .VALUE(FOLD),
    .MSG("illegal parameter: acore_fold_datapath: FOLD must be a fold factor of acore_top above 1"))
    FOLD_must_be_a_fold_factor_above_1 ();
  // The modes this datapath builds (the table's folded modes, rtl/acore_modes.vh, must be among
  // them: acore_top picks this datapath by acore_mode_on_folded).
  acore_check #(.OK(CORRECTION == ACORE_CORR_POLY || CORRECTION == ACORE_CORR_NONE), .VALUE(CORRECTION),
    .MSG("illegal parameter: acore_fold_datapath: CORRECTION must be poly or none (the folded datapath builds these)"))
    CORRECTION_must_be_poly_or_none ();
  acore_check #(.OK(ZERO == 0 || ZERO == 1), .VALUE(ZERO),
    .MSG("illegal parameter: acore_fold_datapath: ZERO must be 0 or 1"))
    ZERO_must_be_0_or_1 ();

  // ---- register file: read ports [0, PP) Horner, PP offset, PP+1 reciprocal, then CORDIC units ----
  wire [PA_W-1:0]     raddr;
  wire [PD_W-1:0]     rdata;
  wire [AT_BUS_W-1:0] atan;
  acore_fold_regs #(
    .REG_W(REG_W), .WORDS(WORDS), .ATAN_BASE(ATAN_BASE), .K(K), .PORTS(PORTS),
    .ATAN_FLOPS((AT_UNITS < U) ? 1 : 0), .LAST_FLOP(ZERO),
    .FLOP_PORT((SC_P == 1) ? PP : -1), .FLOP_WORDS(4), .INIT_FILE(INIT_FILE)
  ) u_regs (
    .clk_i(clk_i), .rst_i(rst_i), .addr_i(reg_addr_i), .wdata_i(reg_wdata_i), .we_i(reg_we_i),
    .rdata_o(reg_rdata_o), .atan_o(atan), .last_o(last_o), .raddr_i(raddr), .rdata_p_o(rdata));

  // The OR of the valid bits' slices (the sparse chain's taps, at most NVTAP).
  function [LATENCY:0] v_or(input [NVTAP*(LATENCY+1)-1:0] one);
    integer i;
    begin
      v_or = {(LATENCY+1){1'b0}};
      for (i = 0; i < NVTAP; i = i + 1) v_or = v_or | one[i*(LATENCY+1) +: LATENCY+1];
    end
  endfunction

  // ---- valid bits: v[t] is high t clocks after the accepting edge (t = 0 the next clock) ----
  wire [LATENCY:0] v_q;
  genvar gt;
  generate
    if (SPARSE == 0) begin : g_vchain
      reg [LATENCY:0] v_sh_q;
      always @(posedge clk_i) begin
        if (rst_i) v_sh_q <= {(LATENCY+1){1'b0}};
        else v_sh_q <= {v_sh_q[LATENCY-1:0], accept_i};
      end
      assign v_q = v_sh_q;
    end else begin : g_vsparse
      // acore_fold_lean: only the clocks read below (vtap) are made, each from the one before by
      // an acore_pulse_delay (samples are FOLD clocks apart at least: a counter per FOLD clocks,
      // not a flop a clock); every other bit is zero.
      localparam integer ND = vtap_rank(LATENCY + 1, H, SL, R, PL, CL, S_PAIR_RAM);
      wire [ND:0] vd;
      // v_one's slice k: segment k's tap, vd[k + 1] at its clock (zero past ND). A loop over the
      // taps, not over every clock: a function call per clock and tap took Yosys 7 s to elaborate.
      wire [NVTAP*(LATENCY+1)-1:0] v_one;
      assign vd[0] = accept_i;
      for (gt = 0; gt < ND; gt = gt + 1) begin : g_seg
        // The previous tap (T0, -1 before the first) and this one, the next above it.
        localparam integer P = (gt == 0) ? -(1 << 30) : vtap_kth(gt - 1, H, SL, R, PL, CL, S_PAIR_RAM);
        localparam integer T = vtap_next(P, H, SL, R, PL, CL, S_PAIR_RAM);
        localparam integer T0 = (gt == 0) ? -1 : P;
        acore_pulse_delay #(.DEPTH(T - T0), .GAP(FOLD)) u_v (
          .clk_i(clk_i), .rst_i(rst_i), .d_i(vd[gt]), .q_o(vd[gt + 1]));
        assign v_one[gt*(LATENCY+1) +: LATENCY+1] = {{LATENCY{1'b0}}, vd[gt + 1]} << T;
      end
      for (gt = ND; gt < NVTAP; gt = gt + 1) begin : g_none
        assign v_one[gt*(LATENCY+1) +: LATENCY+1] = {(LATENCY+1){1'b0}};
      end
      assign v_q = v_or(v_one);
      wire unused_v = ^v_q;
    end
  endgenerate
  assign valid_o = v_q[LATENCY];

  // ---- 1: pre-filter, held until the next sample ----
  wire [D_W-1:0] d13, d24;
  acore_prefilter #(.IN_W(IN_W)) u_pre (
    .clk_i(clk_i), .en_i(accept_i), .c1_i(c1_i), .c2_i(c2_i), .c3_i(c3_i), .c4_i(c4_i),
    .d13_o(d13), .d24_o(d24));

  // ---- 2: scaling, one item per curve: c13 at clock 0, c24 at clock H; the curve's offset and
  // reciprocal read the clock before (SC_P = 1: the reciprocal at the item's clock) ----
  wire sc_second = v_q[H];
  wire sc_second_next = v_q[H - 1];
  localparam integer A_OFF13_I = acore_addr_offset(0), A_OFF24_I = acore_addr_offset(1);
  localparam integer A_RCP13_I = acore_addr_recip(0), A_RCP24_I = acore_addr_recip(1);
  localparam [ADDR_W-1:0] A_OFF13 = A_OFF13_I[ADDR_W-1:0], A_OFF24 = A_OFF24_I[ADDR_W-1:0];
  localparam [ADDR_W-1:0] A_RCP13 = A_RCP13_I[ADDR_W-1:0], A_RCP24 = A_RCP24_I[ADDR_W-1:0];
  // (SC_P = 1: the port reads the register file's flop copy of words 0..3.)
  acore_check #(.OK(A_OFF13_I < 4 && A_OFF24_I < 4 && A_RCP13_I < 4 && A_RCP24_I < 4), .VALUE(A_RCP24_I),
    .MSG("illegal parameter: acore_fold_datapath: the scaler's words must be words 0..3 of the map"))
    scaler_words_must_be_words_0_to_3 ();
  wire [REG_W-1:0] offset, recip;
  generate
    if (SC_P == 2) begin : g_sc2
      assign raddr[PP * ADDR_W +: ADDR_W] = sc_second_next ? A_OFF24 : A_OFF13;
      assign raddr[(PP + 1) * ADDR_W +: ADDR_W] = sc_second_next ? A_RCP24 : A_RCP13;
      assign offset = rdata[PP * REG_W +: REG_W];
      assign recip = rdata[(PP + 1) * REG_W +: REG_W];
    end else begin : g_sc1
      // One port: the offset the clock before the item, its reciprocal at the item's clock (on
      // the port the clock after; the scaler waits for it).
      assign raddr[PP * ADDR_W +: ADDR_W] = v_q[0] ? A_RCP13 : sc_second_next ? A_OFF24 :
                                            sc_second ? A_RCP24 : A_OFF13;
      assign offset = rdata[PP * REG_W +: REG_W];
      assign recip = offset;
    end
  endgenerate
  wire [S_W-1:0] s_sc;
  wire ovf_sc;
  acore_fold_scaler #(
    .D_W(D_W), .REG_W(REG_W), .S_W(S_W), .R_SHIFT(R_SHIFT), .SCALE_G(SCALE_G), .F(F), .MULT(MULT)
  ) u_sc (
    .clk_i(clk_i), .start_i(v_q[0] | sc_second), .d_i(sc_second ? d24 : d13), .offset_i(offset),
    .recip_i(recip), .s_o(s_sc), .ovf_o(ovf_sc));

  // ---- 3: pair the curves, domain selection ----
  // The region select runs on a sample's two clocks alone (en_i at H + SL, its clock 1), so its
  // region and x hold from R until the next sample's, past the c24 item's R + H; s13 reaches its
  // clock 2 from the held s13_q (HELD13), with no copy of its own. The scaler overflow of the
  // sample follows the same two clocks (rs2_q: clock 2).
  reg [S_W-1:0] s13_q;
  reg           sc_ovf13_q, sc_ovf_s_q, sc_ovf_q, rs2_q;
  always @(posedge clk_i) begin
    if (rst_i) rs2_q <= 1'b0;
    else rs2_q <= v_q[SL + H];
  end
  always @(posedge clk_i) begin
    if (v_q[SL]) begin
      s13_q      <= s_sc;
      sc_ovf13_q <= ovf_sc;
    end
    if (v_q[SL + H]) sc_ovf_s_q <= sc_ovf13_q | ovf_sc;
    if (rs2_q) sc_ovf_q <= sc_ovf_s_q;
  end
  wire [RG_W-1:0] region;
  wire [S_W-1:0]  x, s13_r, s24_r;
  acore_region_select #(.S_W(S_W), .REGIONS(REGIONS), .HELD13(1)) u_rs (
    .clk_i(clk_i), .en_i(v_q[SL + H]), .s13_i(s13_q), .s24_i(s_sc),
    .region_o(region), .x_o(x), .s13_o(s13_r), .s24_o(s24_r));

  // ---- 4: correction (CORRECTION), c13 item at R, c24 at R + H (both from the region select's
  // held outputs); pair the results ----
  wire [S_W-1:0] y13, y24;
  wire           pc_ovf;
  generate
    if (CORRECTION == ACORE_CORR_NONE) begin : g_none
      wire unused_x = ^x;
      assign y13 = s13_r;
      assign y24 = s24_r;
      assign pc_ovf = sc_ovf_q;
    end else begin : g_poly
      wire pc_second = v_q[R + H];
      wire unused_s = ^{s13_r, s24_r};  // the curves reach the correction from the scaler
      // Each item's curve, straight from the scaler to the clock the polynomial's value is ready
      // (PL - 3 clocks after the item's start; block RAM with S_RAM).
      wire [S_W-1:0] s_pc;
      if (S_PAIR_RAM != 0) begin : g_spair
        // (The chain's output stage registers the curve first: no flop copy after the block.)
        acore_ram_delay #(.W(S_W), .DEPTH(H + PL - 1), .OUT_REG(0)) u_ds (
          .clk_i(clk_i), .rst_i(rst_i), .d_i(s_sc), .q_o(s_pc));
      end else if (SPARSE != 0) begin : g_ssparse
        // Pushed with each item's scaled curve (clocks SL, SL + H), due H + PL - 1 clocks later.
        acore_sparse_delay #(.W(S_W), .DEPTH(H + PL - 1), .GAP(H)) u_ds (
          .clk_i(clk_i), .rst_i(rst_i), .push_i(v_q[SL] | v_q[SL + H]), .d_i(s_sc),
          .pop_i(v_q[SL + H + PL - 2] | v_q[SL + 2 * H + PL - 2]), .q_o(s_pc));
      end else if (S_RAM != 0) begin : g_sram
        acore_ram_delay #(.W(S_W), .DEPTH(H + PL - 1)) u_ds (
          .clk_i(clk_i), .rst_i(rst_i), .d_i(s_sc), .q_o(s_pc));
      end else begin : g_sflop
        acore_delay #(.W(S_W), .DEPTH(H + PL - 1)) u_ds (
          .clk_i(clk_i), .en_i(1'b1), .d_i(s_sc), .q_o(s_pc));
      end
      // Address of an item's word 0, region r and curve c: a table indexed by {r, c}.
      wire [ADDR_W-1:0] base_tab [0:2*REGIONS-1];
      genvar gb;
      for (gb = 0; gb < 2 * REGIONS; gb = gb + 1) begin : g_base
        localparam integer BASE_I = acore_addr_poly(TERMS, gb >> 1, gb & 1, 0);
        assign base_tab[gb] = BASE_I[ADDR_W-1:0];
      end
      wire [S_W-1:0] y_pc;
      wire ovf_pc;
      acore_fold_poly #(
        .REG_W(REG_W), .S_W(S_W), .S_F(S_F), .DEGREE(DEGREE), .COEF_F(COEF_F), .ACC_G(ACC_G),
        .ACC_I(ACC_I), .XCENTER(XCENTER), .ADDR_W(ADDR_W), .F(F),
        .RAM_DELAY((SPARSE != 0) ? 2 : U_RAM), .MULT(MULT), .PAIRED(1)
      ) u_pc (
        .clk_i(clk_i), .rst_i(rst_i), .start_i(v_q[R] | pc_second), .x_i(x), .s_i(s_pc),
        .base_i(base_tab[{region, pc_second}]), .ovf_i(sc_ovf_q), .coef_addr_o(raddr[0 +: PP * ADDR_W]),
        .coef_i(rdata[0 +: PP * REG_W]), .y_o(y_pc), .ovf_o(ovf_pc));
      reg [S_W-1:0] y13_q;
      reg           ovf13_q;
      always @(posedge clk_i) begin
        if (v_q[R + PL]) begin
          y13_q   <= y_pc;
          ovf13_q <= ovf_pc;
        end
      end
      assign y13 = y13_q;
      assign y24 = y_pc;
      assign pc_ovf = ovf13_q | ovf_pc;
    end
  endgenerate

  // ---- 5: CORDIC from clock C, x = corrected cosine curve, y = corrected sine curve ----
  localparam integer AT_IDX_W = acore_fold_cordic_idx_w(K, FOLD);
  acore_check #(.OK(ADDR_W >= AT_IDX_W), .VALUE(ADDR_W),
    .MSG("illegal parameter: acore_fold_datapath: ADDR_W must be >= clog2(CORDIC iterations on the units)"))
    ADDR_W_must_index_the_CORDIC_iterations ();
  wire [U*AT_IDX_W-1:0] at_idx;
  wire [U*REG_W-1:0]    at_word;
  acore_fold_cordic #(
    .IN_W(S_W), .G(CORDIC_G), .Z_W(Z_W), .ANGLE_W(ANGLE_W), .K(K), .AT_W(REG_W), .N(FOLD),
    .AT_RAM_UNITS(AT_UNITS)
  ) u_cordic (
    .clk_i(clk_i), .start_i(v_q[C]), .x_i(y24), .y_i(y13), .atan_i(atan), .at_idx_o(at_idx),
    .at_word_i(at_word), .angle_o(angle_o), .mag_o(mag_o));
  genvar gu;
  generate
    // Unit u < AT_UNITS reads word ATAN_BASE + its iteration index on port AT_P + u. (Indices
    // past K - 1, in a last unit that N does not fill, read words nobody uses.)
    localparam [ADDR_W-1:0] A_ATAN = ATAN_BASE[ADDR_W-1:0];
    for (gu = 0; gu < U; gu = gu + 1) begin : g_at
      if (gu < AT_UNITS) begin : g_port
        wire [AT_IDX_W-1:0] idx = at_idx[gu * AT_IDX_W +: AT_IDX_W];
        wire [ADDR_W-1:0] idx_a;
        if (ADDR_W > AT_IDX_W) begin : g_ext
          assign idx_a = {{(ADDR_W-AT_IDX_W){1'b0}}, idx};
        end else begin : g_same
          assign idx_a = idx;
        end
        assign raddr[(AT_P + gu) * ADDR_W +: ADDR_W] = A_ATAN + idx_a;
        assign at_word[gu * REG_W +: REG_W] = rdata[(AT_P + gu) * REG_W +: REG_W];
      end else begin : g_flops
        assign at_word[gu * REG_W +: REG_W] = {REG_W{1'b0}};
        wire unused_idx = ^at_idx[gu * AT_IDX_W +: AT_IDX_W];
      end
    end
  endgenerate

  // ---- sideband: region from the region select (in block RAM with S_RAM), overflow from the
  // CORDIC's input ----
  generate
    if (SPARSE != 0) begin : g_rg_sparse
      // One region a sample (clock R), due at valid_o.
      acore_sparse_delay #(.W(RG_W), .DEPTH(C + CL - R), .GAP(FOLD)) u_d_region (
        .clk_i(clk_i), .rst_i(rst_i), .push_i(v_q[R]), .d_i(region), .pop_i(v_q[C + CL - 1]),
        .q_o(region_o));
    end else if (S_RAM != 0) begin : g_rg_ram
      acore_ram_delay #(.W(RG_W), .DEPTH(C + CL - R)) u_d_region (
        .clk_i(clk_i), .rst_i(rst_i), .d_i(region), .q_o(region_o));
    end else begin : g_rg_flop
      acore_delay #(.W(RG_W), .DEPTH(C + CL - R)) u_d_region (
        .clk_i(clk_i), .en_i(1'b1), .d_i(region), .q_o(region_o));
    end
    // The sample's overflow, from the CORDIC's start to the output (sparse: the region's pop).
    if (SPARSE != 0) begin : g_ovf_sparse
      acore_sparse_delay #(.W(1), .DEPTH(CL), .GAP(FOLD)) u_d_ovf (
        .clk_i(clk_i), .rst_i(rst_i), .push_i(v_q[C]), .d_i(pc_ovf), .pop_i(v_q[C + CL - 1]),
        .q_o(ovf_o));
    end else begin : g_ovf_flop
      acore_delay #(.W(1), .DEPTH(CL)) u_d_ovf (
        .clk_i(clk_i), .en_i(1'b1), .d_i(pc_ovf), .q_o(ovf_o));
    end
  endgenerate

endmodule

`resetall
