// SPDX-License-Identifier: MIT
// Recording file I/O (docs/contracts.md, recording file): round trip, column order, CRLF, unknown
// columns, and every error with the FILE:LINE: column 'NAME' it must name.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>

#include "core/angle.hpp"
#include "core/errors.hpp"
#include "core/recording.hpp"

namespace acore {
namespace {

// The InputError message of parsing `text` as "f.csv" (fails the test when nothing is thrown).
std::string error_of(const std::string& text) {
  try {
    parse_recording(text, "f.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return "";
}

bool has(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

TEST(Recording, ParsesMetaCommentsAndColumnsInAnyOrder) {
  const Recording r = parse_recording(
      "# scenario=paper\n#  p = 2 \n# free text, with = in it\n#plain\n"
      "c4,temp,c2,extra,theta_ref,c1,t,c3\n"
      "4,25,2,x,0.5,1,0,3\n"
      " -4e-1 , 26 ,+2.5,y, 1 ,1.25,0.001,3.5\n",
      "mem");
  EXPECT_EQ(r.channels, 4);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r.meta.at("scenario"), "paper");
  EXPECT_EQ(r.meta.at("p"), "2");
  ASSERT_EQ(r.comments.size(), 2u);
  EXPECT_EQ(r.comments[0], "free text, with = in it");
  EXPECT_EQ(r.comments[1], "plain");
  EXPECT_DOUBLE_EQ(r.ch[0][1], 1.25);
  EXPECT_DOUBLE_EQ(r.ch[1][1], 2.5);
  EXPECT_DOUBLE_EQ(r.ch[2][0], 3);
  EXPECT_DOUBLE_EQ(r.ch[3][1], -0.4);
  EXPECT_DOUBLE_EQ(r.theta_ref[1], 1);
  EXPECT_DOUBLE_EQ(r.t[1], 0.001);
  EXPECT_DOUBLE_EQ(r.temp[1], 26);
  EXPECT_DOUBLE_EQ(r.d13(1), 1.25 - 3.5);
}

TEST(Recording, TwoChannelsCrlfAndOptionalColumns) {
  const Recording r = parse_recording("cos,sin\r\n1,0\r\n0.5,-0.5\r\n", "mem");
  EXPECT_EQ(r.channels, 2);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_DOUBLE_EQ(r.ch[0][1], -0.5);  // sin
  EXPECT_DOUBLE_EQ(r.ch[1][1], 0.5);   // cos
  EXPECT_FALSE(r.has_theta());
  EXPECT_FALSE(r.has_t());
  EXPECT_FALSE(r.has_temp());
  EXPECT_TRUE(r.ch[2].empty());
  EXPECT_DOUBLE_EQ(r.d24(0), 1);
}

TEST(Recording, RoundTripIsExact) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1e3, 1e3);
  for (int channels : {2, 4}) {
    Recording r;
    r.channels = channels;
    r.meta["scenario"] = "x";
    r.meta["seed"] = "42";
    r.comments.push_back("a comment");
    for (int i = 0; i < 200; ++i) {
      for (int c = 0; c < channels; ++c)
        r.ch[static_cast<size_t>(c)].push_back(u(rng) * std::pow(10.0, i % 30 - 15));
      r.theta_ref.push_back(u(rng));
      r.t.push_back(i * 1e-3);
      r.temp.push_back(25 + u(rng) * 1e-3);
    }
    r.ch[0][3] = 5e-324;  // denormal
    r.ch[0][4] = -0.0;
    const std::string path = std::string(ACORE_BINARY_DIR) + "/test_recording_roundtrip.csv";
    write_recording(r, path);
    const Recording b = read_recording(path);
    std::remove(path.c_str());
    EXPECT_EQ(b.channels, channels);
    EXPECT_EQ(b.meta, r.meta);
    EXPECT_EQ(b.comments, r.comments);
    for (int c = 0; c < 4; ++c)
      EXPECT_EQ(b.ch[static_cast<size_t>(c)], r.ch[static_cast<size_t>(c)]) << c;
    EXPECT_EQ(b.theta_ref, r.theta_ref);
    EXPECT_EQ(b.t, r.t);
    EXPECT_EQ(b.temp, r.temp);
  }
}

TEST(Recording, WriterRejectsInconsistentColumns) {
  Recording r;
  r.ch = {{{1, 2}, {1, 2}, {1}, {1, 2}}};
  EXPECT_THROW(r.check_consistent("x"), InputError);
  r.ch[2].push_back(2);
  r.theta_ref = {1};
  EXPECT_THROW(r.check_consistent("x"), InputError);
  r.theta_ref = {1, 2};
  EXPECT_NO_THROW(r.check_consistent("x"));
}

TEST(Recording, ErrorsNameFileLineAndColumn) {
  // Missing column: named, on the header line (line 3 after two comment lines).
  std::string e = error_of("# a=b\n# c\ntheta_ref,c1,c2,c4\n0,1,2,3\n");
  EXPECT_TRUE(has(e, "f.csv:3: column 'c3': missing")) << e;
  e = error_of("theta_ref,sin\n0,1\n");
  EXPECT_TRUE(has(e, "f.csv:1: column 'cos': missing")) << e;
  e = error_of("theta_ref\n0\n");
  EXPECT_TRUE(has(e, "f.csv:1: column 'c1': missing")) << e;
  // Both channel sets.
  e = error_of("c1,c2,c3,c4,sin\n1,2,3,4,5\n");
  EXPECT_TRUE(has(e, "f.csv:1: column 'sin':")) << e;
  EXPECT_TRUE(has(e, "both")) << e;
  // Duplicate column.
  e = error_of("c1,c2,c3,c4,c2\n1,2,3,4,5\n");
  EXPECT_TRUE(has(e, "f.csv:1: column 'c2': appears twice")) << e;
  // Non-number, with the data line counted after a CRLF header.
  e = error_of("c1,c2,c3,c4\r\n1,2,3,4\r\n1,2,abc,4\r\n");
  EXPECT_TRUE(has(e, "f.csv:3: column 'c3': not a number: 'abc'")) << e;
  e = error_of("c1,c2,c3,c4\n1,2,3,4x\n");
  EXPECT_TRUE(has(e, "f.csv:2: column 'c4': not a number")) << e;
  e = error_of("c1,c2,c3,c4\n1,2,,4\n");
  EXPECT_TRUE(has(e, "f.csv:2: column 'c3': empty field")) << e;
  e = error_of("c1,c2,c3,c4\n1,2,3 4,4\n");
  EXPECT_TRUE(has(e, "f.csv:2: column 'c3': not a number")) << e;
  e = error_of("c1,c2,c3,c4\n1,+-2,3,4\n");
  EXPECT_TRUE(has(e, "f.csv:2: column 'c2': not a number")) << e;
  e = error_of("c1,c2,c3,c4\n0x10,2,3,4\n");
  EXPECT_TRUE(has(e, "f.csv:2: column 'c1': not a number")) << e;
  // NaN, Inf, out of range.
  e = error_of("c1,c2,c3,c4,theta_ref\n1,2,3,4,nan\n");
  EXPECT_TRUE(has(e, "f.csv:2: column 'theta_ref': NaN or infinite")) << e;
  e = error_of("c1,c2,c3,c4\n1,-inf,3,4\n");
  EXPECT_TRUE(has(e, "f.csv:2: column 'c2': NaN or infinite")) << e;
  e = error_of("c1,c2,c3,c4\n1,2,3,1e999\n");
  EXPECT_TRUE(has(e, "f.csv:2: column 'c4': out of the range")) << e;
  // Ragged rows: too few (the first missing column is named) and too many.
  e = error_of("c1,c2,c3,c4\n1,2,3,4\n\n1,2,3\n");
  EXPECT_TRUE(has(e, "f.csv:4: column 'c4': missing field")) << e;
  e = error_of("c1,c2,c3,c4\n1,2,3,4,5\n");
  EXPECT_TRUE(has(e, "f.csv:2: column 5: extra field")) << e;
  // Empty file, comments only, no data rows.
  e = error_of("");
  EXPECT_TRUE(has(e, "f.csv:1: empty file")) << e;
  e = error_of("# only=meta\n# and text\n");
  EXPECT_TRUE(has(e, "f.csv:3: empty file")) << e;
  e = error_of("c1,c2,c3,c4");  // a header without a newline ends the text
  EXPECT_TRUE(has(e, "f.csv:1: no data rows")) << e;
  e = error_of("# x\nc1,c2,c3,c4\n\n");
  EXPECT_TRUE(has(e, "f.csv:2: no data rows")) << e;
  // An unknown column is ignored, but it still counts for the row width.
  e = error_of("c1,c2,c3,c4,note\n1,2,3,4\n");
  EXPECT_TRUE(has(e, "column 'note': missing field")) << e;
  // Unreadable file.
  try {
    read_recording("/nonexistent/dir/x.csv");
    ADD_FAILURE() << "no error for a missing file";
  } catch (const InputError& err) {
    EXPECT_TRUE(has(err.what(), "/nonexistent/dir/x.csv")) << err.what();
  }
}

TEST(Recording, UnknownColumnsMayHoldAnything) {
  const Recording r = parse_recording("label,c1,c2,c3,c4\nabc,1,2,3,4\n,5,6,7,8\n", "mem");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_DOUBLE_EQ(r.ch[0][1], 5);
}

TEST(Recording, MillionRowsParseInAboutASecond) {
  Recording r;
  std::mt19937_64 rng(1);
  std::normal_distribution<double> g;
  const size_t n = 1000000;
  for (size_t i = 0; i < n; ++i) {
    r.t.push_back(static_cast<double>(i) / n);
    r.theta_ref.push_back(kTwoPi * static_cast<double>(i) / n);
    for (size_t c = 0; c < 4; ++c) r.ch[c].push_back(g(rng));
  }
  const std::string text = format_recording(r);
  const auto t0 = std::chrono::steady_clock::now();
  const Recording b = parse_recording(text, "big");
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(b.size(), n);
  EXPECT_EQ(b.ch[3], r.ch[3]);
  std::printf("parsed %zu rows (%.1f MB) in %.3f s\n", n, text.size() / 1e6, s);
  // Generous for a loaded, unoptimized build; an O(n^2) or stream-based parser would miss it.
  EXPECT_LT(s, 5.0);
}

}  // namespace
}  // namespace acore
