// SPDX-License-Identifier: MIT
// acore_abz: incremental (ABZ quadrature) encoder emulation from the angle stream, as a drive's
// timer/counter input expects it from an AS5047P or MA730, with any resolution N = 1 .. 2^(N_W-1)
// pulses per turn (4N counts a turn), not only powers of two.
//
//   angle (latest sample) --> target = floor(angle 4N / 2^ANGLE_W) --> count steps toward it,
//                             (shift-add, 3 x (NH + 1) clocks)          one step per edge, at most
//                                                                       one edge per SPACING clocks
//   count mod 4 --> A, B (Gray: 00 10 11 01 forward);  count == INDEX --> Z (once per turn)
//
// Why a count that walks toward a target instead of A/B decoded from the angle: a decoder counts
// edges, so a jump of the angle (start-up, a fast move, a sample lost upstream) must still emit
// every count in between, each edge no closer to the previous one than the receiver can resolve
// (the SPACING register, in clocks). The count takes the shorter way round the turn (a jump of
// exactly half a turn goes forward), so a decoder's count equals floor(angle 4N / 2^ANGLE_W) once
// it has caught up, and no edge is ever lost or doubled: one step changes A or B, never both.
//
// The products angle N are computed two bits of N a clock (shift-add, no multiplier: NH =
// ceil(N_W / 2) steps), the three a conversion needs (the angle and the hysteresis window's two
// ends, below) one after the other on one datapath: an angle that arrives while one is converted
// waits, and a newer one replaces it (latest wins), so the target follows the stream LATENCY =
// 3 NH + 5 clocks late at any sample rate (a conversion every 3 NH + 4 clocks: 26 and 25 at the
// board's N_W = 13, so every sample of the board's stream at FOLD 32, one every 32 clocks, is
// converted; a faster stream has the latest converted). One datapath instead of three: the board
// is area-bound.

// Hysteresis (HYS angle LSBs, the hys_i input, as the AS5047P's HYS): the count holds while the
// angle lies within HYS LSBs of the count's own interval, that is while the target t is one of
// the counts the window angle - HYS .. angle + HYS touches (lo(angle - HYS) <= t <= lo(angle + HYS)
// round the turn, lo(x) = floor(x 4N / 2^ANGLE_W)); any other angle lands on lo(angle) exactly.
// So an angle dithering over D + 1 neighbouring LSBs (+-D/2) moves no edge once the count stands
// on any of them when HYS >= D, wherever the dither sits: +-1 LSB needs HYS >= 2 (the board's
// reset). HYS = 0: the count is lo(angle), no hysteresis. HYS is at most 2^HYS_W - 1 < 2^ANGLE_W / 4
// (HYS_W <= ANGLE_W - 2), so the window never covers half a turn.
//
// N changes: the count re-homes, without an edge, in the clock N changes its value: A and B hold
// (the count keeps its two low bits) while the latest angle is converted with the new N (no new
// sample is needed), then the count is set to the value with those low bits nearest the new
// target (at most two counts away) and walks there in legal single steps (a decoder re-homes on
// Z or on an absolute read, as after power-up). A/B never change together. N outside 1 .. NMAX is
// clamped (the register shell refuses such a write). Z is high while the count equals INDEX
// (0 .. 4N-1; an INDEX >= 4N never fires): one count, a quarter period of A, once a turn in either
// direction.
`resetall
`default_nettype none

