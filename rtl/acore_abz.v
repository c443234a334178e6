// SPDX-License-Identifier: MIT
// acore_abz: incremental (ABZ quadrature) encoder emulation from the angle stream, as a drive's
// timer/counter input expects it from an AS5047P or MA730, with any resolution N = 1 .. 2^(N_W-1)
// pulses per turn (4N counts a turn), not only powers of two.
//
//   angle (latest sample) --> target = floor(angle 4N / 2^ANGLE_W) --> count steps toward it,
//                             (shift-add, N_W clocks)                   one step per edge, at most
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
// The product angle N is computed one bit of N a clock (shift-add, no multiplier): an angle that
// arrives while one is computed waits, and a newer one replaces it (latest wins), so the target
// follows the stream N_W + 3 clocks late at any sample rate.
//
// Hysteresis (one angle LSB): with lo = floor(angle 4N / T) and hi = floor((angle + 1) 4N / T)
// (T = 2^ANGLE_W, hi = 4N wraps to 0), the target stays where it is when it equals hi, and is lo
// otherwise. An angle dithering by one LSB across a count boundary (a, a+1 with lo(a+1) = hi(a))
// therefore holds the count still instead of toggling A or B at the sample rate; any move of more
// than one LSB downwards, and every move upwards, lands on lo exactly.
//
// N changes: a new N re-homes the count to the new target at once, without edges (a decoder
// re-homes on Z or on an absolute read, as after power-up). N outside 1 .. NMAX is clamped (the
// register shell refuses such a write). Z is high while the count equals INDEX (0 .. 4N-1; an
// INDEX >= 4N never fires): one count, a quarter period of A, once a turn in either direction.
`resetall
`default_nettype none

