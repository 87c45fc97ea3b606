// Plugins found and loaded by name through the loader, described, configured, and refused clearly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "estimator_test_support.hpp"

namespace plumb::estimator {
namespace {

TEST(EstimatorLoader, FindsTheThreePlugins) {
  const auto found = find_plugins();
  for (const char* name : test::kAllPlugins) {
    auto it = std::find_if(found.begin(), found.end(), [&](const FoundPlugin& p) { return p.name == name; });
    ASSERT_NE(it, found.end()) << name;
    EXPECT_TRUE(it->error.empty()) << it->error;
    EXPECT_FALSE(it->description.empty());
  }
  // The API library shares the file prefix but is not a plugin.
  EXPECT_TRUE(std::none_of(found.begin(), found.end(), [](const FoundPlugin& p) { return p.name == "api"; }));
}

TEST(EstimatorLoader, LoadsByNameAndDescribes) {
  for (const char* name : test::kAllPlugins) {
    auto e = load_estimator(name);
    ASSERT_TRUE(e);
    const Info info = e->info();
    EXPECT_EQ(info.name, name);
    EXPECT_FALSE(info.description.empty());
    EXPECT_FALSE(info.version.empty());
    EXPECT_FALSE(info.uses_gyro);
    ASSERT_FALSE(info.parameters.empty());
    EXPECT_EQ(info.parameters.front().name, "window");
    EXPECT_EQ(info.parameters.front().default_value, "10");
    // Every default configures cleanly.
    Parameters defaults;
    for (const auto& p : info.parameters) defaults[p.name] = p.default_value;
    EXPECT_NO_THROW(e->configure(defaults));
  }
}

TEST(EstimatorLoader, UnknownPluginErrorListsWhatExists) {
  try {
    load_estimator("no_such_estimator");
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& error) {  // a usage error: exit status 2 in every program
    const std::string what = error.what();
    EXPECT_NE(what.find("no_such_estimator"), std::string::npos);
    for (const char* name : test::kAllPlugins) EXPECT_NE(what.find(name), std::string::npos) << what;
  }
}

TEST(EstimatorLoader, AMisspelledNameNamesTheCloseMatches) {
  try {
    load_estimator("compensate");
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("unknown estimator 'compensate': did you mean compensated?"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

TEST(EstimatorLoader, InstancesOutliveEachOtherAndTheirSiblings) {
  // Two instances of one plugin: destroying the first must not unload the code of the second.
  auto first = load_estimator("compensated");
  auto second = load_estimator("compensated");
  first.reset();
  std::vector<Estimate> out;
  second->configure({{"window", "0"}});
  second->flush(out);
  EXPECT_TRUE(out.empty());
  EXPECT_EQ(second->info().name, "compensated");
}

TEST(EstimatorLoader, BadParametersNameTheParameter) {
  auto e = load_estimator("static");
  try {
    e->configure({{"windw", "3"}});
    FAIL();
  } catch (const ParameterError& error) {
    EXPECT_NE(std::string(error.what()).find("windw"), std::string::npos);
  }
  for (const auto& [name, value] : Parameters{{"window", "-1"}, {"window", "abc"}, {"max_turn", "1e9"}}) {
    try {
      e->configure({{name, value}});
      FAIL() << name << "=" << value;
    } catch (const ParameterError& error) {
      EXPECT_NE(std::string(error.what()).find(name), std::string::npos);
    }
  }
  auto c = load_estimator("compensated");
  EXPECT_THROW(c->configure({{"estimate_biases", "maybe"}}), ParameterError);
}

TEST(EstimatorLoader, EnvironmentPathComesFirstAndBadFoldersAreHarmless) {
  ::setenv("PLUMB_ESTIMATOR_PATH", "/nonexistent:/tmp", 1);
  EXPECT_NO_THROW(load_estimator("integral"));
  ::unsetenv("PLUMB_ESTIMATOR_PATH");
}

}  // namespace
}  // namespace plumb::estimator

namespace plumb::estimator {
namespace {

// The estimator is destroyed while its ParameterError propagates: the plugin's code (the
// exception's vtable) must still be mapped when the catch runs.
TEST(EstimatorLoader, PluginExceptionOutlivesItsInstance) {
  for (const char* name : test::kAllPlugins) {
    try {
      auto e = load_estimator(name);
      e->configure({{"bogus", "1"}});
      FAIL();
    } catch (const ParameterError& error) {
      EXPECT_NE(std::string(error.what()).find("bogus"), std::string::npos);
    }
  }
}

}  // namespace
}  // namespace plumb::estimator
