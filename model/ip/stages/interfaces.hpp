// SPDX-License-Identifier: MIT
// The drive interfaces on the angle stream, bit-exact with rtl/acore_abz.v, rtl/acore_uvw.v and
// rtl/acore_spi_as5047.v (what they compute; the RTL's clock timing is documented in each module):
//   - ABZ: the count a quadrature decoder reads once the output has caught up, with the one-LSB
//     hysteresis, and the step-by-step walk toward it (the shorter way, at most one edge per
//     `spacing` clocks);
//   - UVW: the six-step sector of the electrical angle ((angle - offset) pole_pairs) and the three
//     signals;
//   - the AS5047P-compatible SPI port at frame level: command in, the answer of the previous
//     command out, ERRFL and the error flag.
// Register values outside their ranges (N, pole pairs: the board's registers ABZ_N and UVW_PP,
// stages/board_regs.hpp, generated from their description rtl/acore_board_regs.txt) are refused
// with InputError, as the board refuses the write (the RTL clamps what reaches it).
#pragma once
#include <cstdint>

#include "stages/as5047_regs.hpp"
#include "stages/board_regs.hpp"

namespace acore {

// ---- ABZ
// --------------------------------------------------------------------------------------------
// N, pulses a turn: board::kAbzNNMin .. board::kAbzNNMax (the board's ABZ_N.N, kAbzNNBits bits).

// floor(angle 4N / 2^angle_w): the count of an angle (0 .. 4N-1). Throws InputError on N outside
// its range or an angle_w outside 2..32.
int64_t abz_count_of(uint64_t angle, int angle_w, int64_t n);
// The target after a new angle given the previous target, with a hysteresis of `hys` angle LSBs:
// the previous target holds while it is one of the counts the window angle - hys .. angle + hys
// touches (round the turn: abz_count_of(angle - hys) .. abz_count_of(angle + hys)), otherwise the
// target is the angle's count. hys = 0: the angle's count. Throws InputError on hys outside
// 0 .. 2^(angle_w-2) - 1 (the window stays below a quarter turn).
int64_t abz_target(uint64_t angle, int angle_w, int64_t n, int64_t hys, int64_t previous_target);
// A change of N re-homes the count without an edge: the count keeps its two low bits (A and B
// hold) and takes the value nearest the new target (target + d, d = (count - target) mod 4 in
// 0..2, or target - 1 for d = 3, round the new turn of 4n counts); it then walks to the target.
int64_t abz_rehome(int64_t count, int64_t target, int64_t n);
// A quadrature pair from a count: A = c1 ^ c0, B = c1 (Gray 00, 10, 11, 01 forward).
struct AbzPins {
  bool a, b, z;
};
AbzPins abz_pins(int64_t count, int64_t index);

// The count walking toward its target, one clock per step() (acore_abz.v's count register).
class AbzCounter {
 public:
  AbzCounter(int64_t n, int spacing);
  void set_target(int64_t target) { target_ = target; }
  // A new N (acore_abz.v's re-homing): the count as abz_rehome() puts it, the target given.
  void rehome(int64_t n, int64_t target);
  // One clock: a step toward the target (the shorter way, a half turn forward) when the spacing
  // since the last edge has passed. Returns +1, -1 or 0.
  int step();
  int64_t count() const { return count_; }
  int64_t target() const { return target_; }

