// SPDX-License-Identifier: MIT
// acore_board_formal: the formal harness of the board's stream path (rtl/acore_board.v: the
// estimator's angle stream into the tracking observer, whose outputs feed ABZ, UVW and the SPI
// port), driven by tb/formal/run.py. It wraps acore_board with the registry line's parameters and
// drives every input freely (reset high in the first clock; APB, SPI and the sensor's inputs free).
//
// Assume-guarantee: the estimator in its shell (the board's u_shell) is cut by the driver (Yosys
// `cutpoint`: its outputs are free values each clock) and constrained here by what the shell's own
// proof shows of its output stream (acore_stream_formal.sv, SHELL = 1): out_valid low the clock
// after a reset, and out_valid and the angle held while the observer does not take them. So the
// proof covers every estimator, folded or serial, and any angle. The observer's arithmetic (every
// adder, shifter and comparison of 16 bits or more in acore_track: the loop, the product, the
// rounding, the loss-of-tracking test) is cut as well: its data registers and output registers
// stay, and take free values when they load. The observer's control (valid bits, update clock,
// the time-shared schedule and its counter) is kept.
//
//   reset     the observer's ready (the estimator's out_ready) low while rst_i is high; the
//             observer's output valid low the clock after a reset.
//   count     samples the estimator delivered (est_valid && trk_ready) = samples the observer gave
//             (trk_valid_o: its output is always taken) + in flight; nothing given from an empty
//             observer; in flight <= its LATENCY.
//   delay     a reference delay line of LATENCY clocks (the board never stalls the observer's
//             output) gives trk_valid_o exactly: every sample delivered comes out LATENCY clocks
//             later, none lost, duplicated or invented, and in the order delivered (a fixed
//             delay keeps order); the observer's ready is low exactly in the CYCLES - 1 clocks
//             after it took a sample (its update clock, or its time-shared schedule).
//   hold      the observer's compensated angle, which ABZ, UVW and the SPI port read between
//             samples, changes only in a clock that gives a sample; its other outputs (tracked
//             angle, velocity, turns, loss of tracking: the APB's) likewise, except in the
//             word-serial and coarse-shift forms (TRK_SERIAL = 2, 3), whose schedules write them
//             while their sample is in flight (rtl/acore_track.v): there they hold while no sample
//             is in flight.
// The reference's valid bits are also the induction's invariant: in flight = the ones of the
// delay line.
`default_nettype none

module acore_board_formal #(
  // The datapath parameters, passed on to the board (the registry line's, set by the driver).
`include "acore_datapath_params.vh"
  parameter integer SERIAL = 0,
  parameter integer TRK_FRAC_W = 25,
  // The observer as the board elaborates it (the driver reads them from the RTL): clocks from a
  // sample taken to its result, and clocks a sample.
  parameter integer TRK_LAT = 4,
  parameter integer TRK_CYC = 2,
  // The observer's form (acore_track's SERIAL: 2 word-serial and 3 coarse shifts, whose outputs
  // other than the compensated angle move during their schedules).
  parameter integer TRK_SERIAL = 0,
  // The time-shared observer's schedule (TRK_SERIAL = 1 and 3; its elaborated LOOP_END, PROD_END,
  // K_MIN, K_MAX and its counter's width S_W): the invariants below.
  parameter integer TRK_LOOP_END = 0,
  parameter integer TRK_PROD_END = 0,
  parameter integer TRK_K_MIN = 0,
  parameter integer TRK_K_MAX = 0,
  parameter integer TRK_S_W = 6
) (
  input wire               clk_i,
  input wire               rst_i,
  input wire               psel_i,
  input wire               penable_i,
  input wire               pwrite_i,
  input wire [11:0]        paddr_i,
  input wire [31:0]        pwdata_i,
  input wire [3:0]         pstrb_i,
  input wire               in_valid_i,
  input wire [IN_W-1:0]    c1_i,
  input wire [IN_W-1:0]    c2_i,
  input wire [IN_W-1:0]    c3_i,
  input wire [IN_W-1:0]    c4_i,
  input wire               sclk_i,
  input wire               csn_i,
  input wire               mosi_i
);
  localparam integer P_W = ANGLE_W + TRK_FRAC_W;
  wire [31:0]        prdata_o;
  wire               pready_o, pslverr_o, irq_o, in_ready_o, out_valid_o, los_o, dos_o;
  wire [ANGLE_W-1:0] angle_o;
  wire               trk_valid_o, trk_lot_o;
  wire [ANGLE_W-1:0] trk_angle_o, trk_angle_comp_o;
  wire [P_W-1:0]     trk_velocity_o;
  wire [15:0]        trk_turns_o;
  wire               a_o, b_o, z_o, u_o, v_o, w_o, miso_o, miso_oe_o;

  acore_board #(
