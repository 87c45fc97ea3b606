// The addresses plumb-display prints: ones a browser can open, never the 0.0.0.0 it listens on.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>

#include "addresses.hpp"

namespace plumb::display_component {
namespace {

TEST(PageAddresses, EveryInterfaceGivesOpenableAddresses) {
  for (const std::string bind : {"0.0.0.0", "::"}) {
    const auto addresses = page_addresses(bind, 8080);
    ASSERT_FALSE(addresses.empty());
    EXPECT_EQ(addresses.front(), "http://127.0.0.1:8080/");
    for (const auto& a : addresses) {
      EXPECT_EQ(a.find("0.0.0.0"), std::string::npos) << a;
      EXPECT_EQ(a.find("::"), std::string::npos) << a;
    }
    char name[256] = {};
    ASSERT_EQ(gethostname(name, sizeof name - 1), 0);
    EXPECT_NE(std::find(addresses.begin(), addresses.end(), "http://" + std::string(name) + ":8080/"), addresses.end());
  }
}

TEST(PageAddresses, AnAddressIsItself) {
  EXPECT_EQ(page_addresses("127.0.0.1", 9), std::vector<std::string>{"http://127.0.0.1:9/"});
  EXPECT_EQ(page_addresses("192.168.7.2", 8080), std::vector<std::string>{"http://192.168.7.2:8080/"});
}

}  // namespace
}  // namespace plumb::display_component