 private:
  int64_t n_, count_ = 0, target_ = 0;
  int spacing_, wait_ = 0;
};

// ---- UVW
// --------------------------------------------------------------------------------------------
// Pole pairs: board::kUvwPpPolePairsMin .. board::kUvwPpPolePairsMax (the board's UVW_PP).

struct UvwState {
  int sector;  // 0..5: floor(6 e / 2^angle_w)
  bool u, v, w;
};
// The electrical angle e = ((angle - offset) pole_pairs) mod 2^angle_w, its sector and U, V, W
// (U in sectors 0-2, V in 2-4, W in 4, 5, 0). Throws InputError on pole_pairs outside their range.
UvwState uvw_state(uint64_t angle, uint64_t offset, int angle_w, int pole_pairs);

// ---- AS5047P SPI
// ----------------------------------------------------------------------------------
// The registers' addresses, fields, ABIRES's tables and the HYS and UVWPP encodings:
// stages/as5047_regs.hpp, generated from their description rtl/acore_as5047_map.txt.
namespace as5047 {
// ABIRES's tables (SETTINGS1.ABIBIN 1: binary, 0: decimal): N of a code, and the code read back
// for an N (the first entry, largest N first, not above it; the last otherwise).
int64_t abires_n(bool binary, int code);
int abires_code(bool binary, int64_t n);
// MAG and DIAAGC.AGC of the board (rtl/acore_board.v's header has the definition) from the
// estimator's magnitude m (FixedSample::magnitude, mag_w = S_W + 2 bits, 2^s_f per unit of the
// scaled inputs times the CORDIC gain): MAG = m >> (mag_w - 15), saturated to 14 bits; AGC =
// 128 + 32 (s_f + 20/32 - lg m) clamped to 0..255, lg m = e + f/32 by m's leading one e and the
// 5 bits f below it (m = 0: 255). High for a weak field, low for a strong one, as the AS5047P's.
// The fields' widths are the board's MAG_AGC register's (its description); the AGC constants are
// rtl/acore_board.v's AGC_MID, AGC_OCTAVE and AGC_GAIN_F.
constexpr int kMagFieldBits = board::kMagAgcMagBits;
constexpr int kAgcBits = board::kMagAgcAgcBits;
constexpr int kAgcMid = 128, kAgcOctave = 32, kAgcGainF = 20;
uint16_t mag_field(int64_t magnitude, int mag_w);
uint8_t agc_field(int64_t magnitude, int s_f);
// The 16-bit word with bit 15 set so that its parity is even.
uint16_t with_even_parity(uint16_t word15);
bool parity_even(uint16_t word);
}  // namespace as5047

// What the port's registers read (the angles' upper 14 bits are sent).
struct As5047Inputs {
  uint64_t angle_unc = 0, angle_com = 0;
  int angle_w = 16;
  uint16_t mag = 0;
  uint8_t agc = 0;
  bool los = false, dos = false, ovf = false, lot = false;
};

// The AS5047P settings the port maps onto the board's registers (rtl/acore_spi_as5047.v's header):
// IF_ZERO.ZERO (ZPOS, 2^-14 turn), IF_CTRL.DIR, IF_CTRL.DAEC (not DAECDIS), ABZ_N (ABIRES with
// ABIBIN), UVW_PP (UVWPP + kUvwppOffset, at most kUvwppMaxPp), ABZ_HYS ((kHysMax - HYS) LSBs of
// 2^-kHysLsbLog2 turn, in angle LSBs). Their reset values are the board's.
struct As5047Config {
  uint16_t zero = 0;
  bool dir = false, daec = true;
  int64_t n = 1024;
  int pole_pairs = 1;
  int64_t hys = 2;
};

// The port at frame level: frame() takes the master's word and clock count and returns the word
// the port sent (the answer prepared by the previous frame, from `in` as it is when this frame
// starts). short_gap: CSn was high for less than 2 clocks before this frame (the RTL's minimum):
// a framing error, the frame answers 0xC000 (EF, even parity, data 0) and its command is ignored.
class As5047Port {
 public:
  // The settings (`config`, the board's registers) are read for the answers and written by a
  // write's data frame.
  uint16_t frame(uint16_t mosi, const As5047Inputs& in, int bits = 16, bool short_gap = false);
  uint16_t errfl() const { return errfl_; }
  As5047Config config;

 private:
  uint16_t read_register(uint16_t addr, const As5047Inputs& in) const;
  void write_register(uint16_t addr, uint16_t data, int angle_w);
  uint16_t errfl_ = 0;
  uint16_t answer_reg_ = as5047::kNop;
  bool write_data_ = false;
  uint16_t write_reg_ = as5047::kNop;
  // What only the port keeps: PROG's PROGEN and PROGVER, ZPOSL's error enables, SETTINGS1's
  // UVW_ABI, ABIBIN (reset 1), Dataselect, PWMon.
  bool progen_ = as5047::kProgProgenReset != 0, progver_ = as5047::kProgProgverReset != 0,
       uvw_abi_ = as5047::kSettings1UvwAbiReset != 0, abibin_ = as5047::kSettings1AbibinReset != 0,
       dataselect_ = as5047::kSettings1DataselectReset != 0,
       pwmon_ = as5047::kSettings1PwmonReset != 0;
  int error_enables_ = as5047::kZposlErrEnReset;
};

}  // namespace acore
