// Parameters files: the layout, file and line in every refusal, and the file under --param.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "plumb/components/cli.hpp"
#include "plumb/components/params_file.hpp"
#include "plumb/estimator/assignments.hpp"
#include "plumb/estimator/parameter_reader.hpp"
#include "plumb/estimator/runner.hpp"

namespace plumb::components {
namespace {

class ParamsFile : public ::testing::Test {
 protected:
  std::string write(const std::string& text) {
    std::ofstream(path_) << text;
    return path_;
  }
  void TearDown() override { std::remove(path_.c_str()); }
  std::string message_for(const std::string& text) {
    try {
      read_params_file(write(text));
    } catch (const estimator::ParameterError& e) {
      return e.what();
    }
    return "(no error)";
  }
  // One file per test and process: ctest runs the tests of this file side by side.
  std::string path_ = ::testing::TempDir() + "plumb_params_" +
                      ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
                      std::to_string(::getpid()) + ".yaml";
};

estimator::Info plugin(const std::string& name, std::vector<std::string> keys) {
  estimator::Info info;
  info.name = name;
  for (auto& k : keys) info.parameters.push_back({k, "", ""});
  return info;
}

TEST_F(ParamsFile, EntriesArePluginKeyValueTaggedWithFileAndLine) {
  const auto entries = read_params_file(write("# comment\nstrapdown:\n  latitude_deg: 35\n  imu_grade: mems\n"));
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0], estimator::with_origin(path_ + ":3", "strapdown.latitude_deg=35"));
  EXPECT_EQ(entries[1], estimator::with_origin(path_ + ":4", "strapdown.imu_grade=mems"));
}

TEST_F(ParamsFile, UnknownKeyIsRefusedWithFileAndLine) {
  const auto entries = read_params_file(write("strapdown:\n  latitude_deg: 35\n  latitud_deg: 36\n"));
  try {
    estimator::assign_parameters({plugin("strapdown", {"latitude_deg"})}, entries, std::nullopt);
    FAIL() << "accepted an unknown key";
  } catch (const estimator::ParameterError& e) {
    EXPECT_EQ(std::string(e.what()), path_ + ":3: 'latitud_deg': strapdown has no such parameter: did you mean latitude_deg? (see plumb plugins -v)");
  }
}

TEST_F(ParamsFile, PluginNotSelectedIsRefusedWithFileAndLine) {
  const auto entries = read_params_file(write("static:\n  window: 2\nstrapdwn:\n  gravity: 9.8\n"));
  try {
    estimator::assign_parameters({plugin("static", {"window"})}, entries, std::nullopt);
    FAIL() << "accepted a plugin that is not selected";
  } catch (const estimator::ParameterError& e) {
    EXPECT_EQ(std::string(e.what()), path_ + ":4: estimator 'strapdwn' is not selected");
  }
  // A near miss of a selected plugin's name is suggested.
  const auto typo = read_params_file(write("strapdwn:\n  gravity: 9.8\n"));
  try {
    estimator::assign_parameters({plugin("static", {"window"}), plugin("strapdown", {"gravity"})}, typo, std::nullopt);
    FAIL() << "accepted a plugin that is not selected";
  } catch (const estimator::ParameterError& e) {
    EXPECT_EQ(std::string(e.what()), path_ + ":2: estimator 'strapdwn' is not selected: did you mean strapdown?");
  }
}

// A plugin that reads one number in [-90, 90], as the real ones read theirs.
class LatitudeOnly : public estimator::Estimator {
 public:
  estimator::Info info() const override { return plugin("nav", {"latitude_deg", "grade"}); }
  void configure(const estimator::Parameters& p) override {
    estimator::ParameterReader(p, info().parameters).number("latitude_deg", -90, 90);
  }
  void push(std::span<const Sample>, std::vector<Estimate>&) override {}
  void flush(std::vector<Estimate>&) override {}
  estimator::Counters counters() const override { return {}; }
};

// A value the plugin refuses (a word for a number, out of range) is reported at its file and line.
TEST_F(ParamsFile, BadValueIsRefusedWithFileAndLine) {
  const auto entries = read_params_file(write("nav:\n  grade: mems\n  latitude_deg: abc\n"));
  estimator::Runner runner;
  runner.add("nav", estimator::EstimatorPtr(new LatitudeOnly, [](estimator::Estimator* e) { delete e; }));
  try {
    runner.configure(entries, std::nullopt);
    FAIL() << "accepted a word for a number";
  } catch (const estimator::ParameterError& e) {
    EXPECT_EQ(std::string(e.what()), path_ + ":3: parameter 'latitude_deg': 'abc' is not a number in [-90, 90]");
  }
  // The same from --param: no file to name, the message as the plugin gave it.
  try {
    runner.configure({"latitude_deg=91"}, std::nullopt);
    FAIL() << "accepted 91 degrees of latitude";
  } catch (const estimator::ParameterError& e) {
    EXPECT_EQ(std::string(e.what()), "parameter 'latitude_deg': '91' is not a number in [-90, 90]");
  }
}

TEST_F(ParamsFile, LayoutErrorsNameTheLine) {
  EXPECT_EQ(message_for("strapdown: 3\n"), path_ + ":1: plugin 'strapdown' holds no KEY: VALUE lines (expected PLUGIN: then indented KEY: VALUE lines)");
  EXPECT_EQ(message_for("strapdown:\n  a: 1\n  b: [1, 2]\n"), path_ + ":3: 'strapdown.b' needs one value (a list or map is not a parameter value)");
  EXPECT_EQ(message_for("strapdown:\n  a:\n"), path_ + ":2: 'strapdown.a' needs one value (it is empty)");
  EXPECT_EQ(message_for("strapdown:\n  a: 1\n  a: 2\n"), path_ + ":3: 'strapdown.a' is given twice");
  EXPECT_EQ(message_for("- strapdown\n"), path_ + ":1: expected PLUGIN: then indented KEY: VALUE lines");
  EXPECT_EQ(message_for(""), path_ + ": no parameters in the file (expected PLUGIN: then indented KEY: VALUE lines)");
  EXPECT_EQ(message_for("strapdown:\n  a: [1\n"), path_ + ":3: not YAML: end of sequence flow not found");
}

TEST_F(ParamsFile, MissingFileIsNamed) {
  EXPECT_THROW(read_params_file("/nonexistent/params.yaml"), estimator::ParameterError);
}

TEST_F(ParamsFile, ParamOnTheCommandLineOverridesTheFile) {
  write("strapdown:\n  latitude_deg: 35\n  gravity: 9.8\n");
  CLI::App app{"test"};
  std::vector<std::string> params;
  add_param_option(app, params);
  std::vector<std::string> args{"test", "--param", "strapdown.latitude_deg=50", "--params-file", path_};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  app.parse(static_cast<int>(argv.size()), argv.data());
  const auto assigned =
      estimator::assign_parameters({plugin("strapdown", {"latitude_deg", "gravity"})}, params, std::nullopt);
  EXPECT_EQ(assigned[0].at("latitude_deg"), "50");
  EXPECT_EQ(assigned[0].at("gravity"), "9.8");
}

TEST_F(ParamsFile, AFileThatCannotBeReadIsAUsageErrorOfTheOption) {
  CLI::App app{"test"};
  std::vector<std::string> params;
  add_param_option(app, params);
  std::vector<std::string> args{"test", "--params-file", "/nonexistent/params.yaml"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  EXPECT_THROW(app.parse(static_cast<int>(argv.size()), argv.data()), CLI::ValidationError);
}

}  // namespace
}  // namespace plumb::components
