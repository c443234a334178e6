// SPDX-License-Identifier: MIT
#include "regmap/regimage.hpp"

#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <tuple>

#include "core/errors.hpp"
#include "core/fixed_point.hpp"
#include "regmap/codec.hpp"

namespace acore {

namespace {

// The header's configuration keys in the order images have always had them: the correction,
// then the keys written always, those of the Fourier stage (only with it) and zero_word (only when
// 1), each group alphabetically. The table is DatapathConfig's (config_fields()).
std::vector<const ConfigField*> header_fields() {
  std::vector<const ConfigField*> v;
  for (const ConfigField& f : config_fields())
    if (f.in_image) v.push_back(&f);
  auto rank = [](const ConfigField* f) {
    return std::make_tuple(f->member != &DatapathConfig::correction, static_cast<int>(f->shown),
                           std::string(f->key));
  };
  std::sort(v.begin(), v.end(), [&](auto* a, auto* b) { return rank(a) < rank(b); });
  return v;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

}  // namespace

namespace {
int64_t field_of(const RegImage& img, const CodecField& f) { return f.field(img.words.at(f.addr)); }
}  // namespace

int64_t RegImage::offset(int curve) const { return field_of(*this, offset_field(cfg, curve)); }
int64_t RegImage::recip(int curve) const { return field_of(*this, recip_field(cfg, curve)); }
int64_t RegImage::poly(int r, int c, int j) const {
  return field_of(*this, poly_field(cfg, r, c, j));
}
int64_t RegImage::atan(int i) const { return field_of(*this, atan_field(cfg, i)); }
int64_t RegImage::fourier(int j) const { return field_of(*this, fourier_field(cfg, j)); }
uint32_t RegImage::zero_position() const {
  return static_cast<uint32_t>(field_of(*this, zero_field(cfg)));
}

uint32_t RegImage::zero_offset_code() const { return angle_code(zero_offset, cfg.angle_w); }

double RegImage::applied_zero_offset() const {
  return cfg.zero_word ? code_angle(zero_position(), cfg.angle_w) : zero_offset;
}

void RegImage::set_signed(int addr, int64_t value) {
  if (value > fx::smax(cfg.reg_w) || value < fx::smin(cfg.reg_w))
    throw InputError(fmt::format("register {}: value {} does not fit a signed {}-bit word", addr,
                                 value, cfg.reg_w));
  words.at(addr) = static_cast<uint64_t>(value) & fx::mask(cfg.reg_w);
}

void RegImage::set_unsigned(int addr, int64_t value) {
  if (value < 0 || static_cast<uint64_t>(value) > fx::mask(cfg.reg_w))
    throw InputError(fmt::format("register {}: value {} does not fit an unsigned {}-bit word", addr,
                                 value, cfg.reg_w));
  words.at(addr) = static_cast<uint64_t>(value);
}

uint32_t image_crc32(const RegImage& img) {
  std::vector<unsigned char> bytes;
  bytes.reserve(img.words.size() * 4);
  for (const uint64_t w : img.words)
    for (int b = 0; b < 4; ++b) bytes.push_back(static_cast<unsigned char>((w >> (8 * b)) & 0xff));
  return static_cast<uint32_t>(
      crc32(crc32(0L, Z_NULL, 0), bytes.data(), static_cast<uInt>(bytes.size())));
}

RegImage parse_regimage(const std::string& text, const std::string& name) {
  RegImage img;
  const std::vector<const ConfigField*> fields = header_fields();
  std::istringstream in(text);
  std::string line;
  int lineno = 0;
  bool in_scale_seen = false;
  int crc_line = 0;  // line of the crc32 key (0: absent; images before the key have none)
  uint32_t crc_header = 0;
  // The zero offset's two keys (rad, and the code of angle_w bits), checked once angle_w is known.
  int rad_line = 0, code_line = 0;
  long long zero_code = 0;
  while (std::getline(in, line)) {
    ++lineno;
    std::string comment;
    if (const auto pos = line.find("//"); pos != std::string::npos) {
      comment = trim(line.substr(pos + 2));
      line = line.substr(0, pos);
    }
    if (comment.rfind("acore:", 0) == 0) {
      const std::string kv = trim(comment.substr(6));
      const auto eq = kv.find('=');
      if (eq == std::string::npos)
        throw InputError(fmt::format("{}:{}: header: expected 'acore: key=value'", name, lineno));
      const std::string key = trim(kv.substr(0, eq)), val = trim(kv.substr(eq + 1));
      try {
        size_t used = 0;
        if (key == "in_scale") {
          img.in_scale = std::stod(val, &used);
          in_scale_seen = true;
          if (!(img.in_scale > 0) || !std::isfinite(img.in_scale)) used = 0;
        } else if (key == "crc32") {
          if (val.rfind("0x", 0) != 0 || val.size() < 3 || val.size() > 10 ||
              val.find_first_not_of("0123456789abcdefABCDEF", 2) != std::string::npos)
            throw std::invalid_argument(val);
          crc_header = static_cast<uint32_t>(std::stoul(val.substr(2), &used, 16));
          used += 2;
          crc_line = lineno;
        } else if (key == "zero_offset_rad") {
          img.zero_offset = std::stod(val, &used);
          if (!(std::fabs(img.zero_offset) <= M_PI)) used = 0;  // also NaN: an angle in [-pi, pi]
          if (img.zero_offset >= M_PI) img.zero_offset -= 2 * M_PI;
          rad_line = lineno;
        } else if (key == "zero_offset_code") {
          zero_code = std::stoll(val, &used);
          if (zero_code < 0 || val[0] == '-' || val[0] == '+') used = 0;
          code_line = lineno;
        } else if (auto it = std::find_if(fields.begin(), fields.end(),
                                          [&](const ConfigField* f) { return key == f->key; });
                   it != fields.end()) {
          // An absent key keeps the default (correction=poly in images made before the field).
          set_field_text(**it, &img.cfg, val);
          used = val.size();
        } else {
          used = val.size();  // unknown keys (command, date, ...) are provenance
          img.provenance.push_back(kv);
        }
        if (used != val.size()) throw std::invalid_argument(val);
      } catch (const std::exception&) {
        throw InputError(
            fmt::format("{}:{}: header field '{}': bad value '{}'", name, lineno, key, val));
      }
      continue;
    }
    const std::string word = trim(line);
    if (word.empty()) continue;
    if (word.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos || word.size() > 15)
      throw InputError(fmt::format("{}:{}: word {}: '{}' is not a hex word", name, lineno,
                                   img.words.size(), word));
    img.words.push_back(std::stoull(word, nullptr, 16));
  }
  try {
    img.cfg.validate();
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: header: {}", name, e.what()));
  }
  if (!in_scale_seen)
    throw InputError(fmt::format("{}: header: missing 'acore: in_scale=...'", name));
  if (code_line) {
    const long long max = (1LL << img.cfg.angle_w) - 1;
    if (zero_code > max)
      throw InputError(
          fmt::format("{}:{}: header field 'zero_offset_code': {} does not fit angle_w={} bits",
                      name, code_line, zero_code, img.cfg.angle_w));
    if (!rad_line) img.zero_offset = code_angle(static_cast<uint32_t>(zero_code), img.cfg.angle_w);
    if (img.zero_offset_code() != static_cast<uint32_t>(zero_code))
      throw InputError(fmt::format(
          "{}:{}: header field 'zero_offset_code': {} is not zero_offset_rad={} as a "
          "{}-bit angle code ({})",
          name, code_line, zero_code, img.zero_offset, img.cfg.angle_w, img.zero_offset_code()));
  }
  if (static_cast<int>(img.words.size()) != img.cfg.words())
    throw InputError(fmt::format("{}: {} words, but the header's configuration needs {} ({})", name,
                                 img.words.size(), img.cfg.words(), img.cfg.describe()));
  for (size_t a = 0; a < img.words.size(); ++a)
    if (img.words[a] > fx::mask(img.cfg.reg_w))
      throw InputError(fmt::format("{}: word {} = {:x} does not fit {} bits", name, a, img.words[a],
                                   img.cfg.reg_w));
  if (crc_line && crc_header != image_crc32(img))
    throw InputError(
        fmt::format("{}:{}: header field 'crc32': 0x{:08x}, but the words' CRC-32 is 0x{:08x} "
                    "(a word was changed after the image was written)",
                    name, crc_line, crc_header, image_crc32(img)));
  return img;
}

RegImage read_regimage(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError(fmt::format("{}: cannot open register image", path));
  std::stringstream ss;
  ss << f.rdbuf();
  return parse_regimage(ss.str(), path);
}

std::string format_regimage(const RegImage& img) {
  const DatapathConfig& c = img.cfg;
  std::string out = "// AngleCore coefficient register image ($readmemh), docs/register-map.md\n";
  for (const auto& p : img.provenance) out += "// acore: " + p + "\n";
  out += fmt::format("// acore: in_scale={}\n", img.in_scale);
  out += fmt::format("// acore: crc32=0x{:08x}\n", image_crc32(img));
  for (const ConfigField* f : header_fields())
    if (shows(*f, c)) out += fmt::format("// acore: {}={}\n", f->key, field_text(*f, c));
  if (img.zero_offset != 0.0 || c.zero_word) {
    out += fmt::format("// acore: zero_offset_rad={}\n", img.zero_offset);
    out += fmt::format("// acore: zero_offset_code={}\n", img.zero_offset_code());
    out += fmt::format(
        "// zero offset = {:+.6f} deg electrical (sensor angle - p theta_ref), {}\n",
        img.zero_offset * 180 / M_PI,
        c.zero_word ? "subtracted by the ZERO word" : "subtracted by `estimate` in software");
  }
  const int digits = (c.reg_w + 3) / 4;
  for (const CodecField& f : codec_table(c)) {
    const uint64_t w = img.words.at(f.addr);
    const std::string name = f.name(c);
    std::string value;
    switch (f.kind) {
      case CodecKind::kOffset:
        value = fmt::format("{} = {} codes", name, f.field(w));
        break;
      case CodecKind::kRecip:  // the amplitude the reciprocal stands for
        value = fmt::format("{} : A = {:.3f} codes", name, 1.0 / f.value(std::max<uint64_t>(1, w)));
        break;
      case CodecKind::kPoly:
        value = fmt::format("{} = {:+.6f}", name, f.value(w));
        break;
      case CodecKind::kAtan:
        value = fmt::format("{} = {:.6f} deg", name, f.value(w, 360.0));
        break;
      case CodecKind::kFourierA0:
        value = fmt::format("{} = {:+.6f} deg", name, f.value(w, 360.0));
        break;
      case CodecKind::kFourierHarmonic:
        value = fmt::format("{} = {:+.6f} deg (word = value / G_M)", name, f.value(w, 360.0));
        break;
      case CodecKind::kZero: {
        const auto code = static_cast<uint32_t>(f.field(w));
        value = fmt::format("{} = {} = {:+.6f} deg (angle_out = angle - zero)", name, code,
                            code_angle(code, f.width) * 180 / M_PI);
        break;
      }
    }
    out += fmt::format("{:0{}x}  // {:3d} {}\n", w, digits, f.addr, value);
  }
  return out;
}

void write_regimage(const RegImage& img, const std::string& path) {
  std::ofstream f(path, std::ios::binary);
  if (!f) throw InputError(fmt::format("{}: cannot write register image", path));
  f << format_regimage(img);
  if (!f) throw InputError(fmt::format("{}: write failed", path));
}

}  // namespace acore
