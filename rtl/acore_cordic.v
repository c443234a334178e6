// SPDX-License-Identifier: MIT
// acore_cordic: stage 5, pipelined CORDIC arctangent in vectoring mode over the full circle
// (model/ip/stages/cordic.cpp, bit for bit). angle = atan2(y, x), one turn = 2^ANGLE_W.
//
//   NORM=1: x, y <<= L, L = IN_W-2 - msb(|x| | |y|) when positive
//   X = x << G, Y = y << G                               XY_W = IN_W + 2 + G bits
//   pre-rotation: X < 0 -> (X, Y) = (-X, -Y), Z = 2^(Z_W-1); else Z = 0
//                                      (1 clock; 5 clocks with NORM=1, merged with the shift)
//   stage i = 0..K-1, s = (Y < 0):          (1 clock each, 2 with SPLIT=1, reads x_q[i])
//       X += (Y >>> i) ^ {s}  + s        i.e. X += s ? -(Y>>>i) : (Y>>>i)
//       Y += (X >>> i) ^ {~s} + ~s       i.e. Y -= s ? -(X>>>i) : (X>>>i)
//       Z += atan_i ^ {s} + s             (mod 2^Z_W)
//   angle = round_shr(Z, Z_W - ANGLE_W) mod 2^ANGLE_W;  mag = X_K >>> G   (1 clock)
// Each stage register is fed by exactly one adder per word: the conditional negation is the XOR
// and the carry-in of the same adder, written as one (W+1)-bit add whose bit 0 makes the carry.
// atan_i = round(atan(2^-i) / 2pi 2^Z_W) comes in on a bus (the register file's last K words).
// ZTAB=1 (constant atan_i): Z += sum over each group of 4 stages, from a 16-entry table (see ZTAB).
// X never goes negative and |(X, Y)| grows by the CORDIC gain (< 1.65), so XY_W cannot overflow;
// Y shrinks stage by stage and is computed on fewer bits in the later stages (see below).
`resetall
`default_nettype none

module acore_cordic #(
  // Width of the signed x/y inputs.
  parameter integer IN_W = 18,
  // Guard fraction bits of the x/y registers.
  parameter integer G = 3,
  // Angle accumulator, one turn = 2^Z_W.
  parameter integer Z_W = 20,
  // Output angle width, unsigned, one turn = 2^ANGLE_W.
  parameter integer ANGLE_W = 16,
  // Iterations = pipeline stages.
  parameter integer K = 16,
  // Width of one arctangent word on atan_i (unsigned, zero-extended to Z_W, or used modulo 2^Z_W).
  parameter integer AT_W = 18,
  // 1: leading-bit normalization so short vectors keep full angle precision.
  parameter integer NORM = 0,
  // 1: two clocks per stage, the operand XOR (conditional negation) registered before the adder,
  // so the clock period is one carry chain (for Fmax on iCE40); 0: one clock per stage.
  parameter integer SPLIT = 0,
  // 1: atan_i is a constant (a core with a ROM table, synth/acore_cordic16.v): the angle updates
  // of each group of 4 stages are one table lookup on the group's 4 directions and one adder, the
  // output rounding's half LSB folded into the last table (Z adds modulo 2^Z_W, so the order of the
  // additions does not change Z: bit for bit the same angle). The table is 16 sums of the group's
  // words: constants at synthesis when atan_i is; on a register-fed atan_i (the top) it would be
  // 16 adder trees, so the top keeps 0.
  parameter integer ZTAB = 0,
  // Derived, do not override.
  parameter integer XY_W = acore_xy_w(IN_W, G),
  parameter integer MAG_W = acore_mag_w(IN_W)
) (
  input  wire                clk_i,
  input  wire                en_i,
  // Cosine-like input x and sine-like input y.
  input  wire [IN_W-1:0]     x_i,
  input  wire [IN_W-1:0]     y_i,
  // atan_i for i = 0..K-1, word i at bits [i AT_W +: AT_W].
  input  wire [K*AT_W-1:0]   atan_i,
  output reg  [ANGLE_W-1:0]  angle_o,
  // X_K >>> G: vector length times the CORDIC gain, never negative.
  output reg  [MAG_W-1:0]    mag_o
);

