// Launch files: the layout, defaults, and every refusal naming file and line.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>

#include "launch_file.hpp"

namespace plumb::launch {
namespace {

class LaunchFile : public ::testing::Test {
 protected:
  std::string write(const std::string& text) {
    std::ofstream(path_) << text;
    return path_;
  }
  std::string message_for(const std::string& text) {
    try {
      read_launch_file(write(text));
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "(no error)";
  }
  void TearDown() override { std::remove(path_.c_str()); }
  // One file per test and process: ctest runs the tests of this file side by side.
  std::string path_ = ::testing::TempDir() + "plumb_launch_" +
                      ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
                      std::to_string(::getpid()) + ".yaml";
};

TEST_F(LaunchFile, ProgramsWithTheirPolicies) {
  const auto p = read_launch_file(write(
      "launch:\n"
      "  - cmd: plumb-sim --rate x10 --csv 'a b'\n"
      "    on_exit: shutdown\n"
      "  - name: host\n"
      "    cmd: [plumb-estimator, --plugin, static]\n"
      "    restart: on-failure\n"
      "    restart_limit: 5\n"
      "    restart_delay: 0.5\n"
      "    env: {PLUMB_TRANSPORT: fastdds}\n"
      "    cwd: run\n"));
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0].name, "plumb-sim");
  EXPECT_EQ(p[0].argv, (std::vector<std::string>{"plumb-sim", "--rate", "x10", "--csv", "a b"}));
  EXPECT_EQ(p[0].restart, Restart::Never);
  EXPECT_TRUE(p[0].shutdown_on_exit);
  EXPECT_EQ(p[0].where, path_ + ":2");
  EXPECT_EQ(p[1].name, "host");
  EXPECT_EQ(p[1].argv.size(), 3u);
  EXPECT_EQ(p[1].restart, Restart::OnFailure);
  EXPECT_EQ(p[1].restart_limit, 5);
  EXPECT_DOUBLE_EQ(p[1].restart_delay_s, 0.5);
  EXPECT_EQ(p[1].env.at("PLUMB_TRANSPORT"), "fastdds");
  EXPECT_EQ(p[1].cwd, "run");
  EXPECT_FALSE(p[1].shutdown_on_exit);
}

TEST_F(LaunchFile, RefusalsNameTheLine) {
  EXPECT_EQ(message_for("launch:\n  - cmd: a\n    restrat: on-failure\n"),
            path_ + ":3: unknown key 'restrat' (known: name, cmd, restart, restart_limit, restart_delay, required, on_exit, env, cwd)");
  EXPECT_EQ(message_for("launch:\n  - cmd: a\n    restart: always\n"),
            path_ + ":3: 'restart' is never or on-failure, got 'always'");
  EXPECT_EQ(message_for("launch:\n  - name: x\n"), path_ + ":2: a program without 'cmd'");
  EXPECT_EQ(message_for("launch:\n  - cmd: a\n  - cmd: a\n"),
            path_ + ":3: the name 'a' is given twice (name: tells two runs of one program apart)");
  EXPECT_EQ(message_for("launch:\n  - cmd: a 'b\n"), path_ + ":2: cmd: unterminated ' quote");
  EXPECT_EQ(message_for("launch:\n  - cmd: a\n    restart_limit: -1\n"),
            path_ + ":3: 'restart_limit' must be a number >= 0, got '-1'");
  EXPECT_EQ(message_for("programs:\n  - cmd: a\n"),
            path_ + ": expected 'launch:' and below it a list of programs ('- cmd: ...')");
  EXPECT_EQ(message_for("launch: []\n"), path_ + ":1: 'launch' needs a list of programs ('- cmd: ...')");
  EXPECT_EQ(read_launch_file(write("launch:\n  - cmd: a\n"))[0].name, "a");
  EXPECT_NE(message_for("launch:\n  - cmd: [a\n").find(": not YAML"), std::string::npos);
  EXPECT_NE(message_for("").find("expected 'launch:'"), std::string::npos);
}

TEST_F(LaunchFile, RequiredAndWhereTheCommandIs) {
  const auto p = read_launch_file(write("launch:\n  - name: a\n    required: true\n    cmd: x\n  - cmd: y\n"));
  EXPECT_TRUE(p[0].required);
  EXPECT_FALSE(p[1].required) << "a program fails alone unless the file says otherwise";
  EXPECT_EQ(p[0].where, path_ + ":2");
  EXPECT_EQ(p[0].cmd_where, path_ + ":4");
  EXPECT_EQ(message_for("launch:\n  - cmd: a\n    required: yes please\n"),
            path_ + ":3: 'required' is true or false, got 'yes please'");
}

// Launch arguments as ROS 2's: declared with defaults, given as NAME:=VALUE, $(var NAME) in cmd,
// env and cwd.
TEST_F(LaunchFile, ArgumentsReplaceTheirVariables) {
  const std::string file = "arguments:\n  port: \"8080\"\n  dir: run\nlaunch:\n"
                           "  - cmd: plumb-display --port $(var port) --x a$(var port)b\n"
                           "    env: {P: \"$(var port)\"}\n    cwd: $(var dir)/here\n";
  auto p = read_launch_file(write(file));
  EXPECT_EQ(p[0].argv, (std::vector<std::string>{"plumb-display", "--port", "8080", "--x", "a8080b"}));
  p = read_launch_file(write(file), parse_arguments({"port:=8081"}));
  EXPECT_EQ(p[0].argv[2], "8081");
  EXPECT_EQ(p[0].env.at("P"), "8081");
  EXPECT_EQ(p[0].cwd, "run/here");
  try {
    read_launch_file(write(file), {{"prot", "1"}});
    ADD_FAILURE() << "an undeclared argument was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "launch argument 'prot' is not declared in " + path_ + " (declared: dir, port)");
  }
  EXPECT_EQ(message_for("launch:\n  - cmd: a $(var x)\n"),
            path_ + ":2: $(var x): no launch argument 'x' (declared under 'arguments:': none)");
  EXPECT_EQ(message_for("launch:\n  - cmd: a $(env HOME)\n"),
            path_ + ":2: '$(' starts a substitution: $(var NAME), got '$(env HOME)'");
  EXPECT_THROW(parse_arguments({"port=1"}), std::invalid_argument);
  EXPECT_THROW(parse_arguments({":=1"}), std::invalid_argument);
}

TEST(LaunchWords, SplitLikeAShell) {
  EXPECT_EQ(split_words("a  b\tc"), (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(split_words("a 'b c' \"d \\\" e\" f\\ g ''"), (std::vector<std::string>{"a", "b c", "d \" e", "f g", ""}));
  EXPECT_EQ(split_words(""), std::vector<std::string>{});
  EXPECT_THROW(split_words("a \"b"), std::invalid_argument);
}

}  // namespace
}  // namespace plumb::launch
