// SPDX-License-Identifier: MIT
// acore_fold_poly: stage 4 for the folded top (FOLD > 1), the contract of acore_poly_correct
// (model/ip/stages/poly_correct.cpp) on one Horner chain shared by both curves:
//   acc_n = a_n << ACC_G;  acc_j = saturate(shift_add_mul(acc_{j+1}, u, S_W signed, U_SH) +
//   (a_j << ACC_G), ACC_W);  y = saturate(s - round_shr(acc_0, ACC_F - S_F), S_W)
// with u = x (XCENTER = 0) or x -+ 3/8 (XCENTER = 1, U_SH = S_F - 1), as acore_poly_correct.
// An item is one curve of one sample: u, s and base_i, the register address of the item's word 0
// (acore_addr_poly(TERMS, region, curve, 0); the word of power j is j words further). Items come at least F clocks apart; each Horner step is
// an acore_fold_mul folded F times whose addend is the coefficient.
//
// The coefficients come from a synchronous-read memory (the register file's block RAM copies):
// port 0 reads a_n when the item enters, port m + 1 reads a_j (j = DEGREE-1-m) for step m, each
// address one clock before the word is used (coef_addr_o, coef_i one clock later). With
// acore_fold_poly_share (F >= 8 at S_W = 18) port 0 also reads step 0's word, on every clock but
// an item's start (the step's read is INIT_AT + 1 < F clocks after its item's start, so never on
// another item's), and step m reads on port m. With PAIRED (the folded datapath: a sample's two
// items F clocks apart, samples 2F apart at least) and acore_fold_poly_paired() (F = 16 at S_W =
// 18), every read of a pair falls in a window of 2F clocks that is one port (rtl/acore_derived.vh,
// acore_fold_poly_pair_port): reads of one window are less than 2F clocks apart, so two samples'
// reads never meet on a port whatever their gap, and a port presents at each of its read clocks
// that read's address (a_n and steps 0..1 of the first item, a_n and step 0 of the second on port
// 0; the rest on port 1 at F = 16: 2 ports instead of 3).
//
//   clock 0: item in, a_n addressed | 1: a_n read (into step 0's O with the in-place multiplier,
//   acore_fold_mul's A_PRE) | 2: step 0 | step m: ML clocks of multiplier
//   (addend a_j), 1 clock saturate | round, subtract, saturate (one carry chain per clock)
//   LATENCY = 5 + DEGREE (ML + 1) (26 at F = 1 with the defaults), ML = acore_fold_mul's LATENCY
//
// With PAIRED and acore_fold_poly_chain() (F = 16 at S_W = 18, MULT = 0) a multiplier per item in
// flight instead of one per step: item c of a pair runs its whole chain on multiplier c
// (acore_fold_mul's LOAD form, T = acore_fold_mul_load_step clocks a step) and reads on port c;
// the argument, the next word's address and the overflow so far wait in one register each
// (g_chain below):
//   clock 0: a_n addressed | 1: a_n loaded into the accumulator | 2 + m T: step m starts (its word
//   addressed the clock before, O the saturated accumulator) | 2 + DEGREE T: saturated result
//   into round, subtract, saturate, shared by the pair's two items (they end F clocks apart)
//   LATENCY = 5 + DEGREE T (35 at F = 16 with the defaults)
`resetall
`default_nettype none

