// SPDX-License-Identifier: MIT
// The Gowin block RAM cells synth/gowin_bsram_map.v writes (DPB, DPX9B, SDPB, SDPX9B), as black
// boxes: Yosys 0.23's Gowin library does not know them, and the netlist the placer reads needs
// their ports' directions. Read with read_verilog -lib after that techmap (synth/devices.toml).

`define ACORE_GOWIN_INIT_DECL \
  parameter INIT_RAM_00 = 0; \
  parameter INIT_RAM_01 = 0; \
  parameter INIT_RAM_02 = 0; \
  parameter INIT_RAM_03 = 0; \
  parameter INIT_RAM_04 = 0; \
  parameter INIT_RAM_05 = 0; \
  parameter INIT_RAM_06 = 0; \
  parameter INIT_RAM_07 = 0; \
  parameter INIT_RAM_08 = 0; \
  parameter INIT_RAM_09 = 0; \
  parameter INIT_RAM_0A = 0; \
  parameter INIT_RAM_0B = 0; \
  parameter INIT_RAM_0C = 0; \
  parameter INIT_RAM_0D = 0; \
  parameter INIT_RAM_0E = 0; \
  parameter INIT_RAM_0F = 0; \
  parameter INIT_RAM_10 = 0; \
  parameter INIT_RAM_11 = 0; \
  parameter INIT_RAM_12 = 0; \
  parameter INIT_RAM_13 = 0; \
  parameter INIT_RAM_14 = 0; \
  parameter INIT_RAM_15 = 0; \
  parameter INIT_RAM_16 = 0; \
  parameter INIT_RAM_17 = 0; \
  parameter INIT_RAM_18 = 0; \
  parameter INIT_RAM_19 = 0; \
  parameter INIT_RAM_1A = 0; \
  parameter INIT_RAM_1B = 0; \
  parameter INIT_RAM_1C = 0; \
  parameter INIT_RAM_1D = 0; \
  parameter INIT_RAM_1E = 0; \
  parameter INIT_RAM_1F = 0; \
  parameter INIT_RAM_20 = 0; \
  parameter INIT_RAM_21 = 0; \
  parameter INIT_RAM_22 = 0; \
  parameter INIT_RAM_23 = 0; \
  parameter INIT_RAM_24 = 0; \
  parameter INIT_RAM_25 = 0; \
  parameter INIT_RAM_26 = 0; \
  parameter INIT_RAM_27 = 0; \
  parameter INIT_RAM_28 = 0; \
  parameter INIT_RAM_29 = 0; \
  parameter INIT_RAM_2A = 0; \
  parameter INIT_RAM_2B = 0; \
  parameter INIT_RAM_2C = 0; \
  parameter INIT_RAM_2D = 0; \
  parameter INIT_RAM_2E = 0; \
  parameter INIT_RAM_2F = 0; \
  parameter INIT_RAM_30 = 0; \
  parameter INIT_RAM_31 = 0; \
  parameter INIT_RAM_32 = 0; \
  parameter INIT_RAM_33 = 0; \
  parameter INIT_RAM_34 = 0; \
  parameter INIT_RAM_35 = 0; \
  parameter INIT_RAM_36 = 0; \
  parameter INIT_RAM_37 = 0; \
  parameter INIT_RAM_38 = 0; \
  parameter INIT_RAM_39 = 0; \
  parameter INIT_RAM_3A = 0; \
  parameter INIT_RAM_3B = 0; \
  parameter INIT_RAM_3C = 0; \
  parameter INIT_RAM_3D = 0; \
  parameter INIT_RAM_3E = 0; \
  parameter INIT_RAM_3F = 0;

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
