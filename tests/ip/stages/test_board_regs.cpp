// SPDX-License-Identifier: MIT
// The board's register map as the model reads it (model/ip/stages/board_regs.hpp, generated from
// rtl/acore_board_regs.txt) against what the blocks behind the registers take: the ABZ and UVW
// ranges are the values their inputs hold without clamping (1 .. 2^(bits-1), as rtl/acore_abz.v and
// rtl/acore_uvw.v clamp), the index register holds every count 0..4N-1, the reset values are
// registers the observer's model accepts (TrackRegs{} against TrackConfig{}), and TRK_POSITION's
// two fields fill its word without overlap.
#include <gtest/gtest.h>

#include <cstdint>

#include "core/errors.hpp"
#include "stages/board_regs.hpp"
#include "stages/interfaces.hpp"
#include "stages/tracker.hpp"

namespace acore {
namespace {

TEST(BoardRegs, RangesAreWhatTheInterfacesTakeUnclamped) {
  EXPECT_EQ(board::kAbzNNMin, 1);
  EXPECT_EQ(board::kAbzNNMax, int64_t{1} << (board::kAbzNNBits - 1));
  EXPECT_EQ(board::kUvwPpPolePairsMin, 1);
  EXPECT_EQ(board::kUvwPpPolePairsMax, int64_t{1} << (board::kUvwPpPolePairsBits - 1));
  // The largest count, 4 N - 1 at the largest N, fits the index register.
  EXPECT_LE(4 * board::kAbzNNMax - 1, (int64_t{1} << board::kAbzIndexPosBits) - 1);
  // The reset values lie in their ranges, and the interfaces' models take them.
  const int64_t n = (board::kAbzNReset & board::kAbzNNMask) >> board::kAbzNNShift;
  const int pp = static_cast<int>((board::kUvwPpReset & board::kUvwPpPolePairsMask) >>
                                  board::kUvwPpPolePairsShift);
  EXPECT_GE(n, board::kAbzNNMin);
  EXPECT_LE(n, board::kAbzNNMax);
  EXPECT_NO_THROW(abz_count_of(0, 16, n));
  EXPECT_NO_THROW(uvw_state(0, 0, 16, pp));
}

TEST(BoardRegs, ResetValuesAreRegistersTheObserverAccepts) {
  const TrackConfig c;
  const TrackRegs r;
  EXPECT_NO_THROW(c.validate());
  EXPECT_NO_THROW(r.validate(c));
  EXPECT_GE(r.bw, TrackConfig::kMin);
  EXPECT_LE(r.bw, c.k_max());
  EXPECT_EQ(c.lead_w, board::kTrkLeadLeadBits);
  EXPECT_LE(c.lead_f, c.lead_w);
  // The threshold is below half a turn (the largest error) at the default angle width.
  EXPECT_LT(r.lot_thr, uint32_t{1} << (c.angle_w - 1));
}

TEST(BoardRegs, PositionFieldsFillTheirWord) {
  EXPECT_EQ(board::kTrkPositionAngleShift, 0);
  EXPECT_EQ(board::kTrkPositionTurnsShift, board::kTrkPositionAngleBits);
  EXPECT_EQ(board::kTrkPositionTurnsShift + board::kTrkPositionTurnsBits, 32);
  EXPECT_EQ(board::kTrkPositionTurnsMask & board::kTrkPositionAngleMask, 0u);
  EXPECT_EQ(board::kTrkPositionTurnsMask | board::kTrkPositionAngleMask, 0xFFFFFFFFu);
  EXPECT_EQ(board::kTrkVelocityVelocityBits, 32);
}

}  // namespace
}  // namespace acore