module acore_abz #(
  // Bits of the angle: one turn = 2^ANGLE_W.
  parameter integer ANGLE_W = 16,
  // Bits of the N input: N = 1 .. 2^(N_W-1) pulses a turn (at least 2; the board's is ABZ_N.N's).
  parameter integer N_W = 13,
  // Bits of the minimum edge spacing (clocks).
  parameter integer SP_W = 16
) (
  input  wire               clk_i,
  // Synchronous, active high: count 0 (A = B = 0), no target.
  input  wire               rst_i,
  // The angle stream (always accepted: the latest sample wins).
  input  wire               angle_valid_i,
  input  wire [ANGLE_W-1:0] angle_i,
  // Pulses a turn (1 .. 2^(N_W-1), clamped), the index count (0 .. 4N-1), the minimum clocks
  // between two edges (0 and 1 both mean one edge a clock).
  input  wire [N_W-1:0]     n_i,
  input  wire [N_W:0]       index_i,
  input  wire [SP_W-1:0]    spacing_i,
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
  localparam integer P_W = ANGLE_W + N_W;    // angle N
  localparam integer NMAX = 1 << (N_W - 1);
  localparam integer LATENCY = N_W + 3;      // clocks from an accepted angle to its target

  acore_check #(.OK(ANGLE_W >= 2 && ANGLE_W <= 32), .VALUE(ANGLE_W),
    .MSG("illegal parameter: ANGLE_W must be 2..32")) ANGLE_W_must_be_2_to_32 ();
  acore_check #(.OK(N_W >= 2 && N_W <= 16), .VALUE(N_W),
    .MSG("illegal parameter: N_W must be 2..16 (N up to 2^(N_W-1) pulses a turn)")) N_W_must_be_2_to_16 ();
  acore_check #(.OK(SP_W >= 1 && SP_W <= 24), .VALUE(SP_W),
    .MSG("illegal parameter: SP_W must be 1..24")) SP_W_must_be_1_to_24 ();

  // ---- N clamped to 1 .. NMAX ----
  localparam [N_W-1:0] NMAX_V = NMAX[N_W-1:0];
  localparam [N_W-1:0] ONE_N = {{(N_W-1){1'b0}}, 1'b1};
  wire [N_W-1:0] n_clamped = (n_i == {N_W{1'b0}}) ? ONE_N : (n_i > NMAX_V) ? NMAX_V : n_i;

  // ---- the target: angle N, one bit of N a clock, MSB first ----
  reg pend_q, run_q, res_q;
  reg [ANGLE_W-1:0] ang_q, a_run_q;
  reg [N_W-1:0] n_run_q, nsh_q, n_cur_q;
  reg [P_W-1:0] acc_q;
  reg [$clog2(N_W + 1)-1:0] k_q;
  wire [P_W-1:0] addend = nsh_q[N_W-1] ? {{N_W{1'b0}}, a_run_q} : {P_W{1'b0}};
  always @(posedge clk_i) begin
    if (rst_i) begin
      pend_q <= 1'b0;
      run_q <= 1'b0;
      res_q <= 1'b0;
    end else begin
      res_q <= 1'b0;
      if (angle_valid_i) pend_q <= 1'b1;
      else if (!run_q) pend_q <= 1'b0;
      if (!run_q && (pend_q || angle_valid_i)) begin
        run_q <= 1'b1;
        k_q <= N_W[$clog2(N_W + 1)-1:0];
        a_run_q <= angle_valid_i ? angle_i : ang_q;
        n_run_q <= n_clamped;
        nsh_q <= n_clamped;
        acc_q <= {P_W{1'b0}};
        pend_q <= 1'b0;
      end else if (run_q) begin
        acc_q <= {acc_q[P_W-2:0], 1'b0} + addend;
        nsh_q <= {nsh_q[N_W-2:0], 1'b0};
        k_q <= k_q - 1'b1;
        if (k_q == 1) begin
          run_q <= 1'b0;
          res_q <= 1'b1;
        end
      end
    end
    if (angle_valid_i) ang_q <= angle_i;
  end

  // lo = floor(P / 2^(ANGLE_W-2)), hi the same for angle + 1 (P + N), 4N wrapping to 0.
  wire [M_W-1:0] m4 = {n_run_q, 2'b00};
  // (P + N <= 2^ANGLE_W N: no carry out of P_W bits.)
  wire [P_W-1:0] p_hi = acc_q + {{ANGLE_W{1'b0}}, n_run_q};
  wire [M_W-1:0] lo = acc_q[P_W-1:ANGLE_W-2];
  wire [M_W-1:0] hi_raw = p_hi[P_W-1:ANGLE_W-2];
  wire [M_W-1:0] hi = (hi_raw == m4) ? {M_W{1'b0}} : hi_raw;
  // Registered once (the product's carry chain and the band's compare stay off the count's path).
  reg res2_q;
  reg [M_W-1:0] lo_q, hi_q;
  reg [N_W-1:0] n_res_q;
  always @(posedge clk_i) begin
    if (rst_i) res2_q <= 1'b0;
    else res2_q <= res_q;
    if (res_q) begin
      lo_q <= lo;
      hi_q <= hi;
      n_res_q <= n_run_q;
    end
  end

  // ---- the count ----
  reg [C_W-1:0] cnt_q, tgt_q;
  reg [SP_W-1:0] sp_q;
  wire [M_W-1:0] m4_cur = {n_cur_q, 2'b00};
  wire [M_W-1:0] m2_cur = {1'b0, n_cur_q, 1'b0};
  wire [M_W-1:0] cnt_w = {1'b0, cnt_q};
  wire [M_W-1:0] diff0 = {1'b0, tgt_q} - cnt_w;          // modulo 2^M_W
  wire [M_W-1:0] diff = diff0[M_W-1] ? diff0 + m4_cur : diff0;  // modulo 4N
  wire moving = (tgt_q != cnt_q);
  wire up = (diff <= m2_cur);
  wire [C_W-1:0] top_cnt = m4_cur[C_W-1:0] - 1'b1;
  wire [SP_W-1:0] sp_load = (spacing_i == {SP_W{1'b0}}) ? {SP_W{1'b0}} : spacing_i - 1'b1;
  wire [C_W-1:0] new_tgt = (tgt_q == hi_q[C_W-1:0] && hi_q != lo_q) ? tgt_q : lo_q[C_W-1:0];
  always @(posedge clk_i) begin
    if (rst_i) begin
      cnt_q <= {C_W{1'b0}};
      tgt_q <= {C_W{1'b0}};
      sp_q <= {SP_W{1'b0}};
      n_cur_q <= n_clamped;
    end else begin
      if (sp_q != {SP_W{1'b0}}) sp_q <= sp_q - 1'b1;
      if (res2_q && n_res_q != n_cur_q) begin
        // A new N: re-home without edges.
        n_cur_q <= n_res_q;
        cnt_q <= lo_q[C_W-1:0];
        tgt_q <= lo_q[C_W-1:0];
      end else begin
        if (res2_q) tgt_q <= new_tgt;
        if (moving && sp_q == {SP_W{1'b0}}) begin
          sp_q <= sp_load;
          if (up) cnt_q <= (cnt_q == top_cnt) ? {C_W{1'b0}} : cnt_q + 1'b1;
          else cnt_q <= (cnt_q == {C_W{1'b0}}) ? top_cnt : cnt_q - 1'b1;
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
      z_o <= (cnt_q == index_i);
    end
  end
  assign count_o = cnt_q;
  assign settled_o = ~moving & ~pend_q & ~run_q & ~res_q & ~res2_q & ~angle_valid_i;

endmodule

`resetall
