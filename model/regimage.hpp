// SPDX-License-Identifier: MIT
// The coefficient register image (DESIGN 3.2): $readmemh text, one hex word per line in address
// order, `//` comments. The header records the configuration as `// acore: key=value` lines so an
// image is self-describing; readers that only want the words ($readmemh) ignore them.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "datapath_config.hpp"

namespace acore {

struct RegImage {
  DatapathConfig cfg;
  double in_scale = 8192.0;     // input codes per recording unit (the "ADC" gain), a power of two
  std::vector<uint64_t> words;  // REG_W-bit words, unsigned, in address order
  std::vector<std::string> provenance;  // free text lines for the header (command, date, ...)

  // Field accessors (sign-extended where the field is signed).
  int64_t offset(int curve) const;
  int64_t recip(int curve) const;
  int64_t poly(int region, int curve, int power) const;
  int64_t atan(int i) const;
  // Fourier word j: a_0 (REG_W bits), a'_1, b'_1, ... (their low fourier_word_w bits), signed.
  int64_t fourier(int j) const;
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
