// SPDX-License-Identifier: MIT
// Register image: the map of docs/register-map.md, round trip through the $readmemh text,
// and bad input.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include "calibration/calibration.hpp"
#include "core/angle.hpp"
#include "core/errors.hpp"
#include "core/fixed_point.hpp"
#include "engine/fixed_model.hpp"
#include "regmap/regimage.hpp"
#include "stages/cordic.hpp"
#include "stages/fourier_correct.hpp"
#include "support/map_shapes.hpp"
#include "support/paper_signals.hpp"

namespace acore {
namespace {

RegImage paper_image() {
  const Recording rec = test::paper_recording(4096);
  return quantize(calibrate(rec, CalOptions{}), DatapathConfig{}, choose_in_scale(rec, 16));
}

void expect_error(const std::string& text, const std::string& fragment) {
  try {
    parse_regimage(text, "regs.hex");
    FAIL() << "no error for: " << fragment;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(RegImage, DefaultMapIsThePapers52Words) {
  DatapathConfig c;
  EXPECT_EQ(c.words(), 52);
  EXPECT_EQ(c.addr_offset(0), 0);
  EXPECT_EQ(c.addr_offset(1), 1);
  EXPECT_EQ(c.addr_recip(0), 2);
  EXPECT_EQ(c.addr_recip(1), 3);
  for (int r = 0; r < 4; ++r)
    for (int cv = 0; cv < 2; ++cv)
      for (int j = 0; j < 4; ++j) EXPECT_EQ(c.addr_poly(r, cv, j), 4 + 8 * r + 4 * cv + j);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(c.addr_atan(i), 36 + i);
  c.degree = 5;
  c.regions = 8;
  EXPECT_EQ(c.words(), 4 + 2 * 8 * 6 + 16);
}

TEST(RegImage, RoundTripKeepsWordsConfigAndScale) {
  const RegImage a = paper_image();
  const std::string text = format_regimage(a);
  const RegImage b = parse_regimage(text, "x");
  EXPECT_EQ(a.words, b.words);
  EXPECT_EQ(a.in_scale, b.in_scale);
  EXPECT_EQ(a.cfg.describe(), b.cfg.describe());
  // atan(2^0) = 45 deg = 1/8 turn of 2^Z_W, written with its human value.
  EXPECT_EQ(b.atan(0), int64_t{1} << (b.cfg.z_w - 3));
  EXPECT_NE(text.find("atan(2^-0) = 45.000000 deg"), std::string::npos);
}

// FOLD (clocks per sample of rtl/acore_top.v) is an RTL parameter of the schedule, not of the
// arithmetic: the image does not record it, the model ignores it, and validate() rejects what the
// RTL does not fold (as acore_top's elaboration checks do).
TEST(RegImage, FoldIsTheRtlScheduleNotPartOfTheImage) {
  const DatapathConfig four = DatapathConfig{}.with_rtl_params("FOLD=4");
  EXPECT_EQ(four.fold, 4);
  EXPECT_NO_THROW(four.validate());
  EXPECT_EQ(DatapathConfig{}.describe().find("fold"), std::string::npos);
  const std::string d = four.describe();
  EXPECT_EQ(d.substr(d.size() - 7), " fold=4");
  for (const char* bad :
       {"FOLD=3", "FOLD=64", "FOLD=0", "FOLD=2 CORRECTION=1", "FOLD=8 FOURIER_K=4"})
    EXPECT_THROW(DatapathConfig{}.with_rtl_params(bad).validate(), InputError) << bad;
  EXPECT_NO_THROW(DatapathConfig{}.with_rtl_params("FOLD=8 CORRECTION=2").validate());

  RegImage img = paper_image();
  RegImage folded = img;
  folded.cfg.fold = 8;
  const std::string text = format_regimage(folded);
  EXPECT_EQ(text, format_regimage(img));
  const RegImage back = parse_regimage(text, "x");
  EXPECT_EQ(back.cfg.fold, 1);
  EXPECT_EQ(back.words, img.words);
  const FixedModel m1(img), m8(folded);
  for (int k = 0; k < 200; ++k) {
    const int32_t a = (k * 7919) % 20000 - 10000, b = (k * 104729) % 20000 - 10000;
    EXPECT_TRUE(m1.step({a, b, -a / 3, b / 5}) == m8.step({a, b, -a / 3, b / 5}));
  }
}

// format_regimage() as it was written before the codec and field tables (a Q-format and a header
// key list of its own): the images made so far, byte for byte.
std::string legacy_format(const RegImage& img) {
  const DatapathConfig& c = img.cfg;
  std::string out = "// AngleCore coefficient register image ($readmemh), docs/register-map.md\n";
  for (const auto& p : img.provenance) out += "// acore: " + p + "\n";
  out += fmt::format("// acore: in_scale={}\n", img.in_scale);
  out += fmt::format("// acore: crc32=0x{:08x}\n", image_crc32(img));
  out += fmt::format("// acore: correction={}\n", correction_name(c.correction));
  const std::map<std::string, int DatapathConfig::*> keys = {
      {"in_w", &DatapathConfig::in_w},
      {"reg_w", &DatapathConfig::reg_w},
      {"s_w", &DatapathConfig::s_w},
      {"s_f", &DatapathConfig::s_f},
      {"r_shift", &DatapathConfig::r_shift},
      {"scale_guard", &DatapathConfig::scale_guard},
      {"degree", &DatapathConfig::degree},
      {"regions", &DatapathConfig::regions},
      {"xcenter", &DatapathConfig::xcenter},
      {"coef_f", &DatapathConfig::coef_f},
      {"acc_guard", &DatapathConfig::acc_guard},
      {"acc_int", &DatapathConfig::acc_int},
      {"iterations", &DatapathConfig::iterations},
      {"cordic_guard", &DatapathConfig::cordic_guard},
      {"z_w", &DatapathConfig::z_w},
      {"angle_w", &DatapathConfig::angle_w}};
  const std::map<std::string, int DatapathConfig::*> fourier_keys = {
      {"fourier_k", &DatapathConfig::fourier_k},
      {"fourier_iterations", &DatapathConfig::fourier_iterations},
      {"fourier_coef_f", &DatapathConfig::fourier_coef_f},
      {"fourier_word_w", &DatapathConfig::fourier_word_w},
      {"fourier_guard", &DatapathConfig::fourier_guard}};
  for (const auto& [key, field] : keys) out += fmt::format("// acore: {}={}\n", key, c.*field);
  if (c.fourier_k > 0)
    for (const auto& [key, field] : fourier_keys)
      out += fmt::format("// acore: {}={}\n", key, c.*field);
  if (c.zero_word) out += "// acore: zero_word=1\n";
  if (img.zero_offset != 0.0 || c.zero_word) {
    out += fmt::format("// acore: zero_offset_rad={}\n", img.zero_offset);
    out += fmt::format("// acore: zero_offset_code={}\n", img.zero_offset_code());
    out += fmt::format(
        "// zero offset = {:+.6f} deg electrical (sensor angle - p theta_ref), {}\n",
        img.zero_offset * 180 / M_PI,
        c.zero_word ? "subtracted by the ZERO word" : "subtracted by `estimate` in software");
  }
  const int digits = (c.reg_w + 3) / 4;
  auto sx = [&](int addr, int w) { return fx::sext(static_cast<int64_t>(img.words[addr]), w); };
  auto line = [&](int addr, const std::string& what) {
    out += fmt::format("{:0{}x}  // {:3d} {}\n", img.words[addr], digits, addr, what);
  };
  for (int k = 0; k < 2; ++k)
    line(c.addr_offset(k),
         fmt::format("offset O{} = {} codes", k ? "24" : "13", sx(c.addr_offset(k), c.reg_w)));
  for (int k = 0; k < 2; ++k)
    line(c.addr_recip(k),
         fmt::format("1/A{} : A = {:.3f} codes", k ? "24" : "13",
                     std::ldexp(1.0, c.s_f + c.r_shift) /
                         std::max<int64_t>(1, static_cast<int64_t>(img.words[c.addr_recip(k)]))));
  const char* x_name = c.xcenter ? "u" : "x";
  for (int r = 0; r < c.regions; ++r)
    for (int k = 0; k < 2; ++k)
      for (int t = 0; t < c.coef_per_curve(); ++t) {
        std::string term = fmt::format("{}^{}", x_name, t);
        if (c.correction == kPoly2d)
          for (int i = 0; i <= c.degree; ++i)
            for (int j = 0; i + j <= c.degree; ++j)
              if (c.term2d(i, j) == t) term = fmt::format("{}^{} v^{}", x_name, i, j);
        line(c.addr_poly(r, k, t),
             fmt::format(
                 "region {} {} {} = {:+.6f}", r, k ? "c24" : "c13", term,
                 std::ldexp(static_cast<double>(sx(c.addr_poly(r, k, t), c.reg_w)), -c.coef_f)));
      }
  for (int i = 0; i < c.iterations; ++i)
    line(c.addr_atan(i),
         fmt::format("atan(2^-{}) = {:.6f} deg", i,
                     std::ldexp(static_cast<double>(img.words[c.addr_atan(i)]), -c.z_w) * 360.0));
  const double gain = c.fourier_k > 0 ? fourier_gain(c) : 1.0;
  for (int j = 0; j < c.fourier_words(); ++j) {
    const int64_t v = sx(c.addr_fourier(j), j == 0 ? c.reg_w : c.fourier_word_w);
    const double deg = std::ldexp(static_cast<double>(v), -c.fourier_coef_f) * 360.0;
    if (j == 0)
      line(c.addr_fourier(j), fmt::format("fourier a_0 = {:+.6f} deg", deg));
    else
      line(c.addr_fourier(j), fmt::format("fourier {}_{} = {:+.6f} deg (word = value / G_M)",
                                          j % 2 ? "a" : "b", (j + 1) / 2, deg * gain));
  }
  if (c.zero_word) {
    const auto z = static_cast<uint32_t>(img.words[c.addr_zero()] & ((1u << c.angle_w) - 1));
    line(c.addr_zero(), fmt::format("zero position = {} = {:+.6f} deg (angle_out = angle - zero)",
                                    z, code_angle(z, c.angle_w) * 180 / M_PI));
  }
  return out;
}

using test::kMapShapes;

// An image of configuration cfg with random words (signed fields sign-extended, as quantize()
// writes them), random zero offset and in_scale, and provenance lines.
RegImage random_image(const DatapathConfig& cfg, std::mt19937_64& rng) {
  RegImage img;
  img.cfg = cfg;
  img.in_scale = std::ldexp(1.0, static_cast<int>(rng() % 16));
  img.zero_offset = rng() % 3 ? std::uniform_real_distribution<double>(-M_PI, M_PI)(rng) : 0.0;
  img.provenance = {"command=anglecore calibrate --in 'a b.csv'", "periodicity=3"};
  img.words.assign(cfg.words(), 0);
  for (auto& w : img.words) w = rng() & ((uint64_t{1} << cfg.reg_w) - 1);
  for (int j = 1; j < cfg.fourier_words(); ++j)  // a harmonic's upper bits repeat its sign
    img.words[cfg.addr_fourier(j)] =
        static_cast<uint64_t>(
            fx::sext(static_cast<int64_t>(img.words[cfg.addr_fourier(j)]), cfg.fourier_word_w)) &
        ((uint64_t{1} << cfg.reg_w) - 1);
  return img;
}

TEST(RegImage, TextIsByteIdenticalToTheHandWrittenFormat) {
  std::mt19937_64 rng(5);
  for (const char* p : kMapShapes) {
    const DatapathConfig cfg = DatapathConfig{}.with_rtl_params(p);
    ASSERT_NO_THROW(cfg.validate()) << p;
    for (int n = 0; n < 40; ++n) {
      const RegImage img = random_image(cfg, rng);
      const std::string text = format_regimage(img);
      ASSERT_EQ(text, legacy_format(img)) << p;
      const RegImage back = parse_regimage(text, "x");
      EXPECT_EQ(back.words, img.words) << p;
      EXPECT_TRUE(back.cfg == img.cfg) << p;
      EXPECT_EQ(back.provenance, img.provenance) << p;
    }
  }
  // And on calibrated images.
  EXPECT_EQ(format_regimage(paper_image()), legacy_format(paper_image()));
}

// The header's configuration keys are the field table's image keys that shows() writes, and each
// one read back sets its own field.
TEST(RegImage, HeaderKeysAreTheFieldTablesImageKeys) {
  for (const char* p : kMapShapes) {
    const DatapathConfig cfg = DatapathConfig{}.with_rtl_params(p);
    std::mt19937_64 rng(6);
    const std::string text = format_regimage(random_image(cfg, rng));
    std::set<std::string> keys;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line))
      if (line.rfind("// acore: ", 0) == 0) keys.insert(line.substr(10, line.find('=') - 10));
    for (const char* other :
         {"in_scale", "crc32", "command", "periodicity", "zero_offset_rad", "zero_offset_code"})
      keys.erase(other);
    std::set<std::string> want;
    for (const ConfigField& f : config_fields())
      if (f.in_image && shows(f, cfg)) want.insert(f.key);
    EXPECT_EQ(keys, want) << p;
  }
  // Each image key read back sets its own field: for every field, an image of a legal
  // configuration that differs from the base in that field alone.
  const DatapathConfig base = DatapathConfig{}.with_rtl_params("FOURIER_K=3 REGIONS=8");
  std::mt19937_64 rng(7);
  for (const ConfigField& f : config_fields()) {
    if (!f.in_image) continue;
    bool found = false;
    for (int delta : {1, -1, 2, -2, 3, -3, 4, -4}) {
      DatapathConfig want = base;
      want.*f.member += delta;
      try {
        want.validate();
      } catch (const InputError&) {
        continue;
      }
      found = true;
      const DatapathConfig got = parse_regimage(format_regimage(random_image(want, rng)), "x").cfg;
      for (const ConfigField& g : config_fields())
        EXPECT_EQ(got.*g.member, want.*g.member) << f.key << " changed, " << g.key << " read";
      break;
    }
    EXPECT_TRUE(found) << f.key;
  }
}

TEST(RegImage, DequantizeInvertsQuantizeWithinOneLsb) {
  const Recording rec = test::paper_recording(4096);
  const FloatCoefficients fc = calibrate(rec, CalOptions{});
  const RegImage img = quantize(fc, DatapathConfig{}, choose_in_scale(rec, 16));
  const FloatCoefficients back = dequantize(img);
  for (size_t k = 0; k < fc.poly.size(); ++k)
    EXPECT_NEAR(back.poly[k], fc.poly[k], std::ldexp(0.5, -img.cfg.coef_f));
  for (int c = 0; c < 2; ++c) {
    EXPECT_NEAR(back.offset[c], fc.offset[c], 0.5 / img.in_scale);
    EXPECT_NEAR(back.amp[c] / fc.amp[c], 1.0, 1e-4);
  }
}

TEST(RegImage, BadInputNamesFileLineAndField) {
  const std::string good = format_regimage(paper_image());
  expect_error("", "missing 'acore: in_scale");
  std::string bad = good;
  bad.replace(bad.rfind("\n", bad.size() - 2) + 1, 5, "zz");  // corrupt the last word
  expect_error(bad, "regs.hex:");
  expect_error(good + "00001\n", "53 words");
  std::string hdr = good;
  hdr.replace(hdr.find("degree=3"), 8, "degree=x");
  expect_error(hdr, "header field 'degree'");
  std::string deg = good;
  deg.replace(deg.find("degree=3"), 8, "degree=9");
  expect_error(deg, "degree=9 must be 1..7");
  std::string wide = good;
  const auto p = wide.rfind("\n", wide.find("//   0 offset")) + 1;  // first word line
  wide.replace(p, 5, "fffff");                                      // 20 bits in an 18-bit word
  expect_error(wide, "does not fit 18 bits");
  EXPECT_THROW(read_regimage("/nonexistent/regs.hex"), InputError);
}

TEST(RegImage, CorrectionModeRoundTripsAndOlderImagesReadAsPoly) {
  const Recording rec = test::paper_recording(4096);
  CalOptions o;
  o.correction = kPoly2d;
  const RegImage a = quantize(calibrate(rec, o), DatapathConfig{}, choose_in_scale(rec, 16));
  EXPECT_EQ(a.words.size(), 100u);
  const std::string text = format_regimage(a);
  EXPECT_NE(text.find("// acore: correction=poly2d"), std::string::npos);
  EXPECT_NE(text.find("region 0 c13 x^1 v^2"), std::string::npos);
  const RegImage b = parse_regimage(text, "x");
  EXPECT_EQ(b.cfg.correction, kPoly2d);
  EXPECT_EQ(a.words, b.words);
  // An image written before the mode existed has no correction/xcenter keys: the paper's mode.
  std::string old = format_regimage(paper_image());
  for (const char* key : {"// acore: correction=poly\n", "// acore: xcenter=0\n"})
    old.erase(old.find(key), std::string(key).size());
  const RegImage c = parse_regimage(old, "old.hex");
  EXPECT_EQ(c.cfg.correction, kPoly);
  EXPECT_EQ(c.cfg.xcenter, 0);
  EXPECT_EQ(c.words, paper_image().words);
}

// CRC-32 (IEEE 802.3, reflected 0xEDB88320) one bit at a time, table-free: an implementation
// independent of zlib's, itself checked against the standard check value below.
uint32_t bitwise_crc32(const std::vector<unsigned char>& bytes) {
  uint32_t c = 0xFFFFFFFFu;
  for (const unsigned char b : bytes)
    for (int i = 0; i < 8; ++i) c = (c >> 1) ^ (((c ^ (b >> i)) & 1u) ? 0xEDB88320u : 0u);
  return ~c;
}

// The shell's serialization: each word zero-extended to 32 bits, little-endian, address order.
std::vector<unsigned char> le_bytes(const std::vector<uint64_t>& words) {
  std::vector<unsigned char> b;
  for (const uint64_t w : words)
    for (int k = 0; k < 4; ++k) b.push_back(static_cast<unsigned char>(w >> (8 * k)));
  return b;
}

TEST(RegImage, Crc32IsTheStandardCrcOfTheLittleEndianWords) {
  const std::string check = "123456789";
  EXPECT_EQ(bitwise_crc32(std::vector<unsigned char>(check.begin(), check.end())), 0xCBF43926u);
  const RegImage a = paper_image();
  EXPECT_EQ(image_crc32(a), bitwise_crc32(le_bytes(a.words)));
  // Little-endian order: the words 0x34333231, 0x38373635 are the bytes "12345678".
  RegImage b = a;
  b.words.assign({0x34333231, 0x38373635});
  EXPECT_EQ(image_crc32(b), bitwise_crc32({'1', '2', '3', '4', '5', '6', '7', '8'}));
  std::mt19937_64 rng(3);
  for (int n = 0; n < 20; ++n) {
    for (auto& w : b.words) w = rng() & 0x3fffff;
    b.words.resize(1 + rng() % 300);
    EXPECT_EQ(image_crc32(b), bitwise_crc32(le_bytes(b.words)));
  }
}

TEST(RegImage, Crc32HeaderRoundTripsAndCatchesAChangedWord) {
  const RegImage a = paper_image();
  const std::string text = format_regimage(a);
  char key[40];
  std::snprintf(key, sizeof key, "// acore: crc32=0x%08x\n", image_crc32(a));
  const size_t at = text.find(key);
  ASSERT_NE(at, std::string::npos) << text.substr(0, 400);
  EXPECT_EQ(parse_regimage(text, "x").words, a.words);
  // One bit of one word changed in the text: the reader names the file, the key's line and field.
  const int line_no = static_cast<int>(std::count(text.begin(), text.begin() + at, '\n')) + 1;
  std::string flipped = text;
  const size_t w =
      flipped.rfind("\n", flipped.find("//   0 offset")) + 1 + 4;  // word 0's last digit
  flipped[w] = flipped[w] == '0' ? '1' : '0';
  expect_error(flipped, "regs.hex:" + std::to_string(line_no) + ": header field 'crc32'");
  // Without the key (images written before it) the same text parses.
  const std::string old = text.substr(0, at) + text.substr(at + std::strlen(key));
  EXPECT_NO_THROW(
      parse_regimage(flipped.substr(0, at) + flipped.substr(at + std::strlen(key)), "old.hex"));
  EXPECT_EQ(parse_regimage(old, "old.hex").words, a.words);
  std::string bad = text;
  bad.replace(at + 16, 2, "0z");
  expect_error(bad, "header field 'crc32': bad value");
}

// The ZERO word is the last word in every mode (after the atan words and the Fourier words), and
// without it every map is what it was.
TEST(RegImage, ZeroWordIsTheLastWordOfEveryMap) {
  for (const char* p : {"", "DEGREE=5 REGIONS=8", "CORRECTION=1", "CORRECTION=2", "FOURIER_K=8",
                        "CORRECTION=2 FOURIER_K=4", "DEGREE=7 REGIONS=8 XCENTER=1",
                        "REG_W=22 COEF_F=19 K=20 CORDIC_G=5 Z_W=24 ANGLE_W=20"}) {
    const DatapathConfig off = DatapathConfig{}.with_rtl_params(p);
    const DatapathConfig on = off.with_rtl_params("ZERO=1");
    on.validate();
    EXPECT_EQ(on.words(), off.words() + 1) << p;
    EXPECT_EQ(on.addr_zero(), off.words()) << p;
    EXPECT_EQ(on.addr_atan(0), off.addr_atan(0)) << p;
    if (off.fourier_k) EXPECT_EQ(on.addr_fourier(0), off.addr_fourier(0)) << p;
    EXPECT_EQ(off.describe().find("zero_word"), std::string::npos) << p;
    EXPECT_NE(on.describe().find("zero_word=1"), std::string::npos) << p;
  }
  EXPECT_EQ(DatapathConfig{}.words(), 52);
  EXPECT_EQ(DatapathConfig{}.with_rtl_params("ZERO=1").addr_zero(), 52);
  DatapathConfig wide =
      DatapathConfig{}.with_rtl_params("ANGLE_W=20 Z_W=20 ZERO=1");  // 20-bit code, 18-bit word
  EXPECT_THROW(wide.validate(), InputError);
}

TEST(RegImage, ZeroOffsetRoundTripsAndOlderImagesReadAsZero) {
  const Recording rec = test::paper_recording(4096);
  for (Recording r : {rec}) {
    for (double& t : r.theta_ref) t += 160 * M_PI / 180;
    for (int zero_word : {0, 1}) {
      DatapathConfig cfg;
      cfg.zero_word = zero_word;
      const RegImage a = quantize(calibrate(r, CalOptions{}), cfg, choose_in_scale(r, 16));
      const std::string text = format_regimage(a);
      EXPECT_NE(text.find("// acore: zero_offset_rad="), std::string::npos);
      EXPECT_NE(text.find("// acore: zero_offset_code="), std::string::npos);
      EXPECT_NE(text.find("// zero offset = -166.94"), std::string::npos) << text.substr(0, 1500);
      EXPECT_EQ(text.find("// acore: zero_word=1") != std::string::npos, zero_word == 1);
      const RegImage b = parse_regimage(text, "x");
      EXPECT_EQ(b.zero_offset, a.zero_offset);  // exactly: the shortest round-trip decimal
      EXPECT_EQ(b.words, a.words);
      EXPECT_EQ(b.cfg.describe(), a.cfg.describe());
      if (zero_word) {
        EXPECT_EQ(b.zero_position(), b.zero_offset_code());
        EXPECT_NE(text.find("zero position = "), std::string::npos);
      }
    }
  }
  // An image made before the zero offset (no keys) reads as offset 0; and one calibrated against
  // theta_ref itself (offset exactly 0, no ZERO word) is written without the keys, as before.
  std::string old = format_regimage(paper_image());
  for (const char* key :
       {"// acore: zero_offset_rad=", "// acore: zero_offset_code=", "// zero offset ="}) {
    const auto b = old.find(key);
    ASSERT_NE(b, std::string::npos);
    old.erase(b, old.find('\n', b) + 1 - b);
  }
  EXPECT_EQ(parse_regimage(old, "old.hex").zero_offset, 0.0);
  CalOptions as_printed;
  as_printed.estimate_zero = false;
  const RegImage z =
      quantize(calibrate(rec, as_printed), DatapathConfig{}, choose_in_scale(rec, 16));
  EXPECT_EQ(format_regimage(z).find("zero_offset"), std::string::npos);
  // Only the code given: the offset is the code's angle.
  const RegImage c = parse_regimage(old + "// acore: zero_offset_code=32768\n", "c.hex");
  EXPECT_DOUBLE_EQ(c.zero_offset, -M_PI);
}

TEST(RegImage, MalformedZeroOffsetNamesLineAndField) {
  std::string good = format_regimage(paper_image());
  const auto b = good.find("// acore: zero_offset_rad=");
  ASSERT_NE(b, std::string::npos);
  int line = 1;
  for (size_t i = 0; i < b; ++i) line += good[i] == '\n';
  const std::string head = good.substr(0, b), tail = good.substr(good.find('\n', b) + 1);
  const std::string at = "regs.hex:" + std::to_string(line) + ": header field 'zero_offset_rad'";
  expect_error(head + "// acore: zero_offset_rad=north\n" + tail, at);
  expect_error(head + "// acore: zero_offset_rad=4\n" + tail, at);
  expect_error(head + "// acore: zero_offset_rad=nan\n" + tail, at);
  expect_error(head + "// acore: zero_offset_rad=0.1\n" + tail, "header field 'zero_offset_code'");
  std::string code = good;
  const auto cb = code.find("// acore: zero_offset_code=");
  code.replace(cb, code.find('\n', cb) - cb, "// acore: zero_offset_code=65536");
  expect_error(code, "regs.hex:" + std::to_string(line + 1) +
                         ": header field 'zero_offset_code': 65536 does not fit");
  code.replace(cb, code.find('\n', cb) - cb, "// acore: zero_offset_code=-3");
  expect_error(code, "header field 'zero_offset_code': bad value '-3'");
  std::string zw = good;
  zw.replace(zw.find("// acore: angle_w=16"), 20, "// acore: angle_w=16\n// acore: zero_word=2");
  expect_error(zw, "zero_word=2 must be 0 or 1");
  zw = good;
  zw.replace(zw.find("// acore: angle_w=16"), 20, "// acore: angle_w=16\n// acore: zero_word=1");
  expect_error(zw, "53");  // the header now asks for the ZERO word the image lacks
}

TEST(RegImage, QuantizeRejectsCoefficientsOutOfRange) {
  const Recording rec = test::paper_recording(4096);
  FloatCoefficients fc = calibrate(rec, CalOptions{});
  fc.coef(2, 1, 3) = 9.0;  // Q3.15 holds +-4
  try {
    quantize(fc, DatapathConfig{}, 4096);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("region 2 curve c24 x^3"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace acore
