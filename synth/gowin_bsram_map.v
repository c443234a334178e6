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

`include "gowin_bsram_init.vh"

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
