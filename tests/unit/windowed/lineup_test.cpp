// The estimator host's run-time changes (plumb component load|unload, plumb param get|set|dump) are
// refused with the words the command line uses for the same mistake, and a refused change changes
// nothing.
#include <gtest/gtest.h>

#include <functional>

#include "lineup.hpp"
#include "plumb/estimator/loader.hpp"

namespace plumb::estimator_component {
namespace {

// The message an action throws, or "" when it does not.
std::string lineup_refusal(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

// What plumb-estimator says at start for these plugins and --param assignments.
std::string start_refusal(const std::vector<std::string>& plugins, const std::vector<std::string>& params) {
  return lineup_refusal([&] { Lineup(plugins, params, 10); });
}

TEST(Lineup, RefusesAnUnknownParameterAsTheCommandLineDoes) {
  Lineup lineup({"static", "integral"}, {}, 2);
  const std::string at_run_time = lineup_refusal([&] { lineup.set("integral", "windw", "5"); });
  EXPECT_NE(at_run_time, "");
  EXPECT_EQ(at_run_time, start_refusal({"integral"}, {"integral.windw=5"}));
  EXPECT_NE(at_run_time.find("did you mean window"), std::string::npos) << at_run_time;
  EXPECT_EQ(lineup_refusal([&] { lineup.get("integral", "windw"); }), at_run_time);
}

TEST(Lineup, RefusesAValueOutOfRangeAsTheCommandLineDoesAndKeepsTheOldOne) {
  Lineup lineup({"static", "integral"}, {}, 2);
  const std::string at_run_time = lineup_refusal([&] { lineup.set("integral", "window", "-3"); });
  EXPECT_NE(at_run_time, "");
  EXPECT_EQ(at_run_time, start_refusal({"integral"}, {"integral.window=-3"}));
  EXPECT_EQ(lineup.get("integral", "window").value, "2.000000");  // --window 2, as assign_parameters writes it
  EXPECT_EQ(lineup.get("integral", "window").default_value, "10");
}

TEST(Lineup, SetChangesOnlyThatPluginAndNewRunnersStartWithIt) {
  Lineup lineup({"static", "integral"}, {}, 2);
  const auto parameters = lineup.set("integral", "window", "1");
  EXPECT_EQ(parameters.at("window"), "1");
  EXPECT_EQ(lineup.get("integral", "window").value, "1");
  EXPECT_EQ(lineup.get("static", "window").value, "2.000000");
  const estimator::Runner runner = lineup.make_runner();
  ASSERT_NE(runner.find("integral"), nullptr);
  EXPECT_EQ(runner.find("integral")->parameters.at("window"), "1");
  EXPECT_EQ(runner.find("static")->parameters.at("window"), "2.000000");
}

TEST(Lineup, LoadsWithTheHostsWindowAndRefusesTwiceOrUnknown) {
  Lineup lineup({"static"}, {}, 2);
  const auto parameters = lineup.load("integral", {"integral.max_model_error_deg=3"});
  EXPECT_EQ(parameters.at("window"), "2.000000");
  EXPECT_EQ(lineup.entries().size(), 2u);
  EXPECT_EQ(lineup_refusal([&] { lineup.load("integral", {}); }), start_refusal({"integral", "integral"}, {}));
  const std::string unknown = lineup_refusal([&] { lineup.load("integrl", {}); });
  EXPECT_EQ(unknown, lineup_refusal([] { estimator::load_estimator("integrl"); }));
  EXPECT_EQ(lineup_refusal([&] { lineup.load("compensated", {"bogus=1"}); }), start_refusal({"compensated"}, {"bogus=1"}));
  EXPECT_EQ(lineup.entries().size(), 2u);  // the refused loads added nothing
  EXPECT_EQ(lineup.make_runner().slots().size(), 2u);
}

TEST(Lineup, LoadAssignmentsTravelSemicolonSeparated) {
  EXPECT_EQ(split_assignments("a=1;integral.window=2"), (std::vector<std::string>{"a=1", "integral.window=2"}));
  EXPECT_EQ(split_assignments(""), std::vector<std::string>{});
  EXPECT_EQ(split_assignments(";a=1;;"), std::vector<std::string>{"a=1"});
  Lineup lineup({"static"}, {}, 2);
  EXPECT_EQ(lineup.load("integral", split_assignments("max_model_error_deg=3;window=4")).at("window"), "4");
}

TEST(Lineup, UnloadsALoadedPluginButNeverTheLast) {
  Lineup lineup({"static", "integral"}, {}, 2);
  EXPECT_NE(lineup_refusal([&] { lineup.unload("integrall"); }).find("not loaded (loaded: static, integral): did you mean integral"),
            std::string::npos);
  lineup.unload("integral");
  EXPECT_EQ(lineup.find("integral"), nullptr);
  EXPECT_NE(lineup_refusal([&] { lineup.unload("static"); }).find("only one loaded"), std::string::npos);
  EXPECT_EQ(lineup.make_runner().slots().size(), 1u);
}

TEST(Lineup, DumpsEveryDeclaredParameterWithItsValueInUse) {
  Lineup lineup({"integral"}, {"integral.window=4"}, 2);
  const auto all = lineup.dump("integral");
  ASSERT_FALSE(all.empty());
  EXPECT_EQ(all.front().name, "window");
  EXPECT_EQ(all.front().value, "4");
  for (const auto& v : all) EXPECT_EQ(v.plugin, "integral");
}

}  // namespace
}  // namespace plumb::estimator_component
