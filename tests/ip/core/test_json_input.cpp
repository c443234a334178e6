// SPDX-License-Identifier: MIT
// JSON input: every nlohmann failure becomes an InputError naming the file and the line.
#include <gtest/gtest.h>

#include <string>

#include "core/errors.hpp"
#include "core/json_input.hpp"

namespace {

std::string message(const std::string& text) {
  try {
    acore::parse_json_text(text, "f.json");
  } catch (const acore::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(JsonInput, ParsesValidText) {
  EXPECT_EQ(acore::parse_json_text("{\"p\": [1, 2]}", "f.json")["p"][1], 2);
}

TEST(JsonInput, SyntaxErrorNamesItsLine) {
  const std::string m = message("{\n  \"a\": 1,\n  \"b\": ]\n}\n");
  EXPECT_EQ(m.rfind("f.json:3: not valid JSON", 0), 0u) << m;
}

TEST(JsonInput, TruncatedTextNamesTheLastLine) {
  const std::string m = message("[\n{\"DEGREE\": [3]");
  EXPECT_EQ(m.rfind("f.json:2: not valid JSON", 0), 0u) << m;
}

TEST(JsonInput, OverflowingNumberNamesItsLine) {
  // nlohmann reports no position for a number too large for a double: the token is found.
  const std::string m = message("{\n\"A0\": 0,\n\n\"B0\": -1e999\n}");
  EXPECT_EQ(m.rfind("f.json:4: not valid JSON", 0), 0u) << m;
  EXPECT_NE(m.find("1e999"), std::string::npos) << m;
}

TEST(JsonInput, NanIsNotJson) {
  EXPECT_EQ(message("{\"A0\": NaN}").rfind("f.json:1: not valid JSON", 0), 0u);
}

TEST(JsonInput, MissingFileIsNamed) {
  try {
    acore::read_json_file("/nonexistent/grid.json", "sweep grid");
    FAIL() << "no exception";
  } catch (const acore::InputError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/grid.json: cannot open the sweep grid");
  }
}

}  // namespace
