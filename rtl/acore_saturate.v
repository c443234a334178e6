// SPDX-License-Identifier: MIT
// acore_saturate: clamps a signed IN_W-bit word to a signed OUT_W-bit word (model fx::saturate).
// Combinational. Example (IN_W=8, OUT_W=4): 8'sd9 -> 4'sd7, ovf_o=1; -8'sd3 -> -4'sd3, ovf_o=0.
// OUT_W >= IN_W: every value fits (sign extension), as in the model.
`resetall
`default_nettype none

module acore_saturate #(
  // Input width, signed.
  parameter integer IN_W = 8,
  // Output width, signed (any width: wider than IN_W sign-extends).
  parameter integer OUT_W = 4
) (
  input  wire [IN_W-1:0]  d_i,
  output wire [OUT_W-1:0] q_o,
  // The value did not fit and was clamped.
  output wire             ovf_o
);

  generate
    if (OUT_W == IN_W) begin : g_pass
      assign q_o   = d_i;
      assign ovf_o = 1'b0;
    end else if (OUT_W > IN_W) begin : g_extend
      assign q_o   = {{(OUT_W-IN_W){d_i[IN_W-1]}}, d_i};
      assign ovf_o = 1'b0;
    end else begin : g_clamp
      // The value fits when every dropped top bit equals the kept sign bit.
      wire [IN_W-OUT_W:0] top = d_i[IN_W-1:OUT_W-1];
      wire fits = (top == {(IN_W-OUT_W+1){1'b0}}) || (top == {(IN_W-OUT_W+1){1'b1}});
      wire neg  = d_i[IN_W-1];
      assign q_o   = fits ? d_i[OUT_W-1:0] : {neg, {(OUT_W-1){~neg}}};
      assign ovf_o = ~fits;
    end
  endgenerate

endmodule

`resetall
