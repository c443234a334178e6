// SPDX-License-Identifier: MIT
// acore_fold_cordic: stage 5 for the folded top (FOLD = N > 1), acore_cordic's contract (NORM = 0,
// model/ip/stages/cordic.cpp, bit for bit) on U = ceil(K / N) stage units instead of K stages: unit u does
// iterations uN .. uN + N - 1 on consecutive clocks, so a vector can enter every N clocks.
//
//   pre-rotation: X < 0 -> (X, Y) = (-X, -Y), Z = half a turn        (1 clock)
//   iteration i, s = (Y < 0):  X += (Y >>> i) ^ {s} + s,  Y += (X >>> i) ^ {~s} + ~s,
//                              Z += atan_i ^ {s} + s                   (1 clock each)
//   angle = round_shr(Z, Z_W - ANGLE_W);  mag = X_K >>> G               (1 clock)
//   LATENCY = acore_fold_cordic_latency(K, N): K + 2 as acore_cordic, 2K + 2 in the split form.
//
// The rounding's half LSB is added to Z's start value (sums modulo 2^Z_W: the same bits), so the
// output takes Z's top bits with no adder.
//
// Split form (acore_fold_cordic_split: N >= 2K, one unit with clocks to spare): an iteration takes
// two clocks and the unit one barrel shifter instead of two. Phase A (clock 2i after the
// pre-rotation) shifts Y into a register T, already conditionally inverted:
// T = (Y >>> i) ^ {s}; phase B shifts X through the same barrel and updates X += T + s,
// Y += (X >>> i) ^ {~s} + ~s, Z += atan_i ^ {s} + s. One inversion flag (s in phase A, ~s in B),
// registered, shares the barrel's last LUT, which then feeds both T and the Y adder.
// X's pre-rotation takes no adder of its own there: the start loads x ^ {neg} and clears T,
// and the X adder, idle in phase A, adds the negation's carry on the clock after the start.
//
// Unit u at phase p (p = 0 the clock a vector arrives from unit u-1 or the pre-rotation) adds the
// operand shifted by uN + p and atan word uN + p: at p = 0 it reads the previous unit's registers,
// else its own. The phase counter of each unit restarts from the vector's start (start_i delayed
// uN clocks), so vectors need only be N clocks apart, not aligned to a grid. Per bit and word, a
// unit costs the own/previous choice of the adder's first operand, a barrel of log2(N) 2:1 stages
// for the shifted operand (the last stage shares its LUT with the conditional negation) and the
// adder: at N = 2 three LUTs for two iterations, against two per iteration unfolded. The
// arctangent word's N:1 choice merges with its negation at N = 2; from N = 4 on it costs more than
// a block RAM port per unit (AT_RAM_UNITS). The last iterations
// of the last unit (when N does not divide K) compute values nobody reads: the result is taken
// the clock after iteration K-1.
`resetall
`default_nettype none

