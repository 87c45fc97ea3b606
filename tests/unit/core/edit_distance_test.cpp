// The distance behind every "did you mean": a metric on strings, and the textbook values.
#include <gtest/gtest.h>

#include "plumb/core/edit_distance.hpp"

namespace plumb {
namespace {

TEST(EditDistance, TextbookValuesAndMetricProperties) {
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("abc", ""), 3u);
  EXPECT_EQ(edit_distance("plumb/attitude/compensate", "plumb/attitude/compensated"), 1u);
  const char* words[] = {"", "a", "fx", "wx", "Gyro X (deg/s)", "Gyroscope X (deg/s)", "plumb/depth"};
  for (const char* a : words) {
    EXPECT_EQ(edit_distance(a, a), 0u);
    for (const char* b : words) {
      EXPECT_EQ(edit_distance(a, b), edit_distance(b, a));
      for (const char* c : words) EXPECT_LE(edit_distance(a, c), edit_distance(a, b) + edit_distance(b, c));
    }
  }
}

// The suggestions: a typo's few edits, a name cut short, the closest first; nothing for a known
// name or a different one.
TEST(ClosestNames, SuggestNearMissesOnly) {
  const std::vector<std::string> names{"static", "integral", "compensated", "strapdown"};
  EXPECT_EQ(closest_names("strapdwn", names), std::vector<std::string>{"strapdown"});
  EXPECT_EQ(closest_names("compens", names), std::vector<std::string>{"compensated"});
  EXPECT_TRUE(closest_names("strapdown", names).empty());
  EXPECT_TRUE(closest_names("kalman", names).empty());
  EXPECT_EQ(did_you_mean({"a", "b", "c"}), "did you mean a, b or c?");
  EXPECT_EQ(did_you_mean({}), "");
}

}  // namespace
}  // namespace plumb