module acore_fold_poly #(
  parameter integer REG_W = 18,
  // Curve width, signed, S_F fraction bits.
  parameter integer S_W = 18,
  parameter integer S_F = 16,
  // Polynomial degree n.
  parameter integer DEGREE = 3,
  // Fraction bits of a coefficient (REG_W-bit signed word).
  parameter integer COEF_F = 15,
  // Guard fraction bits and integer bits (incl. sign) of the Horner accumulator.
  parameter integer ACC_G = 4,
  parameter integer ACC_I = 6,
  // 1 (8 regions only): the polynomial is in u = x -+ 3/8, centred in its half region.
  parameter integer XCENTER = 0,
  // Register address width.
  parameter integer ADDR_W = 6,
  // Clocks per item of each multiplier.
  parameter integer F = 1,
  // Where the argument (with the base address) waits for the Horner steps, DEGREE - 1 lines of
  // S_W + ADDR_W bits: 0 flop chains (acore_delay), 1 block RAM (acore_ram_delay), 2 a few
  // words of flops (acore_sparse_delay: the items come F clocks apart at least). Not read by the
  // chain per item (acore_fold_poly_chain), which keeps the argument in a register.
  parameter integer RAM_DELAY = 0,
  // 0: products on adders and shifters; 1: on hardware multipliers (acore_hw_mul.v, DSP blocks).
  parameter integer MULT = 0,
  // 1: the items come in pairs (the folded datapath's two curves of a sample: the second F clocks
  // after the first, pairs 2F clocks apart at least, the first item after reset a pair's first),
  // and where acore_fold_poly_paired() says so, the reads share fewer ports on a static schedule.
  parameter integer PAIRED = 0,
  // Derived, do not override: coefficient read ports.
  parameter integer PORTS = acore_fold_poly_ports_paired(PAIRED, DEGREE, S_W, F, MULT)
) (
  input  wire                     clk_i,
  // Synchronous reset (of the start bits and the delay lines' pointers).
  input  wire                     rst_i,
  // An item starts: x_i, base_i, ovf_i are valid.
  input  wire                     start_i,
  // Polynomial argument; the curve to correct, LATENCY - 3 clocks after start_i (when the
  // polynomial's value is ready: the caller delays it, from wherever it is cheapest).
  input  wire [S_W-1:0]           x_i,
  input  wire [S_W-1:0]           s_i,
  // Address of the item's coefficient of x^0.
  input  wire [ADDR_W-1:0]        base_i,
  // An earlier stage saturated (carried to ovf_o).
  input  wire                     ovf_i,
  // Read port p: address (port p at bits [p ADDR_W +: ADDR_W]) and its word one clock later.
  output wire [PORTS*ADDR_W-1:0]  coef_addr_o,
  input  wire [PORTS*REG_W-1:0]   coef_i,
  // Corrected curve and "some stage saturated".
  output wire [S_W-1:0]           y_o,
  output wire                     ovf_o
);

