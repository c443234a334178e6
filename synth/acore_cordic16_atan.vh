// SPDX-License-Identifier: MIT
// The stand-alone 16-bit CORDIC's parameters and arctangent table, for synth/acore_cordic16.v:
// the `cordic16` line of rtl/configs.txt, and atan_i = round(atan(2^-i) / 2 pi * 2^Z_W) from
// cordic_atan_table() of model/ip/stages/cordic.cpp. Written by (from the repository root)
//   acore_gen_tables cordic16_atan IN_W=16 G=4 Z_W=21 ANGLE_W=16 K=17 AT_W=20 NORM=1 SPLIT=1 > synth/acore_cordic16_atan.vh
// (model/cli/gen_tables.cpp); do not edit: the CTest gen_tables_current compares it.
localparam integer C16_IN_W = 16;
localparam integer C16_G = 4;
localparam integer C16_Z_W = 21;
localparam integer C16_ANGLE_W = 16;
localparam integer C16_K = 17;
localparam integer C16_AT_W = 20;
localparam integer C16_NORM = 1;
localparam integer C16_SPLIT = 1;
// atan(2^-0) = 262144 = 45.000000 deg
// atan(2^-1) = 154753 = 26.565113 deg
// atan(2^-2) = 81767 = 14.036236 deg
// atan(2^-3) = 41506 = 7.124977 deg
// atan(2^-4) = 20834 = 3.576393 deg
// atan(2^-5) = 10427 = 1.789913 deg
// atan(2^-6) = 5215 = 0.895214 deg
// atan(2^-7) = 2608 = 0.447693 deg
// atan(2^-8) = 1304 = 0.223846 deg
// atan(2^-9) = 652 = 0.111923 deg
// atan(2^-10) = 326 = 0.055962 deg
// atan(2^-11) = 163 = 0.027981 deg
// atan(2^-12) = 81 = 0.013905 deg
// atan(2^-13) = 41 = 0.007038 deg
// atan(2^-14) = 20 = 0.003433 deg
// atan(2^-15) = 10 = 0.001717 deg
// atan(2^-16) = 5 = 0.000858 deg
localparam [339:0] C16_ATAN = 340'h50000a000140002900051000a3001460028c0051800a300145f028bb051620a22213f6725c8140000;
