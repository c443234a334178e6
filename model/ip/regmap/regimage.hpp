// SPDX-License-Identifier: MIT
// The coefficient register image (docs/contracts.md, register image): $readmemh text, one hex word
// per line in address order, `//` comments. The header records the configuration as `// acore:
// key=value` lines so an image is self-describing; readers that only want the words ($readmemh)
// ignore them.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/angle.hpp"
#include "core/datapath_config.hpp"

namespace acore {

struct RegImage {
  DatapathConfig cfg;
  double in_scale = 8192.0;     // input codes per recording unit (the "ADC" gain), a power of two
  std::vector<uint64_t> words;  // REG_W-bit words, unsigned, in address order
  std::vector<std::string> provenance;  // free text lines for the header (command, date, ...)
  // The calibration's constant electrical angle offset, sensor angle - p theta_ref, in rad, wrapped
  // to [-pi, pi) (docs/datapath.md "Zero offset"); header keys zero_offset_rad and
  // zero_offset_code, absent (images made before) = 0. The estimate subtracts it in software unless
  // the ZERO word does.
  double zero_offset = 0.0;

  // Field accessors: the field integer of a word as the codec table reads it (regmap/codec.hpp:
  // the field's low bits, sign-extended where the field is signed).
  int64_t offset(int curve) const;
  int64_t recip(int curve) const;
  int64_t poly(int region, int curve, int power) const;
  int64_t atan(int i) const;
  // Fourier word j: a_0 (REG_W bits), a'_1, b'_1, ... (their low fourier_word_w bits), signed.
  int64_t fourier(int j) const;
  // The ZERO word's zero position: its low ANGLE_W bits (cfg.zero_word = 1 only).
  uint32_t zero_position() const;
  // zero_offset as an ANGLE_W-bit angle code: round(zero_offset / 2 pi * 2^ANGLE_W) mod 2^ANGLE_W.
  uint32_t zero_offset_code() const;
  // The offset the estimate subtracts in software to bring the chain's output into the reference
  // frame: zero_offset without the ZERO word, 0 with it (the hardware subtracts the word).
  double software_zero_offset() const { return cfg.zero_word ? 0.0 : zero_offset; }
  // The offset the whole chain removes (rad, wrapped): the ZERO word's value, or zero_offset.
  double applied_zero_offset() const;
  // Header key zero_reference=none (a self-calibration: the zero offset is unknown, errors against
  // a reference are judged about their mean); absent: the image's zero is the reference's.
  bool zero_reference_unknown() const {
    for (const auto& p : provenance)
      if (p == "zero_reference=none") return true;
    return false;
  }
  void set_signed(int addr, int64_t value);  // throws InputError when value does not fit REG_W
  void set_unsigned(int addr, int64_t value);
};

// CRC-32 of the words as the register shell (rtl/acore_apb.v) computes it: zlib's crc32 (IEEE
// 802.3) over each word zero-extended to 32 bits, four little-endian bytes, in address order. The
// image text carries it as `// acore: crc32=0x...`; a reader checks it when present.
uint32_t image_crc32(const RegImage& img);
RegImage read_regimage(const std::string& path);
RegImage parse_regimage(const std::string& text, const std::string& name);
std::string format_regimage(const RegImage& img);  // with a human value per word
void write_regimage(const RegImage& img, const std::string& path);

}  // namespace acore
