// CSV replay: good rows come out in order, bad rows are counted with their line and column and
// skipped (or, strict, stop the replay), and the pacing follows the file's own time.
#include "plumb/bridge/replay_source.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace plumb::bridge {
namespace {

using namespace std::chrono_literals;

struct TempFile {
  std::string path;
  explicit TempFile(const std::string& text) {
    char tmpl[] = "/tmp/plumb-replay-test-XXXXXX";
    const int fd = ::mkstemp(tmpl);
    ::close(fd);
    path = tmpl;
    std::ofstream(path) << text;
  }
  ~TempFile() { std::filesystem::remove(path); }
};

const char* kCsv =
    "t,fx,fy,fz,bx,by,bz\n"
    "0.00,1,2,3,4,5,6\n"
    "0.01,1,x,3,4,5,6\n"
    "0.02,1,2,3,4,5,6\n"
    "0.03,1,2,3\n"
    "0.04,1,2,3,4,5,6\n";

std::vector<Sample> drain(ReplaySource& source) {
  std::vector<Sample> out;
  for (int guard = 0; guard < 1000 && source.poll(out, 50ms); ++guard) {
  }
  return out;
}

TEST(ReplaySource, AnotherLoggersFileIsImportedAndItsUnitsChecked) {
  std::string text = "\"time (ms)\",\"ax (g)\",\"ay (g)\",\"az (g)\"\n";
  for (int k = 0; k < 50; ++k) text += std::to_string(10 * k) + ",0,0.5,0.8660254\n";
  TempFile file(text);
  Counters c;
  std::vector<std::string> warnings;
  const auto warn = [&](const std::string& w) { warnings.push_back(w); };
  // Declared m/s^2: the start of the file is checked before the first sample is replayed.
  const csv::Import columns_only = csv::make_import({"t=time (ms)", "fx=ax (g)", "fy=ay (g)", "fz=az (g)"}, {"time=ms"}, "");
  ReplaySource wrong(file.path, 0.0, c, true, {}, columns_only, warn);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("give --units accel=g"), std::string::npos) << warnings[0];

  warnings.clear();
  const csv::Import right = csv::make_import({"t=time (ms)", "fx=ax (g)", "fy=ay (g)", "fz=az (g)"},
                                             {"time=ms,accel=g"}, "x,-y,-z");
  ReplaySource source(file.path, 0.0, c, true, {}, right, warn);
  EXPECT_TRUE(warnings.empty());
  EXPECT_NE(source.describe().find("axes x,-y,-z"), std::string::npos) << source.describe();
  const auto samples = drain(source);
  ASSERT_EQ(samples.size(), 50u);
  EXPECT_DOUBLE_EQ(samples[1].t, 0.01);
  EXPECT_NEAR(samples[1].f.y(), -0.5 * 9.80665, 1e-12);
  EXPECT_TRUE(samples[1].flags & flags::kNoMagnetometer);
}

TEST(ReplaySource, BadRowsAreCountedNamedAndSkipped) {
  TempFile file(kCsv);
  Counters c;
  std::vector<std::string> errors;
  ReplaySource source(file.path, 0.0, c, false, [&](const csv::Error& e) { errors.push_back(e.what()); });
  const auto samples = drain(source);
  ASSERT_EQ(samples.size(), 3u);
  EXPECT_EQ(samples[1].t, 0.02);
  EXPECT_EQ(samples[1].seq, 1u);  // rows are numbered as read, bad ones not counted
  EXPECT_EQ(c.csv_errors, 2u);
  EXPECT_EQ(c.lines_ok, 3u);
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_NE(errors[0].find(":3: column 'fy': bad number 'x'"), std::string::npos) << errors[0];
  EXPECT_NE(errors[1].find(":5: column 'bx'"), std::string::npos) << errors[1];
}

TEST(ReplaySource, StrictStopsAtTheFirstBadRow) {
  TempFile file(kCsv);
  Counters c;
  ReplaySource source(file.path, 0.0, c, true);
  std::vector<Sample> out;
  EXPECT_THROW(
      {
        for (int guard = 0; guard < 100 && source.poll(out, 10ms); ++guard) {
        }
      },
      csv::Error);
  EXPECT_EQ(out.size(), 1u);
}

TEST(ReplaySource, MissingFileOrColumnIsAnErrorAtOnce) {
  Counters c;
  EXPECT_THROW(ReplaySource("/nonexistent/plumb.csv", 1.0, c, false), csv::Error);
  TempFile file("t,fx,fy,fz,bx,by\n0,1,2,3,4,5\n");
  EXPECT_THROW(ReplaySource(file.path, 1.0, c, false), csv::Error);
}

TEST(ReplaySource, RealTimePacingReleasesOnlySamplesWhoseTimeHasCome) {
  // 0 s and 100 s: in real time the second one cannot be due within one short poll.
  TempFile file("t,fx,fy,fz,bx,by,bz\n0,1,2,3,4,5,6\n100,1,2,3,4,5,6\n");
  Counters c;
  ReplaySource source(file.path, 1.0, c, false);
  std::vector<Sample> out;
  EXPECT_TRUE(source.poll(out, 20ms));
  EXPECT_TRUE(source.poll(out, 20ms));
  EXPECT_EQ(out.size(), 1u);
}

}  // namespace
}  // namespace plumb::bridge
