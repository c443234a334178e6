// SPDX-License-Identifier: MIT
// acore_serial_top: the AngleCore estimator on one adder, one shifter, an accumulator and two
// temporary registers (the paper's "simplest hardware platform"), bit for bit the chain of
// rtl/acore_top.v and model/ip/engine/fixed_model.cpp (pre-filter, scaling, domain selection, Horner
// correction, CORDIC, status flags, with ZERO = 1 the zero position subtracted), one sample every
// CYCLES clocks. MULT = 1 adds one hardware product (rtl/acore_hw_mul.v) for the scaling and the
// Horner steps, each then one operation instead of a shift-add step per bit (86 clocks a sample
// instead of 226 at the defaults), and the products' rounding rule of MULT = 1 (fixed_point.hpp
// hw_mul: the exact product floored once).
//
//   pins c1, mag_lo/hi, Q, T1, T2 --> A_q ----------------------------+
//   pins c3, Q, T1, T2, ACC --> shifter --> B_q --> gate/negate --> ADDER --> saturate --> ACC
//                                                                          \--> T1, T2, flags
//   RAM: coefficients + 3 scratch words (s13, s24, y13), one read port -> Q  <-- scratch writes
//   acore_serial_ctrl: one operation per clock, each in two stages (schedule in acore_serial_ctrl.v)
//
// Variables live in ACC, T1, T2 (W bits) and the scratch words; A_q and B_q are the pipeline's
// operand registers (copies, so the adder and the shifter are in different clocks). Besides them
// the core keeps the sample's small state in flops: region (2-3 bits), the x choice, the
// pre-rotation sign, ovf/LOS/DOS, and the output registers.
//
// Streaming: in_ready_o is high while the core is idle and rst_i is low; a sample is taken when
// in_valid_i && in_ready_o, in_ready_o drops the next clock and returns CYCLES clocks after the
// accepting clock; the result appears on out_valid_o LATENCY = CYCLES + 1 clocks after it. With in_valid_i and
// out_ready_i high the core takes one sample every CYCLES clocks. A result is held until
// out_ready_i; the next result waits for it (the core stalls in its last clock, in_ready_o low).
//
//   clk         _/‾\_/‾\_/‾\_/‾\_ ... _/‾\_/‾\_/‾\_/‾\_
//   in_valid_i  ‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾ ... ‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾
//   in_ready_o  ‾‾‾‾‾‾‾\__________ ... ___/‾‾‾‾‾\_______    (high again CYCLES clocks after S0)
//   c*_i        =X S0  X========== ... ===X S1  X=======
//   out_valid_o ___________________ ... _________/‾‾‾‾‾‾   (LATENCY clocks after S0 is taken)
//   angle_o                                      =X A0 X
//
// Register port: the same map and host port timing as acore_top: a write taken at a clock edge
// lands at the next one (writes while rst_i is high are ignored), and reg_rdata_o is the word at
// reg_addr_i of two clocks before. The RAM has one read port: the host reads while the core is idle
// (in_ready_o high in the clock of the address); while a sample is computed the datapath owns it
// and the read-back is zero. Every host write lands; in the two clocks a sample writes a scratch
// word (stage 2 of RND and of the first HY), a host write landing in the same clock delays the
// sample by one clock. Writing coefficients while a sample is in flight gives that sample a mix of
// old and new words.
//
// Only control flops are reset (rst_i synchronous, active high); the outputs are forced to zero
// while out_valid_o is low.
`resetall
`default_nettype none

module acore_serial_top #(
  // The datapath parameters (IN_W .. MULT; generated from the model's field table, each with its
  // default and meaning). The serial core is the 1-D polynomial correction on the raw x without
  // Fourier stage, not folded: acore_config_check stops any other CORRECTION (the mode table's
  // rows say which tops build a mode), XCENTER, FOURIER_K or FOLD, and the Fourier parameters are
  // not used otherwise. MULT = 1: the hardware product (above). ZERO = 1: one more register word
  // (the last) holding the zero position z, angle_o = angle - z (mod a turn), one more operation a
  // sample.
