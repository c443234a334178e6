// SPDX-License-Identifier: MIT
#include "stages/interfaces.hpp"

#include <algorithm>
#include <string>

#include "core/errors.hpp"

namespace acore {

namespace {
void check_abz(int angle_w, int64_t n) {
  if (n < board::kAbzNNMin || n > board::kAbzNNMax)
    throw InputError("ABZ: N must be " + std::to_string(board::kAbzNNMin) + ".." +
                     std::to_string(board::kAbzNNMax) + " pulses a turn, not " + std::to_string(n));
  if (angle_w < 2 || angle_w > 32)
    throw InputError("ABZ: angle width must be 2..32, not " + std::to_string(angle_w));
}
}  // namespace

int64_t abz_count_of(uint64_t angle, int angle_w, int64_t n) {
  check_abz(angle_w, n);
  const uint64_t a = angle & ((uint64_t{1} << angle_w) - 1);
  // (a N) >> (angle_w - 2): the RTL's shift-add product, then its upper bits.
  uint64_t p = 0;
  for (int i = 0; i < board::kAbzNNBits; ++i)
    if ((static_cast<uint64_t>(n) >> i) & 1) p += a << i;
  return static_cast<int64_t>(p >> (angle_w - 2));
}

int64_t abz_target(uint64_t angle, int angle_w, int64_t n, int64_t hys, int64_t previous_target) {
  const int64_t lo = abz_count_of(angle, angle_w, n);
  if (hys < 0 || hys >= (int64_t{1} << (angle_w - 2)))
    throw InputError("ABZ: hysteresis must be 0.." +
                     std::to_string((int64_t{1} << (angle_w - 2)) - 1) +
                     " angle LSBs at an angle width of " + std::to_string(angle_w) + ", not " +
                     std::to_string(hys));
  const uint64_t h = static_cast<uint64_t>(hys);
  const int64_t first = abz_count_of(angle - h, angle_w, n);  // abz_count_of wraps the angle
  const int64_t last = abz_count_of(angle + h, angle_w, n);
  const bool inside = first <= last ? previous_target >= first && previous_target <= last
                                    : previous_target >= first || previous_target <= last;
  return inside ? previous_target : lo;
}

int64_t abz_rehome(int64_t count, int64_t target, int64_t n) {
  const int64_t m = 4 * n;
  const int64_t d = ((count - target) % 4 + 4) % 4;
  return ((target + (d == 3 ? -1 : d)) % m + m) % m;
}

AbzPins abz_pins(int64_t count, int64_t index) {
  return {((count >> 1) ^ count) & 1 ? true : false, ((count >> 1) & 1) != 0, count == index};
}

AbzCounter::AbzCounter(int64_t n, int spacing) : n_(n), spacing_(spacing < 1 ? 1 : spacing) {
  check_abz(16, n);
}

int AbzCounter::step() {
  if (wait_ > 0) {
    --wait_;
    return 0;
  }
  if (count_ == target_) return 0;
  const int64_t m = 4 * n_;
  const int64_t d = ((target_ - count_) % m + m) % m;
  const int dir = d <= 2 * n_ ? 1 : -1;
  count_ = ((count_ + dir) % m + m) % m;
  wait_ = spacing_ - 1;
  return dir;
}

void AbzCounter::rehome(int64_t n, int64_t target) {
  check_abz(16, n);
  count_ = abz_rehome(count_, target, n);
  n_ = n;
  target_ = target;
}

UvwState uvw_state(uint64_t angle, uint64_t offset, int angle_w, int pole_pairs) {
  if (pole_pairs < board::kUvwPpPolePairsMin || pole_pairs > board::kUvwPpPolePairsMax)
    throw InputError("UVW: pole pairs must be " + std::to_string(board::kUvwPpPolePairsMin) + ".." +
                     std::to_string(board::kUvwPpPolePairsMax) + ", not " +
                     std::to_string(pole_pairs));
  if (angle_w < 3 || angle_w > 32)
    throw InputError("UVW: angle width must be 3..32, not " + std::to_string(angle_w));
  const uint64_t mask = (uint64_t{1} << angle_w) - 1;
  const uint64_t d = (angle - offset) & mask;
  uint64_t e = 0;
  for (int i = 0; i < board::kUvwPpPolePairsBits; ++i)
    if ((pole_pairs >> i) & 1) e += d << i;
  e &= mask;
  // Sector thresholds ceil(k 2^angle_w / 6), as the RTL's constants.
  int s = 0;
  for (int k = 1; k <= 5; ++k) {
    const uint64_t t = ((uint64_t{1} << angle_w) * static_cast<uint64_t>(k) + 5) / 6;
    if (e >= t) s = k;
  }
  return {s, s <= 2, s >= 2 && s <= 4, s >= 4 || s == 0};
}

namespace as5047 {
bool parity_even(uint16_t word) {
  int c = 0;
  for (int i = 0; i < 16; ++i) c ^= (word >> i) & 1;
  return c == 0;
}
uint16_t with_even_parity(uint16_t word15) {
  const uint16_t w = word15 & 0x7FFF;
  return static_cast<uint16_t>(w | (parity_even(w) ? 0 : 0x8000));
}
}  // namespace as5047

namespace as5047 {
int64_t abires_n(bool binary, int code) {
  const int c = code & 7;
  if (binary) return kAbiresBin[c < kAbiresBinLast ? c : kAbiresBinLast];
  return kAbiresDec[c < kAbiresDecLast ? c : kAbiresDecLast];
}
int abires_code(bool binary, int64_t n) {
  const int last = binary ? kAbiresBinLast : kAbiresDecLast;
  for (int c = 0; c <= last; ++c)
    if (n >= abires_n(binary, c)) return c;
  return last;
}
}  // namespace as5047

namespace {
// A field of a register's word: its value, and the word with it replaced.
constexpr uint16_t get(uint16_t word, uint16_t mask) {
  int shift = 0;
  while (!((mask >> shift) & 1)) ++shift;
  return static_cast<uint16_t>((word & mask) >> shift);
}
constexpr uint16_t put(uint16_t word, uint16_t mask, int value) {
  int shift = 0;
  while (!((mask >> shift) & 1)) ++shift;
  return static_cast<uint16_t>((word & ~mask) | ((value << shift) & mask));
}
// UVWPP of a pole-pair count (read back), and the pole pairs of a code (written).
int uvwpp_code(int pole_pairs) {
  using namespace as5047;
  const int pp = pole_pairs >= kUvwppMaxPp   ? kUvwppMaxPp
                 : pole_pairs < kUvwppOffset ? kUvwppOffset
                                             : pole_pairs;
  return pp - kUvwppOffset;
}
int uvwpp_pole_pairs(int code) {
  using namespace as5047;
  return code + kUvwppOffset >= kUvwppMaxPp ? kUvwppMaxPp : code + kUvwppOffset;
}
}  // namespace

uint16_t as5047::mag_field(int64_t magnitude, int mag_w) {
  if (mag_w < kMagFieldBits + 1 || magnitude < 0)
    throw InputError("MAG: magnitude " + std::to_string(magnitude) + " of " +
                     std::to_string(mag_w) + " bits (at least " +
                     std::to_string(kMagFieldBits + 1) + " bits, not negative)");
  const int64_t field_max = (int64_t{1} << kMagFieldBits) - 1;
  return static_cast<uint16_t>(std::min(magnitude >> (mag_w - kMagFieldBits - 1), field_max));
}

uint8_t as5047::agc_field(int64_t magnitude, int s_f) {
  if (magnitude < 0) throw InputError("AGC: negative magnitude " + std::to_string(magnitude));
  // lg m in 1/32: the leading one's position e and the 5 bits below it (zeros below bit 0).
  int e = 0;
  while (e < 62 && (magnitude >> (e + 1)) != 0) ++e;
  const int64_t f = e >= 5 ? (magnitude >> (e - 5)) & 31 : (magnitude << (5 - e)) & 31;
  const int64_t agc = kAgcMid + int64_t{kAgcOctave} * s_f + kAgcGainF - (kAgcOctave * e + f);
  return static_cast<uint8_t>(std::clamp<int64_t>(agc, 0, (int64_t{1} << kAgcBits) - 1));
}

uint16_t As5047Port::read_register(uint16_t addr, const As5047Inputs& in) const {
  using namespace as5047;
  const auto top14 = [&](uint64_t a) {
    return static_cast<uint16_t>((a >> (in.angle_w - 14)) & 0x3FFF);
  };
  switch (addr) {
    case kErrfl:
      return errfl_;
    case kProg: {
      uint16_t w = put(kProgFixed, kProgProgen, progen_);
      return put(w, kProgProgver, progver_);
    }
    case kZposm:
      return put(kZposmFixed, kZposmZposHiMask, config.zero >> kZposlZposLoBits);
    case kZposl: {
      const uint16_t w = put(kZposlFixed, kZposlErrEnMask, error_enables_);
      return put(w, kZposlZposLoMask, config.zero & ((1 << kZposlZposLoBits) - 1));
    }
    case kSettings1: {
      uint16_t w = kSettings1Fixed;
      w = put(w, kSettings1Pwmon, pwmon_);
      w = put(w, kSettings1Dataselect, dataselect_);
      w = put(w, kSettings1Abibin, abibin_);
      w = put(w, kSettings1Daecdis, !config.daec);
      w = put(w, kSettings1UvwAbi, uvw_abi_);
      return put(w, kSettings1Dir, config.dir);
    }
    case kSettings2: {
      // HYS: kHysMax - ceil(hys / LSB), at least 0 (the LSB 2^-kHysLsbLog2 turn).
      const int64_t lsb = int64_t{1} << (in.angle_w - kHysLsbLog2);
      const int64_t lsbs = (config.hys + lsb - 1) / lsb;
      const int hys = lsbs >= kHysMax ? 0 : static_cast<int>(kHysMax - lsbs);
      uint16_t w = put(kSettings2Fixed, kSettings2AbiresMask, abires_code(abibin_, config.n));
      w = put(w, kSettings2HysMask, hys);
      return put(w, kSettings2UvwppMask, uvwpp_code(config.pole_pairs));
    }
    case kDiaagc: {
      uint16_t w = put(kDiaagcFixed, kDiaagcMagl, in.los);
      w = put(w, kDiaagcMagh, in.dos);
      w = put(w, kDiaagcCof, in.ovf);
      w = put(w, kDiaagcLf, !in.lot);
      return put(w, kDiaagcAgcMask, in.agc);
    }
    case kMag:
      return in.mag & 0x3FFF;
    case kAngleunc:
      return top14(in.angle_unc);
    case kAnglecom:
      return top14(dataselect_ ? in.angle_unc : in.angle_com);
    default:
      return 0;
  }
}

void As5047Port::write_register(uint16_t addr, uint16_t data, int angle_w) {
  using namespace as5047;
  const int zpos_lo = (1 << kZposlZposLoBits) - 1;
  switch (addr) {
    case kProg:
      progen_ = get(data, kProgProgen);
      progver_ = get(data, kProgProgver);
      break;
    case kZposm:
      config.zero = static_cast<uint16_t>((get(data, kZposmZposHiMask) << kZposlZposLoBits) |
                                          (config.zero & zpos_lo));
      break;
    case kZposl:
      config.zero =
          static_cast<uint16_t>((config.zero & ~zpos_lo & 0x3FFF) | get(data, kZposlZposLoMask));
      error_enables_ = get(data, kZposlErrEnMask);
      break;
    case kSettings1: {
      const bool bin = get(data, kSettings1Abibin);
      if (bin != abibin_) config.n = abires_n(bin, abires_code(abibin_, config.n));
      config.dir = get(data, kSettings1Dir);
      config.daec = !get(data, kSettings1Daecdis);
      uvw_abi_ = get(data, kSettings1UvwAbi);
      abibin_ = bin;
      dataselect_ = get(data, kSettings1Dataselect);
      pwmon_ = get(data, kSettings1Pwmon);
      break;
    }
    case kSettings2:
      config.pole_pairs = uvwpp_pole_pairs(get(data, kSettings2UvwppMask));
      config.hys = static_cast<int64_t>(kHysMax - get(data, kSettings2HysMask))
                   << (angle_w - kHysLsbLog2);
      config.n = abires_n(abibin_, get(data, kSettings2AbiresMask));
      break;
    default:
      break;
  }
}

uint16_t As5047Port::frame(uint16_t mosi, const As5047Inputs& in, int bits, bool short_gap) {
  using namespace as5047;
  // The answer, from the register chosen by the previous frame, as the frame starts.
  const uint16_t data = read_register(answer_reg_, in);
  const bool ef = errfl_ != 0;
  const uint16_t answer = short_gap
                              ? uint16_t{0xC000}
                              : with_even_parity(static_cast<uint16_t>((ef ? 0x4000 : 0) | data));
  if (answer_reg_ == kErrfl && !short_gap) errfl_ = 0;  // read clears
  // The command at the end of the frame.
  const uint16_t addr = mosi & 0x3FFF;
  const bool read = (mosi >> 14) & 1;
  const bool is_writable = writable(addr);
  const bool is_known = known(addr);
  const bool write = !read && addr != kNop;
  if (bits != 16 || short_gap) {
    errfl_ |= kErrflFrerr;
    answer_reg_ = kNop;
    if (bits == 16) write_data_ = false;
  } else if (!parity_even(mosi)) {
    errfl_ |= kErrflParerr;
    answer_reg_ = kNop;
    write_data_ = false;
  } else if (write_data_) {
    // The data frame: the register written, its new content answered next.
    write_data_ = false;
    if (write_reg_ != kNop)
      write_register(write_reg_, static_cast<uint16_t>(mosi & ((1 << kDataW) - 1)), in.angle_w);
    answer_reg_ = write_reg_;
  } else {
    if (!is_known || (write && !is_writable)) errfl_ |= kErrflInvcomm;
    write_data_ = write;
    write_reg_ = write && is_writable ? addr : kNop;
    answer_reg_ = (read && is_known) || (write && is_writable) ? addr : kNop;
  }
  // The answer the master received: only the bits it clocked.
  return bits >= 16 ? answer : static_cast<uint16_t>(answer >> (16 - bits));
}

}  // namespace acore
