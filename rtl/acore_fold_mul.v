// SPDX-License-Identifier: MIT
// acore_fold_mul: the adder/shifter multiplier of model/ip/core/fixed_point.hpp shift_add_mul(), folded
// over F clocks, plus an addend:
//   p = init + sum over bits j of b of  b[j] w_j floor(a 2^(j - RSHIFT))      (w_j = -1 for the
//   top bit of a signed b, else 1), every partial product floored on its own, as the contract says.
//
// F = 1: the whole tree (acore_shift_add_mul) and one adder for init; one product per clock.
// F > 1: B = ceil(B_W / F) bits of b per clock, most significant group first, accumulated. The
// operand register O holds floor(a 2^(t - RSHIFT)) for the top bit t of the current group and
// shifts right (arithmetic) by B each clock: floor(floor(z) / 2^B) = floor(z / 2^B), so partial
// product k of the group, O >>> k, is exactly floor(a 2^(t - k - RSHIFT)). b is padded with zeros
// below its bit 0 up to F B bits (zero bits add nothing). Each partial product is loaded into a
// register beside O, cleared when its bit of b is 0 (the AND gate of a partial product becomes a
// flop's synchronous clear). The negative top bit is the first partial product of the first
// group: loaded inverted, with a carry-in in the first tree level.
//
//   F = 1: clock 0 a_i, b_i | 1..L adder tree (L = clog2(B_W)) | init added
//   F > 1: clock 0 a_i, b_i | O, X loaded | group g: partial products and the first tree level,
//          L - 1 more tree levels (L = clog2(B)), accumulate: acc = (g == 0 ? init : acc) + T_g
//   LATENCY = L + 1 (F = 1) or L + 1 + F (F > 1) clocks from start_i to p_o (valid one clock);
//   init_i is read INIT_AT = LATENCY - F clocks after start_i.
//
// F > 1 with B = 2 and its NG = ceil(B_W / 2) groups done NG + 2 <= F clocks after start_i (the
// drive's folds: F = 16, 18 bits of b; acore_fold_mul_seq): no partial-product or tree registers.
// Clock 0 (start_i) loads O and X and clears the accumulator (a synchronous clear: no multiplexer
// in front of the adder); clock 1 adds init_i in the second partial product's place while O and X
// wait (INIT_AT = 1); clocks 2 .. NG + 1 each add both gated partial products of the top group
// straight into the accumulator (acc = acc + (O or -O) + O >>> 1), O shifts by 2 and X by 2
// (zeros in). Once X is empty the accumulator adds nothing and holds the result until the next
// start_i, F clocks later: LATENCY = F. One O, one X and one accumulator serve every product.
// A new product may start every F clocks. With A_PRE = 1 (g_seq only) a_i is read at pre_i, one
// clock before start_i, and O waits through the start clock: the caller need not hold a in a
// register of its own (acore_fold_poly's first step reads its coefficient word straight from the
// register file's memory). With LOAD = 1 (g_seq only) start_i loads init_i into the accumulator
// (read at start_i: INIT_AT = 0) beside O and X, and the groups follow on clocks 1 .. NG: the
// result is in the accumulator acore_fold_mul_load_step = NG + 1 clocks after start_i and held
// until the next start_i, which may come on that clock (a Horner chain's steps back to back on one
// multiplier, acore_fold_poly_chain: one clock a step less than the cleared form, at the cost of a
// multiplexer per accumulator bit). Sums are modulo 2^P_W (harmless while the exact result
// fits P_W bits, which the elaboration check enforces). No reset: data only; start_i must be low
// (or its product ignored) until the first real operand.
//
// MULT = 1 (hardware multipliers, fixed_point.hpp hw_mul()): p = init + ((a * b) >>> RSHIFT), the
// exact product floored once (acore_hw_mul: a DSP block), carried to INIT_AT, where init is added,
// then to LATENCY: the same interface and schedule as MULT = 0. On the in-place form's schedule
// (acore_fold_mul_seq: products F clocks apart, LATENCY = F) the sum waits in one register.
`resetall
`default_nettype none

