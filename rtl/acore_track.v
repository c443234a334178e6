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
// LOOP_CLOCKS = 2). SERIAL = 1 (time-shared, below): the result acore_track_serial_cycles() clocks
// after the sample, in_ready_o low until then (a sample every that many clocks at most); bw_i is
// latched with each sample, lead_i and lot_thr_i are read during its schedule (static registers).
// SERIAL = 2 (word-serial, below) likewise with acore_track_word_cycles() clocks (16 at the board's
// widths and PROD_BITS = 1): whole words a clock, one shifter, v * D PROD_BITS bits of D a clock;
// its outputs other than out_angle_comp_o take the sample's values during the schedule, while
// out_valid_o is low (all hold while out_valid_o is high and until the next sample is taken).
// SERIAL = 3 (time-shared with coarse shifts, below) likewise with acore_track_shift_cycles()
// clocks (30 at the board's widths, FOLD 32's COMP_LATENCY and SHIFT_BITS = 3): g_ser's one adder,
// the error shifted SHIFT_BITS or one bit a clock; its outputs as the word-serial form's.
// In every form out_angle_comp_o changes only in the clock out_valid_o rises.
// rst_i is synchronous, active high.
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
  // for an estimator that delivers a sample every that many clocks or fewer often. 2: word-serial
  // (whole words a clock on an adder for phi, one for v, one shifter and a PROD_BITS-term product
  // step; acore_track_word_cycles() clocks a sample): for the folded estimator at FOLD 16. 3: as
  // 1 with the error shifted SHIFT_BITS bits a clock (acore_track_shift_cycles() clocks a
  // sample): for the folded estimator at FOLD 32.
  parameter integer SERIAL = 0,
  // SERIAL = 2: bits of D the product takes a clock (1..4; each one more adder, fewer clocks).
  parameter integer PROD_BITS = 1,
  // SERIAL = 3: bits the error shifts in a clock while that many or more remain (2..8; the board
  // takes acore_track_shift_bits(), the fewest that fit its clocks a sample).
  parameter integer SHIFT_BITS = 3
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
  localparam integer LATENCY = (SERIAL == 1) ? acore_track_serial_cycles(ANGLE_W, FRAC_W, LEAD_W) :
      (SERIAL == 2) ? acore_track_word_cycles(COMP_LATENCY, LEAD_W, LEAD_F, PROD_BITS) :
      (SERIAL == 3) ? acore_track_shift_cycles(FRAC_W, COMP_LATENCY, LEAD_W, LEAD_F, SHIFT_BITS) :
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
  acore_check #(.OK(SERIAL >= 0 && SERIAL <= 3), .VALUE(SERIAL),
    .MSG("illegal parameter: SERIAL must be 0..3"))
    SERIAL_must_be_0_to_3 ();
  acore_check #(.OK(PROD_BITS >= 1 && PROD_BITS <= 4), .VALUE(PROD_BITS),
    .MSG("illegal parameter: PROD_BITS must be 1..4"))
    PROD_BITS_must_be_1_to_4 ();
  acore_check #(.OK(SHIFT_BITS >= 2 && SHIFT_BITS <= 8), .VALUE(SHIFT_BITS),
    .MSG("illegal parameter: SHIFT_BITS must be 2..8"))
    SHIFT_BITS_must_be_2_to_8 ();
  acore_check #(.OK(COMP_LATENCY >= 0 && COMP_LATENCY <= 255), .VALUE(COMP_LATENCY),
    .MSG("illegal parameter: COMP_LATENCY must be 0..255"))
    COMP_LATENCY_must_be_0_to_255 ();
  acore_check #(.OK(SERIAL != 3 || COMP_LATENCY >= 1), .VALUE(COMP_LATENCY),
    .MSG("illegal parameter: COMP_LATENCY must be >= 1 with SERIAL = 3"))
    COMP_LATENCY_must_be_at_least_1_with_SERIAL_3 ();
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
  // D = COMP_LATENCY + lead / 2^LEAD_F with LEAD_F fraction bits; SERIAL = 3 takes D - 1 (its
  // phi register carries one v: g_shf).
  localparam integer LAT_D = (COMP_LATENCY - ((SERIAL == 3) ? 1 : 0)) * (2 ** LEAD_F);
  wire [D_W-1:0] d = LAT_D[D_W-1:0] + {{(D_W - LEAD_W){1'b0}}, lead_i};
  // Half an output LSB in the loop's scale (round to nearest; SERIAL = 3 takes its low FRAC_W bits).
  /* verilator lint_off UNUSEDSIGNAL */
  wire [P_W-1:0] half = {{ANGLE_W{1'b0}}, 1'b1, {(FRAC_W - 1){1'b0}}};
  /* verilator lint_on UNUSEDSIGNAL */

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

    end else if (SERIAL == 2) begin : g_word
    // ---- word-serial: whole words a clock, a fixed schedule of acore_track_word_cycles() clocks ----
    // The same arithmetic as the one-sample-a-clock form, spread so that each resource serves
    // several steps: an adder on phi (x_q + B with B one of v, ~theta, the shifted error, half),
    // one on v, one arithmetic right shifter of the error (amounts up to K_MAX + 1, the
    // error shifted in place twice: by k, then by k + 1 more, so 2k + 1 in all), and the product
    // v * D, MSB first, PROD_BITS bits of D a clock (m = m * 2^PROD_BITS + digit * v modulo 2^M_W,
    // the model's product modulo 2^(P_W + LEAD_F) exactly). D's bits above DE_W are zero
    // (COMP_LATENCY is a parameter, lead_i at most 2^LEAD_W - 1), so the product takes
    // ceil(DE_W / PROD_BITS) clocks. Per sample, after the clock taking it (m = 0 there):
    //   c1  phi = phi + v (the prediction; with its turn carry)
    //   c2  e = theta - phi (on phi's adder)
    //   c3  loss of tracking from e (its upper ANGLE_W bits against the threshold, the rest
    //       nonzero or not) to its output; e = e >>> k
    //   c4  phi = phi + e; e = e >>> (k + 1)
    //   c5  v = v + e; the rounded angle and turn count (phi + half) to the outputs
    //   c6.. the product steps; then the compensated angle phi + half + (v * D) / 2^LEAD_F and the
    //       output's valid. The first sample after reset: phi and v are 0, k is taken as 0, so
    //       phi = theta; the turn count and v stay.
    localparam integer DE_W = acore_track_word_d_w(COMP_LATENCY, LEAD_W, LEAD_F);
    localparam integer NP = (DE_W + PROD_BITS - 1) / PROD_BITS;  // product steps
    localparam integer SH_W = $clog2(K_MAX + 2);                 // shift amounts 0 .. K_MAX + 1
    localparam integer J_W = (NP > 1) ? $clog2(NP) : 1;
    localparam integer J_LAST_I = NP - 1;
    localparam [J_W-1:0] J_LAST = J_LAST_I[J_W-1:0];

    reg             busy_q;
    reg             c1, c2, c3, c4, c5, pp, fin;  // the schedule's phases (one hot)
    reg [J_W-1:0]   j_q;      // the product's digit (NP - 1 down to 0)
    reg [3:0]       k_q;
    reg             started_q;
    reg [ANGLE_W-1:0] th_q;
    reg [X_W-1:0]   x_q;      // {turns, phi}
    // v is the velocity output register itself: a sample's v changes at its c5, and a sample is
    // taken only once the output before it has been read.
    wire [P_W-1:0]  v_q = out_velocity_o;
    reg [P_W-1:0]   e_q;      // the error, shifted in place
    reg [P_W-1:0]   xr_q;     // phi + half
    reg [M_W-1:0]   m_q;      // v * D so far

    assign in_ready_o = !rst_i && !busy_q && (!out_valid_o || out_ready_i);
    wire take = in_valid_i && in_ready_o;

    // phi's adder: B = v (c1), ~theta (c2: e = theta - phi = ~(phi + ~theta)), the shifted error
    // (c4), half (c5); all sign-extended.
    wire [P_W-1:0] bx = ({P_W{c1}} & v_q) | ({P_W{c2}} & {~th_q, {FRAC_W{1'b1}}}) |
                        ({P_W{c4}} & e_q) | ({P_W{c5}} & half);
    wire [X_W-1:0] x_sum = x_q + {{TURN_W{bx[P_W-1]}}, bx};
    wire [P_W-1:0] v_sum = v_q + e_q;
    // The shifter: by k (by 0 for the first sample) at c3, by k + 1 at c4.
    /* verilator lint_off UNUSEDSIGNAL */
    wire [4:0] sh5 = c3 ? (started_q ? {1'b0, k_q} : 5'd0) : {1'b0, k_q} + 5'd1;
    /* verilator lint_on UNUSEDSIGNAL */
    wire [SH_W-1:0] sh_a = sh5[SH_W-1:0];
    wire [P_W-1:0] e_sh = $signed(e_q) >>> sh_a;
    // Loss of tracking: e > thr * 2^FRAC_W or e < -thr * 2^FRAC_W, on e's upper ANGLE_W bits
    // (e > thr * 2^FRAC_W: above thr, or equal with low bits not all zero, which is {e's upper
    // bits, low bits nonzero} > {thr, 0}; e < -thr * 2^FRAC_W: its upper bits below -thr).
    wire signed [ANGLE_W:0] e_gt = {e_q[P_W-1:FRAC_W], |e_q[FRAC_W-1:0]};
    wire signed [ANGLE_W:0] thr_gt = {1'b0, lot_thr_i, 1'b0};
    wire signed [ANGLE_W-1:0] e_hi = e_q[P_W-1:FRAC_W];
    wire signed [ANGLE_W-1:0] thr_hi = {1'b0, lot_thr_i};
    wire lot_cmp = (e_gt > thr_gt) || (e_hi < -thr_hi);
    // The product step: D's digit (MSB first) times v, added to m shifted by a digit.
    // (d's bits from DE_W up are zero; padded so that the last digit may reach above D_W.)
    // (the shift by j * PROD_BITS as a select over the NP digits: constant shifts, no product)
    wire [D_W+3:0] d_pad = {4'b0000, d};
    /* verilator lint_off UNUSEDSIGNAL */
    reg  [D_W+3:0] d_sh;
    /* verilator lint_on UNUSEDSIGNAL */
    integer jd;
    always @* begin
      d_sh = d_pad;
      for (jd = 0; jd < NP; jd = jd + 1) if (j_q == jd[J_W-1:0]) d_sh = d_pad >> (jd * PROD_BITS);
    end
    wire [PROD_BITS-1:0] dig = d_sh[PROD_BITS-1:0];
    wire [M_W-1:0] v_ext = {{LEAD_F{v_q[P_W-1]}}, v_q};
    reg  [M_W-1:0] m_n;
    integer i;
    always @* begin
      m_n = m_q << PROD_BITS;
      for (i = 0; i < PROD_BITS; i = i + 1) if (dig[i]) m_n = m_n + (v_ext << i);
    end
    /* verilator lint_off UNUSEDSIGNAL */
    wire [P_W-1:0] comp = xr_q + m_q[M_W-1:LEAD_F];  // its low FRAC_W bits are rounded away
    /* verilator lint_on UNUSEDSIGNAL */

    always @(posedge clk_i) begin
      if (rst_i) begin
        busy_q <= 1'b0;
        {c1, c2, c3, c4, c5, pp, fin} <= 7'd0;
        started_q <= 1'b0;
        x_q <= {X_W{1'b0}};
        out_valid_o <= 1'b0;
        out_angle_o <= {ANGLE_W{1'b0}};
        out_angle_comp_o <= {ANGLE_W{1'b0}};
        out_velocity_o <= {P_W{1'b0}};
        out_turns_o <= {TURN_W{1'b0}};
        out_lot_o <= 1'b0;
      end else begin
        if (out_valid_o && out_ready_i) out_valid_o <= 1'b0;
        if (take) busy_q <= 1'b1;
        if (fin) busy_q <= 1'b0;
        c1 <= take;
        c2 <= c1;
        c3 <= c2;
        c4 <= c3;
        c5 <= c4;
        pp <= c5 || (pp && j_q != {J_W{1'b0}});
        fin <= pp && j_q == {J_W{1'b0}};
        if (c1 || c4) begin
          x_q[P_W-1:0] <= x_sum[P_W-1:0];
          if (started_q) x_q[X_W-1:P_W] <= x_sum[X_W-1:P_W];
        end
        if (c5 && started_q) out_velocity_o <= v_sum;
        if (c3) out_lot_o <= started_q && lot_cmp;
        if (c5) begin
          out_angle_o <= x_sum[P_W-1:FRAC_W];
          out_turns_o <= x_sum[X_W-1:P_W];
        end
        if (fin) begin
          started_q <= 1'b1;
          out_valid_o <= 1'b1;
          out_angle_comp_o <= comp[P_W-1:FRAC_W];
        end
      end
    end
    // Data registers without reset (each sample sets them before use).
    always @(posedge clk_i) begin
      if (take) begin
        k_q <= k;
        th_q <= in_angle_i;
      end
      if (c2) e_q <= ~x_sum[P_W-1:0];
      if (c3 || c4) e_q <= e_sh;
      if (c5) xr_q <= x_sum[P_W-1:0];
      j_q <= c5 ? J_LAST : j_q - 1'b1;
      if (take) m_q <= {M_W{1'b0}};
      else if (pp) m_q <= m_n;
    end

    end else if (SERIAL == 3) begin : g_shf
    // ---- time-shared, coarse shifts: one adder, acore_track_shift_cycles() clocks a sample ----
    // The time-shared form's adder and registers (below, g_ser: sum = t + B with B one of phi
    // (x_q), v, ~theta, half or 0; one register t for every sum; the turn count moved by the two
    // bits of sum above phi), with the error shifted SHIFT_BITS bits a clock while SHIFT_BITS or
    // more remain, else one bit (a two-way choice on t's input, not a barrel shifter), the loss of
    // tracking from one more sum on the adder, and the product over D's DE_W nonzero bits only:
    // 30 clocks a sample at the board's widths and FOLD 32's COMP_LATENCY with SHIFT_BITS = 3.
    // Per sample, after the clock taking it (t is 0 then: cleared after each sample and by reset):
    // Its phi register holds X = phi + v + half, with the turn count of that sum: the prediction
    // and half an output LSB (reset: half, phi = v = 0), so that the prediction needs no sum of its
    // own and the rounded angle is X itself.
    //   C1      t = ~theta * 2^FRAC_W - half (t's input as the complement of theta, not B's)
    //   C2      t = ~(t + X) = theta * 2^FRAC_W - pred: the error e (all of it, not yet wrapped to
    //           P_W bits: the loop's first shift does that, and the first sample's e >= 0 needs none)
    //   C3      idle
    //   C4      sum = e +- thr * 2^FRAC_W: the loss of tracking to its output (t stays)
    //   loop    LOOP_L clocks: rem = k (0 for the first sample) shifts of e, then a pause
    //           X = t + X = phi + half (its bits above FRAC_W and its turn count: the rounded
    //           angle and turn count, to the outputs); rem = k + 1 more shifts, then a pause
    //           v = t + v (not the first sample); idle to the loop's end, whose last clock clears t
    //   R2, R3  t = v, X = t + X = phi + v + half: the next sample's prediction; t = 0
    //   product v * (D - 1) + X * 2^LEAD_F least significant bit of D - 1 first, as g_ser's (X
    //           carries the one v and the half): phi + half + v * D
    //   fin     the compensated angle and the output's valid; t = 0
    // v is the velocity output register itself and the outputs other than out_angle_comp_o take
    // the sample's values during the schedule (as the word-serial form's): a sample is taken only
    // once the output before it has been read.
    localparam integer SB = SHIFT_BITS;
    localparam integer DE_W = acore_track_word_d_w(COMP_LATENCY, LEAD_W, LEAD_F);
    localparam integer LOOP_L = acore_track_shift_loop(FRAC_W, SB);
    localparam integer TW = (M_W > P_W + 2) ? M_W : P_W + 2;
    localparam integer S_MAX = (LOOP_L > DE_W + 2) ? LOOP_L : DE_W + 2;
    localparam integer S_W = $clog2(S_MAX + 1);
    localparam integer LOOP_END = LOOP_L - 1;          // the loop's last clock
    localparam integer PROD_END = DE_W + 1;            // the product's last step
    localparam [S_W-1:0] S_LOOP_END = LOOP_END[S_W-1:0], S_PEND = PROD_END[S_W-1:0];
    localparam [S_W-1:0] S_LF = LEAD_F[S_W-1:0], S_LH = S_LF + 1'b1;
    // Shifts left: 0 .. K_MAX + 1, and SB itself (4 bits at the board's widths, where the code is
    // at most 12).
    localparam integer R_K = $clog2(K_MAX + 2);
    localparam integer R_S = $clog2(SB + 1);
    localparam integer R_W = (R_K > R_S) ? R_K : R_S;
    localparam [R_W-1:0] R_SB = SB[R_W-1:0];
    // The bits of D - 1 (d here: COMP_LATENCY >= 1) in the order the product takes them, two
    // zeros where X is added and the step after it (a step without an addition).
    localparam integer LO_M = (1 << LEAD_F) - 1;
    localparam integer HI_M = ((1 << (DE_W + 2)) - 1) & ~((1 << (LEAD_F + 2)) - 1);
    // (D's bits from DE_W up are zero)
    /* verilator lint_off UNUSEDSIGNAL */
    wire [D_W-1:0] d_s = d;
    /* verilator lint_on UNUSEDSIGNAL */
    wire [DE_W-1:0] de = d_s[DE_W-1:0];
    wire [DE_W+1:0] w = ({2'b00, de} & LO_M[DE_W+1:0]) | ({de, 2'b00} & HI_M[DE_W+1:0]);
    wire [(1 << S_W)-1:0] w_pad = {{((1 << S_W) - DE_W - 2){1'b0}}, w};

    reg             busy_q;
    reg             c1, c2, c3, c4, pl, r2, r3, ph, fin;  // the schedule's phases (one hot)
    reg [S_W-1:0]   s_q;       // the loop's clocks; the product's steps
    reg [R_W-1:0]   rem_q;     // shifts left before the next update
    reg             xd_q, vd_q;  // the loop's phi and v updates done
    reg [3:0]       k_q;       // the code, latched with the sample
    reg             started_q;
    reg [ANGLE_W-1:0] th_q;    // theta from the clock taking it to C1's end, then 0
    reg [TW-1:0]    t_q;
    reg [DE_W-1:0]  tf_q;      // the product's bits below t
    reg [P_W-1:0]   x_q;       // X = phi + v + half (between samples and until the loop's pause)
    reg [TURN_W-1:0] turns_q;
    wire [P_W-1:0]  v_q = out_velocity_o;

    assign in_ready_o = !rst_i && !busy_q && (!out_valid_o || out_ready_i);
    wire take = in_valid_i && in_ready_o;

    // Each clock's operations registered from the phases' and counters' next values (the adder's
    // operand select and t's input select one LUT level from flops): at_x X = X + e >>> k (phi +
    // half), at_v v = v + e >>> (2k + 1), shb / sh1 the loop's shifts by SB / 1 bit, ins_x the
    // product's addition of X, p_sh its other steps; op_lp / op_ln the threshold's complement or
    // itself on B (e >= 0 or e < 0).
    reg eq_lend, eq_pend;
    reg at_x, at_v, shb, sh1, p_sh, op_x, op_v, op_lp, op_ln;
    reg s_x, s_v;
    // t's next value, registered likewise: written (t_we) or cleared (t_clr), with tm the choice
    // of sum, ~(sum ^ th_x) (C1: theta's complement, sum being 0; C2: ~sum, th_q being 0), sum
    // shifted one bit, t shifted SB bits.
    reg t_we, t_clr;
    reg [1:0] tm;

    // ---- the adder: t + B ----
    wire sx = op_v & v_q[P_W-1];  // B's sign above phi
    // Loss of tracking, e > thr * 2^FRAC_W or e < -thr * 2^FRAC_W, on the adder in C4 (t = e, not
    // written): with sg e's sign, e + ~(thr * 2^FRAC_W) >= 0 (sg = 0) or e + thr * 2^FRAC_W < 0
    // (sg = 1); neither sum leaves P_W signed bits (0 <= thr * 2^FRAC_W < 2^(P_W-1)), so it is
    // the sum's bit P_W-1 against sg.
    wire sg = t_q[P_W-1];
    // B's low FRAC_W bits are X's, v's, all ones (~(thr * 2^FRAC_W)'s low bits) or 0: a registered
    // two-bit code (s_x: X or the ones, s_v: v or the ones; the selects are exclusive) makes every
    // such bit of B one LUT of the code and X's and v's bit, one LUT level from flops.
    wire [FRAC_W-1:0] b_lo = s_v ? (s_x ? {FRAC_W{1'b1}} : v_q[FRAC_W-1:0]) :
                             (s_x ? x_q[FRAC_W-1:0] : {FRAC_W{1'b0}});
    wire [ANGLE_W-1:0] thr = {1'b0, lot_thr_i};
    wire [ANGLE_W-1:0] b_hi = ({ANGLE_W{op_x}} & x_q[P_W-1:FRAC_W]) |
                              ({ANGLE_W{op_v}} & v_q[P_W-1:FRAC_W]) | ({ANGLE_W{op_lp}} & ~thr) |
                              ({ANGLE_W{op_ln}} & thr);
    wire [TW-1:0] b = {{(TW - P_W){sx}}, b_hi, b_lo};
    wire [TW-1:0] sum = t_q + b;
    // The turn count moved by the carry above phi (two bits: -1, 0 or +1).
    wire [1:0] dlt = sum[P_W+1:P_W];
    wire [TURN_W-1:0] turns_sum = turns_q + {{(TURN_W - 1){dlt[1]}}, dlt[0]};
    // sum shifted right one bit: in the loop e's sign (bit P_W-1) fills the bits above it; t
    // shifted right SB bits (B is 0 in the loop's shifts), e's sign filling.
    wire [TW-1:0] sum_sh = {pl ? {(TW - P_W + 1){sum[P_W-1]}} : {sum[TW-1], sum[TW-1:P_W]},
                            sum[P_W-1:1]};
    wire [TW-1:0] t_shb = {{(TW - P_W + SB){t_q[P_W-1]}}, t_q[P_W-1:SB]};
    // t's input in two LUTs a bit, theta's complement with no LUT of its own: the first picks the
    // shift (tm[1]) or gives tm[0], which the second takes as its choice of sum or ~(sum ^ th_x).
    // th_x: theta in C1 with half's bit (t = ~theta * 2^FRAC_W - half, all ones above P_W), 0 after.
    wire [TW-1:0] th_x = {{(TW - P_W){1'b0}}, th_q, c1, {(FRAC_W - 1){1'b0}}};
    wire [TW-1:0] t_l1 = tm[1] ? (tm[0] ? t_shb : sum_sh) : {TW{tm[0]}};
    wire [TW-1:0] t_n = tm[1] ? t_l1 : ((t_l1 & ~(sum ^ th_x)) | (~t_l1 & sum));

    wire lot_cmp = ~(sum[P_W-1] ^ sg);
    /* verilator lint_off UNUSEDSIGNAL */
    wire [TW+DE_W-1:0] t_all = {t_q, tf_q};  // the compensated angle is its middle
    wire [DE_W:0] tf_in = {sum[0], tf_q};
    /* verilator lint_on UNUSEDSIGNAL */

    always @(posedge clk_i) begin
      if (rst_i) begin
        busy_q <= 1'b0;
        {c1, c2, c3, c4, pl, r2, r3, ph, fin} <= 9'd0;
        started_q <= 1'b0;
        t_q <= {TW{1'b0}};
        x_q <= half;
        turns_q <= {TURN_W{1'b0}};
        out_valid_o <= 1'b0;
        out_angle_o <= {ANGLE_W{1'b0}};
        out_angle_comp_o <= {ANGLE_W{1'b0}};
        out_velocity_o <= {P_W{1'b0}};
        out_turns_o <= {TURN_W{1'b0}};
        out_lot_o <= 1'b0;
      end else begin
        if (out_valid_o && out_ready_i) out_valid_o <= 1'b0;
        if (take) busy_q <= 1'b1;
        if (fin) busy_q <= 1'b0;
        c1 <= take;
        c2 <= c1;
        c3 <= c2;
        c4 <= c3;
        pl <= c4 || (pl && !eq_lend);
        r2 <= pl && eq_lend;
        r3 <= r2;
        ph <= r3 || (ph && !eq_pend);
        fin <= ph && eq_pend;
        if (take) k_q <= k;
        if (c1) th_q <= {ANGLE_W{1'b0}};
        else if (take) th_q <= in_angle_i;
        if (at_x || r3) begin
          x_q <= sum[P_W-1:0];
          turns_q <= turns_sum;
        end
        if (at_x) begin
          out_angle_o <= sum[P_W-1:FRAC_W];
          out_turns_o <= turns_sum;
        end
        if (at_v && started_q) out_velocity_o <= sum[P_W-1:0];
        if (c4) out_lot_o <= started_q && lot_cmp;
        if (t_clr) t_q <= {TW{1'b0}};
        else if (t_we) t_q <= t_n;
        if (fin) begin
          started_q <= 1'b1;
          out_valid_o <= 1'b1;
          out_angle_comp_o <= t_all[LEAD_F+P_W-1:LEAD_F+FRAC_W];
        end
      end
    end
    // The schedule's counters and next operations (no reset: each sample sets them first).
    wire [S_W-1:0] s_n = (c4 || r3) ? {S_W{1'b0}} : (pl || ph) ? s_q + 1'b1 : s_q;
    // The code in R_W bits (k_q <= K_MAX < 2^R_W: the bits dropped are zero).
    /* verilator lint_off UNUSEDSIGNAL */
    wire [8:0] k9 = {5'b00000, k_q};
    /* verilator lint_on UNUSEDSIGNAL */
    wire [R_W-1:0] k_r = k9[R_W-1:0];
    wire [R_W-1:0] kx = started_q ? k_r : {R_W{1'b0}};
    wire [R_W-1:0] rem_n = c4 ? kx : at_x ? k_r + 1'b1 :
                           shb ? rem_q - R_SB : sh1 ? rem_q - 1'b1 : rem_q;
    wire pl_n = c4 || (pl && !eq_lend);
    wire ph_n = r3 || (ph && !eq_pend);
    wire xd_n = !c4 && (xd_q || at_x);
    wire vd_n = !c4 && (vd_q || at_v);
    wire z_n = rem_n == {R_W{1'b0}};
    wire big_n = rem_n >= R_SB;
    wire at_x_n = pl_n && !xd_n && z_n;
    wire at_v_n = pl_n && xd_n && !vd_n && z_n;
    wire shb_n = pl_n && !vd_n && big_n;
    wire sh1_n = pl_n && !vd_n && !z_n && !big_n;
    wire ins_x_n = ph_n && s_n == S_LF;
    wire ins_h_n = ph_n && s_n == S_LH;  // the step after it: t holds
    wire p_sh_n = ph_n && !ins_x_n && !ins_h_n;
    wire op_x_n = c1 || at_x_n || ins_x_n || r2;
    wire op_v_n = (pl && eq_lend) || at_v_n || (p_sh_n && w_pad[s_n]);
    always @(posedge clk_i) begin
      if (rst_i) begin
        {at_x, at_v, shb, sh1, p_sh, op_x, op_v, op_lp, op_ln, s_x, s_v} <= 11'd0;
        {t_we, t_clr, tm} <= 4'd0;
      end else begin
        t_clr <= (ph && eq_pend) || r2 || (pl_n && s_n == S_LOOP_END);
        t_we <= take || c1 || (pl && eq_lend) || shb_n || sh1_n || p_sh_n || ins_x_n;
        tm <= {shb_n || sh1_n || p_sh_n, take || c1 || shb_n};
        at_x <= at_x_n;
        at_v <= at_v_n;
        shb <= shb_n;
        sh1 <= sh1_n;
        p_sh <= p_sh_n;
        op_x <= op_x_n;
        op_v <= op_v_n;
        // C4: e + ~(thr * 2^FRAC_W) when e >= 0, e + thr * 2^FRAC_W when e < 0 (t = e from C3).
        op_lp <= c3 && !sg;
        op_ln <= c3 && sg;
        // The ones: ~(thr * 2^FRAC_W)'s in C4 when e >= 0.
        s_x <= op_x_n || (c3 && !sg);
        s_v <= op_v_n || (c3 && !sg);
      end
    end
    always @(posedge clk_i) begin
      s_q <= s_n;
      rem_q <= rem_n;
      eq_lend <= s_n == S_LOOP_END;
      eq_pend <= s_n == S_PEND;
      xd_q <= xd_n;
      vd_q <= vd_n;
      if (p_sh) tf_q <= tf_in[DE_W:1];
    end

    end else begin : g_ser
    // ---- time-shared: one adder, a fixed schedule of acore_track_serial_cycles() clocks ----
    // The same arithmetic as above on one TW-bit adder, sum = t + B with B one of phi (x_q), v,
    // ~theta, half or 0, and one register t that holds the sums and shifts right one bit a clock.
    // The turn count is a counter beside it: the two bits of sum above phi (zero in t before each
    // sum that moves phi) are its carry, -1, 0 or +1 turn. Per sample, after the clock taking it:
    //   S1..S3  t = 0, t = phi, t = phi + v: the prediction, written to phi and the turn count
    //   S4      t = ~(t + ~theta) = theta - pred: the error e
    //   loop    t shifts right (arithmetic) one bit a clock, P_W - 1 shifts: after s shifts it holds
    //           e >>> s. At s = k a pause: phi = t + phi (the first sample: phi = theta at s = 0,
    //           the turn count stays 0); at s = 2k + 1 a pause: v = t + v (not the first sample).
    //           The bits of e leave t at t[0], one a shift: loss of tracking is their bit-serial
    //           comparison with the threshold, least significant first.
    //   product t = 0, then v * D + (phi + half) * 2^LEAD_F least significant bit of D first:
    //           t = (t + d_j v) >>> 1 (the bit leaving t enters tf_q), with t + phi and t + half
    //           inserted after LEAD_F steps; {t, tf_q} is then the whole sum, whose bits
    //           LEAD_F + FRAC_W .. M_W - 1 are the compensated angle
    //   R1..R3  t = 0, t = phi, t = phi + half: the rounded angle and turn count; every output
    //           register written
    // No barrel shifter, no multiplier, two operands on the adder's B input (phi, v) beside two
    // constants; registers with an enable and a synchronous reset cost no logic on iCE40. A
    // sample is taken when the schedule is idle and the output register free (or being read).
    localparam integer TW = (M_W > P_W + 2) ? M_W : P_W + 2;
    localparam integer S_W = $clog2(P_W + D_W + 2);
    localparam integer LOOP_END = P_W - 2;            // the last shift of the loop phase
    localparam integer PROD_END = D_W + 1;            // the product's last step
    localparam [S_W-1:0] S_LOOP_END = LOOP_END[S_W-1:0], S_PEND = PROD_END[S_W-1:0];
    localparam [S_W-1:0] S_F = FRAC_W[S_W-1:0];       // e's first bit above the threshold's LSB
    localparam [S_W-1:0] S_LF = LEAD_F[S_W-1:0], S_LH = S_LF + 1'b1;
    // D's bits in the order the product takes them, two zeros where phi and half are added.
    localparam integer LO_M = (1 << LEAD_F) - 1;
    localparam integer HI_M = ((1 << (D_W + 2)) - 1) & ~((1 << (LEAD_F + 2)) - 1);
    wire [D_W+1:0] w = ({2'b00, d} & LO_M[D_W+1:0]) | ({d, 2'b00} & HI_M[D_W+1:0]);
    wire [(1 << S_W)-1:0] w_pad = {{((1 << S_W) - D_W - 2){1'b0}}, w};

    reg             busy_q;
    reg             p1, p2, p3, p4, pl, pc, ph, r1, r2, r3;  // the schedule's phases (one hot)
    reg [S_W-1:0]   s_q;       // shifts in the loop; steps in the product
    reg             xd_q, vd_q;  // the loop's phi and v updates done
    reg [3:0]       k_q;       // the code, latched with the sample
    reg             started_q;
    reg             g_q;       // LOT: the comparison so far
    reg [ANGLE_W-1:0] th_q;
    reg [TW-1:0]    t_q;
    reg [D_W-1:0]   tf_q;      // the product's bits below t
    reg [P_W-1:0]   x_q;       // phi
    reg [TURN_W-1:0] turns_q;
    reg [P_W-1:0]   v_q;       // velocity, signed
    reg [ANGLE_W-1:0] comp_q;  // the compensated angle until the outputs are written

    assign in_ready_o = !rst_i && !busy_q && (!out_valid_o || out_ready_i);
    wire take = in_valid_i && in_ready_o;

    // ---- the phases' operations ----
    wire [S_W-1:0] kx = started_q ? {{(S_W - 4){1'b0}}, k_q} : {S_W{1'b0}};
    // Each clock's operations are registered from the phases' and the counter's next values (the
    // adder's operand select is then one LUT level from flops): at_x phi = pred + e >>> k, at_v
    // v = v + e >>> (2k + 1), ins_x_n / ins_h_n the product's additions of phi and half, p_sh its
    // other steps; l_sh the loop's shifts.
    reg eq_lend, eq_pend, lt_f, eq_0, thr_b;
    reg at_x, at_v, p_sh, op_x, op_v, op_t, op_h;
    wire l_sh = pl && !at_x && !at_v;

    // ---- the adder: t + B ----
    wire sx = op_v & v_q[P_W-1];  // B's sign above phi
    wire [TW-1:0] b = {{(TW - P_W){sx}},
                       ({P_W{op_x}} & x_q) | ({P_W{op_v}} & v_q) |
                       ({P_W{op_t}} & {~th_q, {FRAC_W{1'b1}}}) | ({P_W{op_h}} & half)};
    wire [TW-1:0] sum = t_q + b;
    // The turn count moved by the carry above phi (two bits: -1, 0 or +1).
    wire [1:0] dlt = sum[P_W+1:P_W];
    wire [TURN_W-1:0] turns_sum = turns_q + {{(TURN_W - 1){dlt[1]}}, dlt[0]};
    // sum shifted right: in the loop e's sign (bit P_W-1) fills the bits above it.
    wire [TW-1:0] sum_sh = {pl ? {(TW - P_W + 1){sum[P_W-1]}} : {sum[TW-1], sum[TW-1:P_W]},
                            sum[P_W-1:1]};

    // Loss of tracking, e > thr * 2^FRAC_W or e < -thr * 2^FRAC_W, bit-serially from the least
    // significant bit of e (t[0] at shift s is e's bit s): with sg its sign and u = e (sg = 0) or
    // ~e = -e - 1 (sg = 1), it is {u's bits FRAC_W .. P_W-2, sg | e's low bits} > {thr, 0}: g
    // starts as sg, ORs e's low FRAC_W bits, then takes each higher bit's comparison (a bit that
    // differs decides over the lower ones).
    wire sg = t_q[P_W-1];
    wire u_b = t_q[0] ^ sg;
    always @(posedge clk_i)
      if (l_sh) begin
        if (lt_f) g_q <= (eq_0 ? sg : g_q) | t_q[0];
        else g_q <= (u_b & ~thr_b) | (~(u_b ^ thr_b) & g_q);
      end

    always @(posedge clk_i) begin
      if (rst_i) begin
        busy_q <= 1'b0;
        {p1, p2, p3, p4, pl, pc, ph, r1, r2, r3} <= 10'd0;
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
        if (take) busy_q <= 1'b1;
        if (r3) busy_q <= 1'b0;
        p1 <= take;
        p2 <= p1;
        p3 <= p2;
        p4 <= p3;
        pl <= p4 || (pl && !(l_sh && eq_lend));
        pc <= l_sh && eq_lend;
        ph <= pc || (ph && !eq_pend);
        r1 <= ph && eq_pend;
        r2 <= r1;
        r3 <= r2;
        if (take) begin
          k_q <= k;
          th_q <= in_angle_i;
        end
        if (p3 || at_x) x_q <= sum[P_W-1:0];
        if (p3 || (at_x && started_q)) turns_q <= turns_sum;
        if (at_v && started_q) v_q <= sum[P_W-1:0];
        if (r3) begin
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
    /* verilator lint_off UNUSEDSIGNAL */
    wire [TW+D_W-1:0] t_all = {t_q, tf_q};  // the compensated angle is its middle
    /* verilator lint_on UNUSEDSIGNAL */
    // The schedule's counter, t and the product's low bits (no reset: each sample sets them first).
    wire [S_W-1:0] s_n = (p4 || pc) ? {S_W{1'b0}} : (l_sh || ph) ? s_q + 1'b1 : s_q;
    wire pl_n = p4 || (pl && !(l_sh && eq_lend));
    wire ph_n = pc || (ph && !eq_pend);
    wire xd_n = !p4 && (xd_q || at_x);
    wire vd_n = !p4 && (vd_q || at_v);
    wire at_x_n = pl_n && !xd_n && s_n == kx;
    wire at_v_n = pl_n && xd_n && !vd_n && s_n == {{(S_W - 5){1'b0}}, k_q, 1'b1};
    wire ins_x_n = ph_n && s_n == S_LF;
    wire ins_h_n = ph_n && s_n == S_LH;
    wire p_sh_n = ph_n && !ins_x_n && !ins_h_n;
    always @(posedge clk_i) begin
      if (rst_i) begin
        {at_x, at_v, p_sh, op_x, op_v, op_t, op_h} <= 7'd0;
      end else begin
        at_x <= at_x_n;
        at_v <= at_v_n;
        p_sh <= p_sh_n;
        op_x <= p1 || at_x_n || ins_x_n || r1;
        op_v <= p2 || at_v_n || (p_sh_n && w_pad[s_n]);
        op_t <= p3;
        op_h <= ins_h_n || r2;
      end
    end
    /* verilator lint_off UNUSEDSIGNAL */
    wire [S_W-1:0] thr_i = s_n - S_F;  // its low bits index the threshold
    /* verilator lint_on UNUSEDSIGNAL */
    always @(posedge clk_i) begin
      s_q <= s_n;
      eq_lend <= s_n == S_LOOP_END;
      eq_pend <= s_n == S_PEND;
      lt_f <= s_n < S_F;
      eq_0 <= s_n == {S_W{1'b0}};
      thr_b <= lot_thr_i[thr_i[$clog2(ANGLE_W)-1:0]];
      xd_q <= xd_n;
      vd_q <= vd_n;
      if (p1 || pc || r1) t_q <= {TW{1'b0}};
      else if (l_sh || p_sh) t_q <= sum_sh;
      else if (p4) t_q <= ~sum;
      else if (!at_x && !at_v) t_q <= sum;
      if (p_sh) tf_q <= {sum[0], tf_q[D_W-1:1]};
      if (r1) comp_q <= t_all[LEAD_F+P_W-1:LEAD_F+FRAC_W];
    end
    end
  endgenerate

endmodule

`resetall