module acore_fold_cordic #(
  // Width of the signed x/y inputs.
  parameter integer IN_W = 18,
  // Guard fraction bits of the x/y registers.
  parameter integer G = 3,
  // Angle accumulator, one turn = 2^Z_W.
  parameter integer Z_W = 20,
  // Output angle width, unsigned, one turn = 2^ANGLE_W.
  parameter integer ANGLE_W = 16,
  // Iterations.
  parameter integer K = 16,
  // Width of one arctangent word on atan_i (unsigned, zero-extended to Z_W).
  parameter integer AT_W = 18,
  // Clocks per vector: iterations per unit (a power of two, >= 2).
  parameter integer N = 2,
  // Units 0 .. AT_RAM_UNITS-1 read their arctangent word from a synchronous-read memory port
  // (at_idx_o: iteration index for the next clock; at_word_i: that word, one clock later), which
  // saves the unit's N:1 word choice (or at N = 2 the flops of its two words); the others take
  // theirs from atan_i.
  parameter integer AT_RAM_UNITS = 0,
  // Derived, do not override.
  parameter integer XY_W = acore_xy_w(IN_W, G),
  parameter integer MAG_W = acore_mag_w(IN_W)
) (
  input  wire                  clk_i,
  // x_i, y_i are valid: a vector starts (at least N clocks after the previous one).
  input  wire                  start_i,
  // Cosine-like input x and sine-like input y.
  input  wire [IN_W-1:0]       x_i,
  input  wire [IN_W-1:0]       y_i,
  // atan_i for i = 0..K-1, word i at bits [i AT_W +: AT_W].
  input  wire [K*AT_W-1:0]     atan_i,
  // Per unit (AT_RAM_UNITS), the iteration whose word it needs next clock, and that word.
  output wire [acore_fold_cordic_units(K, N)*acore_fold_cordic_idx_w(K, N)-1:0] at_idx_o,
  input  wire [acore_fold_cordic_units(K, N)*AT_W-1:0] at_word_i,
  output reg  [ANGLE_W-1:0]    angle_o,
  // X_K >>> G: vector length times the CORDIC gain, never negative.
  output reg  [MAG_W-1:0]      mag_o
);

