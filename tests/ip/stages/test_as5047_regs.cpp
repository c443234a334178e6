// SPDX-License-Identifier: MIT
// The AS5047P's register map as the model reads it (model/ip/stages/as5047_regs.hpp, generated from
// rtl/acore_as5047_map.txt) against the datasheet's register table (addresses, field positions,
// the ABIRES resolutions) and against what the port and the board need of it: ZPOS's two halves
// fill the board's 14-bit IF_ZERO, ERRFL's flags fit the port's three error bits, every ABIRES
// entry and UVWPP's largest pole-pair count is a value the board's ABZ_N and UVW_PP hold, HYS's
// widest hysteresis fits ABZ_HYS at the board's angle width, and ABIBIN's reset reads the board's
// reset N as ABIRES 0.
#include <gtest/gtest.h>

#include <cstdint>

#include "stages/as5047_regs.hpp"
#include "stages/board_regs.hpp"
#include "stages/interfaces.hpp"

namespace acore {
namespace {

using namespace as5047;

TEST(As5047Regs, AddressesAndFieldsAreTheDatasheets) {
  EXPECT_EQ(kNop, 0x0000);
  EXPECT_EQ(kErrfl, 0x0001);
  EXPECT_EQ(kProg, 0x0003);
  EXPECT_EQ(kZposm, 0x0016);
  EXPECT_EQ(kZposl, 0x0017);
  EXPECT_EQ(kSettings1, 0x0018);
  EXPECT_EQ(kSettings2, 0x0019);
  EXPECT_EQ(kDiaagc, 0x3FFC);
  EXPECT_EQ(kMag, 0x3FFD);
  EXPECT_EQ(kAngleunc, 0x3FFE);
  EXPECT_EQ(kAnglecom, 0x3FFF);
  EXPECT_EQ(kErrflFrerr | kErrflInvcomm | kErrflParerr, 0x7);
  EXPECT_EQ(kProgProgen, 0x01);
  EXPECT_EQ(kProgProgver, 0x40);
  EXPECT_EQ(kSettings1Dir, 1 << 2);
  EXPECT_EQ(kSettings1Daecdis, 1 << 4);
  EXPECT_EQ(kSettings1Abibin, 1 << 5);
  EXPECT_EQ(kSettings1Dataselect, 1 << 6);
  EXPECT_EQ(kSettings2UvwppMask, 0x07);
  EXPECT_EQ(kSettings2HysMask, 0x18);
  EXPECT_EQ(kSettings2AbiresMask, 0xE0);
  EXPECT_EQ(kDiaagcAgcMask, 0xFF);
  EXPECT_EQ(kDiaagcLf | kDiaagcCof | kDiaagcMagh | kDiaagcMagl, 0xF00);
  // ABIRES: decimal 1000 .. 25 pulses, binary 1024, 512, 256 (the datasheet's tables).
  const int64_t dec[] = {1000, 500, 400, 300, 200, 100, 50, 25};
  for (int c = 0; c < 8; ++c) EXPECT_EQ(abires_n(false, c), dec[c]) << c;
  for (int c = 0; c < 8; ++c) EXPECT_EQ(abires_n(true, c), c == 0 ? 1024 : c == 1 ? 512 : 256) << c;
}

TEST(As5047Regs, FitWhatThePortAndTheBoardHold) {
  // ZPOSM's and ZPOSL's halves make the 14-bit zero (the board's IF_ZERO.ZERO).
  EXPECT_EQ(kZposmZposHiBits + kZposlZposLoBits, board::kIfZeroZeroBits);
  // The port keeps ERRFL in three bits; a write's data frame carries kDataW bits.
  EXPECT_LT(kErrflFrerr | kErrflInvcomm | kErrflParerr, 1 << 3);
  for (uint16_t m : {kSettings2AbiresMask, kSettings2HysMask, kSettings2UvwppMask, kZposlErrEnMask,
                     kZposmZposHiMask})
    EXPECT_LT(m, 1 << kDataW);
  // Every table entry is an N the board holds, largest first (the read-back picks the first entry
  // not above N), and the tables' codes fit ABIRES.
  for (bool bin : {false, true}) {
    const int last = bin ? kAbiresBinLast : kAbiresDecLast;
    EXPECT_LT(last, 1 << kSettings2AbiresBits);
    for (int c = 0; c <= last; ++c) {
      const int64_t n = abires_n(bin, c);
      EXPECT_GE(n, board::kAbzNNMin);
      EXPECT_LE(n, board::kAbzNNMax);
      if (c > 0) EXPECT_LT(n, abires_n(bin, c - 1));
      EXPECT_EQ(abires_code(bin, n), c);
    }
  }
  // UVWPP's codes give pole pairs the board holds; HYS's widest window fits ABZ_HYS at the board's
  // 16-bit angle.
  EXPECT_GE(kUvwppOffset, board::kUvwPpPolePairsMin);
  EXPECT_LE(kUvwppMaxPp, board::kUvwPpPolePairsMax);
  EXPECT_LE(int64_t{kHysMax} << (16 - kHysLsbLog2), (int64_t{1} << board::kAbzHysWidthBits) - 1);
  // ABIBIN's reset reads the board's reset N (ABZ_N) as ABIRES 0.
  const int64_t n_reset = (board::kAbzNReset & board::kAbzNNMask) >> board::kAbzNNShift;
  EXPECT_EQ(abires_code(kSettings1AbibinReset != 0, n_reset), 0);
  EXPECT_EQ(abires_n(kSettings1AbibinReset != 0, 0), n_reset);
  // Every writable address is a register; NOP is one, and not writable.
  EXPECT_TRUE(known(kNop));
  EXPECT_FALSE(writable(kNop));
  for (uint16_t a = 0; a < 0x4000; ++a)
    if (writable(a)) EXPECT_TRUE(known(a)) << a;
}

}  // namespace
}  // namespace acore
