// The one number rule and the one pace rule that every reader of text uses.
#include "plumb/core/number.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace plumb {
namespace {

TEST(ParseNumber, WholeTextDecimalWithSignAndExponent) {
  EXPECT_EQ(parse_number("1.5"), 1.5);
  EXPECT_EQ(parse_number("+2"), 2.0);
  EXPECT_EQ(parse_number("-2.5e-3"), -2.5e-3);
  EXPECT_EQ(parse_number("1E3"), 1000.0);
  EXPECT_EQ(parse_number(".5"), 0.5);
  for (const char* bad : {"", " 1", "1 ", "1,5", "0x10", "+-1", "--1", "+", "1e999", "1.5.2", "abc", "nan", "inf"})
    EXPECT_FALSE(parse_number(bad)) << bad;
}

TEST(ParseNumber, NonFiniteOnlyWhereAllowed) {
  ASSERT_TRUE(parse_number("nan", true));
  EXPECT_TRUE(std::isnan(*parse_number("nan", true)));
  EXPECT_EQ(parse_number("-inf", true), -INFINITY);
  EXPECT_FALSE(parse_number("1e999", true)) << "out of range is not infinity";
}

TEST(ParsePace, NamesAndFactors) {
  EXPECT_EQ(parse_pace("realtime"), 1.0);
  EXPECT_EQ(parse_pace("max"), 0.0);
  EXPECT_EQ(parse_pace("x10"), 10.0);
  EXPECT_EQ(parse_pace("10x"), 10.0);
  EXPECT_EQ(parse_pace("2.5X"), 2.5);
  EXPECT_EQ(parse_pace("4"), 4.0);
  for (const char* bad : {"", "x", "fast", "x0", "-2", "x-2", "x1e999", "3y", "xx2", "x 2"}) EXPECT_FALSE(parse_pace(bad)) << bad;
}

}  // namespace
}  // namespace plumb