`include "acore_datapath_params.vh"
  // $readmemh register image for the power-up contents ("" = none).
  parameter INIT_FILE = "",
  // Derived, do not override (rtl/acore_derived.vh).
  parameter integer RG_W = $clog2(REGIONS),
  // The map of the 1-D polynomial (the only mode the serial core builds) with the ZERO word.
  parameter integer WORDS = acore_words(acore_terms_poly(DEGREE), REGIONS, K, 0, ZERO),
  parameter integer ADDR_W = $clog2(WORDS),
  parameter integer MAG_W = acore_mag_w(S_W)
) (
  input  wire               clk_i,
  input  wire               rst_i,
  // Register file host port, timed as acore_top's: a write taken at a clock edge lands at the next
  // one (ignored while rst_i is high); reg_rdata_o is the word at reg_addr_i of two clocks before
  // if the core was idle in that clock (0 otherwise, and past the last word).
  input  wire [ADDR_W-1:0]  reg_addr_i,
  input  wire [REG_W-1:0]   reg_wdata_i,
  input  wire               reg_we_i,
  output wire [REG_W-1:0]   reg_rdata_o,
  // Status window on the magnitude (unsigned).
  input  wire [MAG_W-1:0]   mag_lo_i,
  input  wire [MAG_W-1:0]   mag_hi_i,
  // Input stream: four channel codes (two-channel sensors: c3 = c4 = 0).
  input  wire               in_valid_i,
  output wire               in_ready_o,
  input  wire [IN_W-1:0]    c1_i,
  input  wire [IN_W-1:0]    c2_i,
  input  wire [IN_W-1:0]    c3_i,
  input  wire [IN_W-1:0]    c4_i,
  // Output stream.
  output wire               out_valid_o,
  input  wire               out_ready_i,
  // Angle, unsigned, one turn = 2^ANGLE_W.
  output wire [ANGLE_W-1:0] angle_o,
  output wire [RG_W-1:0]    region_o,
  output wire               ovf_o,
  output wire               los_o,
  output wire               dos_o,
  // Magnitude with the angle: the CORDIC's X_K >>> CORDIC_G, as acore_top's mag_o.
  output wire [MAG_W-1:0]   mag_o
);

`include "acore_derived.vh"

  function integer st_max(input integer a, input integer b);
    st_max = (a > b) ? a : b;
  endfunction

  // ---- derived widths: W holds every exact intermediate of the fixed-point contract ----
  localparam integer D_W = acore_d_w(IN_W);
  localparam integer T_W = acore_t_w(D_W, REG_W);                    // t = d - O
  localparam integer RS = R_SHIFT - SCALE_G;                         // scaling product shift
  localparam integer P_SC_W = T_W + st_max(REG_W - RS, 0) + 1;       // scaling product
  localparam integer ACC_F = acore_acc_f(COEF_F, ACC_G);
  localparam integer ACC_W = acore_acc_w(COEF_F, ACC_G, ACC_I);
  localparam integer P_H_W = ACC_W + st_max(S_W - S_F, 0) + 2;       // Horner product + a_j
  localparam integer RN = ACC_F - S_F;                               // correction rounding
  localparam integer Y_W = st_max(ACC_W + 1 - RN, S_W) + 1;          // s - round(acc_0)
  localparam integer XY_W = acore_xy_w(S_W, CORDIC_G);               // CORDIC X, Y
  localparam integer DROP = Z_W - ANGLE_W;
  localparam integer W = st_max(st_max(st_max(P_SC_W, P_H_W), st_max(Y_W, XY_W + 1)),
                                st_max(st_max(MAG_W + 1, Z_W), st_max(REG_W + 1, S_W + 2)));
  localparam integer MEM_W = st_max(REG_W, S_W);
  // Shifter range: left up to LS (scaling and Horner partial products, the latter with the
  // coefficient alignment ACC_G folded in for the first Horner step; CORDIC guard bits), right up
  // to MAXR (partial products, roundings, CORDIC stages).
  localparam integer LS = st_max(st_max(REG_W - 1 - RS, S_W - 1 - S_F + ACC_G), CORDIC_G);
  localparam integer MAXR = st_max(st_max(st_max(RS, S_F), st_max(SCALE_G, RN)),
                                   st_max(st_max(DROP, CORDIC_G), K - 1));
  localparam integer SHA_W = $clog2(LS + MAXR + 1);
  localparam integer BI_W = $clog2(st_max(REG_W, S_W));
  // MULT = 1: the hardware product's multiplicand (the scaling's t, ACC, a leading coefficient)
  // and the product's right shifts (the scaling's RS, a Horner step's S_F, the first step's
  // S_F - ACC_G: its multiplicand is the coefficient before its ACC_G alignment).
  localparam integer MA_W = st_max(st_max(T_W, ACC_W), REG_W);
  localparam integer PSH_H0 = S_F - ACC_G;

  // Clocks per sample (between two accepts at full rate) and from the accepting clock to
  // out_valid_o (see the schedule in acore_serial_ctrl.v). The testbench reads both
  // (rtl/verilator.vlt).
  localparam integer CYCLES = acore_serial_cycles(REG_W, S_W, DEGREE, K, ZERO, MULT);
  localparam integer LATENCY = acore_serial_latency(REG_W, S_W, DEGREE, K, ZERO, MULT);

  // Parameter rules: the model's DatapathConfig::validate(DatapathTop::kSerial) (acore_config_check.v
  // with SERIAL = 1: the serial core's modes and options), and the derived parameters. An illegal
  // configuration stops Verilator, Icarus and Yosys.
  acore_config_check #(