`include "acore_derived.vh"

  // Derived, do not override.
  localparam integer PW = $clog2(N);                 // phase counter width
  localparam integer U = acore_fold_cordic_units(K, N);
  localparam integer LATENCY = acore_fold_cordic_latency(K, N);
  localparam integer SPLIT = acore_fold_cordic_split(K, N);
  localparam integer DROP = Z_W - ANGLE_W;
  // Half an output LSB (the rounding), in Z's start value.
  localparam [Z_W-1:0] Z_RND = (DROP > 0) ? ({{(Z_W-1){1'b0}}, 1'b1} << (DROP - 1)) : {Z_W{1'b0}};
  localparam integer AT_IDX_W = acore_fold_cordic_idx_w(K, N);
  localparam integer WORD_BUS_W = U * AT_W;

  // The barrel's stage order: from N = 8 on the widest shift first (fewer LUT4s after mapping: 25
  // fewer at N = 8 and 16, 8 at N = 32), below it the narrowest (5 fewer at N = 4).
  localparam integer SH_DESC = (N >= 8) ? 1 : 0;
  // v shifted right by sh (arithmetic if sgn): log2(N) stages of 2:1, stage k shifting by 2^k.
  function automatic [XY_W-1:0] barrel(input [XY_W-1:0] v, input [PW-1:0] sh, input sgn);
    integer k, j;
    reg [XY_W-1:0] r;
    begin
      r = v;
      // Separate assignments: in one conditional expression the unsigned branch would make the
      // arithmetic shift a logical one.
      for (k = 0; k < PW; k = k + 1) begin
        j = (SH_DESC != 0) ? PW - 1 - k : k;
        if (sh[j]) begin
          if (sgn) r = $signed(r) >>> (1 << j);
          else r = r >> (1 << j);
        end
      end
      barrel = r;
    end
  endfunction

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(Z_W >= ANGLE_W), .VALUE(Z_W),
    .MSG("illegal parameter: acore_fold_cordic: Z_W must be >= ANGLE_W"))
    Z_W_must_be_at_least_ANGLE_W ();
  acore_check #(.OK(AT_W <= Z_W), .VALUE(AT_W),
    .MSG("illegal parameter: acore_fold_cordic: AT_W must be <= Z_W"))
    AT_W_must_be_at_most_Z_W ();
  acore_check #(.OK(K >= 1 && K < XY_W), .VALUE(K),
    .MSG("illegal parameter: acore_fold_cordic: K must be 1..XY_W-1"))
    K_must_be_1_to_XY_W_minus_1 ();
  acore_check #(.OK(N >= 2 && (1 << PW) == N), .VALUE(N),
    .MSG("illegal parameter: acore_fold_cordic: N must be a power of two >= 2"))
    N_must_be_a_power_of_two ();
  acore_check #(.OK(XY_W == acore_xy_w(IN_W, G)), .VALUE(XY_W),
    .MSG("illegal parameter: acore_fold_cordic: XY_W is derived (IN_W+2+G), do not override"))
    XY_W_is_derived ();
  acore_check #(.OK(MAG_W == acore_mag_w(IN_W)), .VALUE(MAG_W),
    .MSG("illegal parameter: acore_fold_cordic: MAG_W is derived (IN_W+2), do not override"))
    MAG_W_is_derived ();

  // Registers after the pre-rotation (index 0) and of every unit (index u + 1). X is never
  // negative (no sign bit kept); Y of unit u holds the results of iterations uN.. and is computed on
  // YW(u) = the width of iteration uN's result (acore_cordic's bound: entering iteration i,
  // |Y| < 2^(XY_W - i), and a 2x margin), stored and read sign-extended.
  wire [XY_W-2:0] xr [0:U];
  wire [XY_W-1:0] yr [0:U];
  wire [Z_W-1:0]  zr [0:U];
  // The sign of each register's next Y (its D input): a unit registers the sign it will use.
  wire            ysign_d [0:U];

  // ---- pre-rotation: X < 0 -> (X, Y) = (-X, -Y), Z = half a turn ----
  wire [XY_W-1:0] x0 = {{2{x_i[IN_W-1]}}, x_i, {G{1'b0}}};
  wire [XY_W-1:0] y0 = {{2{y_i[IN_W-1]}}, y_i, {G{1'b0}}};
  wire neg0 = x_i[IN_W-1];
  // -v = ~(v - 1): one carry chain (v plus neg0 in every bit, i.e. v - neg0) and an exclusive or
  // that merges into the LUT reading it (a register's choice), where neg0 ? 0 - v : v costs a
  // subtractor and a choice.
  wire [XY_W-1:0] x0_dec = x0 + {XY_W{neg0}};
  wire [XY_W-1:0] y0_dec = y0 + {XY_W{neg0}};
  wire [XY_W-1:0] x0_abs = x0_dec ^ {XY_W{neg0}};
  wire [XY_W-1:0] y_pre_d = y0_dec ^ {XY_W{neg0}};
  reg [XY_W-2:0] x_pre_q;
  reg [XY_W-1:0] y_pre_q;
  reg [Z_W-1:0]  z_pre_q;
  // Held until the next start: the split form reads them on two clocks.
  always @(posedge clk_i) begin
    if (start_i) begin
      x_pre_q <= x0_abs[XY_W-2:0];
      y_pre_q <= y_pre_d;
      z_pre_q <= {neg0, {(Z_W-1){1'b0}}} | Z_RND;
    end
  end
  assign ysign_d[0] = y_pre_d[XY_W-1];
  assign xr[0] = x_pre_q;
  assign yr[0] = y_pre_q;
  assign zr[0] = z_pre_q;

  // The start, delayed: unit u's phase restarts when start_i delayed uN clocks is high.
  localparam integer ST_D = (U - 1) * N;
  wire [ST_D:0] st;
  assign st[0] = start_i;
  genvar u;
  generate
    if (ST_D > 0) begin : g_st
      reg [ST_D-1:0] st_q;
      if (ST_D > 1) begin : g_sh
        always @(posedge clk_i) st_q <= {st_q[ST_D-2:0], start_i};
      end else begin : g_one
        always @(posedge clk_i) st_q <= start_i;
      end
      assign st[ST_D:1] = st_q;
    end

    // Arctangent words nobody reads (named unused_* for lint).
    if (AT_RAM_UNITS >= U) begin : g_no_bus
      wire unused_bus = ^atan_i;
    end else if (AT_RAM_UNITS == 0) begin : g_no_ram
      wire unused_ram = ^at_word_i;
    end else begin : g_part
      wire unused_ram = ^at_word_i[WORD_BUS_W-1:AT_RAM_UNITS*AT_W];
      wire unused_bus = ^atan_i[AT_RAM_UNITS*N*AT_W-1:0];
    end

    if (SPLIT != 0) begin : g_split
      // One unit (N >= 2K > K). The start loads X, Y and Z with the pre-rotation (no take
      // choice in front of the adders and the barrel: a vector's last X and Z go to the output
      // from the adders, and its last Y is not needed). ph: 0 the clock after the start, then
      // 1 ..; iteration it = ph / 2, phase B when ph is odd. Only the shifts of real iterations
      // (below K) need their stages.
      localparam integer SW = (K > 1) ? $clog2(K) : 0;
      localparam integer SH_MASK_I = ((1 << SW) - 1) << 1;
      localparam [PW-1:0] SH_MASK = SH_MASK_I[PW-1:0];
      localparam integer LAST_I = 2 * K - 1;  // phase B of iteration K-1
      localparam [PW-1:0] LAST = LAST_I[PW-1:0];
      reg  [PW-1:0] ph_q;
      wire [PW-1:0] ph_d = start_i ? {PW{1'b0}} : ph_q + 1'b1;
      wire phase_b = ph_q[0];
      // s: the rotation direction, the sign of Y entering the iteration (registered for phase
      // A); inv: the barrel's inversion (s in phase A, ~s in phase B); last: phase B of the last
      // iteration, whose X and Z are the result.
      reg s_q, inv_q, last_q;
      wire [XY_W:0] y_sum;
      wire s_next = start_i ? ysign_d[0] : y_sum[XY_W];
      always @(posedge clk_i) begin
        ph_q   <= ph_d;
        if (!ph_d[0]) s_q <= s_next;
        inv_q  <= ph_d[0] ? ~s_q : s_next;
        last_q <= (ph_d == LAST);
      end
      reg [XY_W-2:0] x_q;
      reg [XY_W-1:0] y_q;
      reg [Z_W-1:0]  z_q;
      // The shared barrel: Y in phase A, X (never negative, so its arithmetic shift is the
      // logical one) in phase B; shift it = ph / 2 (the mask keeps its real bits).
      wire [XY_W-1:0] bin = phase_b ? {1'b0, x_q} : y_q;
      wire [PW-1:0] sh = (ph_q & SH_MASK) >> 1;
      wire [XY_W-1:0] w = barrel(bin, sh, 1'b1) ^ {XY_W{inv_q}};
      reg [XY_W-2:0] t_q;  // the X adder's operand: X's width
      // X's pre-rotation on the X adder: the start loads x ^ {neg0} (~x = -x - 1 when x < 0: no
      // adder of its own) and clears T, and on the clock after it (phase A of iteration 0, when
      // the X adder is otherwise idle) X += T + neg0 completes -x = ~x + 1. neg0 waits in Z's
      // top bit, which the start loads with it and phase A leaves alone.
      reg first_q;
      always @(posedge clk_i) begin
        first_q <= start_i;
        if (start_i) t_q <= {(XY_W-1){1'b0}};
        else t_q <= w[XY_W-2:0];
      end
      // The pre-rotation's registers are the units' form's (this form loads X, Y, Z directly).
      wire unused_pre = ^{st, xr[0], yr[0], zr[0]};
      // The arctangent word of iteration it: from the bus (an N/2:1 choice) or from a memory
      // port addressed the clock before (phase A, with ph_d / 2 = it).
      wire [Z_W-1:0] at;
      if (AT_RAM_UNITS > 0) begin : g_at_ram
        wire [PW-1:0] idx = ph_d >> 1;
        if (AT_IDX_W > PW) begin : g_wide
          assign at_idx_o = {{(AT_IDX_W-PW){1'b0}}, idx};
        end else begin : g_fit
          assign at_idx_o = idx[AT_IDX_W-1:0];
        end
        assign at = {{(Z_W-AT_W){1'b0}}, at_word_i[0 +: AT_W]};
      end else begin : g_at_bus
        // Two phases an iteration: iteration ph_q / 2 (N / 2 >= K: the words past K - 1 are
        // read by phases nobody uses).
        acore_fold_atan_pick #(
          .K(K), .AT_W(AT_W), .Z_W(Z_W), .N(N / 2), .IDX_W(PW - 1), .I0(0)
        ) u_at (.atan_i(atan_i), .idx_i(ph_q[PW-1:1]), .at_o(at));
        assign at_idx_o = {AT_IDX_W{1'b0}};
      end
      // {a, 1} + {b, c}: bit 0 carries c into the real sum, so this is a + b + c in one adder.
      wire x_cin = first_q ? z_q[Z_W-1] : s_q;
      wire [XY_W-1:0] x_sum = {x_q, 1'b1} + {t_q, x_cin};
      assign y_sum = {y_q, 1'b1} + {w, inv_q};
      wire [Z_W:0] z_sum = {z_q, 1'b1} + {at ^ {Z_W{s_q}}, s_q};
      always @(posedge clk_i) begin
        if (start_i) begin
          x_q <= x0[XY_W-2:0] ^ {(XY_W-1){neg0}};
          y_q <= y_pre_d;
          z_q <= {neg0, {(Z_W-1){1'b0}}} | Z_RND;
        end else begin
          if (phase_b || first_q) x_q <= x_sum[XY_W-1:1];
          if (phase_b) begin
            y_q <= y_sum[XY_W:1];
            z_q <= z_sum[Z_W:1];
          end
        end
      end
      // The result, from the last iteration's adders (held until the next vector's).
      wire [Z_W-1:0] z_k = z_sum[Z_W:1];
      wire [XY_W-2:0] x_k = x_sum[XY_W-1:1];
      if (DROP > 0) begin : g_drop
        wire unused_z = ^z_k[DROP-1:0];
      end
      always @(posedge clk_i) begin
        if (last_q) begin
          angle_o <= z_k[Z_W-1:DROP];
          mag_o   <= {1'b0, x_k[XY_W-2:G]};
        end
      end
      assign xr[1] = x_q;
      assign yr[1] = y_q;
      assign zr[1] = z_q;
      assign ysign_d[1] = y_sum[XY_W];
    end else begin : g_units
    for (u = 0; u < U; u = u + 1) begin : g_unit
      localparam integer I0 = u * N;  // first iteration of the unit
      localparam integer YW = (I0 + 1 <= 2) ? XY_W : XY_W + 1 - I0;
      // Phase: 0 the clock the vector arrives, then 1 .. N-1 (ph_d: the next clock's).
      // take: phase 0 (operands from the previous unit); s = (Y < 0), the rotation direction. Both
      // are registered (from the next clock's phase and the sign of the next Y): s drives every
      // bit of the three adders, so no logic sits between its flop and that fan-out.
      reg  [PW-1:0] ph_q;
      wire [PW-1:0] ph_d = st[I0] ? {PW{1'b0}} : ph_q + 1'b1;
      wire take_d = (ph_d == {PW{1'b0}});
      reg take_q, s_q;
      always @(posedge clk_i) begin
        ph_q   <= ph_d;
        take_q <= take_d;
        s_q    <= take_d ? ysign_d[u] : ysign_d[u+1];
      end
      wire take = take_q;
      wire s = s_q;
      wire [XY_W-2:0] xa = take ? xr[u] : xr[u+1];
      wire signed [XY_W-1:0] ya = take ? yr[u] : yr[u+1];
      wire [Z_W-1:0]  za = take ? zr[u] : zr[u+1];
      // Operands shifted by I0 + phase: the fixed I0 is wiring, the phase a barrel of log2(N)
      // 2:1 stages (the last one shares its LUT with the conditional negation). Only the phases
      // of real iterations (below K - I0) need their shift: when N is above that (N = 32 for
      // K = 16) the high phase bits are masked and their stages vanish; the phases past K - 1
      // compute values nobody reads either way.
      localparam integer NS = (K - I0 < N) ? K - I0 : N;
      localparam integer SW = (NS > 1) ? $clog2(NS) : 0;
      localparam integer SH_MASK_I = (1 << SW) - 1;
      localparam [PW-1:0] SH_MASK = SH_MASK_I[PW-1:0];
      wire [PW-1:0] sh = ph_q & SH_MASK;
      wire signed [XY_W-1:0] ys0 = ya >>> I0;
      wire [XY_W-1:0] ys_full = barrel(ys0, sh, 1'b1);
      wire [XY_W-2:0] ys = ys_full[XY_W-2:0];
      wire [XY_W-1:0] xs = barrel({1'b0, xa >> I0}, sh, 1'b0);
      // The arctangent word of iteration I0 + phase: from the bus (an N:1 choice) or, with
      // AT_RAM, from a memory port addressed the clock before (iteration I0 + ph_d).
      wire [Z_W-1:0] at;
      if (u < AT_RAM_UNITS) begin : g_at_ram
        // I0 is a multiple of N, so I0 + ph_d is I0 with ph_d in its low bits.
        wire [AT_IDX_W-1:0] idx;
        if (AT_IDX_W > PW) begin : g_hi
          localparam [AT_IDX_W-1:0] I0_A = I0[AT_IDX_W-1:0];
          assign idx = {I0_A[AT_IDX_W-1:PW], ph_d};
        end else begin : g_lo
          assign idx = ph_d;
        end
        assign at_idx_o[u * AT_IDX_W +: AT_IDX_W] = idx;
        assign at = {{(Z_W-AT_W){1'b0}}, at_word_i[u * AT_W +: AT_W]};
      end else begin : g_at_bus
        acore_fold_atan_pick #(
          .K(K), .AT_W(AT_W), .Z_W(Z_W), .N(N), .IDX_W(PW), .I0(I0)
        ) u_at (.atan_i(atan_i), .idx_i(ph_q), .at_o(at));
        assign at_idx_o[u * AT_IDX_W +: AT_IDX_W] = {AT_IDX_W{1'b0}};
      end
      // {a, 1} + {b, c}: bit 0 carries c into the real sum, so this is a + b + c in one adder.
      wire [XY_W-1:0] x_sum = {xa, 1'b1} + {ys ^ {(XY_W-1){s}}, s};
      wire [YW:0]     y_sum = {ya[YW-1:0], 1'b1} + {xs[YW-1:0] ^ {YW{~s}}, ~s};
      wire [Z_W:0]    z_sum = {za, 1'b1} + {at ^ {Z_W{s}}, s};
      reg [XY_W-2:0] x_q;
      reg [YW-1:0]   y_q;
      reg [Z_W-1:0]  z_q;
      always @(posedge clk_i) begin
        x_q <= x_sum[XY_W-1:1];
        y_q <= y_sum[YW:1];
        z_q <= z_sum[Z_W:1];
      end
      assign xr[u+1] = x_q;
      assign yr[u+1] = {{(XY_W-YW){y_q[YW-1]}}, y_q};
      assign zr[u+1] = z_q;
      assign ysign_d[u+1] = y_sum[YW];
    end
    // ---- output: the clock after iteration K-1, the angle (rounded: Z_RND is in Z's start
    // value), drop the guard bits ----
    wire [Z_W-1:0] z_k = zr[U];
    wire [XY_W-2:0] x_k = xr[U];
    if (DROP > 0) begin : g_drop
      wire unused_z = ^z_k[DROP-1:0];
    end
    always @(posedge clk_i) begin
      angle_o <= z_k[Z_W-1:DROP];
      mag_o   <= {1'b0, x_k[XY_W-2:G]};
    end
    end
  endgenerate

endmodule

`resetall
