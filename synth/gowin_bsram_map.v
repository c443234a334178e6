// SPDX-License-Identifier: MIT
// Renames the Gowin block RAM cells of Yosys 0.23's synth_gowin to the ones the place-and-route
// program of the devices table places (synth/devices.toml [family.gowin] after): synth_gowin maps
// the memories to DP/DPX9 (dual port) and SDP/SDPX9 (semi-dual port), which that nextpnr rejects
// ("Unsupported BSRAM type"); it packs the same blocks as DPB/DPX9B and SDPB/SDPX9B, whose block
// select is one bus a port (BLKSELA, BLKSELB; parameters BLK_SEL_0, BLK_SEL_1). The SDPB has no
// write enable: its write port writes whenever its clock is enabled, so CEA carries CEA & WREA
// (WREB, the read port's write enable, is 0 in every SDP synth_gowin writes).
// Every parameter and port keeps its meaning; the INIT_RAM_* words are passed on as they are.
// Read by techmap after synth_gowin; scripts/synth.sh's reports count the renamed cells.

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

`define ACORE_GOWIN_INIT_PASS \
.INIT_RAM_00(INIT_RAM_00), \
.INIT_RAM_01(INIT_RAM_01), \
.INIT_RAM_02(INIT_RAM_02), \
.INIT_RAM_03(INIT_RAM_03), \
.INIT_RAM_04(INIT_RAM_04), \
.INIT_RAM_05(INIT_RAM_05), \
.INIT_RAM_06(INIT_RAM_06), \
.INIT_RAM_07(INIT_RAM_07), \
.INIT_RAM_08(INIT_RAM_08), \
.INIT_RAM_09(INIT_RAM_09), \
.INIT_RAM_0A(INIT_RAM_0A), \
.INIT_RAM_0B(INIT_RAM_0B), \
.INIT_RAM_0C(INIT_RAM_0C), \
.INIT_RAM_0D(INIT_RAM_0D), \
.INIT_RAM_0E(INIT_RAM_0E), \
.INIT_RAM_0F(INIT_RAM_0F), \
.INIT_RAM_10(INIT_RAM_10), \
.INIT_RAM_11(INIT_RAM_11), \
.INIT_RAM_12(INIT_RAM_12), \
.INIT_RAM_13(INIT_RAM_13), \
.INIT_RAM_14(INIT_RAM_14), \
.INIT_RAM_15(INIT_RAM_15), \
.INIT_RAM_16(INIT_RAM_16), \
.INIT_RAM_17(INIT_RAM_17), \
.INIT_RAM_18(INIT_RAM_18), \
.INIT_RAM_19(INIT_RAM_19), \
.INIT_RAM_1A(INIT_RAM_1A), \
.INIT_RAM_1B(INIT_RAM_1B), \
.INIT_RAM_1C(INIT_RAM_1C), \
.INIT_RAM_1D(INIT_RAM_1D), \
.INIT_RAM_1E(INIT_RAM_1E), \
.INIT_RAM_1F(INIT_RAM_1F), \
.INIT_RAM_20(INIT_RAM_20), \
.INIT_RAM_21(INIT_RAM_21), \
.INIT_RAM_22(INIT_RAM_22), \
.INIT_RAM_23(INIT_RAM_23), \
.INIT_RAM_24(INIT_RAM_24), \
.INIT_RAM_25(INIT_RAM_25), \
.INIT_RAM_26(INIT_RAM_26), \
.INIT_RAM_27(INIT_RAM_27), \
.INIT_RAM_28(INIT_RAM_28), \
.INIT_RAM_29(INIT_RAM_29), \
.INIT_RAM_2A(INIT_RAM_2A), \
.INIT_RAM_2B(INIT_RAM_2B), \
.INIT_RAM_2C(INIT_RAM_2C), \
.INIT_RAM_2D(INIT_RAM_2D), \
.INIT_RAM_2E(INIT_RAM_2E), \
.INIT_RAM_2F(INIT_RAM_2F), \
.INIT_RAM_30(INIT_RAM_30), \
.INIT_RAM_31(INIT_RAM_31), \
.INIT_RAM_32(INIT_RAM_32), \
.INIT_RAM_33(INIT_RAM_33), \
.INIT_RAM_34(INIT_RAM_34), \
.INIT_RAM_35(INIT_RAM_35), \
.INIT_RAM_36(INIT_RAM_36), \
.INIT_RAM_37(INIT_RAM_37), \
.INIT_RAM_38(INIT_RAM_38), \
.INIT_RAM_39(INIT_RAM_39), \
.INIT_RAM_3A(INIT_RAM_3A), \
.INIT_RAM_3B(INIT_RAM_3B), \
.INIT_RAM_3C(INIT_RAM_3C), \
.INIT_RAM_3D(INIT_RAM_3D), \
.INIT_RAM_3E(INIT_RAM_3E), \
.INIT_RAM_3F(INIT_RAM_3F)

module DP (DOA, DOB, DIA, DIB, BLKSEL, ADA, ADB, WREA, WREB, CLKA, CLKB, CEA, CEB, OCEA, OCEB, RESETA, RESETB);
parameter READ_MODE0 = 1'b0;
parameter READ_MODE1 = 1'b0;
parameter WRITE_MODE0 = 2'b00;
parameter WRITE_MODE1 = 2'b00;
parameter BIT_WIDTH_0 = 16;
parameter BIT_WIDTH_1 = 16;
parameter BLK_SEL = 3'b000;
parameter RESET_MODE = "SYNC";
`ACORE_GOWIN_INIT_DECL
output [15:0] DOA, DOB;
input [15:0] DIA, DIB;
input [2:0] BLKSEL;
input [13:0] ADA, ADB;
input WREA, WREB, CLKA, CLKB, CEA, CEB, OCEA, OCEB, RESETA, RESETB;
DPB #(
	.READ_MODE0(READ_MODE0), .READ_MODE1(READ_MODE1), .WRITE_MODE0(WRITE_MODE0),
	.WRITE_MODE1(WRITE_MODE1), .BIT_WIDTH_0(BIT_WIDTH_0), .BIT_WIDTH_1(BIT_WIDTH_1),
	.BLK_SEL_0(BLK_SEL), .BLK_SEL_1(BLK_SEL), .RESET_MODE(RESET_MODE), `ACORE_GOWIN_INIT_PASS
) _TECHMAP_REPLACE_ (
	.DOA(DOA), .DOB(DOB), .DIA(DIA), .DIB(DIB), .BLKSELA(BLKSEL), .BLKSELB(BLKSEL), .ADA(ADA),
	.ADB(ADB), .WREA(WREA), .WREB(WREB), .CLKA(CLKA), .CLKB(CLKB), .CEA(CEA), .CEB(CEB),
	.OCEA(OCEA), .OCEB(OCEB), .RESETA(RESETA), .RESETB(RESETB)
);
endmodule

module DPX9 (DOA, DOB, DIA, DIB, BLKSEL, ADA, ADB, WREA, WREB, CLKA, CLKB, CEA, CEB, OCEA, OCEB, RESETA, RESETB);
parameter READ_MODE0 = 1'b0;
parameter READ_MODE1 = 1'b0;
parameter WRITE_MODE0 = 2'b00;
parameter WRITE_MODE1 = 2'b00;
parameter BIT_WIDTH_0 = 18;
parameter BIT_WIDTH_1 = 18;
parameter BLK_SEL = 3'b000;
parameter RESET_MODE = "SYNC";
`ACORE_GOWIN_INIT_DECL
output [17:0] DOA, DOB;
input [17:0] DIA, DIB;
input [2:0] BLKSEL;
input [13:0] ADA, ADB;
input WREA, WREB, CLKA, CLKB, CEA, CEB, OCEA, OCEB, RESETA, RESETB;
DPX9B #(
	.READ_MODE0(READ_MODE0), .READ_MODE1(READ_MODE1), .WRITE_MODE0(WRITE_MODE0),
	.WRITE_MODE1(WRITE_MODE1), .BIT_WIDTH_0(BIT_WIDTH_0), .BIT_WIDTH_1(BIT_WIDTH_1),
	.BLK_SEL_0(BLK_SEL), .BLK_SEL_1(BLK_SEL), .RESET_MODE(RESET_MODE), `ACORE_GOWIN_INIT_PASS
) _TECHMAP_REPLACE_ (
	.DOA(DOA), .DOB(DOB), .DIA(DIA), .DIB(DIB), .BLKSELA(BLKSEL), .BLKSELB(BLKSEL), .ADA(ADA),
	.ADB(ADB), .WREA(WREA), .WREB(WREB), .CLKA(CLKA), .CLKB(CLKB), .CEA(CEA), .CEB(CEB),
	.OCEA(OCEA), .OCEB(OCEB), .RESETA(RESETA), .RESETB(RESETB)
);
endmodule

module SDP (DO, DI, BLKSEL, ADA, ADB, WREA, WREB, CLKA, CLKB, CEA, CEB, OCE, RESETA, RESETB);
parameter READ_MODE = 1'b0;
parameter BIT_WIDTH_0 = 32;
parameter BIT_WIDTH_1 = 32;
parameter BLK_SEL = 3'b000;
parameter RESET_MODE = "SYNC";
`ACORE_GOWIN_INIT_DECL
output [31:0] DO;
input [31:0] DI;
input [2:0] BLKSEL;
input [13:0] ADA, ADB;
input WREA, WREB, CLKA, CLKB, CEA, CEB, OCE, RESETA, RESETB;
parameter _TECHMAP_CONSTMSK_CEA_ = 0;
parameter _TECHMAP_CONSTVAL_CEA_ = 0;
parameter _TECHMAP_CONSTMSK_WREA_ = 0;
parameter _TECHMAP_CONSTVAL_WREA_ = 0;
// The write port's enable: one of the two when the other is tied high, else a LUT of both.
wire wce;
generate
  if (_TECHMAP_CONSTMSK_CEA_ && _TECHMAP_CONSTVAL_CEA_) assign wce = WREA;
  else if (_TECHMAP_CONSTMSK_WREA_ && _TECHMAP_CONSTVAL_WREA_) assign wce = CEA;
  else LUT2 #(.INIT(4'h8)) wce_lut (.F(wce), .I0(CEA), .I1(WREA));