module acore_fold_mul #(
  // Width of a, signed.
  parameter integer A_W = 25,
  // Width of b.
  parameter integer B_W = 18,
  // 1: b is two's complement (its top bit weighs -2^(B_W-1)); 0: unsigned.
  parameter integer B_SIGNED = 1,
  // Right shift of the product (fraction bits of b).
  parameter integer RSHIFT = 16,
  // Width of the addend init (signed) and of the result p (signed, must hold init + product).
  parameter integer INIT_W = 25,
  parameter integer P_W = 29,
  // Clocks per product (1, 2, 4, ...).
  parameter integer F = 2,
  // 0: adders and shifters (every partial product floored); 1: the multiply operator (DSP blocks;
  // the full product floored once).
  parameter integer MULT = 0,
  // 1 (the accumulate-in-place form only): a_i is read at pre_i, one clock before start_i.
  parameter integer A_PRE = 0,
  // 1 (the accumulate-in-place form only, without A_PRE): init_i is loaded at start_i, the groups
  // follow at once (see the header).
  parameter integer LOAD = 0
) (
  input  wire              clk_i,
  // a_i and b_i are valid (a product starts); needed for F > 1 only.
  input  wire              start_i,
  // A_PRE = 1: a_i is valid (one clock before start_i); else unused.
  input  wire              pre_i,
  input  wire [A_W-1:0]    a_i,
  input  wire [B_W-1:0]    b_i,
  // Addend, valid INIT_AT clocks after start_i.
  input  wire [INIT_W-1:0] init_i,
  // init + a b, valid LATENCY clocks after start_i.
  output wire [P_W-1:0]    p_o
);

