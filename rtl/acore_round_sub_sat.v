// SPDX-License-Identifier: MIT
// acore_round_sub_sat: the correction's last step, y = saturate(s - round_shr(acc, RN), S_W)
// (model fx::round_shr, fx::saturate), shared by the 1-D, 2-D and folded polynomial corrections.
// Three clocks: round, subtract, saturate; LATENCY = 3 advancing clocks from acc_i/s_i/ov_i.
// ovf_o = ov_i (the accumulator overflowed on the way) | the subtraction did not fit S_W.
`resetall
`default_nettype none

module acore_round_sub_sat #(
  // Accumulator width, signed.
  parameter integer ACC_W = 32,
  // Rounding shift of the accumulator (ACC_F - S_F), 0..ACC_W-1.
  parameter integer RN = 14,
  // Curve and result width, signed.
  parameter integer S_W = 18
) (
  input  wire             clk_i,
  // Pipeline advance (tie high where the datapath never stalls).
  input  wire             en_i,
  input  wire [ACC_W-1:0] acc_i,
  input  wire [S_W-1:0]   s_i,
  input  wire             ov_i,
  output wire [S_W-1:0]   y_o,
  output wire             ovf_o
);

`include "acore_derived.vh"

  // Derived, do not override.
  localparam integer LATENCY = acore_round_sub_sat_latency();
  localparam integer R_W = ACC_W + 1 - RN;  // width of round_shr(acc, RN)
  localparam integer Y_W = ((R_W > S_W) ? R_W : S_W) + 1;

  acore_check #(.OK(RN >= 0 && RN < ACC_W), .VALUE(RN),
    .MSG("illegal parameter: acore_round_sub_sat: RN must be 0..ACC_W-1"))
    RN_must_be_0_to_ACC_W_minus_1 ();

  // Half an LSB added before the shift; the low RN bits of the sum are dropped (waived in verilator.vlt).
  wire [ACC_W:0] acc_ext = {acc_i[ACC_W-1], acc_i};
  wire [ACC_W:0] acc_rnd;
  generate
    if (RN > 0) begin : g_rnd
      assign acc_rnd = acc_ext + ({{ACC_W{1'b0}}, 1'b1} << (RN - 1));
    end else begin : g_nornd
      assign acc_rnd = acc_ext;
    end
  endgenerate
  reg [R_W-1:0] p_r_q;
  reg [S_W-1:0] s_r_q;
  reg           ov_r_q, ov_y_q;
  reg [Y_W-1:0] y_full_q;
  always @(posedge clk_i) begin
    if (en_i) begin
      p_r_q    <= acc_rnd[ACC_W:RN];
      s_r_q    <= s_i;
      ov_r_q   <= ov_i;
      y_full_q <= {{(Y_W-S_W){s_r_q[S_W-1]}}, s_r_q} - {{(Y_W-R_W){p_r_q[R_W-1]}}, p_r_q};
      ov_y_q   <= ov_r_q;
    end
  end
  wire [S_W-1:0] y_sat;
  wire y_ovf;
  acore_saturate #(.IN_W(Y_W), .OUT_W(S_W)) u_ysat (.d_i(y_full_q), .q_o(y_sat), .ovf_o(y_ovf));

  reg [S_W-1:0] y_q;
  reg ovf_q;
  always @(posedge clk_i) begin
    if (en_i) begin
      y_q   <= y_sat;
      ovf_q <= ov_y_q | y_ovf;
    end
  end
  assign y_o   = y_q;
  assign ovf_o = ovf_q;

endmodule

`resetall
