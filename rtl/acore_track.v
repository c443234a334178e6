// SPDX-License-Identifier: MIT
// acore_track: a type-II tracking observer on the estimator's angle stream (model/ip/stages/
// tracker.cpp, bit for bit): tracked angle, velocity, signed turn count, loss of tracking, and the
// angle extrapolated over the datapath's latency plus a LEAD register (dynamic angle-error
// compensation). Shift gains only: no multiplier.
//
// Scales. The loop state holds the angle with FRAC_W fraction bits below the input LSB, as an
// unsigned P_W = ANGLE_W + FRAC_W bit turn fraction, extended above by a TURN_W-bit signed turn
// count (one (TURN_W + P_W)-bit accumulator, so the turn count and the angle cannot disagree).
// The velocity v is a P_W-bit signed word in the same LSB: 2^-P_W turns per sample (the default
// P_W = 41: 4.5e-13 turn/sample; at 1 MS/s one LSB is 2.7e-5 rpm).
//
// Loop (one accepted sample theta, bandwidth code k = bw_i clamped to K_MIN..K_MAX):
//   pred = phi + v                                 (the prediction for this sample)
//   e    = wrap(theta * 2^FRAC_W - pred)           (signed P_W bits, half a turn either way)
//   phi  = pred + (e >>> k)                        (gain kp = 2^-k)
//   v    = v + (e >>> (2k + 1))                    (gain ki = 2^-(2k+1) = kp^2 / 2)
// ki = kp^2 / 2 makes the equivalent continuous loop's damping 1/sqrt(2) at every code, with
// natural frequency wn = 2^-(k + 1/2) rad/sample (the velocity output's -3 dB frequency; the
// angle's is 2.058 wn). The first sample after reset loads phi = theta, v = 0, turns = 0.
// Zero steady-state error at constant speed (the double integrator of a type-II loop).
//
// Outputs (registered):
//   out_angle_o       round(phi) to ANGLE_W bits (the tracked angle, unsigned turn fraction)
//   out_turns_o       the turn count of that rounded angle (signed, wraps at TURN_W bits)
//   out_velocity_o    v (signed, P_W bits, 2^-P_W turns per sample)
//   out_angle_comp_o  round(phi + v * D) to ANGLE_W bits, D = COMP_LATENCY + lead_i / 2^LEAD_F samples
//                     (v * D on shifts and adders over D's bits; floor at 2^-P_W turn)
//   out_lot_o         |e| > lot_thr_i (input LSBs) for this sample: loss of tracking
//
// Register inputs (static while samples flow; the model refuses values out of range, the RTL
// clamps bw_i into K_MIN..K_MAX so that no register value makes the loop unstable):
//   bw_i       [3:0]          the bandwidth code k (K_MIN = 2 .. K_MAX = (FRAC_W - 1) / 2)
//   lead_i     [LEAD_W-1:0]   LEAD, unsigned, LEAD_F fraction bits (samples)
//   lot_thr_i  [ANGLE_W-2:0]  the loss-of-tracking threshold in input angle LSBs
//
// Streaming: in_valid_i/in_ready_o take a sample; out_valid_o/out_ready_i give its result three
// clocks later (loop register; rounding and v * D in partial sums; output register), four with
// LOOP_CLOCKS = 2, which also keeps in_ready_o low for the clock after a sample is taken. The pipeline stalls as a whole when the output is
// held: in_ready_o = !rst_i && !(out_valid_o && !out_ready_i) (&& not the update clock with
// LOOP_CLOCKS = 2). rst_i is synchronous, active high.
`resetall
`default_nettype none

