// The record an estimator host leaves for its next instance, and what that instance makes of it:
// the samples sent while the host was down, a source that started again, another run.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "resume_record.hpp"

namespace plumb::estimator_component {
namespace {

constexpr std::int64_t kResumeSecond = 1000000000;

TEST(ResumeRecord, MarksSurviveTheirText) {
  ToolMarks marks{{"sim", {12345, 123 * kResumeSecond, 1764380000 * kResumeSecond}},
                  {"tool with spaces", {0, -5, 7}}};
  EXPECT_EQ(parse_marks(format_marks(marks)), marks);
}

TEST(ResumeRecord, TheTextOfATwoToolRecordKeepsItsLengthAsNumbersGrow) {
  // Rewritten in place: a shorter text would leave the end of the former one behind.
  const ToolMarks small{{"a", {1, 2, 3}}, {"b", {4, 5, 6}}};
  const ToolMarks large{{"a", {999999999999, 2 * kResumeSecond, 1764380000 * kResumeSecond}}, {"b", {4, -5, 6}}};
  EXPECT_EQ(format_marks(small).size(), format_marks(large).size());
}

TEST(ResumeRecord, ADamagedRecordCountsNothing) {
  EXPECT_TRUE(parse_marks("").empty());
  EXPECT_TRUE(parse_marks("something else\n00001 2 3 sim\n").empty());
  const ToolMarks some = parse_marks(format_marks({{"sim", {10, 20, 30}}}) + "garbage line\n");
  EXPECT_EQ(some.size(), 1u);
}

TEST(ResumeRecord, CountsTheSamplesSentWhileDown) {
  // 100 Hz, down 3 s: the last taken 999 at t 10 s; the first batch after the restart starts at
  // 1300 and ends at 1331 (t 13.31 s), 3.3 s of wall clock after the mark.
  const ToolMark mark{999, 10 * kResumeSecond, 1000 * kResumeSecond};
  const DownLoss d = loss_while_down(mark, 1300, 13310000000, 1000 * kResumeSecond + 3300000000);
  EXPECT_EQ(d.kind, DownLoss::Kind::Lost);
  EXPECT_EQ(d.first, 1000u);
  EXPECT_EQ(d.last, 1299u);
  EXPECT_EQ(d.count(), 300u);
}

TEST(ResumeRecord, NothingLostWhenTheStreamGoesOnWhereItStopped) {
  const ToolMark mark{999, 10 * kResumeSecond, 1000 * kResumeSecond};
  const DownLoss d = loss_while_down(mark, 1000, 10320000000, 1000 * kResumeSecond + 400000000);
  EXPECT_EQ(d.kind, DownLoss::Kind::Lost);
  EXPECT_EQ(d.count(), 0u);
}

TEST(ResumeRecord, ASequenceOrClockThatWentBackIsANewSource) {
  const ToolMark mark{999, 10 * kResumeSecond, 1000 * kResumeSecond};
  EXPECT_EQ(loss_while_down(mark, 40, 400000000, 1003 * kResumeSecond).kind, DownLoss::Kind::SourceRestarted);
  EXPECT_EQ(loss_while_down(mark, 5000, 9 * kResumeSecond, 1003 * kResumeSecond).kind, DownLoss::Kind::SourceRestarted);
}

TEST(ResumeRecord, ARecordFromAnotherRunIsNotCounted) {
  // An hour later a new simulation is 20 s in: its clock moved 10 s, the wall clock 3600 s.
  const ToolMark mark{999, 10 * kResumeSecond, 1000 * kResumeSecond};
  const DownLoss d = loss_while_down(mark, 2000, 20 * kResumeSecond, 4600 * kResumeSecond);
  EXPECT_EQ(d.kind, DownLoss::Kind::ClocksDisagree);
  EXPECT_EQ(d.count(), 0u);
}

TEST(ResumeRecord, WallTimeIsSaidInUtc) {
  EXPECT_EQ(wall_time_text(1764381003250000000), "2025-11-29 01:50:03.250 UTC");
}

TEST(ResumeRecord, FileNamesTheDomainTopicAndTool) {
  EXPECT_EQ(resume_file_name(7, "plumb/sensor/calibrated", ""), "plumb-estimator-domain7-plumb_sensor_calibrated.resume");
  EXPECT_EQ(resume_file_name(7, "plumb/sensor/raw", "T 1"), "plumb-estimator-domain7-plumb_sensor_raw-tool-T_1.resume");
}

TEST(ResumeRecord, TheNextInstanceReadsWhatThePreviousSavedAndTwoRunningHostsKeepOneFileEach) {
  const auto dir = std::filesystem::temp_directory_path() / ("plumb-resume-test-" + std::to_string(getpid()));
  const std::string path = (dir / "sub" / "host.resume").string();
  const ToolMarks marks{{"sim", {41, 42, 43}}};
  std::string why;
  {
    auto first = ResumeFile::open(path, why);
    ASSERT_TRUE(first) << why;
    EXPECT_TRUE(first->previous().empty());
    EXPECT_TRUE(first->save(marks));
    auto second = ResumeFile::open(path, why);  // the first is held by a running host
    ASSERT_TRUE(second) << why;
    EXPECT_EQ(second->path(), path + ".2");
    EXPECT_TRUE(second->previous().empty());
  }
  auto again = ResumeFile::open(path, why);
  ASSERT_TRUE(again) << why;
  EXPECT_EQ(again->path(), path);
  EXPECT_EQ(again->previous(), marks);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace plumb::estimator_component
