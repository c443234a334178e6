// SPDX-License-Identifier: MIT
// acore_check: one elaboration-time parameter rule, instantiated with the rule's truth value and
// named after the rule (the instance name is the rule: `DEGREE_must_be_1_to_7`). When OK is 0 it
// stops elaboration in every tool the project uses, naming the rule, the parameter and its value:
//
//   lint, verilate():  %Warning-USERERROR: ...: illegal parameter: DEGREE must be 1..7 (value 8)
//                      ... In instance acore_top.u_config.DEGREE_must_be_1_to_7
//   iverilog:          error: Unable to bind wire/reg/memory `illegal_parameter' in
//                      `acore_top.u_config.DEGREE_must_be_1_to_7.failed.value[8]'
//   yosys:             ERROR: illegal parameter: DEGREE must be 1..7.
//
// Why three branches: an elaboration-time $error in a generate block stops Verilator and Yosys,
// but Icarus 11 rejects $error there as a syntax error; Icarus stops at elaboration on a name it
// cannot bind, and prints the scope, which carries the rule (instance name) and the value (the
// index of a one-pass generate loop). Yosys 0.23 prints $error's string without formatting it, so
// its message has no value. With OK = 1 the module is empty.
`resetall
`default_nettype none

module acore_check #(
  // The rule holds (1) or not (0: elaboration stops).
  parameter [0:0] OK = 1'b1,
  // The offending value, for the message.
  parameter integer VALUE = 0,
  // The rule in words: "illegal parameter: DEGREE must be 1..7".
  parameter MSG = ""
) ();

  generate
    if (!OK) begin : failed
`ifdef __ICARUS__
      genvar v;
      for (v = VALUE; v == VALUE; v = v + 1) begin : value
        wire stop = illegal_parameter;
      end
`elsif YOSYS
      $error(MSG);
`else
      $error("%s (value %0d)", MSG, VALUE);
`endif
    end
  endgenerate

endmodule

`resetall