`include "acore_datapath_pass.vh"
    .SERIAL(SERIAL), .INIT_FILE(""), .TRK_FRAC_W(TRK_FRAC_W)
  ) dut (
    .clk_i(clk_i), .rst_i(rst_i), .psel_i(psel_i), .penable_i(penable_i), .pwrite_i(pwrite_i),
    .paddr_i(paddr_i), .pwdata_i(pwdata_i), .pstrb_i(pstrb_i), .prdata_o(prdata_o),
    .pready_o(pready_o), .pslverr_o(pslverr_o), .irq_o(irq_o), .in_valid_i(in_valid_i),
    .in_ready_o(in_ready_o), .c1_i(c1_i), .c2_i(c2_i), .c3_i(c3_i), .c4_i(c4_i),
    .out_valid_o(out_valid_o), .angle_o(angle_o), .los_o(los_o), .dos_o(dos_o),
    .trk_valid_o(trk_valid_o), .trk_angle_o(trk_angle_o), .trk_angle_comp_o(trk_angle_comp_o),
    .trk_velocity_o(trk_velocity_o), .trk_turns_o(trk_turns_o), .trk_lot_o(trk_lot_o),
    .a_o(a_o), .b_o(b_o), .z_o(z_o), .u_o(u_o), .v_o(v_o), .w_o(w_o), .sclk_i(sclk_i),
    .csn_i(csn_i), .mosi_i(mosi_i), .miso_o(miso_o), .miso_oe_o(miso_oe_o));

  // (taps, connected by the driver to the board's wires: the estimator's stream into the observer
  // and the observer's ready)
  wire               tap_est_valid, tap_trk_ready;
  wire [ANGLE_W-1:0] tap_est_angle;

  // Reset in the first clock (the flops' power-up values are free).
  reg init_q = 1'b1;
  always @(posedge clk_i) init_q <= 1'b0;
  always @(*) if (init_q) assume (rst_i);

  wire take = tap_est_valid && tap_trk_ready;

  // ---- the estimator's stream as its shell's proof shows it (assumed) ----
  reg               past_rst_q = 1'b1;
  reg               past_est_held_q = 1'b0;
  reg [ANGLE_W-1:0] past_est_angle_q;
  always @(posedge clk_i) begin
    past_rst_q <= rst_i;
    past_est_held_q <= tap_est_valid && !tap_trk_ready && !rst_i;
    past_est_angle_q <= tap_est_angle;
  end
  always @(*) begin
    if (past_rst_q) assume (!tap_est_valid);
    if (past_est_held_q && !rst_i) assume (tap_est_valid && tap_est_angle == past_est_angle_q);
  end

  // ---- count ----
  localparam integer CW = 12;
  reg [CW-1:0] taken_q, given_q;
  wire [CW-1:0] inflight = taken_q - given_q;
  always @(posedge clk_i) begin
    if (rst_i) begin
      taken_q <= 0;
      given_q <= 0;
    end else begin
      taken_q <= taken_q + take;
      given_q <= given_q + trk_valid_o;
    end
  end

  // ---- delay: the reference delay line (bit i: a sample taken i + 1 clocks ago) ----
  reg [TRK_LAT-1:0] ref_q;
  always @(posedge clk_i) begin
    if (rst_i) ref_q <= 0;
    else ref_q <= {ref_q[TRK_LAT-2:0], take};
  end
  integer i;
  reg [CW-1:0] ones;
  reg          busy;  // a sample taken in the last CYCLES - 1 clocks
  // clocks since the sample in a time-shared schedule was taken; 0: none (the schedule invariants
  // below read it)
  localparam integer AGE_W = 8;
  reg [AGE_W-1:0] age;
  always @(*) begin
    ones = 0;
    for (i = 0; i < TRK_LAT; i = i + 1) ones = ones + ref_q[i];
    busy = 1'b0;
    for (i = 0; i < TRK_CYC - 1; i = i + 1) busy = busy | ref_q[i];
    age = 0;
    for (i = 0; i < TRK_LAT - 1; i = i + 1) if (ref_q[i]) age = i + 1;
  end

  // ---- hold: the observer's outputs of the clock before ----
  localparam integer OUT_W = ANGLE_W + P_W + 16 + 1;
  wire [OUT_W-1:0] trk_out = {trk_angle_o, trk_velocity_o, trk_turns_o, trk_lot_o};
  reg  [OUT_W-1:0] past_trk_out_q;
  reg  [ANGLE_W-1:0] past_trk_comp_q;
  always @(posedge clk_i) begin
    past_trk_out_q <= trk_out;
    past_trk_comp_q <= trk_angle_comp_o;
  end
  // (the word-serial observer's tracked angle, velocity, turns and LOT may move while one of its
  // samples is in flight; every form's hold with none in flight)
  wire out_may_move = trk_valid_o || ((TRK_SERIAL == 2 || TRK_SERIAL == 3) && inflight != 0);

  // ---- the time-shared observer's schedule tied to the delay line (TRK_SERIAL = 1) ----
  // Its schedule (rtl/acore_track.v, g_ser) after the clock that takes a sample (age 0): P1..P4 at
  // ages 1..4; the loop (PL) from age 5, one clock a shift (s, up to LOOP_END) or a pause for phi's
  // update (xd) or v's (xd, vd; at s = k and s = 2k + 1); PC; the product (PH, s = 0..PROD_END);
  // R1..R3, the last at age LATENCY - 1. Tapped and asserted exactly, so that the induction need
  // not unroll a 71-clock schedule: the age is the delay line's one bit (one sample at a time).
  generate
    if (TRK_SERIAL == 1) begin : g_ser_inv
      localparam integer A_PL1 = TRK_LOOP_END + 7;     // the loop's last clock
      localparam integer A_PC = TRK_LOOP_END + 8;
      localparam integer A_PH0 = TRK_LOOP_END + 9;
      localparam integer A_PH1 = A_PH0 + TRK_PROD_END;
      wire       tap_p1, tap_p2, tap_p3, tap_p4, tap_pl, tap_pc, tap_ph, tap_r1, tap_r2, tap_r3;
      wire       tap_busy, tap_xd, tap_vd, tap_at_x, tap_at_v, tap_started, tap_eq_lend, tap_eq_pend;
      wire [TRK_S_W-1:0] tap_s;
      wire [3:0] tap_k;
      wire [7:0] s = {{(8 - TRK_S_W){1'b0}}, tap_s};
      wire [7:0] kx = tap_started ? {4'b0000, tap_k} : 8'd0;
      wire [7:0] k2 = {3'b000, tap_k, 1'b1};
      wire [7:0] pl_clock = age - 8'd5;
      wire [7:0] ph_clock = age - A_PH0[7:0];
      always @(posedge clk_i) begin
        if (!init_q && !rst_i) begin
          assert (A_PH1 + 3 == TRK_LAT - 1);  // (the schedule read as the RTL elaborates it)
          assert (ones - ref_q[TRK_LAT-1] <= 1);  // one sample in the schedule at a time
          assert (tap_busy == (age != 0));
          if (tap_at_x || tap_at_v) assert (tap_pl);
          if (age != 0) assert (tap_k >= TRK_K_MIN && tap_k <= TRK_K_MAX);
          assert (tap_p1 == (age == 1) && tap_p2 == (age == 2));
          assert (tap_p3 == (age == 3) && tap_p4 == (age == 4));
          assert (tap_pl == (age >= 5 && age <= A_PL1));
          assert (tap_pc == (age == A_PC));
          assert (tap_ph == (age >= A_PH0 && age <= A_PH1));
          assert (tap_r1 == (age == A_PH1 + 1) && tap_r2 == (age == A_PH1 + 2));
          assert (tap_r3 == (age == A_PH1 + 3));
          assert (tap_eq_lend == (s == TRK_LOOP_END) && tap_eq_pend == (s == TRK_PROD_END));
          if (tap_pl) begin
            assert (s + tap_xd + tap_vd == pl_clock);
            assert (tap_xd ? s >= kx : s <= kx);
            assert (tap_vd ? (tap_xd && s >= k2) : s <= k2);
            assert (tap_at_x == (!tap_xd && s == kx));
            assert (tap_at_v == (tap_xd && !tap_vd && s == k2));
          end
          if (tap_ph) assert (s == ph_clock);
        end
      end
    end
  endgenerate

  // ---- the coarse-shift observer's schedule tied to the delay line (TRK_SERIAL = 3) ----
  // Its schedule (rtl/acore_track.v, g_shf) after the clock that takes a sample (age 0): C1..C4 at
  // ages 1..4; the loop (PL) from age 5, s = 0..LOOP_END a clock, its updates (at_x, at_v) within
  // it; R2, R3; the product (PH, s = 0..PROD_END); FIN at age LATENCY - 1.
  // The loop's shift counts decide no timing (the loop lasts LOOP_END + 1 clocks whatever k).
  generate
    if (TRK_SERIAL == 3) begin : g_shf_inv
      localparam integer A_PL1 = TRK_LOOP_END + 5;     // the loop's last clock
      localparam integer A_PH0 = TRK_LOOP_END + 8;
      localparam integer A_PH1 = A_PH0 + TRK_PROD_END;
      wire       tap_c1, tap_c2, tap_c3, tap_c4, tap_pl, tap_r2, tap_r3, tap_ph, tap_fin;
      wire       tap_busy, tap_at_x, tap_at_v, tap_eq_lend, tap_eq_pend;
      wire [TRK_S_W-1:0] tap_s;
      wire [7:0] s = {{(8 - TRK_S_W){1'b0}}, tap_s};
      always @(posedge clk_i) begin
        if (!init_q && !rst_i) begin
          assert (A_PH1 + 1 == TRK_LAT - 1);  // (the schedule read as the RTL elaborates it)
          assert (ones - ref_q[TRK_LAT-1] <= 1);  // one sample in the schedule at a time
          assert (tap_busy == (age != 0));
          if (tap_at_x || tap_at_v) assert (tap_pl);
          assert (tap_c1 == (age == 1) && tap_c2 == (age == 2) && tap_c3 == (age == 3));
          assert (tap_c4 == (age == 4));
          assert (tap_pl == (age >= 5 && age <= A_PL1));
          assert (tap_r2 == (age == A_PL1 + 1) && tap_r3 == (age == A_PL1 + 2));
          assert (tap_ph == (age >= A_PH0 && age <= A_PH1));
          assert (tap_fin == (age == A_PH1 + 1));
          assert (tap_eq_lend == (s == TRK_LOOP_END) && tap_eq_pend == (s == TRK_PROD_END));
          if (tap_pl) assert (s == age - 8'd5);
          if (tap_ph) assert (s == age - A_PH0[7:0]);
        end
      end
    end
  endgenerate

  always @(posedge clk_i) begin
    if (!init_q) begin
      // reset
      if (rst_i) assert (!tap_trk_ready);
      if (past_rst_q) assert (!trk_valid_o);
      if (!rst_i) begin
        // count
        if (trk_valid_o) assert (inflight != 0);
        assert (inflight <= TRK_LAT);
        // delay (and the induction's invariant)
        assert (trk_valid_o == ref_q[TRK_LAT-1]);
        assert (inflight == ones);
        assert (tap_trk_ready == !busy);
        // hold
        if (!past_rst_q && !trk_valid_o) assert (trk_angle_comp_o == past_trk_comp_q);
        if (!past_rst_q && !out_may_move) assert (trk_out == past_trk_out_q);
      end
    end
  end
endmodule