`include "acore_derived.vh"

  // Derived, do not override.
  localparam integer TERMS = acore_terms_poly(DEGREE);
  localparam integer ACC_F = acore_acc_f(COEF_F, ACC_G);
  localparam integer ACC_W = acore_acc_w(COEF_F, ACC_G, ACC_I);
  localparam integer U_SH = S_F - XCENTER;
  localparam integer P_W = ACC_W + ((S_W > U_SH) ? (S_W - U_SH) : 0) + 2;  // product + addend
  localparam integer ML = acore_fold_mul_latency(S_W, F);
  localparam integer INIT_AT = acore_fold_mul_init_at(S_W, F);
  localparam integer STEP = ML + 1;
  localparam integer LATENCY = acore_fold_poly_latency(PAIRED, DEGREE, S_W, F, MULT);
  // A Horner chain per item in flight (acore_fold_poly_chain), else a multiplier per step.
  localparam integer CH = acore_fold_poly_chain(PAIRED, DEGREE, S_W, F, MULT);
  localparam integer RN = ACC_F - S_F;      // rounding shift of the final accumulator
  localparam integer SHARE = acore_fold_poly_share(S_W, F);  // a_n and step 0 on port 0
  localparam integer PM = acore_fold_poly_paired(PAIRED, DEGREE, S_W, F);  // the paired schedule
  // PM: the reads (2 k + c: read k of item c) on port p but those of its first read's k (the
  // port's default address), and the reads k whose two items share a port.
  function [2*DEGREE+1:0] own_reads(input integer p);
    integer i;
    begin
      own_reads = {(2*DEGREE+2){1'b0}};
      for (i = 0; i < 2 * DEGREE + 2; i = i + 1)
        if (acore_fold_poly_pair_port(i, DEGREE, S_W, F) == p && i / 2 != first_read(p) / 2)
          own_reads[i] = 1'b1;
    end
  endfunction
  function [DEGREE:0] both_ports();
    integer k;
    begin
      both_ports = {(DEGREE+1){1'b0}};
      for (k = 0; k <= DEGREE; k = k + 1)
        if (acore_fold_poly_pair_port(2 * k, DEGREE, S_W, F) ==
            acore_fold_poly_pair_port(2 * k + 1, DEGREE, S_W, F)) both_ports[k] = 1'b1;
    end
  endfunction
  // PM: the first read (2 k + c: read k of item c) on port p.
  function integer first_read(input integer p);
    integer i;
    begin
      first_read = 0;
      for (i = 2 * DEGREE + 1; i >= 0; i = i - 1)
        if (acore_fold_poly_pair_port(i, DEGREE, S_W, F) == p) first_read = i;
    end
  endfunction
  // The address of the item's word of power j, from its word 0 (the map: the powers of a region's
  // curve are consecutive words).
  function integer term_off(input integer j);
    term_off = acore_addr_poly(TERMS, 0, 0, j) - acore_addr_poly(TERMS, 0, 0, 0);
  endfunction

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(ACC_F >= S_F), .VALUE(ACC_F),
    .MSG("illegal parameter: acore_fold_poly: COEF_F+ACC_G must be >= S_F"))
    COEF_F_plus_ACC_G_must_be_at_least_S_F ();
  acore_check #(.OK(ACC_I >= REG_W - COEF_F + 1), .VALUE(ACC_I),
    .MSG("illegal parameter: acore_fold_poly: ACC_I must be >= REG_W-COEF_F+1"))
    ACC_I_must_be_at_least_REG_W_minus_COEF_F_plus_1 ();
  acore_check #(.OK(DEGREE >= 1), .VALUE(DEGREE),
    .MSG("illegal parameter: acore_fold_poly: DEGREE must be >= 1"))
    DEGREE_must_be_at_least_1 ();
  acore_check #(.OK(XCENTER == 0 || (XCENTER == 1 && S_F >= 3)), .VALUE(XCENTER),
    .MSG("illegal parameter: acore_fold_poly: XCENTER must be 0, or 1 with S_F >= 3"))
    XCENTER_must_be_0_or_1 ();
  acore_check #(.OK(F >= 1 && (F & (F - 1)) == 0), .VALUE(F),
    .MSG("illegal parameter: acore_fold_poly: F must be a power of two (FOLD/2)"))
    F_must_be_a_power_of_two ();
  acore_check #(.OK(RAM_DELAY != 2 || (F >= 2 && INIT_AT < F)), .VALUE(F),
    .MSG("illegal parameter: acore_fold_poly: sparse lines (RAM_DELAY = 2) need INIT_AT < F (a line's output is held F clocks)"))
    RAM_DELAY_2_needs_INIT_AT_below_F ();
  acore_check #(.OK(PORTS == acore_fold_poly_ports_paired(PAIRED, DEGREE, S_W, F, MULT)), .VALUE(PORTS),
    .MSG("illegal parameter: acore_fold_poly: PORTS is derived (acore_fold_poly_ports_paired), do not override"))
    PORTS_is_derived ();

  // A coefficient word, sign-extended and shifted to ACC_F fraction bits.
  function automatic [ACC_W-1:0] coef_acc(input [REG_W-1:0] w);
    coef_acc = {{(ACC_W-REG_W-ACC_G){w[REG_W-1]}}, w, {ACC_G{1'b0}}};
  endfunction

  // Clock 0: address a_n; u (centred with XCENTER) and the item registered. Clock 1: a_n into a
  // register (a block RAM's word should not start a path through logic: no more than the one
  // multiplexer of the first step's O, where that register is O itself), the item beside it.
  wire [S_W-1:0] u_next;
  generate
    if (XCENTER != 0) begin : g_centre
      localparam [S_W-1:0] CENTRE = {{(S_W-S_F+1){1'b0}}, 2'b11, {(S_F-3){1'b0}}};  // 3/8
      assign u_next = x_i[S_W-1] ? x_i + CENTRE : x_i - CENTRE;
    end else begin : g_raw
      assign u_next = x_i;
    end
  endgenerate
  // The address of the item's a_n, from its word 0; the output stage's input (the chain's last
  // result, saturated, with its overflow so far).
  localparam integer DEG_I = term_off(DEGREE);
  localparam [ADDR_W-1:0] DEG_A = DEG_I[ADDR_W-1:0];
  wire [ACC_W-1:0] out_acc;
  wire             out_ov;
  genvar gk, gp, m, gc;
  generate
    if (CH != 0) begin : g_chain
      // Item c of a pair (c = cur_q: 0 the pair's first, toggled by each start) runs its whole
      // chain on multiplier c (acore_fold_mul, LOAD form), in item clocks (0: start_i):
      //   0: a_n addressed on port c | 1: a_n loaded into the accumulator (the multiplier's start,
      //   its addend a_n; the operands' load is ignored), a_{n-1} addressed | 2: step 0 starts: O
      //   the saturated accumulator (a_n), X the argument, the accumulator a_{n-1} | every T
      //   clocks the next step, its word addressed the clock before, O the saturated result |
      //   END = 2 + DEGREE T: the last result, saturated, into the shared round, subtract, saturate
      //   (the pair's two items end F clocks apart).
      // The next item on a multiplier loads its a_n at its clock 1, 2F + 1 clocks or more after
      // this one's start: no earlier than END + 1 (acore_fold_poly_chain), so the result is read in
      // time; an item's reads fall in clocks 0 .. 1 + (DEGREE - 1) T < 2F, so the next item's
      // reads on the port never meet them. Each multiplier keeps its item's argument, its next
      // word's address and its overflow so far in one register each.
      localparam integer T = acore_fold_mul_load_step(S_W);
      localparam integer END = 2 + DEGREE * T;
      localparam integer CNT_W = $clog2(END + 1);
      localparam [CNT_W-1:0] END_C = END[CNT_W-1:0];
      localparam integer NEXT_I = term_off(DEGREE - 1);
      localparam [ADDR_W-1:0] NEXT_A = NEXT_I[ADDR_W-1:0];
      // The powers of a region's curve are consecutive words (the map): each step's word one
      // STEP_A below the last.
      localparam integer STEP_I = term_off(1) - term_off(0);
      localparam [ADDR_W-1:0] STEP_A = STEP_I[ADDR_W-1:0];
      reg cur_q;
      always @(posedge clk_i) begin
        if (rst_i) cur_q <= 1'b0;
        else if (start_i) cur_q <= ~cur_q;
      end
      wire [ADDR_W-1:0] top_addr = base_i + DEG_A;
      wire [ADDR_W-1:0] next_addr = base_i + NEXT_A;
      wire [2*ACC_W-1:0] res;  // multiplier c's saturated result at bits [c ACC_W +: ACC_W]
      wire [1:0] res_ov, fin;
      for (gc = 0; gc < 2; gc = gc + 1) begin : g_c
        wire go = start_i & (cur_q == (gc != 0));
        // Item clock: 1 the clock after go, held at END between items (and after reset).
        reg [CNT_W-1:0] cnt_q;
        always @(posedge clk_i) begin
          if (rst_i) cnt_q <= END_C;
          else if (go) cnt_q <= {{(CNT_W-1){1'b0}}, 1'b1};
          else if (cnt_q != END_C) cnt_q <= cnt_q + 1'b1;
        end
        // The steps' reads: item clocks 1 + k T (k = 0 .. DEGREE - 1).
        wire [DEGREE-1:0] rd_k;
        for (gk = 0; gk < DEGREE; gk = gk + 1) begin : g_rd
          localparam integer RD_I = 1 + gk * T;
          localparam [CNT_W-1:0] RD_C = RD_I[CNT_W-1:0];
          assign rd_k[gk] = (cnt_q == RD_C);
        end
        wire rd = |rd_k;
        assign fin[gc] = (cnt_q == END_C);
        // The multiplier starts the clock after each read (the a_n load, the steps); ld_q: the
        // a_n load (no result of this item to take then).
        reg st_q, ld_q;
        always @(posedge clk_i) begin
          if (rst_i) begin
            st_q <= 1'b0;
            ld_q <= 1'b0;
          end else begin
            st_q <= go | rd;
            ld_q <= go;
          end
        end
        reg [S_W-1:0]    u_q;
        reg [ADDR_W-1:0] a_q;
        reg              ov_q;
        wire [ACC_W-1:0] sat;
        wire             sat_ovf;
        always @(posedge clk_i) begin
          if (go) begin
            u_q  <= u_next;
            a_q  <= next_addr;
            ov_q <= ovf_i;
          end else begin
            if (rd) a_q <= a_q - STEP_A;
            if (st_q & ~ld_q) ov_q <= ov_q | sat_ovf;
          end
        end
        assign coef_addr_o[gc * ADDR_W +: ADDR_W] = go ? top_addr : a_q;
        wire [P_W-1:0] sum;
        acore_fold_mul #(
          .A_W(ACC_W), .B_W(S_W), .B_SIGNED(1), .RSHIFT(U_SH), .INIT_W(ACC_W), .P_W(P_W), .F(F),
          .MULT(MULT), .LOAD(1)
        ) u_mul (
          .clk_i(clk_i), .start_i(st_q), .pre_i(1'b0), .a_i(sat), .b_i(u_q),
          .init_i(coef_acc(coef_i[gc * REG_W +: REG_W])), .p_o(sum));
        acore_saturate #(.IN_W(P_W), .OUT_W(ACC_W)) u_sat (.d_i(sum), .q_o(sat), .ovf_o(sat_ovf));
        assign res[gc * ACC_W +: ACC_W] = sat;
        assign res_ov[gc] = ov_q | sat_ovf;
      end
      // The pair's two results meet here: item 1 ends F clocks after item 0 (at item 0's END item
      // 1 is at its clock F), so fin of multiplier 1 says which.
      wire sel = fin[1];
      wire unused_fin0 = fin[0];
      assign out_acc = sel ? res[ACC_W +: ACC_W] : res[0 +: ACC_W];
      assign out_ov = sel ? res_ov[1] : res_ov[0];
    end else begin : g_steps
      // Read k (0: a_n, at the item's start; m + 1: step m's word, one clock before its multiplier
      // adds it): its address, its read clock (rd: PM only) and its word, one clock later.
      wire [(DEGREE+1)*ADDR_W-1:0] ra;  // read k at bits [k ADDR_W +: ADDR_W]
      wire [DEGREE:0]   rd;
      wire [REG_W-1:0]  cw [0:DEGREE];
      assign ra[0 +: ADDR_W] = base_i + DEG_A;
      assign rd[0] = start_i;
      if (PM == 0) begin : g_ports
        // One port a read, but a_n and step 0 on port 0 with SHARE (the step's read is never at an
        // item's start).
        wire unused_rd = ^rd;
        if (SHARE != 0) begin : g_share
          assign coef_addr_o[ADDR_W-1:0] = start_i ? ra[0 +: ADDR_W] : ra[ADDR_W +: ADDR_W];
        end else begin : g_own
          assign coef_addr_o[ADDR_W-1:0] = ra[0 +: ADDR_W];
        end
        for (gk = 0; gk <= DEGREE; gk = gk + 1) begin : g_k
          localparam integer P = (gk == 0) ? 0 : gk - SHARE;
          if (gk > SHARE) begin : g_addr
            assign coef_addr_o[P * ADDR_W +: ADDR_W] = ra[gk * ADDR_W +: ADDR_W];
          end
          assign cw[gk] = coef_i[P * REG_W +: REG_W];
        end
      end else begin : g_pair
        // The static schedule (acore_fold_poly_pair_port): port p presents, at each read clock of
        // its reads, that read's address, else its first read's (a read's item: a toggle per read,
        // 0 at the pair's first item; it flips at the read, so the clock after, with the word, it
        // is the other's). The windows keep two reads of a port off one clock (checked above).
        wire [DEGREE:0] sec;
        localparam [DEGREE:0] BOTH = both_ports();
        wire unused_sec = ^sec;  // (read only where an item's two reads are on two ports)
        for (gk = 0; gk <= DEGREE; gk = gk + 1) begin : g_k
          reg tg_q;
          always @(posedge clk_i) begin
            if (rst_i) tg_q <= 1'b0;
            else if (rd[gk]) tg_q <= ~tg_q;
          end
          assign sec[gk] = tg_q;
          localparam integer P0 = acore_fold_poly_pair_port(2 * gk, DEGREE, S_W, F);
          localparam integer P1 = acore_fold_poly_pair_port(2 * gk + 1, DEGREE, S_W, F);
          if (P0 == P1) begin : g_one
            assign cw[gk] = coef_i[P0 * REG_W +: REG_W];
          end else begin : g_two
            assign cw[gk] = tg_q ? coef_i[P0 * REG_W +: REG_W] : coef_i[P1 * REG_W +: REG_W];
          end
        end
        for (gp = 0; gp < PORTS; gp = gp + 1) begin : g_port
          localparam integer FIRST = first_read(gp);
          localparam [2*DEGREE+1:0] OWN = own_reads(gp);
          reg [ADDR_W-1:0] a_p;
          integer i;
          always @(*) begin
            a_p = ra[(FIRST / 2) * ADDR_W +: ADDR_W];
            for (i = 0; i < 2 * DEGREE + 2; i = i + 1)
              if (OWN[i] && rd[i / 2] && (BOTH[i / 2] || sec[i / 2] == ((i % 2) != 0)))
                a_p = ra[(i / 2) * ADDR_W +: ADDR_W];
          end
          assign coef_addr_o[gp * ADDR_W +: ADDR_W] = a_p;
        end
      end

      // Per step m: its inputs at its start clock (accumulator, argument, curve, base address,
      // overflow so far, start).
      wire [ACC_W-1:0]  acc [0:DEGREE];
      wire [S_W-1:0]    us  [0:DEGREE];
      wire [ADDR_W-1:0] bs  [0:DEGREE];
      wire              ov  [0:DEGREE];
      wire              st  [0:DEGREE];
      // F >= 2: the item's registers load at its start only and hold it until the next item's, at
      // least 2 clocks later, so they present it at the first step's start as well (clock 2): no
      // second register each. F = 1: a register a clock (an item may come every clock).
      localparam integer HOLD0 = (F >= 2) ? 1 : 0;
      reg [S_W-1:0]    u0_q;
      reg [ADDR_W-1:0] b0_q;
      reg              ov0_q, st0_q, st1_q;
      always @(posedge clk_i) begin
        if (HOLD0 == 0 || start_i) begin
          u0_q  <= u_next;
          b0_q  <= base_i;
          ov0_q <= ovf_i;
        end
        if (rst_i) begin
          st0_q <= 1'b0;
          st1_q <= 1'b0;
        end else begin
          st0_q <= start_i;
          st1_q <= st0_q;
        end
      end
      // a_n for the first step: with the accumulate-in-place multiplier (A_PRE) read by it straight
      // from the memory's word at clock 1 (its O register is the word's register); else a register.
      localparam integer A_PRE = (MULT == 0) ? acore_fold_mul_seq(S_W, F) : 0;
      if (A_PRE != 0) begin : g_anpre
        assign acc[0] = coef_acc(cw[0]);
      end else begin : g_anreg
        reg [ACC_W-1:0] an_q;
        always @(posedge clk_i) an_q <= coef_acc(cw[0]);
        assign acc[0] = an_q;
      end
      if (HOLD0 != 0) begin : g_hold0
        assign us[0] = u0_q;
        assign bs[0] = b0_q;
        assign ov[0] = ov0_q;
      end else begin : g_item1
        reg [S_W-1:0]    u1_q;
        reg [ADDR_W-1:0] b1_q;
        reg              ov1_q;
        always @(posedge clk_i) begin
          u1_q  <= u0_q;
          b1_q  <= b0_q;
          ov1_q <= ov0_q;
        end
        assign us[0] = u1_q;
        assign bs[0] = b1_q;
        assign ov[0] = ov1_q;
      end
      assign st[0]  = st1_q;

      for (m = 0; m < DEGREE; m = m + 1) begin : g_step
        // Address of a_j, formed at the step's start and presented one clock before the multiplier
        // adds the word (INIT_AT clocks into the step). From step 1 on with sparse lines the base
        // address is the line's output, held from the step's start until the next item's (F > INIT_AT
        // clocks): the address needs no delay of its own.
        localparam integer J_I = term_off(DEGREE - 1 - m);
        localparam [ADDR_W-1:0] J_A = J_I[ADDR_W-1:0];
        localparam integer DA = (RAM_DELAY == 2 && m > 0) ? 0 : INIT_AT - 1;
        if (DA == 0) begin : g_ahold
          assign ra[(m + 1) * ADDR_W +: ADDR_W] = bs[m] + J_A;
        end else begin : g_adelay
          acore_delay #(.W(ADDR_W), .DEPTH(DA)) u_da (
            .clk_i(clk_i), .en_i(1'b1), .d_i(bs[m] + J_A), .q_o(ra[(m + 1) * ADDR_W +: ADDR_W]));
        end
        // Its read clock (PM): the step's start, INIT_AT - 1 clocks later (reset, as the starts).
        if (PM != 0 && INIT_AT > 1) begin : g_rd
          reg [INIT_AT-2:0] rd_q;
          if (INIT_AT > 2) begin : g_sh
            always @(posedge clk_i) begin
              if (rst_i) rd_q <= {(INIT_AT-1){1'b0}};
              else rd_q <= {rd_q[INIT_AT-3:0], st[m]};
            end
          end else begin : g_one
            always @(posedge clk_i) begin
              if (rst_i) rd_q <= 1'b0;
              else rd_q <= st[m];
            end
          end
          assign rd[m + 1] = rd_q[INIT_AT-2];
        end else if (PM != 0) begin : g_rd0
          assign rd[m + 1] = st[m];
        end else begin : g_nord
          assign rd[m + 1] = 1'b0;
        end
        wire [P_W-1:0] sum;
        acore_fold_mul #(
          .A_W(ACC_W), .B_W(S_W), .B_SIGNED(1), .RSHIFT(U_SH), .INIT_W(ACC_W), .P_W(P_W), .F(F), .MULT(MULT),
          .A_PRE((m == 0) ? A_PRE : 0)
        ) u_mul (
          .clk_i(clk_i), .start_i(st[m]), .pre_i((m == 0) ? st0_q : 1'b0), .a_i(acc[m]), .b_i(us[m]),
          .init_i(coef_acc(cw[m + 1])), .p_o(sum));
        // The item beside the multiplier to the next step: start, and argument with base address.
        // The start bits are reset (as the chain's first two), so a sparse line's pushes and pops
        // pair up from reset on; st_p: the start one clock early, the sparse line's pop.
        // st_o: the start STEP - 2 clocks later (the overflow line's pop). With sparse lines and
        // F >= 16 a pulse delay (a counter, the starts come F clocks apart) and two flops; else a
        // flop a clock.
        wire st_o, st_p;
        if (RAM_DELAY == 2 && F >= 16 && STEP >= 3) begin : g_stpulse
          acore_pulse_delay #(.DEPTH(STEP - 2), .GAP(F)) u_dst (
            .clk_i(clk_i), .rst_i(rst_i), .d_i(st[m]), .q_o(st_o));
          reg [1:0] st_t_q;
          always @(posedge clk_i) begin
            if (rst_i) st_t_q <= 2'b00;
            else st_t_q <= {st_t_q[0], st_o};
          end
          assign st_p = st_t_q[0];
          assign st[m+1] = st_t_q[1];
        end else begin : g_stchain
          reg [STEP-1:0] st_d_q;
          always @(posedge clk_i) begin
            if (rst_i) st_d_q <= {STEP{1'b0}};
            else st_d_q <= {st_d_q[STEP-2:0], st[m]};
          end
          if (STEP >= 3) begin : g_sto
            assign st_o = st_d_q[STEP-3];
          end else begin : g_sto0
            assign st_o = 1'b0;
          end
          assign st_p = st_d_q[STEP-2];
          assign st[m+1] = st_d_q[STEP-1];
        end
        if (m == DEGREE - 1) begin : g_ulast
          assign {bs[m+1], us[m+1]} = {(ADDR_W+S_W){1'b0}};  // no step after the last
          wire unused_stp = st_p;
        end else if (RAM_DELAY == 2) begin : g_usparse
          acore_sparse_delay #(.W(ADDR_W + S_W), .DEPTH(STEP), .GAP(F)) u_du (
            .clk_i(clk_i), .rst_i(rst_i), .push_i(st[m]), .d_i({bs[m], us[m]}), .pop_i(st_p),
            .q_o({bs[m+1], us[m+1]}));
        end else if (RAM_DELAY == 1) begin : g_uram
          acore_ram_delay #(.W(ADDR_W + S_W), .DEPTH(STEP)) u_du (
            .clk_i(clk_i), .rst_i(rst_i), .d_i({bs[m], us[m]}), .q_o({bs[m+1], us[m+1]}));
          wire unused_stp = st_p;
        end else begin : g_uflop
          wire unused_stp = st_p;
          acore_delay #(.W(ADDR_W + S_W), .DEPTH(STEP)) u_du (
            .clk_i(clk_i), .en_i(1'b1), .d_i({bs[m], us[m]}), .q_o({bs[m+1], us[m+1]}));
        end
        // The overflow so far, to the clock the step saturates (STEP - 1 clocks): with sparse lines a
        // two-word buffer popped by the start chain's tap STEP - 2 clocks after the push.
        wire ov_e;
        if (RAM_DELAY == 2 && STEP >= 3) begin : g_ovsparse
          acore_sparse_delay #(.W(1), .DEPTH(STEP - 1), .GAP(F)) u_dov (
            .clk_i(clk_i), .rst_i(rst_i), .push_i(st[m]), .d_i(ov[m]), .pop_i(st_o),
            .q_o(ov_e));
        end else begin : g_ovflop
          wire unused_sto = st_o;
          acore_delay #(.W(1), .DEPTH(STEP - 1)) u_dov (
            .clk_i(clk_i), .en_i(1'b1), .d_i(ov[m]), .q_o(ov_e));
        end
        // Clock ML: saturate to ACC_W.
        wire [ACC_W-1:0] sum_sat;
        wire sum_ovf;
        acore_saturate #(.IN_W(P_W), .OUT_W(ACC_W)) u_sat (.d_i(sum), .q_o(sum_sat), .ovf_o(sum_ovf));
        reg [ACC_W-1:0] acc_q;
        reg             ov_q;
        always @(posedge clk_i) begin
          acc_q <= sum_sat;
          ov_q  <= ov_e | sum_ovf;
        end
        assign acc[m+1] = acc_q;
        assign ov[m+1]  = ov_q;
      end

      // The last step's result to the output stage.
      assign out_acc = acc[DEGREE];
      assign out_ov = ov[DEGREE];

      // The last step's start, base and argument have no further reader.
      wire unused_tail = st[DEGREE] ^ ^bs[DEGREE] ^ ^us[DEGREE];
    end
  endgenerate

  // y = saturate(s - round_shr(acc, RN), S_W): round, subtract, saturate, one clock each.
  acore_round_sub_sat #(.ACC_W(ACC_W), .RN(RN), .S_W(S_W)) u_out (
    .clk_i(clk_i), .en_i(1'b1), .acc_i(out_acc), .s_i(s_i), .ov_i(out_ov), .y_o(y_o), .ovf_o(ovf_o));

endmodule

`resetall