module acore_track #(
  // Input and output angle width (unsigned turn fraction).
  parameter integer ANGLE_W = 16,
  // Fraction bits of the loop state below the input LSB (bounds K_MAX = (FRAC_W - 1) / 2).
  parameter integer FRAC_W = 25,
  // Turn counter width (signed).
  parameter integer TURN_W = 16,
  // The latency compensated in whole samples (the estimator's LATENCY at one sample a clock; a top
  // taking CYCLES clocks a sample: acore_comp_latency(LATENCY, CYCLES) of rtl/acore_derived.vh).
  parameter integer COMP_LATENCY = 0,
  // LEAD register width and its fraction bits.
  parameter integer LEAD_W = 8,
  parameter integer LEAD_F = 4,
  // Clocks of the loop update: 1 (a sample every clock) or 2 (a sample every other clock at most,
  // a shorter clock period).
  parameter integer LOOP_CLOCKS = 1,
  // 1: time-shared over the clocks a sample takes (one adder for every sum, the shifts one bit a
  // clock; acore_track_serial_cycles() of rtl/acore_derived.vh clocks a sample, LOOP_CLOCKS unused):
  // for an estimator that delivers a sample every that many clocks or fewer often.
  parameter integer SERIAL = 0
) (
  input  wire                      clk_i,
  input  wire                      rst_i,
  // The angle stream in (the estimator's angle_o).
  input  wire                      in_valid_i,
  output wire                      in_ready_o,
  input  wire [ANGLE_W-1:0]        in_angle_i,
  // Registers.
  input  wire [3:0]                bw_i,
  input  wire [LEAD_W-1:0]         lead_i,
  input  wire [ANGLE_W-2:0]        lot_thr_i,
  // The tracked stream out.
  output reg                       out_valid_o,
  input  wire                      out_ready_i,
  output reg  [ANGLE_W-1:0]        out_angle_o,
  output reg  [ANGLE_W-1:0]        out_angle_comp_o,
  output reg  [ANGLE_W+FRAC_W-1:0] out_velocity_o,
  output reg  [TURN_W-1:0]         out_turns_o,
  output reg                       out_lot_o
);