`include "acore_derived.vh"

  // Derived, do not override: bits per clock, latency, the clock init_i is read.
  localparam integer B = acore_fold_mul_b(B_W, F);
  localparam integer LATENCY = acore_fold_mul_latency(B_W, F);
  localparam integer INIT_AT = acore_fold_mul_init_at(B_W, F);
  // Bits the exact product can need (as acore_shift_add_mul), plus one for init.
  localparam integer NEED_W = A_W + ((B_W > RSHIFT) ? (B_W - RSHIFT) : 0) + 1;

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(F >= 1), .VALUE(F),
    .MSG("illegal parameter: acore_fold_mul: F must be >= 1"))
    F_must_be_at_least_1 ();
  // The accumulate-in-place form (see the header): two bits a clock, all groups done in time.
  localparam integer NG = (B_W + 1) / 2;
  localparam integer SEQ = (MULT == 0) ? acore_fold_mul_seq(B_W, F) : 0;

  acore_check #(.OK(A_PRE == 0 || SEQ != 0), .VALUE(A_PRE),
    .MSG("illegal parameter: acore_fold_mul: A_PRE = 1 needs the accumulate-in-place form (acore_fold_mul_seq, MULT = 0)"))
    A_PRE_needs_the_in_place_form ();
  acore_check #(.OK(LOAD == 0 || (SEQ != 0 && A_PRE == 0)), .VALUE(LOAD),
    .MSG("illegal parameter: acore_fold_mul: LOAD = 1 needs the accumulate-in-place form (acore_fold_mul_seq, MULT = 0) without A_PRE"))
    LOAD_needs_the_in_place_form ();
  acore_check #(.OK(F == 1 || B >= 2), .VALUE(B_W),
    .MSG("illegal parameter: acore_fold_mul: B_W over F clocks must leave at least 2 bits a clock"))
    B_W_must_leave_2_bits_a_clock ();
  acore_check #(.OK(P_W >= NEED_W + 1 && P_W >= INIT_W + 1), .VALUE(P_W),
    .MSG("illegal parameter: acore_fold_mul: P_W cannot hold init + product"))
    P_W_must_hold_init_plus_product ();

  wire [P_W-1:0] init_ext = {{(P_W-INIT_W){init_i[INIT_W-1]}}, init_i};

  // The folded forms' first operand: O_0 = floor(a 2^SH0) for the top bit B_W-1 of b (read by
  // g_seq and g_fold only).
  localparam integer SH0 = B_W - 1 - RSHIFT;
  localparam integer O_W = A_W + ((SH0 > 0) ? SH0 : 0);
  wire [O_W-1:0] o0;
  generate
    if (SH0 > 0) begin : g_shl
      assign o0 = {a_i, {SH0{1'b0}}};
    end else if (SH0 == 0) begin : g_same
      assign o0 = a_i;
    end else begin : g_shr
      wire signed [A_W-1:0] a_s = a_i;
      assign o0 = a_s >>> (-SH0);
    end
  endgenerate

  generate
    if (F == 1) begin : g_tree
      // The whole tree (or the hardware product), then the addend.
      wire [P_W-1:0] prod;
      acore_shift_add_mul #(
        .A_W(A_W), .B_W(B_W), .B_SIGNED(B_SIGNED), .RSHIFT(RSHIFT), .P_W(P_W), .MULT(MULT)
      ) u_mul (
        .clk_i(clk_i), .en_i(1'b1), .a_i(a_i), .b_i(b_i), .p_o(prod));
      reg [P_W-1:0] p_q;
      always @(posedge clk_i) p_q <= prod + init_ext;
      assign p_o = p_q;
      // start_i is not needed: the tree takes an operand every clock.
      wire unused_start = ^{start_i, pre_i, o0};  // (o0, pre_i: the in-place form's)
    end else if (MULT != 0) begin : g_hw
      // The product of the operands of start_i, floored, INIT_AT clocks later (the multiplier runs
      // every clock; only the start clock's product is used), then the addend, then to LATENCY.
      wire [P_W-1:0] prod;
      acore_hw_mul #(
        .A_W(A_W), .B_W(B_W), .B_SIGNED(B_SIGNED), .RSHIFT(RSHIFT), .P_W(P_W), .DEPTH(INIT_AT)
      ) u_hw (
        .clk_i(clk_i), .en_i(1'b1), .a_i(a_i), .b_i(b_i), .p_o(prod));
      reg [P_W-1:0] sum_q;
      if (acore_fold_mul_seq(B_W, F) != 0) begin : g_hold
        // The in-place form's schedule (INIT_AT = 1, LATENCY = F, products F clocks apart): the
        // sum is taken at clock 1 only and waits in its register until the next product's, F
        // clocks later, past LATENCY: no delay line.
        reg ld_q;
        always @(posedge clk_i) begin
          ld_q <= start_i;
          if (ld_q) sum_q <= prod + init_ext;
        end
        assign p_o = sum_q;
        wire unused_start = ^{pre_i, o0};  // (o0, pre_i: the in-place form's)
      end else begin : g_line
        always @(posedge clk_i) sum_q <= prod + init_ext;
        acore_delay #(.W(P_W), .DEPTH(LATENCY - INIT_AT - 1)) u_dsum (
          .clk_i(clk_i), .en_i(1'b1), .d_i(sum_q), .q_o(p_o));
        wire unused_start = ^{start_i, pre_i, o0};  // (o0, pre_i: the in-place form's)
      end
    end else if (SEQ != 0) begin : g_seq
      // X: b padded to NG groups.
      localparam integer X_W = 2 * NG;
      wire [X_W-1:0] b_pad;
      if (X_W > B_W) begin : g_pad
        assign b_pad = {b_i, 1'b0};
      end else begin : g_nopad
        assign b_pad = b_i;
      end
      // start_i delayed 1 and 2 clocks: the addend's clock (O and X wait), the first group's;
      // with LOAD no addend's clock: the first group one clock after start_i.
      wire add_init, first;
      if (LOAD != 0) begin : g_sdload
        reg sd_q;
        always @(posedge clk_i) sd_q <= start_i;
        assign add_init = 1'b0;
        assign first = sd_q;
      end else begin : g_sdclr
        reg [1:0] sd_q;
        always @(posedge clk_i) sd_q <= {sd_q[0], start_i};
        assign add_init = sd_q[0];
        assign first = sd_q[1];
      end
      reg [O_W-1:0] o_q;
      reg [X_W-1:0] x_q;
      wire signed [O_W-1:0] o_s = o_q;
      wire [O_W-1:0] o_next = o_s >>> 2;
      wire [O_W-1:0] o_h = o_s >>> 1;
      // O is loaded at start_i (or at pre_i with A_PRE, then waits through the start clock).
      wire o_load = (A_PRE != 0) ? pre_i : start_i;
      wire o_wait = (A_PRE != 0) ? start_i : 1'b0;
      always @(posedge clk_i) begin
        if (o_load) o_q <= o0;
        else if (!add_init && !o_wait) o_q <= o_next;
        if (start_i) x_q <= b_pad;
        else if (!add_init) x_q <= {x_q[X_W-3:0], 2'b00};
      end
      // The two terms of a clock, each as wide as its operands plus a sign bit for their sum: the
      // first group's top bit of a signed b weighs -2^(B_W-1) (~O plus a carry-in); the addend
      // takes the second term's place on its clock (the first term is 0 then).
      localparam integer T_W = ((O_W > INIT_W) ? O_W : INIT_W) + 1;
      wire neg = (B_SIGNED != 0) & first & x_q[X_W-1];
      wire take0 = x_q[X_W-1] & ~add_init;
      wire [O_W-1:0] pp0_o = take0 ? (neg ? ~o_q : o_q) : {O_W{1'b0}};
      wire [T_W-1:0] pp0 = {{(T_W-O_W){pp0_o[O_W-1]}}, pp0_o};
      wire [T_W-1:0] pp1_o = {{(T_W-O_W){o_h[O_W-1]}}, o_h};
      wire [T_W-1:0] init_t = {{(T_W-INIT_W){init_i[INIT_W-1]}}, init_i};
      wire [T_W-1:0] pp1 = add_init ? init_t : (x_q[X_W-2] ? pp1_o : {T_W{1'b0}});
      wire [T_W:0] s0 = {pp0, 1'b1} + {pp1, neg};
      // The accumulator as wide as init + product can be (sums modulo 2^ACC_W, exact at the end),
      // sign-extended to P_W.
      localparam integer ACC_W = (NEED_W > T_W) ? NEED_W : T_W;
      wire [ACC_W-1:0] s0_ext = {{(ACC_W-T_W){s0[T_W]}}, s0[T_W:1]};
      // Cleared at start_i (a synchronous clear), or loaded with the addend (LOAD).
      wire [ACC_W-1:0] acc_start = (LOAD != 0) ? {{(ACC_W-INIT_W){init_i[INIT_W-1]}}, init_i} :
                                                 {ACC_W{1'b0}};
      reg [ACC_W-1:0] acc_q;
      always @(posedge clk_i)
        if (start_i) acc_q <= acc_start;
        else acc_q <= acc_q + s0_ext;
      assign p_o = {{(P_W-ACC_W){acc_q[ACC_W-1]}}, acc_q};
      wire unused_init_ext = ^init_ext;  // (the other forms')
      if (A_PRE == 0) begin : g_nopre
        wire unused_pre = pre_i;
      end
    end else begin : g_fold
      localparam integer X_W = F * B;
      localparam integer PAD = X_W - B_W;
      localparam integer NT = (B + 1) >> 1;  // terms after the first tree level
      wire [X_W-1:0] b_pad;
      if (PAD > 0) begin : g_pad
        assign b_pad = {b_i, {PAD{1'b0}}};
      end else begin : g_nopad
        assign b_pad = b_i;
      end
      reg [O_W-1:0] o_q;
      reg [X_W-1:0] x_q;
      reg           first_q;
      // Arithmetic shift in its own expression (a conditional with an unsigned operand would make
      // it a logical one).
      wire signed [O_W-1:0] o_s = o_q;
      wire [O_W-1:0] o_next = o_s >>> B;
      wire [O_W-1:0] o_d = start_i ? o0 : o_next;
      wire [X_W-1:0] x_d = start_i ? b_pad : x_q << B;
      // The first group's top bit of a signed b weighs -2^(B_W-1): its partial product is negated,
      // as ~O_0 here plus a carry-in in the first tree level.
      wire neg_d = start_i & (B_SIGNED != 0) & b_pad[X_W-1];
      reg neg_q;
      always @(posedge clk_i) begin
        o_q     <= o_d;
        x_q     <= x_d;
        first_q <= start_i;
        neg_q   <= neg_d;
      end
      // Partial product k of the group, O >>> k gated by bit k from the top of the group, in a
      // register of its own loaded beside O: the gate is the flop's synchronous clear, so it costs
      // no LUT (on iCE40 and xc7 alike; the flops replace the AND gates).
      wire [P_W-1:0] pp [0:B-1];
      genvar k;
      for (k = 0; k < B; k = k + 1) begin : g_pp
        wire signed [O_W-1:0] o_d_s = o_d;
        wire [O_W-1:0] sh = o_d_s >>> k;
        reg  [O_W-1:0] pp_q;
        if (k == 0) begin : g_top
          wire [O_W-1:0] v = neg_d ? ~o0 : sh;
          always @(posedge clk_i) pp_q <= x_d[X_W-1] ? v : {O_W{1'b0}};
        end else begin : g_rest
          always @(posedge clk_i) pp_q <= x_d[X_W-1-k] ? sh : {O_W{1'b0}};
        end
        assign pp[k] = {{(P_W-O_W){pp_q[O_W-1]}}, pp_q};
      end
      // First tree level: pairs (0, 1), (2, 3), ...; the carry-in completes -O_0 = ~O_0 + 1 (bit 0
      // of the wider add makes the carry-in).
      localparam integer T_BUS = NT * P_W;
      wire [T_BUS-1:0] lvl1;
      for (k = 0; k < NT; k = k + 1) begin : g_l1
        reg [P_W-1:0] s_q;
        if (k == 0) begin : g_first
          wire [P_W:0] s0 = {pp[0], 1'b1} + {pp[1], neg_q};
          always @(posedge clk_i) s_q <= s0[P_W:1];
        end else if ((k << 1) + 1 < B) begin : g_pair
          always @(posedge clk_i) s_q <= pp[k << 1] + pp[(k << 1) + 1];
        end else begin : g_single
          always @(posedge clk_i) s_q <= pp[k << 1];
        end
        assign lvl1[k * P_W +: P_W] = s_q;
      end
      reg first1_q;
      always @(posedge clk_i) first1_q <= first_q;
      // The remaining levels, and "first group" beside them.
      wire [P_W-1:0] t_sum;
      wire           t_first;
      if (NT > 1) begin : g_tree
        acore_adder_tree #(.N(NT), .W(P_W)) u_tree (
          .clk_i(clk_i), .en_i(1'b1), .terms_i(lvl1), .sum_o(t_sum));
        acore_delay #(.W(1), .DEPTH($clog2(NT))) u_dfirst (
          .clk_i(clk_i), .en_i(1'b1), .d_i(first1_q), .q_o(t_first));
      end else begin : g_one
        assign t_sum = lvl1;
        assign t_first = first1_q;
      end
      // Accumulate the groups; the first one starts from the addend.
      reg [P_W-1:0] acc_q;
      always @(posedge clk_i) acc_q <= (t_first ? init_ext : acc_q) + t_sum;
      assign p_o = acc_q;
      wire unused_pre = pre_i;  // (the in-place form's)
    end
  endgenerate

endmodule

`resetall
