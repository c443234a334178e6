// SPDX-License-Identifier: MIT
// acore_pwm: the angle as a PWM output in the AS5047P's frame, so a drive that reads that sensor's
// PWM pin (a timer in input-capture mode) reads AngleCore's angle unchanged. One frame is 4119
// PWM clock periods (a PWM clock is PRE + 1 clocks):
//   12 high (init) | 4 high if no error, else low (error_n) | 4095: high for the angle's upper 12
//   bits, low for the rest (data) | 8 low (exit)
// so the high time is 16 + angle12 periods without error (12 + angle12 with one) and a decoder
// computes angle12 = 4119 t_high / (t_high + t_low) - 16. The angle and the error flag are taken
// at the start of each frame (the frame never changes in its middle).
`resetall
`default_nettype none

module acore_pwm #(
  // Bits of the angle (the upper 12 are sent).
  parameter integer ANGLE_W = 16,
  // Bits of the prescaler.
  parameter integer PRE_W = 8
) (
  input  wire               clk_i,
  input  wire               rst_i,
  input  wire [ANGLE_W-1:0] angle_i,
  input  wire               err_i,
  // PWM clock = clk_i / (pre_i + 1).
  input  wire [PRE_W-1:0]   pre_i,
  output reg                pwm_o,
  // A pulse at the start of each frame.
  output wire               frame_o
);

  acore_check #(.OK(ANGLE_W >= 12 && ANGLE_W <= 32), .VALUE(ANGLE_W),
    .MSG("illegal parameter: ANGLE_W must be 12..32 (the frame carries 12 bits)")) ANGLE_W_must_be_12_to_32 ();
  acore_check #(.OK(PRE_W >= 1 && PRE_W <= 24), .VALUE(PRE_W),
    .MSG("illegal parameter: PRE_W must be 1..24")) PRE_W_must_be_1_to_24 ();

  localparam [12:0] FRAME = 13'd4119;
  reg [PRE_W-1:0] div_q;
  reg [12:0] pos_q;      // 0 .. 4118: the PWM period within the frame
  reg [11:0] ang_q;
  reg err_q;
  wire tick = (div_q == {PRE_W{1'b0}});
  wire start = tick & (pos_q == FRAME - 13'd1);
  // High in init, in error_n without error, and for the first ang_q periods of the data.
  wire [12:0] data_pos = pos_q - 13'd16;
  wire high = (pos_q < 13'd12) | ((pos_q < 13'd16) & ~err_q) |
              ((pos_q >= 13'd16) & (pos_q < 13'd4111) & (data_pos < {1'b0, ang_q}));
  always @(posedge clk_i) begin
    if (rst_i) begin
      div_q <= {PRE_W{1'b0}};
      pos_q <= FRAME - 13'd1;
      ang_q <= 12'd0;
      err_q <= 1'b1;
      pwm_o <= 1'b0;
    end else begin
      div_q <= tick ? pre_i : div_q - 1'b1;
      if (tick) begin
        pos_q <= start ? 13'd0 : pos_q + 13'd1;
        if (start) begin
          ang_q <= angle_i[ANGLE_W-1 -: 12];
          err_q <= err_i;
        end
      end
      pwm_o <= high;
    end
  end
  assign frame_o = start;

endmodule

`resetall