`include "acore_derived.vh"

  // The block's own pipeline, as the other modules state it: LATENCY clocks from a sample taken to
  // its result on the output (no stall), CYCLES clocks a sample at full rate.
  localparam integer LATENCY = (SERIAL != 0) ? acore_track_serial_cycles(ANGLE_W, FRAC_W, LEAD_W) :
      acore_track_latency(LOOP_CLOCKS);
  localparam integer CYCLES = (SERIAL != 0) ? LATENCY : LOOP_CLOCKS;
  localparam integer P_W = ANGLE_W + FRAC_W;
  localparam integer X_W = TURN_W + P_W;
  localparam integer K_MIN = acore_track_k_min();
  localparam integer K_MAX = acore_track_k_max(FRAC_W);
  // D = COMP_LATENCY + lead / 2^LEAD_F in LEAD_F fraction bits: D_W bits hold its largest value.
  localparam integer D_W = LEAD_W + 10;
  localparam integer M_W = P_W + LEAD_F;

  acore_check #(.OK(ANGLE_W >= 8 && ANGLE_W <= 24), .VALUE(ANGLE_W),
    .MSG("illegal parameter: ANGLE_W must be 8..24"))
    ANGLE_W_must_be_8_to_24 ();
  acore_check #(.OK(FRAC_W >= 5 && FRAC_W <= 31), .VALUE(FRAC_W),
    .MSG("illegal parameter: FRAC_W must be 5..31"))
    FRAC_W_must_be_5_to_31 ();
  acore_check #(.OK(ANGLE_W + FRAC_W <= 48), .VALUE(ANGLE_W + FRAC_W),
    .MSG("illegal parameter: ANGLE_W+FRAC_W must be <= 48"))
    ANGLE_W_plus_FRAC_W_must_be_at_most_48 ();
  acore_check #(.OK(TURN_W >= 2 && TURN_W <= 32), .VALUE(TURN_W),
    .MSG("illegal parameter: TURN_W must be 2..32"))
    TURN_W_must_be_2_to_32 ();
  acore_check #(.OK(TURN_W + ANGLE_W + FRAC_W <= 64), .VALUE(TURN_W + ANGLE_W + FRAC_W),
    .MSG("illegal parameter: TURN_W+ANGLE_W+FRAC_W must be <= 64"))
    TURN_W_plus_ANGLE_W_plus_FRAC_W_must_be_at_most_64 ();
  acore_check #(.OK(LOOP_CLOCKS == 1 || LOOP_CLOCKS == 2), .VALUE(LOOP_CLOCKS),
    .MSG("illegal parameter: LOOP_CLOCKS must be 1 or 2"))
    LOOP_CLOCKS_must_be_1_or_2 ();
  acore_check #(.OK(SERIAL == 0 || SERIAL == 1), .VALUE(SERIAL),
    .MSG("illegal parameter: SERIAL must be 0 or 1"))
    SERIAL_must_be_0_or_1 ();
  acore_check #(.OK(COMP_LATENCY >= 0 && COMP_LATENCY <= 255), .VALUE(COMP_LATENCY),
    .MSG("illegal parameter: COMP_LATENCY must be 0..255"))
    COMP_LATENCY_must_be_0_to_255 ();
  acore_check #(.OK(LEAD_W >= 1 && LEAD_W <= 12), .VALUE(LEAD_W),
    .MSG("illegal parameter: LEAD_W must be 1..12"))
    LEAD_W_must_be_1_to_12 ();
  acore_check #(.OK(LEAD_F >= 0 && LEAD_F <= LEAD_W), .VALUE(LEAD_F),
    .MSG("illegal parameter: LEAD_F must be 0..LEAD_W"))
    LEAD_F_must_be_0_to_LEAD_W ();

  // ---- shared by both forms: the bandwidth code clamped, D, the rounding constant ----
  localparam [3:0] K_MIN4 = K_MIN[3:0];
  localparam [3:0] K_MAX4 = K_MAX[3:0];
  wire [3:0] k = (bw_i < K_MIN4) ? K_MIN4 : (bw_i > K_MAX4) ? K_MAX4 : bw_i;
  // D = COMP_LATENCY + lead / 2^LEAD_F with LEAD_F fraction bits.
  localparam integer LAT_D = COMP_LATENCY * (2 ** LEAD_F);
  wire [D_W-1:0] d = LAT_D[D_W-1:0] + {{(D_W - LEAD_W){1'b0}}, lead_i};
  // Half an output LSB in the loop's scale (round to nearest).
  wire [P_W-1:0] half = {{ANGLE_W{1'b0}}, 1'b1, {(FRAC_W - 1){1'b0}}};

  generate
    if (SERIAL == 0) begin : g_par
    // ---- loop ----
    // LOOP_CLOCKS = 1: the whole update in the clock that takes the sample. LOOP_CLOCKS = 2: the
    // error in that clock (registered with the prediction), the update in the next; the observer then
    // takes a sample every other clock at most (in_ready_o low in the update clock), which a folded
    // estimator (FOLD >= 2 clocks a sample) never notices, and its clock is not bounded by the
    // prediction-error-update chain of one clock.
    wire advance = !out_valid_o || out_ready_i;
    reg  busy_q;  // LOOP_CLOCKS = 2: the update clock of the sample taken last
    assign in_ready_o = !rst_i && advance && !busy_q;
    wire take = in_valid_i && in_ready_o;

    reg [X_W-1:0] x_q;      // {turns, phi}
    reg [P_W-1:0] v_q;      // velocity, signed
    reg           started_q;
    reg           a_valid_q;
    reg           lot_q;

    wire [4:0] k2 = {k, 1'b1};  // 2k + 1

    // The prediction and the error; the first sample after reset loads phi = theta (error 0; x_q
    // and v_q are 0 then).
    wire [P_W-1:0] theta_s = {in_angle_i, {FRAC_W{1'b0}}};
    wire [X_W-1:0] pred = started_q ? x_q + {{TURN_W{v_q[P_W-1]}}, v_q} : {{TURN_W{1'b0}}, theta_s};
    wire signed [P_W-1:0] e = $signed(theta_s - pred[P_W-1:0]);
    wire [P_W-1:0] thr_s = {1'b0, lot_thr_i, {FRAC_W{1'b0}}};
    wire lot_next = (e > $signed(thr_s)) || (e < -$signed(thr_s));

    // The update from a prediction and its error (this clock's, or the registered ones).
    reg [X_W-1:0] pred_q;
    reg [P_W-1:0] e_q;
    wire [X_W-1:0] u_pred = (LOOP_CLOCKS == 2) ? pred_q : pred;
    wire signed [P_W-1:0] u_e = (LOOP_CLOCKS == 2) ? $signed(e_q) : e;
    wire signed [P_W-1:0] e_p = u_e >>> k;
    wire signed [P_W-1:0] e_i = u_e >>> k2;
    wire [X_W-1:0] x_next = u_pred + {{TURN_W{e_p[P_W-1]}}, e_p};
    wire [P_W-1:0] v_next = v_q + e_i;
    wire update = (LOOP_CLOCKS == 2) ? busy_q : take;

    always @(posedge clk_i) begin
      if (rst_i) begin
        x_q <= {X_W{1'b0}};
        v_q <= {P_W{1'b0}};
        started_q <= 1'b0;
        a_valid_q <= 1'b0;
        lot_q <= 1'b0;
        busy_q <= 1'b0;
      end else if (advance) begin
        a_valid_q <= update;
        busy_q <= (LOOP_CLOCKS == 2) && take;
        if (take) begin
          started_q <= 1'b1;
          lot_q <= started_q && lot_next;
          pred_q <= pred;
          e_q <= e;
        end
        if (update) begin
          x_q <= x_next;
          v_q <= v_next;
        end
      end
    end

    // ---- product stage: v * D in G partial sums of GS terms each, registered ----
    // v * d modulo 2^M_W on shifts and adders, one term per bit of d, summed in groups of GS terms
    // (a chain of GS adders per group) so that no clock period holds the whole D_W-term sum.
    localparam integer GS = 5;
    localparam integer G = (D_W + GS - 1) / GS;
    wire [M_W-1:0] v_ext = {{LEAD_F{v_q[P_W-1]}}, v_q};
    reg  [M_W-1:0] group_sum [0:G-1];
    integer j;
    always @* begin
      for (j = 0; j < G; j = j + 1) group_sum[j] = {M_W{1'b0}};
      for (j = 0; j < D_W; j = j + 1)
        if (d[j]) group_sum[j / GS] = group_sum[j / GS] + (v_ext << j);
    end

    reg           b_valid_q;
    // {turns, phi} + half: the rounded angle and its turn count (the low FRAC_W bits rounded away).
    /* verilator lint_off UNUSEDSIGNAL */
    wire [X_W-1:0] x_round = x_q + {{TURN_W{1'b0}}, half};
    /* verilator lint_on UNUSEDSIGNAL */
    reg [TURN_W+ANGLE_W-1:0] b_round_q;
    reg [P_W-1:0] b_comp_q;    // phi + half, to which v * D is added
    reg [P_W-1:0] b_v_q;
    reg           b_lot_q;
    reg [M_W-1:0] b_group_q [0:G-1];
    integer g;
    always @(posedge clk_i) begin
      if (rst_i) begin
        b_valid_q <= 1'b0;
      end else if (advance) begin
        b_valid_q <= a_valid_q;
        if (a_valid_q) begin
          b_round_q <= x_round[X_W-1:FRAC_W];
          b_comp_q <= x_q[P_W-1:0] + half;
          b_v_q <= v_q;
          b_lot_q <= lot_q;
          for (g = 0; g < G; g = g + 1) b_group_q[g] <= group_sum[g];
        end
      end
    end

    // ---- output stage ----
    reg [M_W-1:0] prod;
    always @* begin
      prod = {M_W{1'b0}};
      for (j = 0; j < G; j = j + 1) prod = prod + b_group_q[j];
    end
    // Its low FRAC_W bits are rounded away.
    /* verilator lint_off UNUSEDSIGNAL */
    wire [P_W-1:0] comp_round = b_comp_q + prod[M_W-1:LEAD_F];
    /* verilator lint_on UNUSEDSIGNAL */

    always @(posedge clk_i) begin
      if (rst_i) begin
        out_valid_o <= 1'b0;
        out_angle_o <= {ANGLE_W{1'b0}};
        out_angle_comp_o <= {ANGLE_W{1'b0}};
        out_velocity_o <= {P_W{1'b0}};
        out_turns_o <= {TURN_W{1'b0}};
        out_lot_o <= 1'b0;
      end else if (advance) begin
        out_valid_o <= b_valid_q;
        if (b_valid_q) begin
          out_angle_o <= b_round_q[ANGLE_W-1:0];
          out_turns_o <= b_round_q[TURN_W+ANGLE_W-1:ANGLE_W];
          out_angle_comp_o <= comp_round[P_W-1:FRAC_W];
          out_velocity_o <= b_v_q;
          out_lot_o <= b_lot_q;
        end
      end
    end

    end else begin : g_ser
    // ---- time-shared: one adder, a fixed schedule of acore_track_serial_cycles() clocks ----
    // The same arithmetic as above on one TW-bit adder, sum = t + B, B one of phi (x), v, e,
    // ~theta, half or 0; its result goes to the accumulator t or to x, v, e. The turn count is a
    // counter of its own beside it: t's two bits above phi (zero before each sum that moves phi)
    // hold the carry, -1, 0 or +1 turn. Per sample, the clock count c (1 in the clock after the
    // sample is taken):
    //   1..3   t = 0, t = phi, t = phi + v: the prediction, written to phi and the turn count
    //   4      t + ~theta = ~(theta - pred): e (low P_W bits) into the shift register e_q
    //   5..6   t = 0, t = pred
    //   7 + s  e_q holds e >>> s (one shift a clock); at s = k: phi = pred + e_q (the first sample:
    //          phi = theta at s = 0, the turn count stays 0); then t = 0, t = v, and at s = 2k + 1:
    //          v = v + e_q (the first sample: v stays 0). The bits of e leave e_q at e_q[0] one a
    //          clock: loss of tracking is a bit-serial comparison of them with the threshold.
    //   H0..HL v * D + (phi + half) * 2^LEAD_F modulo 2^M_W by Horner over D's bits, most
    //          significant first: t = (t + d_j v) * 2, with t + phi and t + half inserted where
    //          LEAD_F doublings remain; bits LEAD_F + FRAC_W .. M_W-1 are the compensated angle
    //   QL-1..QL  t = phi + half: the rounded angle and turn count; every output register written
    // The shifts of e and the doublings of t are one bit a clock (no barrel shifter, no
    // multiplier); registers with an enable and a synchronous reset cost no logic on iCE40. The
    // schedule's controls are decoded a clock ahead and registered. A sample is taken when the
    // schedule is idle and the output register free (or being read).
    localparam integer TW = (M_W > P_W + 2) ? M_W : P_W + 2;
    localparam integer H0 = 7 + 2 * K_MAX + 2;        // t cleared for v * D
    localparam integer HL = H0 + D_W + 2;             // v * D's last step: the compensated angle
    localparam integer QL = LATENCY - 1;              // the rounding's last: the outputs
    localparam integer C_W = $clog2(QL + 2);
    localparam integer HI_X = D_W - 1 - LEAD_F;       // the Horner step adding phi (half next)

    reg             busy_q;
    reg [C_W-1:0]   c_q;
    reg [3:0]       k_q;       // the code, latched with the sample
    reg             started_q;
    reg             g_q;       // LOT: the comparison so far
    reg [ANGLE_W-1:0] th_q;
    reg [TW-1:0]    t_q;
    reg [P_W-1:0]   x_q;       // phi
    reg [TURN_W-1:0] turns_q;
    reg [P_W-1:0]   v_q;       // velocity, signed
    reg [P_W-1:0]   e_q;       // the error, shifted right one bit a clock from c = 7
    reg [ANGLE_W-1:0] comp_q;  // the compensated angle until the outputs are written

    assign in_ready_o = !rst_i && !busy_q && (!out_valid_o || out_ready_i);
    wire take = in_valid_i && in_ready_o;

    // ---- the schedule: the controls of count n (the next clock's c) ----
    wire [C_W-1:0] n = take ? {{(C_W - 1){1'b0}}, 1'b1} : c_q + 1'b1;
    wire n_busy = take || (busy_q && c_q != QL[C_W-1:0]);
    wire [3:0] kx = started_q ? k_q : 4'd0;  // the first sample: e unshifted
    wire [C_W-1:0] n_x = 7 + {{(C_W - 4){1'b0}}, kx};           // phi = pred + (e >>> k)
    wire [C_W-1:0] n_v = 8 + {{(C_W - 5){1'b0}}, k_q, 1'b0};    // v = v + (e >>> (2k + 1))
    wire [C_W-1:0] hi = n - (H0[C_W-1:0] + 1'b1);                // the Horner step
    wire n_horner = n > H0[C_W-1:0] && n <= HL[C_W-1:0];
    wire n_ins_x = n_horner && hi == HI_X[C_W-1:0];
    wire n_ins_h = n_horner && hi == HI_X[C_W-1:0] + 1'b1;
    // The bit of D a Horner step adds: D_W - 1 - step before the insertion, D_W + 1 - step after.
    wire [C_W-1:0] j = (hi < HI_X[C_W-1:0]) ? D_W[C_W-1:0] - 1'b1 - hi : D_W[C_W-1:0] + 1'b1 - hi;
    wire n_dj = n_horner && !n_ins_x && !n_ins_h && d[j[$clog2(D_W)-1:0]];
    wire n_dbl = n_horner && !n_ins_x && !n_ins_h && j != 0;
    localparam [C_W-1:0] N1 = 1, N2 = 2, N3 = 3, N4 = 4, N5 = 5, N6 = 6;
    localparam integer LOT_END = P_W - 2;  // e's bits 0 .. P_W-2 are compared (P_W-1 is s)
    localparam [C_W-1:0] N7 = 7, L_F = FRAC_W[C_W-1:0], L_E = LOT_END[C_W-1:0];
    wire [C_W-1:0] lot_i = n - N7;  // the bit of e at e_q[0] in clock n
    reg op_x, op_v, op_e, op_t, op_h, t_clr, dbl, wr_p, wr_x, wr_v, ld_e, sh_e, g_init, g_or, g_cmp;
    reg thr_b, wr_c, wr_o;
    always @(posedge clk_i) begin
      if (rst_i) begin
        {op_x, op_v, op_e, op_t, op_h, t_clr, dbl, wr_p, wr_x, wr_v, ld_e, sh_e} <= 12'd0;
        {g_init, g_or, g_cmp, thr_b, wr_c, wr_o} <= 6'd0;
      end else begin
        op_x <= n_busy && (n == N2 || n == N6 || n == QL[C_W-1:0] - 1'b1 || n_ins_x);
        op_v <= n_busy && (n == N3 || n == n_x + N2 || n_dj);
        op_e <= n_busy && (n == n_x || (started_q && n == n_v));
        op_t <= n_busy && n == N4;
        op_h <= n_busy && (n == QL[C_W-1:0] || n_ins_h);
        t_clr <= n_busy && (n == N1 || n == N5 || n == n_x + 1'b1 || n == H0[C_W-1:0] ||
                            n == HL[C_W-1:0]);
        dbl <= n_busy && n_dbl;
        wr_p <= n_busy && n == N3;
        wr_x <= n_busy && n == n_x;
        wr_v <= n_busy && started_q && n == n_v;
        ld_e <= n_busy && n == N4;
        sh_e <= n_busy && n > N6;
        g_init <= n_busy && n == N5;
        g_or <= n_busy && n > N6 && lot_i < L_F;
        g_cmp <= n_busy && n > N6 && lot_i >= L_F && lot_i <= L_E;
        thr_b <= lot_thr_i[lot_i[$clog2(ANGLE_W)-1:0] - FRAC_W[$clog2(ANGLE_W)-1:0]];
        wr_c <= n_busy && n == HL[C_W-1:0];
        wr_o <= n_busy && n == QL[C_W-1:0];
      end
    end

    // ---- the adder: t + B ----
    wire sx = (op_v & v_q[P_W-1]) | (op_e & e_q[P_W-1]);  // B's sign above phi
    wire [TW-1:0] b = {{(TW - P_W){sx}},
                       ({P_W{op_x}} & x_q) | ({P_W{op_v}} & v_q) | ({P_W{op_e}} & e_q) |
                       ({P_W{op_t}} & {~th_q, {FRAC_W{1'b1}}}) | ({P_W{op_h}} & half)};
    wire [TW-1:0] sum = t_q + b;
    // The turn count moved by the carry above phi (two bits: -1, 0 or +1).
    wire [1:0] dlt = sum[P_W+1:P_W];
    wire [TURN_W-1:0] turns_sum = turns_q + {{(TURN_W - 1){dlt[1]}}, dlt[0]};

    // Loss of tracking, e > thr * 2^FRAC_W or e < -thr * 2^FRAC_W, bit-serially from the least
    // significant bit of e: with s its sign and u = e (s = 0) or ~e = -e - 1 (s = 1), it is
    // {u's bits FRAC_W .. P_W-2, s | e's low bits} > {thr, 0}: g starts as s, ORs e's low FRAC_W
    // bits, then takes each higher bit's comparison (a bit that differs decides over the lower).
    wire e_s = e_q[P_W-1];
    wire u_b = e_q[0] ^ e_s;
    always @(posedge clk_i) begin
      if (g_init) g_q <= e_s;
      else if (g_or) g_q <= g_q | e_q[0];
      else if (g_cmp) g_q <= (u_b & ~thr_b) | (~(u_b ^ thr_b) & g_q);
    end

    always @(posedge clk_i) begin
      if (rst_i) begin
        busy_q <= 1'b0;
        c_q <= {C_W{1'b0}};
        started_q <= 1'b0;
        x_q <= {P_W{1'b0}};
        turns_q <= {TURN_W{1'b0}};
        v_q <= {P_W{1'b0}};
        out_valid_o <= 1'b0;
        out_angle_o <= {ANGLE_W{1'b0}};
        out_angle_comp_o <= {ANGLE_W{1'b0}};
        out_velocity_o <= {P_W{1'b0}};
        out_turns_o <= {TURN_W{1'b0}};
        out_lot_o <= 1'b0;
      end else begin
        if (out_valid_o && out_ready_i) out_valid_o <= 1'b0;
        busy_q <= n_busy;
        if (n_busy) c_q <= n;
        if (take) begin
          k_q <= k;
          th_q <= in_angle_i;
        end
        if (wr_p || wr_x) x_q <= sum[P_W-1:0];
        if (wr_p || (wr_x && started_q)) turns_q <= turns_sum;
        if (wr_v) v_q <= sum[P_W-1:0];
        if (wr_c) comp_q <= sum[M_W-1:LEAD_F+FRAC_W];
        if (wr_o) begin
          started_q <= 1'b1;
          out_valid_o <= 1'b1;
          out_angle_o <= sum[P_W-1:FRAC_W];
          out_turns_o <= turns_sum;
          out_angle_comp_o <= comp_q;
          out_velocity_o <= v_q;
          out_lot_o <= started_q && g_q;
        end
      end
    end
    // The accumulator and the error register (no reset: each sample clears or loads them first).
    // Doubling moves the bits below M_W only (v * D is taken modulo 2^M_W).
    if (TW > M_W) begin : g_t_hi
      always @(posedge clk_i)
        if (t_clr) t_q[TW-1:M_W] <= {(TW - M_W){1'b0}};
        else t_q[TW-1:M_W] <= sum[TW-1:M_W];
    end
    always @(posedge clk_i) begin
      if (t_clr) t_q[M_W-1:0] <= {M_W{1'b0}};
      else if (dbl) t_q[M_W-1:0] <= {sum[M_W-2:0], 1'b0};
      else t_q[M_W-1:0] <= sum[M_W-1:0];
      if (ld_e) e_q <= ~sum[P_W-1:0];
      else if (sh_e) e_q <= {e_q[P_W-1], e_q[P_W-1:1]};
    end
    end
  endgenerate

endmodule

`resetall