`include "acore_derived.vh"

  // Derived, do not override.
  localparam integer LATENCY = acore_cordic_latency(K, NORM, SPLIT);
  localparam integer DROP = Z_W - ANGLE_W;

  // Parameter rules (acore_check.v: stops Verilator, Icarus and Yosys at elaboration).
  acore_check #(.OK(Z_W >= ANGLE_W), .VALUE(Z_W),
    .MSG("illegal parameter: acore_cordic: Z_W must be >= ANGLE_W"))
    Z_W_must_be_at_least_ANGLE_W ();
  acore_check #(.OK(K >= 1 && K < XY_W), .VALUE(K),
    .MSG("illegal parameter: acore_cordic: K must be 1..XY_W-1"))
    K_must_be_1_to_XY_W_minus_1 ();
  acore_check #(.OK(XY_W == acore_xy_w(IN_W, G)), .VALUE(XY_W),
    .MSG("illegal parameter: acore_cordic: XY_W is derived (IN_W+2+G), do not override"))
    XY_W_is_derived ();
  acore_check #(.OK(MAG_W == acore_mag_w(IN_W)), .VALUE(MAG_W),
    .MSG("illegal parameter: acore_cordic: MAG_W is derived (IN_W+2), do not override"))
    MAG_W_is_derived ();

  // ---- normalization (optional) and quadrant pre-rotation -> x_q[0], y_q[0], z_q[0] ----
  // X never goes negative and stays below 2^(XY_W-1) (|x| <= 2^(IN_W-1), gain < 2.33 with the
  // 45-degree pre-rotation), so it is kept without a sign bit. Y converges: entering stage i its
  // angle is within sum_{k>=i} atan(2^-k) < 2^(1-i) rad, so |Y_i| < 2^(XY_W - i) and Y_i fits
  // YW(i) = min(XY_W, XY_W + 2 - i) signed bits (a 2x margin over the bound, which also covers the
  // truncation of at most one LSB per stage). Each stage computes only YW(i+1) bits of Y (the adds
  // are exact modulo 2^YW and the true value fits) and stores them sign-extended; synthesis merges
  // the duplicated sign flops. tb/blocks/test_cordic16.cpp checks the margin on sweeps of both configs.
  reg [XY_W-2:0] x_q [0:K];
  reg [XY_W-1:0] y_q [0:K-1];
  reg [Z_W-1:0]  z_q [0:K];
  // ZTAB=1: the directions of the current group's earlier stages, travelling with the vector.
  reg [3:0]      gd_q [0:K];
  always @(posedge clk_i) if (en_i) gd_q[0] <= 4'b0000;

  // ZTAB=1: the sum of the group's words w (word p at bits [p Z_W +: Z_W], n of them) with the
  // directions of pt (bit p set: -w_p), modulo a turn, plus the output rounding's half LSB when rnd.
  // Called with constant pt: on constant words it is a constant.
  function automatic [Z_W-1:0] ztab_sum(input [3:0] pt, input [4*Z_W-1:0] w, input integer n,
                                        input integer rnd);
    integer p;
    begin
      ztab_sum = {Z_W{1'b0}};
      for (p = 0; p < n; p = p + 1)
        ztab_sum = pt[p] ? ztab_sum - w[p*Z_W +: Z_W] : ztab_sum + w[p*Z_W +: Z_W];
      if (rnd != 0 && DROP > 0) ztab_sum = ztab_sum + ({{(Z_W-1){1'b0}}, 1'b1} << (DROP - 1));
    end
  endfunction

  generate
    if (NORM != 0) begin : g_norm
      // Clock 1: |x|, |y| and the pre-rotated y (-y when x < 0). Clock 2: m = |x| | |y|.
      // Clock 3: per 4-bit group of m, "any bit set" and the shift L = IN_W-2 - msb (when positive,
      // else 0) that its highest set bit would give. Clock 4: L of the highest non-empty group. Clock 5: X = |x| << L, Y = +-y << L.
      // Each clock is one or two LUT levels deep. Shifting before or after the pre-rotation is the
      // same (no overflow: the msb lands at IN_W-2).
      localparam integer SH_W = $clog2(IN_W);
      localparam integer NG = (IN_W + 3) / 4;  // 4-bit groups of m
      wire sx = x_i[IN_W-1];
      wire sy = y_i[IN_W-1];
      // Conditional negation as (v ^ {s}) + s, one adder each (bit 0 of the wider add makes the
      // carry-in, as in the stages).
      wire [IN_W:0]   ax_sum = {x_i ^ {IN_W{sx}}, 1'b1} + {{IN_W{1'b0}}, sx};
      wire [IN_W:0]   ay_sum = {y_i ^ {IN_W{sy}}, 1'b1} + {{IN_W{1'b0}}, sy};
      wire [IN_W:0]   y_ext = {sy, y_i};
      wire [IN_W+1:0] yr_sum = {y_ext ^ {(IN_W+1){sx}}, 1'b1} + {{(IN_W+1){1'b0}}, sx};
      wire [IN_W-1:0] ax = ax_sum[IN_W:1];
      wire [IN_W-1:0] ay = ay_sum[IN_W:1];
      wire [IN_W:0]   yr = yr_sum[IN_W+1:1];
      // Pipeline of the vector beside the shift computation: index 0 = clock 1 ... 3 = clock 4.
      reg [IN_W-1:0] ax_q [0:3];
      reg [IN_W:0]   yr_q [0:3];
      reg            sx_q [0:3];
      reg [IN_W-1:0] ay_q;
      reg [(NG<<2)-1:0] m_q;
      reg [NG-1:0]   any_q;
      localparam integer CAND_W = SH_W * NG;
      reg [CAND_W-1:0] cand_q;
      reg [SH_W-1:0] sh_q;
      wire [(NG<<2)-1:0] m = {{((NG<<2)-IN_W){1'b0}}, ax_q[0] | ay_q};
      // The shift group g asks for if its highest set bit is the msb of m: a function of the
      // group's 4 bits (one LUT level per output bit).
      function automatic [SH_W-1:0] cand_of(input integer g, input [3:0] bits);
        integer b, msb, l;
        begin
          cand_of = {SH_W{1'b0}};
          for (b = 0; b < 4; b = b + 1) begin
            msb = (g << 2) + b;
            l = (msb < IN_W - 2) ? (IN_W - 2 - msb) : 0;
            if (bits[b]) cand_of = l[SH_W-1:0];
          end
        end
      endfunction
      wire [NG-1:0]  any_d;
      wire [CAND_W-1:0] cand_d;
      genvar gg;
      for (gg = 0; gg < NG; gg = gg + 1) begin : g_grp
        localparam integer OFF = gg * SH_W;
        assign any_d[gg] = |m_q[(gg << 2) +: 4];
        assign cand_d[OFF +: SH_W] = cand_of(gg, m_q[(gg << 2) +: 4]);
      end
      // The highest non-empty group holds the msb of m (none: no shift).
      function automatic [SH_W-1:0] pick(input [NG-1:0] any, input [CAND_W-1:0] cand);
        integer g, off;
        begin
          pick = {SH_W{1'b0}};
          off = 0;
          for (g = 0; g < NG; g = g + 1) begin
            if (any[g]) pick = cand[off +: SH_W];
            off = off + SH_W;
          end
        end
      endfunction
      wire [SH_W-1:0] sh_d = pick(any_q, cand_q);
      integer j;
      always @(posedge clk_i) begin
        if (en_i) begin
          ax_q[0] <= ax;
          ay_q    <= ay;
          yr_q[0] <= yr;
          sx_q[0] <= sx;
          for (j = 1; j < 4; j = j + 1) begin
            ax_q[j] <= ax_q[j-1];
            yr_q[j] <= yr_q[j-1];
            sx_q[j] <= sx_q[j-1];
          end
          m_q    <= m;
          any_q  <= any_d;
          cand_q <= cand_d;
          sh_q   <= sh_d;
        end
      end
      wire [IN_W-1:0] ax_sh = ax_q[3] << sh_q;
      wire [IN_W:0]   yr_sh = yr_q[3] << sh_q;
      always @(posedge clk_i) begin
        if (en_i) begin
          x_q[0] <= {1'b0, ax_sh, {G{1'b0}}};
          y_q[0] <= {yr_sh[IN_W], yr_sh, {G{1'b0}}};
          z_q[0] <= {sx_q[3], {(Z_W-1){1'b0}}};
        end
      end
    end else begin : g_prerot
      // One clock: X < 0 -> (X, Y) = (-X, -Y), Z = half a turn.
      wire [XY_W-1:0] x0 = {{2{x_i[IN_W-1]}}, x_i, {G{1'b0}}};
      wire [XY_W-1:0] y0 = {{2{y_i[IN_W-1]}}, y_i, {G{1'b0}}};
      wire neg0 = x_i[IN_W-1];
      wire [XY_W-1:0] x0_abs = neg0 ? ({XY_W{1'b0}} - x0) : x0;
      always @(posedge clk_i) begin
        if (en_i) begin
          x_q[0] <= x0_abs[XY_W-2:0];
          y_q[0] <= neg0 ? ({XY_W{1'b0}} - y0) : y0;
          z_q[0] <= {neg0, {(Z_W-1){1'b0}}};
        end
      end
    end
  endgenerate

  genvar i;
  generate
    for (i = 0; i < K; i = i + 1) begin : g_stage
      // s = (Y < 0): the rotation direction.
      wire s = y_q[i][XY_W-1];
      wire [XY_W-1:0] ys_full = $signed(y_q[i]) >>> i;
      wire [XY_W-2:0] ys = ys_full[XY_W-2:0];
      localparam integer AT_OFF = i * AT_W;
      wire [Z_W-1:0]  at;
      if (AT_W > Z_W) begin : g_at_low
        // Z counts modulo a turn (2^Z_W), so a word's bits above Z_W do not change it (the model
        // adds the whole word and wraps): a word wider than Z (REG_W > Z_W) is used modulo a turn.
        assign at = atan_i[AT_OFF +: Z_W];
        wire unused_at_high = ^atan_i[AT_OFF + Z_W +: AT_W - Z_W];
      end else begin : g_at_ext
        assign at = {{(Z_W-AT_W){1'b0}}, atan_i[AT_OFF +: AT_W]};
      end
      // Adder inputs a + b + c: X += s ? -(Y>>>i) : (Y>>>i) is X + ((Y>>>i) ^ {s}) + s.
      wire [XY_W-2:0] x_a, x_b;
      wire [Z_W-1:0]  z_a, z_b;
      wire [3:0]      gd_a;  // ZTAB=1: the group's earlier directions, beside z_a
      wire            sc_x, sc_z, nsc_y;  // s (and ~s) as seen by the adders' carry-ins
      if (SPLIT != 0) begin : g_split
        reg [XY_W-2:0] x_a_q, x_b_q;
        reg [Z_W-1:0]  z_a_q, z_b_q;
        // Copies of s for the carry-ins (the Y adder gets ~s straight from a flop).
        reg s_x_q, s_z_q, ns_y_q;
        always @(posedge clk_i) begin
          if (en_i) begin
            x_a_q  <= x_q[i];
            x_b_q  <= ys ^ {(XY_W-1){s}};
            z_a_q  <= z_q[i];
            z_b_q  <= at ^ {Z_W{s}};
            s_x_q  <= s;
            s_z_q  <= s;
            ns_y_q <= ~s;
          end
        end
        assign x_a  = x_a_q;
        assign x_b  = x_b_q;
        reg [3:0] gd_a_q;
        always @(posedge clk_i) if (en_i) gd_a_q <= gd_q[i];
        assign z_a  = z_a_q;
        assign z_b  = z_b_q;
        assign gd_a = gd_a_q;
        assign sc_x = s_x_q;
        assign sc_z = s_z_q;
        assign nsc_y = ns_y_q;
      end else begin : g_direct
        assign x_a  = x_q[i];
        assign x_b  = ys ^ {(XY_W-1){s}};
        assign z_a  = z_q[i];
        assign z_b  = at ^ {Z_W{s}};
        assign gd_a = gd_q[i];
        assign sc_x = s;
        assign sc_z = s;
        assign nsc_y = ~s;
      end
      // {a, 1} + {b, c}: bit 0 carries c into the real sum, so this is a + b + c in one adder.
      wire [XY_W-1:0] x_sum = {x_a, 1'b1} + {x_b, sc_x};
      always @(posedge clk_i) if (en_i) x_q[i+1] <= x_sum[XY_W-1:1];
      if (ZTAB == 0) begin : g_zadd
        wire [Z_W:0] z_sum = {z_a, 1'b1} + {z_b, sc_z};
        always @(posedge clk_i) begin
          if (en_i) begin
            z_q[i+1]  <= z_sum[Z_W:1];
            gd_q[i+1] <= 4'b0000;  // no table: never read
          end
        end
      end else begin : g_ztab
        // Directions of this group's stages so far (bit p: stage 4g + p), this stage's added.
        localparam integer P = i % 4;
        localparam integer LAST = (P == 3 || i == K - 1) ? 1 : 0;
        wire [3:0] dirs = gd_a | ({3'b000, sc_z} << P);
        if (LAST != 0) begin : g_add
          // Table of the group's sums, by its directions (d = 1: -atan, as Z += atan ^ {s} + s).
          localparam integer G0 = i - P;
          // The group's words as Z_W-bit values (zero-extended, or modulo a turn), unused ones 0.
          wire [4*Z_W-1:0] gw;
          genvar q;
          for (q = 0; q < 4; q = q + 1) begin : g_w
            if (q > P) begin : g_none
              assign gw[q*Z_W +: Z_W] = {Z_W{1'b0}};
            end else if (AT_W >= Z_W) begin : g_low
              assign gw[q*Z_W +: Z_W] = atan_i[(G0 + q) * AT_W +: Z_W];
            end else begin : g_ext
              assign gw[q*Z_W +: Z_W] = {{(Z_W-AT_W){1'b0}}, atan_i[(G0 + q) * AT_W +: AT_W]};
            end
          end
          wire [Z_W-1:0] tab [0:15];
          genvar pt;
          for (pt = 0; pt < 16; pt = pt + 1) begin : g_pt
            localparam [3:0] PT = pt;
            assign tab[pt] = ztab_sum(PT, gw, P + 1, (i == K - 1) ? 1 : 0);
          end
          wire [Z_W-1:0] z_sum = z_a + tab[dirs];
          always @(posedge clk_i) begin
            if (en_i) begin
              z_q[i+1]  <= z_sum;
              gd_q[i+1] <= 4'b0000;
            end
          end
        end else begin : g_pass
          always @(posedge clk_i) begin
            if (en_i) begin
              z_q[i+1]  <= z_a;
              gd_q[i+1] <= dirs;
            end
          end
        end
      end
      // Y -= s ? -(X>>i) : (X>>i), i.e. Y + ((X>>i) ^ {~s}) + ~s, on YWN bits. The last stage's Y
      // is never read.
      if (i < K - 1) begin : g_y
        localparam integer YWN = (i + 1 <= 2) ? XY_W : XY_W + 1 - i;
        wire [XY_W-1:0] xs_full = {1'b0, x_q[i] >> i};
        wire [YWN-1:0]  xs = xs_full[YWN-1:0];
        wire [YWN-1:0]  y_a, y_b;
        if (SPLIT != 0) begin : g_split
          reg [YWN-1:0] y_a_q, y_b_q;
          always @(posedge clk_i) begin
            if (en_i) begin
              y_a_q <= y_q[i][YWN-1:0];
              y_b_q <= xs ^ {YWN{~s}};
            end
          end
          assign y_a = y_a_q;
          assign y_b = y_b_q;
        end else begin : g_direct
          assign y_a = y_q[i][YWN-1:0];
          assign y_b = xs ^ {YWN{~s}};
        end
        wire [YWN:0] y_sum = {y_a, 1'b1} + {y_b, nsc_y};
        always @(posedge clk_i) if (en_i) y_q[i+1] <= {{(XY_W-YWN){y_sum[YWN]}}, y_sum[YWN:1]};
      end
    end
  endgenerate

  // ---- output: round the angle, drop the guard bits of the magnitude ----
  wire [Z_W-1:0] z_k = z_q[K];
  wire [Z_W-1:0] z_rnd;
  generate
    if (DROP > 0 && ZTAB == 0) begin : g_rnd
      assign z_rnd = z_k + ({{(Z_W-1){1'b0}}, 1'b1} << (DROP - 1));
    end else begin : g_nornd
      assign z_rnd = z_k;
    end
  endgenerate
  wire [XY_W-2:0] x_k = x_q[K];
  always @(posedge clk_i) begin
    if (en_i) begin
      angle_o <= z_rnd[Z_W-1:DROP];
      mag_o   <= {1'b0, x_k[XY_W-2:G]};
    end
  end

endmodule

`resetall