`include "acore_datapath_pass.vh"
    .SERIAL(1)
  ) u_config ();
  acore_check #(.OK(RG_W == $clog2(REGIONS)), .VALUE(RG_W),
    .MSG("illegal parameter: RG_W is derived (clog2(REGIONS)), do not override"))
    RG_W_is_derived ();
  acore_check #(.OK(WORDS == acore_words(acore_terms_poly(DEGREE), REGIONS, K, 0, ZERO)),
    .VALUE(WORDS),
    .MSG("illegal parameter: WORDS is derived (4 + 2 REGIONS (DEGREE+1) + K + ZERO word), do not override"))
    WORDS_is_derived ();
  acore_check #(.OK(ADDR_W == $clog2(WORDS)), .VALUE(ADDR_W),
    .MSG("illegal parameter: ADDR_W is derived (clog2(WORDS)), do not override"))
    ADDR_W_is_derived ();
  acore_check #(.OK(MAG_W == acore_mag_w(S_W)), .VALUE(MAG_W),
    .MSG("illegal parameter: MAG_W is derived (S_W+2), do not override"))
    MAG_W_is_derived ();

  localparam integer DA_W = $clog2(WORDS + 3);

  // ---- sequencer ----
  wire en, dp_read, ram_we, host_wr;
  wire a_half, t1_mv, t2_mv, t2_mv_src;
  wire a_acc, acc_we, t1_we, t2_we, t2_we_u13, ovf_clr, region_we, neg_we;
  wire los_we, dos_we, out_we;
  wire [2:0] a_sel, b_sel, sub_sel;
  wire [1:0] q_ext, gate_sel, t1_mv_src, cin_sel, sat_sel, mul_sel, mul_a;
  wire mul_r;
  wire [SHA_W-1:0] sh_amt;
  wire [BI_W-1:0] bit_idx;
  wire [DA_W-1:0] raddr, waddr;
  wire [RG_W-1:0] region;
  acore_serial_ctrl #(
    .REG_W(REG_W), .S_W(S_W), .S_F(S_F), .DEGREE(DEGREE), .REGIONS(REGIONS), .K(K), .ZERO(ZERO),
    .MULT(MULT), .WORDS(WORDS), .LS(LS), .SHA_W(SHA_W), .BI_W(BI_W), .RS(RS), .SG(SCALE_G), .RN(RN),
    .DROP(DROP), .ACC_G(ACC_G), .G(CORDIC_G)
  ) u_ctrl (
    .clk_i(clk_i), .rst_i(rst_i), .in_valid_i(in_valid_i), .in_ready_o(in_ready_o),
    .out_valid_o(out_valid_o), .out_ready_i(out_ready_i), .host_we_i(host_wr),
    .region_i(region), .en_o(en),
    .a_sel_o(a_sel), .a_half_o(a_half), .b_sel_o(b_sel), .q_ext_o(q_ext), .sh_amt_o(sh_amt),
    .gate_sel_o(gate_sel), .bit_idx_o(bit_idx), .t1_mv_o(t1_mv), .t1_mv_src_o(t1_mv_src),
    .t2_mv_o(t2_mv), .t2_mv_src_o(t2_mv_src), .sub_sel_o(sub_sel), .cin_sel_o(cin_sel),
    .mul_sel_o(mul_sel), .mul_a_o(mul_a), .mul_r_o(mul_r), .a_acc_o(a_acc), .sat_sel_o(sat_sel),
    .acc_we_o(acc_we), .t1_we_o(t1_we), .t2_we_o(t2_we), .t2_we_u13_o(t2_we_u13),
    .ovf_clr_o(ovf_clr), .region_we_o(region_we), .neg_we_o(neg_we),
    .los_we_o(los_we), .dos_we_o(dos_we), .out_we_o(out_we),
    .dp_read_o(dp_read), .raddr_o(raddr), .ram_we_o(ram_we), .waddr_o(waddr));

  // ---- coefficient RAM with the scratch words ----
  wire [MEM_W-1:0] q, wdata;
  acore_serial_ram #(
    .REG_W(REG_W), .MEM_W(MEM_W), .WORDS(WORDS), .SCRATCH(3), .INIT_FILE(INIT_FILE)
  ) u_ram (
    .clk_i(clk_i), .rst_i(rst_i), .host_addr_i(reg_addr_i), .host_wdata_i(reg_wdata_i),
    .host_we_i(reg_we_i), .host_rdata_o(reg_rdata_o), .host_wr_o(host_wr), .dp_read_i(dp_read), .dp_re_i(en),
    .dp_raddr_i(raddr), .dp_we_i(ram_we & en), .dp_waddr_i(waddr), .dp_wdata_i(wdata), .q_o(q));

  // ---- datapath ----
  wire [ANGLE_W-1:0] angle;
  wire [RG_W-1:0] out_region;
  wire ovf, los, dos;
  wire [MAG_W-1:0] mag;
  acore_serial_datapath #(
    .IN_W(IN_W), .REG_W(REG_W), .MEM_W(MEM_W), .S_W(S_W), .ACC_W(ACC_W), .Z_W(Z_W),
    .ANGLE_W(ANGLE_W), .REGIONS(REGIONS), .W(W), .LS(LS), .SHA_W(SHA_W), .BI_W(BI_W),
    .MULT(MULT), .MA_W(MA_W), .PSH_SC(RS), .PSH_H(S_F), .PSH_H0(PSH_H0),
    .G(CORDIC_G)
  ) u_dp (
    .clk_i(clk_i), .en_i(en), .c1_i(c1_i), .c2_i(c2_i), .c3_i(c3_i), .c4_i(c4_i),
    .mag_lo_i(mag_lo_i), .mag_hi_i(mag_hi_i), .q_i(q),
    .a_sel_i(a_sel), .a_half_i(a_half), .b_sel_i(b_sel), .q_ext_i(q_ext), .sh_amt_i(sh_amt),
    .gate_sel_i(gate_sel), .bit_idx_i(bit_idx), .t1_mv_i(t1_mv), .t1_mv_src_i(t1_mv_src),
    .t2_mv_i(t2_mv), .t2_mv_src_i(t2_mv_src), .sub_sel_i(sub_sel), .cin_sel_i(cin_sel),
    .mul_sel_i(mul_sel), .mul_a_i(mul_a), .mul_r_i(mul_r), .a_acc_i(a_acc), .sat_sel_i(sat_sel),
    .acc_we_i(acc_we), .t1_we_i(t1_we), .t2_we_i(t2_we), .t2_we_u13_i(t2_we_u13),
    .ovf_clr_i(ovf_clr), .region_we_i(region_we), .neg_we_i(neg_we),
    .los_we_i(los_we), .dos_we_i(dos_we), .out_we_i(out_we),
    .wdata_o(wdata), .region_o(region),
    .angle_o(angle), .out_region_o(out_region), .ovf_o(ovf), .los_o(los), .dos_o(dos),
    .mag_o(mag));

  assign angle_o  = angle & {ANGLE_W{out_valid_o}};
  assign region_o = out_region & {RG_W{out_valid_o}};
  assign ovf_o    = ovf & out_valid_o;
  assign los_o    = los & out_valid_o;
  assign dos_o    = dos & out_valid_o;
  assign mag_o    = mag & {MAG_W{out_valid_o}};

endmodule

`resetall