endgenerate
SDPB #(
	.READ_MODE(READ_MODE), .BIT_WIDTH_0(BIT_WIDTH_0), .BIT_WIDTH_1(BIT_WIDTH_1),
	.BLK_SEL_0(BLK_SEL), .BLK_SEL_1(BLK_SEL), .RESET_MODE(RESET_MODE), `ACORE_GOWIN_INIT_PASS
) _TECHMAP_REPLACE_ (
	.DO(DO), .DI(DI), .BLKSELA(BLKSEL), .BLKSELB(BLKSEL), .ADA(ADA), .ADB(ADB), .CLKA(CLKA),
	.CLKB(CLKB), .CEA(wce), .CEB(CEB), .OCE(OCE), .RESETA(RESETA), .RESETB(RESETB)
);
endmodule

module SDPX9 (DO, DI, BLKSEL, ADA, ADB, WREA, WREB, CLKA, CLKB, CEA, CEB, OCE, RESETA, RESETB);
parameter READ_MODE = 1'b0;
parameter BIT_WIDTH_0 = 36;
parameter BIT_WIDTH_1 = 36;
parameter BLK_SEL = 3'b000;
parameter RESET_MODE = "SYNC";
`ACORE_GOWIN_INIT_DECL
output [35:0] DO;
input [35:0] DI;
input [2:0] BLKSEL;
input [13:0] ADA, ADB;
input WREA, WREB, CLKA, CLKB, CEA, CEB, OCE, RESETA, RESETB;
parameter _TECHMAP_CONSTMSK_CEA_ = 0;
parameter _TECHMAP_CONSTVAL_CEA_ = 0;
parameter _TECHMAP_CONSTMSK_WREA_ = 0;
parameter _TECHMAP_CONSTVAL_WREA_ = 0;
// The write port's enable: one of the two when the other is tied high, else a LUT of both.
wire wce;
generate
  if (_TECHMAP_CONSTMSK_CEA_ && _TECHMAP_CONSTVAL_CEA_) assign wce = WREA;
  else if (_TECHMAP_CONSTMSK_WREA_ && _TECHMAP_CONSTVAL_WREA_) assign wce = CEA;
  else LUT2 #(.INIT(4'h8)) wce_lut (.F(wce), .I0(CEA), .I1(WREA));
endgenerate
SDPX9B #(
	.READ_MODE(READ_MODE), .BIT_WIDTH_0(BIT_WIDTH_0), .BIT_WIDTH_1(BIT_WIDTH_1),
	.BLK_SEL_0(BLK_SEL), .BLK_SEL_1(BLK_SEL), .RESET_MODE(RESET_MODE), `ACORE_GOWIN_INIT_PASS
) _TECHMAP_REPLACE_ (
	.DO(DO), .DI(DI), .BLKSELA(BLKSEL), .BLKSELB(BLKSEL), .ADA(ADA), .ADB(ADB), .CLKA(CLKA),
	.CLKB(CLKB), .CEA(wce), .CEB(CEB), .OCE(OCE), .RESETA(RESETA), .RESETB(RESETB)
);
endmodule
