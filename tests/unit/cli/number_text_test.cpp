// Strict numbers and "A,B" pairs for command-line values (cli/include/cyber/cli/number_text.hpp).

#include "cyber/cli/number_text.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cyber::cli {
namespace {

TEST(NumberText, PairsOfFiniteNumbers) {
  EXPECT_EQ(parseNumberPair("0.2,1.57"), (std::array<double, 2>{0.2, 1.57}));
  EXPECT_EQ(parseNumberPair("-0.2,1"), (std::array<double, 2>{-0.2, 1.0}));
  EXPECT_EQ(parseNumberPair("1e-3,-2E2"), (std::array<double, 2>{1e-3, -200.0}));
  for (const char* bad : {"", ",", "1", "1,", ",1", "1;2", "1,2,3", "1,,2", "1,2x", "x1,2", " 1,2", "1,2 ", "+1,2",
                          "1,nan", "inf,1", "1,-inf", "1e999,1", "0x10,1"}) {
    EXPECT_FALSE(parseNumberPair(bad)) << bad;
  }
}

TEST(NumberText, NonFiniteOnlyWhenAsked) {
  const auto pair = parseNumberPair("nan,-inf", NonFinite::kAccept);
  ASSERT_TRUE(pair);
  EXPECT_TRUE(std::isnan((*pair)[0]));
  EXPECT_TRUE(std::isinf((*pair)[1]) && (*pair)[1] < 0);
  EXPECT_FALSE(parseNumberPair("nan,1,2", NonFinite::kAccept));
  EXPECT_FALSE(parseNumber("inf"));
  EXPECT_TRUE(parseNumber("inf", NonFinite::kAccept));
}

TEST(NumberText, NumbersAndIntegers) {
  EXPECT_EQ(parseNumber("2.5"), 2.5);
  EXPECT_EQ(parseNumber("-0"), -0.0);
  for (const char* bad : {"", "+1", "abc", "1 ", "1e999", "1,2"}) EXPECT_FALSE(parseNumber(bad)) << bad;
  EXPECT_EQ(parseInteger("42"), 42);
  EXPECT_EQ(parseInteger("-7"), -7);
  for (const char* bad : {"", "+1", "4x", "1.5", "99999999999999999999"}) EXPECT_FALSE(parseInteger(bad)) << bad;
}

}  // namespace
}  // namespace cyber::cli
