// SPDX-License-Identifier: MIT
// The Gowin block RAM cells synth/gowin_bsram_map.v writes (DPB, DPX9B, SDPB, SDPX9B), as black
// boxes: Yosys 0.23's Gowin library does not know them, and the netlist the placer reads needs
// their ports' directions. Read with read_verilog -lib after that techmap (synth/devices.toml).

`include "gowin_bsram_init.vh"

(* blackbox *)
module DPB (DOA, DOB, DIA, DIB, BLKSELA, BLKSELB, ADA, ADB, WREA, WREB, CLKA, CLKB, CEA, CEB, OCEA,
    OCEB, RESETA, RESETB);
  parameter READ_MODE0 = 1'b0;
  parameter READ_MODE1 = 1'b0;
  parameter WRITE_MODE0 = 2'b00;
  parameter WRITE_MODE1 = 2'b00;
  parameter BIT_WIDTH_0 = 16;
  parameter BIT_WIDTH_1 = 16;
  parameter BLK_SEL_0 = 3'b000;
  parameter BLK_SEL_1 = 3'b000;
  parameter RESET_MODE = "SYNC";
  `ACORE_GOWIN_INIT_DECL
  output [15:0] DOA, DOB;
  input [15:0] DIA, DIB;
  input [2:0] BLKSELA, BLKSELB;
  input [13:0] ADA, ADB;
  input WREA, WREB, CLKA, CLKB, CEA, CEB, OCEA, OCEB, RESETA, RESETB;
endmodule

(* blackbox *)
module DPX9B (DOA, DOB, DIA, DIB, BLKSELA, BLKSELB, ADA, ADB, WREA, WREB, CLKA, CLKB, CEA, CEB, OCEA,
    OCEB, RESETA, RESETB);
  parameter READ_MODE0 = 1'b0;
  parameter READ_MODE1 = 1'b0;
  parameter WRITE_MODE0 = 2'b00;
  parameter WRITE_MODE1 = 2'b00;
  parameter BIT_WIDTH_0 = 18;
  parameter BIT_WIDTH_1 = 18;
  parameter BLK_SEL_0 = 3'b000;
  parameter BLK_SEL_1 = 3'b000;
  parameter RESET_MODE = "SYNC";
  `ACORE_GOWIN_INIT_DECL
  output [17:0] DOA, DOB;
  input [17:0] DIA, DIB;
  input [2:0] BLKSELA, BLKSELB;
  input [13:0] ADA, ADB;
  input WREA, WREB, CLKA, CLKB, CEA, CEB, OCEA, OCEB, RESETA, RESETB;
endmodule

(* blackbox *)
module SDPB (DO, DI, BLKSELA, BLKSELB, ADA, ADB, CLKA, CLKB, CEA, CEB, OCE, RESETA, RESETB);
  parameter READ_MODE = 1'b0;
  parameter BIT_WIDTH_0 = 32;
  parameter BIT_WIDTH_1 = 32;
  parameter BLK_SEL_0 = 3'b000;
  parameter BLK_SEL_1 = 3'b000;
  parameter RESET_MODE = "SYNC";
  `ACORE_GOWIN_INIT_DECL
  output [31:0] DO;
  input [31:0] DI;
  input [2:0] BLKSELA, BLKSELB;
  input [13:0] ADA, ADB;
  input CLKA, CLKB, CEA, CEB, OCE, RESETA, RESETB;
endmodule

(* blackbox *)
module SDPX9B (DO, DI, BLKSELA, BLKSELB, ADA, ADB, CLKA, CLKB, CEA, CEB, OCE, RESETA, RESETB);
  parameter READ_MODE = 1'b0;
  parameter BIT_WIDTH_0 = 36;
  parameter BIT_WIDTH_1 = 36;
  parameter BLK_SEL_0 = 3'b000;
  parameter BLK_SEL_1 = 3'b000;
  parameter RESET_MODE = "SYNC";
  `ACORE_GOWIN_INIT_DECL
  output [35:0] DO;
  input [35:0] DI;
  input [2:0] BLKSELA, BLKSELB;
  input [13:0] ADA, ADB;
  input CLKA, CLKB, CEA, CEB, OCE, RESETA, RESETB;
endmodule