module acore_abz #(
  // Bits of the angle: one turn = 2^ANGLE_W.
  parameter integer ANGLE_W = 16,
  // Bits of the N input: N = 1 .. 2^(N_W-1) pulses a turn (at least 2; the board's is ABZ_N.N's).
  parameter integer N_W = 13,
  // Bits of the minimum edge spacing (clocks).
  parameter integer SP_W = 16,
  // Bits of the hysteresis width (angle LSBs): 1 .. ANGLE_W - 2 (the board's is ABZ_HYS.WIDTH's).
  parameter integer HYS_W = 8,
  // 1: n_i is always 1 .. 2^(N_W-1) (a register that refuses other values feeds it, as the
  // board's ABZ_N): no clamp. 0: N outside that range is clamped.
  parameter integer N_IN_RANGE = 0
) (
  input  wire               clk_i,
  // Synchronous, active high: count 0 (A = B = 0), no target.
  input  wire               rst_i,
  // The angle stream (always accepted: the latest sample wins).
  input  wire               angle_valid_i,
  input  wire [ANGLE_W-1:0] angle_i,
  // Pulses a turn (1 .. 2^(N_W-1), clamped), the index count (0 .. 4N-1), the minimum clocks
  // between two edges (0 and 1 both mean one edge a clock), the hysteresis in angle LSBs.
  input  wire [N_W-1:0]     n_i,
  input  wire [N_W:0]       index_i,
  input  wire [SP_W-1:0]    spacing_i,
  input  wire [HYS_W-1:0]   hys_i,
  // Registered quadrature and index (one clock after the count).
  output reg                a_o,
  output reg                b_o,
  output reg                z_o,
  // The count (0 .. 4N-1) and its state: high when the count has reached the latest target and
  // no angle is waiting or being converted.
  output wire [N_W:0]       count_o,
  output wire               settled_o
);

  localparam integer C_W = N_W + 1;          // a count, 0 .. 4 NMAX - 1
  localparam integer M_W = N_W + 2;          // 4N itself (and a signed difference of counts)
  localparam integer NH = (N_W + 1) / 2;     // steps of a product: two bits of N each
  localparam integer L_W = 2 * NH;           // N's bits, padded to a whole number of steps
  localparam integer P_W = ANGLE_W + L_W;    // angle N
  localparam integer NMAX = 1 << (N_W - 1);
  localparam integer LATENCY = 3 * NH + 5;   // clocks from an accepted angle to its target
  localparam integer K_W = $clog2(NH + 1);

  acore_check #(.OK(ANGLE_W >= 2 && ANGLE_W <= 32), .VALUE(ANGLE_W),
    .MSG("illegal parameter: ANGLE_W must be 2..32")) ANGLE_W_must_be_2_to_32 ();
  acore_check #(.OK(N_W >= 2 && N_W <= 16), .VALUE(N_W),
    .MSG("illegal parameter: N_W must be 2..16 (N up to 2^(N_W-1) pulses a turn)")) N_W_must_be_2_to_16 ();
  acore_check #(.OK(N_IN_RANGE == 0 || N_IN_RANGE == 1), .VALUE(N_IN_RANGE),
    .MSG("illegal parameter: N_IN_RANGE must be 0 or 1")) N_IN_RANGE_must_be_0_or_1 ();
  acore_check #(.OK(SP_W >= 1 && SP_W <= 24), .VALUE(SP_W),
    .MSG("illegal parameter: SP_W must be 1..24")) SP_W_must_be_1_to_24 ();
  acore_check #(.OK(HYS_W >= 1 && HYS_W <= ANGLE_W - 2), .VALUE(HYS_W),
    .MSG("illegal parameter: HYS_W must be 1..ANGLE_W-2 (the window stays below a quarter turn)"))
    HYS_W_must_be_1_to_ANGLE_W_minus_2 ();

  // ---- N clamped to 1 .. NMAX ----
  localparam [N_W-1:0] NMAX_V = NMAX[N_W-1:0];
  localparam [N_W-1:0] ONE_N = {{(N_W-1){1'b0}}, 1'b1};
  wire [N_W-1:0] n_clamped = (N_IN_RANGE != 0) ? n_i :
                             (n_i == {N_W{1'b0}}) ? ONE_N : (n_i > NMAX_V) ? NMAX_V : n_i;

  // ---- N: the one in use, and a change seen in the clock it happens ----
  reg [N_W-1:0] n_cur_q;
  reg have_q;                    // an angle has arrived since reset
  wire n_change = (n_clamped != n_cur_q);

  // ---- the target: three products on one adder, one bit of N a clock, LSB first ----
  // lo = floor(angle 4N / 2^ANGLE_W) and the hysteresis window's ends lm, lp: the same with the
  // angle taken as (angle - HYS) and (angle + HYS) modulo a turn. A window end that passes a turn
  // then lies exactly 4N counts lower or higher, so each product lands on its count modulo 4N with
  // no wrap to undo, and each takes an adder as wide as the angle: the partial sum keeps the
  // product's upper ANGLE_W bits and shifts the settled low bit out (kept below it only as far
  // as a count reaches, when N_W > ANGLE_W - 2), instead of an adder as wide as the product.
  // The passes: 0 the operand angle - HYS (lm), 1 that + 2 HYS = angle + HYS (lp), 2 that - HYS =
  // angle (lo): each operand from the last on one more adder, so the angle being converted needs
  // no register of its own (ang_q takes the next while this one converts). A pass is NH clocks of
  // steps and one that takes its count and loads the next operand.
  reg pend_q, run_q;
  reg [1:0] pass_q;
  reg [ANGLE_W-1:0] ang_q, op_q;
  reg [L_W-1:0] low_q, nsh_q;
  // The partial sum, signed: a digit may subtract (below), so it lies in -op .. op - 1.
  reg [ANGLE_W:0] acc_q;
  reg cy_q;                      // the digit before took 4 too many: this one owes it
  // N changed during this conversion: its result is dropped (the change converts again).
  reg stale_q;
  reg [K_W-1:0] k_q;
  wire load = ~run_q & pend_q;
  wire turn = run_q & (k_q == {K_W{1'b0}});  // a pass's steps done
  wire res = turn & (pass_q == 2'd2);                      // lo is in acc_q, low_q
  wire [ANGLE_W-1:0] hys_a = {{(ANGLE_W-HYS_W){1'b0}}, hys_i};
  // The next operand on one adder: ang - HYS at a load, then + 2 HYS, then - HYS (- HYS as
  // ~HYS + 1). The window passes the turn's end exactly when the + 2 HYS carries out: with a
  // borrow of ang - HYS it always does, and otherwise it does when ang + HYS reaches a turn.
  wire add2 = ~load & (pass_q == 2'd0);
  wire [ANGLE_W-1:0] op_base = load ? ang_q : op_q;
  wire [ANGLE_W-1:0] op_addend = add2 ? {hys_a[ANGLE_W-2:0], 1'b0} : ~hys_a;
  wire [ANGLE_W:0] op_sum = {1'b0, op_base} + {1'b0, op_addend} + {{ANGLE_W{1'b0}}, ~add2};
  wire [ANGLE_W-1:0] op_next = op_sum[ANGLE_W-1:0];
  // A step adds op times a digit of N, two bits of N and the carry of the digit before:
  // v = 0 .. 4 is 0, op, 2 op, 4 op - op (-op now, the 4 op owed to the next digit: cy), 4 op (0
  // now, owed likewise). One adder with a four-way operand (0, op, 2 op, ~op with a carry in: one
  // LUT a bit) instead of two adders for op and 2 op. The last digit owes nothing: N's top pair
  // with the carry is at most 2 (N <= 2^(N_W-1)), so the product is exact and the sum ends >= 0.
  // The digit is recoded a clock ahead (dsel_q, from the next pair of N and the carry), so each
  // bit of the operand is one LUT of op's two bits and dsel_q's.
  reg [1:0] dsel_q;
  function [2:0] recode;         // {carry out, select} of a pair of N and the carry in
    input [1:0] pair;
    input cin;
    reg [2:0] v;
    begin
      v = {1'b0, pair} + {2'b00, cin};
      recode = {pair[1] & (pair[0] | cin),                       // v >= 3: 4 op owed onward
                (v == 3'd2) | (v == 3'd3), (v == 3'd1) | (v == 3'd3)};
    end
  endfunction
  wire [2:0] rc_first = recode(n_clamped[1:0], 1'b0);
  wire [2:0] rc_next = recode(nsh_q[1:0], cy_q);
  reg [ANGLE_W+2:0] dop;
  always @(*) begin
    case (dsel_q)
      2'd1: dop = {3'b000, op_q};
      2'd2: dop = {2'b00, op_q, 1'b0};
      2'd3: dop = {3'b111, ~op_q};
      default: dop = {(ANGLE_W+3){1'b0}};
    endcase
  end
  // acc + digit op lies in -2 op .. 3 op - 1: ANGLE_W + 3 bits, signed; two settle.
  wire [ANGLE_W+2:0] psum = {{2{acc_q[ANGLE_W]}}, acc_q} + dop + {{(ANGLE_W+2){1'b0}}, dsel_q == 2'd3};
  // (Its two low bits go below the partial sum, which takes its upper bits, its sign included.)
  /* verilator lint_off UNUSEDSIGNAL */
  wire [P_W+2:0] step_nxt = {psum, low_q} >> 2;
  /* verilator lint_on UNUSEDSIGNAL */
  // A new N converts the latest angle again (the count re-homes on that result).
  wire redo = n_change & have_q;
  always @(posedge clk_i) begin
    if (rst_i) begin
      pend_q <= 1'b0;
      run_q <= 1'b0;
      have_q <= 1'b0;
    end else begin
      if (angle_valid_i) have_q <= 1'b1;
      if (angle_valid_i || redo) pend_q <= 1'b1;
      else if (load) pend_q <= 1'b0;
      if (load) run_q <= 1'b1;
      else if (res) run_q <= 1'b0;
    end
    if (angle_valid_i) ang_q <= angle_i;
    // The datapath needs no reset: run_q says when it holds a product.
    if (load) stale_q <= 1'b0;
    else if (n_change) stale_q <= 1'b1;
    if (load || (turn && !res)) begin
      op_q <= op_next;
      acc_q <= {(ANGLE_W+1){1'b0}};
      {cy_q, dsel_q} <= rc_first;
      low_q <= {L_W{1'b0}};
      // (Every pass takes N as it is: should it change during a conversion, the result is stale.)
      nsh_q <= {{(L_W-N_W){1'b0}}, n_clamped} >> 2;  // the pairs after the first
      k_q <= NH[K_W-1:0];
      pass_q <= load ? 2'd0 : pass_q + 2'd1;
    end else if (run_q && !turn) begin
      {acc_q, low_q} <= step_nxt[P_W:0];
      {cy_q, dsel_q} <= rc_next;
      nsh_q <= nsh_q >> 2;
      k_q <= k_q - 1'b1;
    end
  end
  // The product's count: the bits from ANGLE_W - 2 up (below 4N: C_W bits hold them).
  /* verilator lint_off UNUSEDSIGNAL */
  wire [P_W-1:0] prod = {acc_q[ANGLE_W-1:0], low_q};
  /* verilator lint_on UNUSEDSIGNAL */
  wire [C_W-1:0] cnt_of = prod[ANGLE_W-2 +: C_W];
  wire [C_W-1:0] lo_q = cnt_of;
  // The window's ends are compared with the target as each pass ends (the target changes only
  // with a result, so it is the one the result is checked against), on one comparator:
  // lm > target after pass 0, lp + 1 (the carry in) > target after pass 1; lm > lp exactly
  // when the window passes the turn's end (it covers less than half a turn).
  reg ge_lm_q, le_lp_q, wrap_q;
  // The target is kept inverted (ntgt = ~target): the comparator here and the count's difference
  // below then subtract it with no inverter in front of their carry chains (a carry chain takes
  // its operands as they are); the inverter sits before the register's input, in its cell.
  reg [C_W-1:0] ntgt_q;
  /* verilator lint_off UNUSEDSIGNAL */
  wire [C_W:0] cmp = {1'b0, ntgt_q} + {1'b0, cnt_of} + {{C_W{1'b0}}, pass_q != 2'd0};
  /* verilator lint_on UNUSEDSIGNAL */
  always @(posedge clk_i) begin
    if (turn && pass_q == 2'd0) begin
      ge_lm_q <= ~cmp[C_W];
      wrap_q <= op_sum[ANGLE_W];
    end
    if (turn && pass_q == 2'd1) le_lp_q <= cmp[C_W];
  end

  // ---- the count ----
  reg [C_W-1:0] cnt_q;
  reg [SP_W-1:0] sp_q;
  reg rehome_q;                  // N changed: hold A/B until the first target with the new N
  wire [M_W-1:0] m2_cur = {1'b0, n_cur_q, 1'b0};
  wire [M_W-1:0] cnt_w = {1'b0, cnt_q};
  // (tgt - cnt) mod 4N <= 2N, the shorter way forward, from e = cnt - tgt = cnt + ntgt + 1:
  // e < 0 (tgt > cnt) goes up when e + 2N >= 0, e >= 0 (tgt <= cnt) when e - 2N >= 0 (that is
  // tgt - cnt <= -2N; tgt = cnt is no step), on one adder (-2N as ~2N + 1): a sign each, no test
  // for 0 but e's own. Both lie in -2N .. 2N - 1.
  wire [M_W-1:0] e_ct = cnt_w + {1'b1, ntgt_q} + {{(M_W-1){1'b0}}, 1'b1};  // modulo 2^M_W
  wire pos = ~e_ct[M_W-1];                               // e >= 0
  /* verilator lint_off UNUSEDSIGNAL */
  wire [M_W-1:0] e_dir = e_ct + (pos ? ~m2_cur : m2_cur) + {{(M_W-1){1'b0}}, pos};
  /* verilator lint_on UNUSEDSIGNAL */
  reg adj_q, adj_up_q;           // re-homing: the count's upper part moves by +-1 (4 counts) now
  wire moving = (e_ct != {M_W{1'b0}}) & ~rehome_q & ~adj_q;  // tgt != cnt
  wire up = ~e_dir[M_W-1];
  // The top count 4N - 1 is {N - 1, 2'b11}: its upper part (from the register N, beside the step,
  // not after it: the path through the direction and the step's adder is the board's longest).
  wire [C_W-3:0] top_hi = n_cur_q[C_W-3:0] - 1'b1;
  // The spacing counter is loaded with SPACING at an edge and counts down to 1 (a 0 loaded stays);
  // the next edge may come once it is at 1 or 0 (SPACING clocks after the last; 0 and 1: the next
  // clock), so the load needs no subtractor and the count stops on the same test.
  wire sp_ready = ((sp_q >> 1) == {SP_W{1'b0}});
  // The window lm .. lp round the turn holds the target.
  wire in_win = wrap_q ? (ge_lm_q | le_lp_q) : (ge_lm_q & le_lp_q);
  // A result with the N in use (one converted before a change is dropped).
  wire res_ok = res & ~stale_q & ~n_change;
  // Re-homing: the count keeps its two low bits (A, B hold) and takes the value nearest the new
  // target lo: lo + d with d = (count - lo) mod 4 in 0 .. 2, or lo - 1 for d = 3, round the turn.
  // In two clocks on the step's adder: the upper part of lo with the count's low bits, then that
  // +-4 counts where lo + d carries past lo's low bits (or lo - 1 borrows), round the turn (Z
  // holds for that clock: the count between is no count of the output).
  wire [1:0] dlow = cnt_q[1:0] - lo_q[1:0];
  /* verilator lint_off UNUSEDSIGNAL */
  wire [2:0] lo_d = {1'b0, lo_q[1:0]} + {1'b0, dlow};
  /* verilator lint_on UNUSEDSIGNAL */
  wire home_up = (dlow != 2'd3) & lo_d[2];
  wire home_dn = (dlow == 2'd3) & (lo_q[1:0] == 2'd0);
  // One step of the count on one adder, round the turn: +-1, or +-4 when re-homing (low bits kept).
  wire dir = adj_q ? adj_up_q : up;
  localparam [C_W-1:0] ONE_C = {{(C_W-1){1'b0}}, 1'b1}, ALL_C = {C_W{1'b1}};
  wire [C_W-1:0] addend = adj_q ? (adj_up_q ? ONE_C << 2 : ALL_C << 2) : (up ? ONE_C : ALL_C);
  wire [C_W-1:0] step = cnt_q + addend;
  wire hi_top = (cnt_q[C_W-1:2] == top_hi), hi_zero = (cnt_q[C_W-1:2] == {(C_W-2){1'b0}});
  wire wrap_up = dir & hi_top & (adj_q | (cnt_q[1:0] == 2'b11));
  wire wrap_dn = ~dir & hi_zero & (adj_q | (cnt_q[1:0] == 2'b00));
  wire [C_W-1:0] cnt_next = wrap_up ? {{(C_W-2){1'b0}}, step[1:0]} : wrap_dn ? {top_hi, step[1:0]} : step;
  always @(posedge clk_i) begin
    if (rst_i) begin
      cnt_q <= {C_W{1'b0}};
      ntgt_q <= {C_W{1'b1}};
      sp_q <= {SP_W{1'b0}};
      n_cur_q <= n_clamped;
      rehome_q <= 1'b0;
      adj_q <= 1'b0;
    end else begin
      if (!sp_ready) sp_q <= sp_q - 1'b1;  // down to 1 (or the 0 loaded): ready
      adj_q <= 1'b0;
      if (n_change) begin
        // A new N: A and B hold; without an angle yet the count is 0 and stays.
        n_cur_q <= n_clamped;
        rehome_q <= have_q;
      end else if (res_ok && rehome_q) begin
        rehome_q <= 1'b0;
        cnt_q <= {lo_q[C_W-1:2], cnt_q[1:0]};
        ntgt_q <= ~lo_q;
        adj_q <= home_up | home_dn;
        adj_up_q <= home_up;
      end else if (adj_q) begin
        cnt_q <= cnt_next;
      end else begin
        if (res_ok && !in_win) ntgt_q <= ~lo_q;
        if (moving && sp_ready) begin
          sp_q <= spacing_i;
          cnt_q <= cnt_next;
        end
      end
    end
  end

  // ---- A, B, Z ----
  always @(posedge clk_i) begin
    if (rst_i) begin
      a_o <= 1'b0;
      b_o <= 1'b0;
      z_o <= 1'b0;
    end else begin
      a_o <= cnt_q[1] ^ cnt_q[0];
      b_o <= cnt_q[1];
      if (!adj_q) z_o <= (cnt_q == index_i);
    end
  end
  assign count_o = cnt_q;
  assign settled_o = ~moving & ~rehome_q & ~adj_q & ~n_change & ~pend_q & ~run_q & ~angle_valid_i;

endmodule

`resetall
