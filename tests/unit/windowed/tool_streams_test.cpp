// Two tools on one sensor topic: each is its own stream with its own sequence accounting; a
// selected tool takes only its own batches and counts the others.
#include <gtest/gtest.h>

#include <cstdint>

#include "tool_streams.hpp"

namespace plumb::estimator_component {
namespace {

void feed(ToolStreams& streams, const std::string& tool, std::uint64_t first, int n) {
  SequenceAccount* a = streams.route(tool);
  if (!a) return;
  for (int i = 0; i < n; ++i) a->account(first + static_cast<std::uint64_t>(i));
}

TEST(ToolStreams, InterleavedToolsLoseNothing) {
  ToolStreams streams;
  // A turntable counting from 0 and a tool counting from 50000, batch by batch in turn.
  for (int b = 0; b < 100; ++b) {
    feed(streams, "sim-turntable", static_cast<std::uint64_t>(32 * b), 32);
    feed(streams, "T1", 50000 + static_cast<std::uint64_t>(32 * b), 32);
  }
  EXPECT_EQ(streams.streams().size(), 2u);
  EXPECT_EQ(streams.lost(), 0u);
  EXPECT_EQ(streams.gaps(), 0u);
  EXPECT_EQ(streams.backwards(), 0u);
  EXPECT_EQ(streams.other_tool_batches(), 0u);
}

TEST(ToolStreams, GapsAreCountedPerTool) {
  ToolStreams streams;
  feed(streams, "A", 0, 10);
  feed(streams, "B", 0, 10);
  feed(streams, "A", 15, 5);  // 10..14 lost on A
  feed(streams, "B", 10, 5);
  EXPECT_EQ(streams.streams().at("A").lost, 5u);
  EXPECT_EQ(streams.streams().at("B").lost, 0u);
  EXPECT_EQ(streams.lost(), 5u);
}

TEST(ToolStreams, SelectedToolCountsTheOthers) {
  ToolStreams streams("T1");
  feed(streams, "T1", 0, 32);
  EXPECT_EQ(streams.route("sim-turntable"), nullptr);
  feed(streams, "T1", 32, 32);
  EXPECT_EQ(streams.streams().size(), 1u);
  EXPECT_EQ(streams.other_tool_batches(), 1u);
  EXPECT_EQ(streams.lost(), 0u);
}

TEST(ToolStreams, RestartForgetsTheExpectedNumber) {
  ToolStreams streams;
  feed(streams, "A", 0, 10);
  streams.restart_all();
  feed(streams, "A", 1000, 10);
  EXPECT_EQ(streams.lost(), 0u);
}

TEST(ToolStreams, PauseCostsAreCountedApart) {
  ToolStreams streams;
  feed(streams, "A", 0, 10);
  streams.restart_all();
  feed(streams, "A", 1000, 10);  // a link down: 990 samples never came
  EXPECT_EQ(streams.silent_gaps(), 1u);
  EXPECT_EQ(streams.silent_lost(), 990u);
  streams.restart_all();
  feed(streams, "A", 0, 10);  // the source started again
  EXPECT_EQ(streams.source_restarts(), 1u);
  streams.restart_all();
  feed(streams, "A", 10, 10);  // a pause that lost nothing
  EXPECT_EQ(streams.silent_gaps(), 1u);
  EXPECT_EQ(streams.gaps(), 0u);
  EXPECT_EQ(streams.lost(), 0u);
  EXPECT_EQ(streams.backwards(), 0u);
}

TEST(ToolStreams, PauseBeforeTheFirstSampleIsNoGap) {
  ToolStreams streams;
  streams.route("A");
  streams.restart_all();
  feed(streams, "A", 500, 10);
  EXPECT_EQ(streams.silent_gaps(), 0u);
  EXPECT_EQ(streams.lost(), 0u);
}

// A source started again while the stream flows (no pause between the runs): its clock goes back,
// and its sequence starting over is a source restart, not a step back.
TEST(ToolStreams, ClockGoingBackIsASourceRestart) {
  ToolStreams streams;
  SequenceAccount& a = *streams.route("A");
  a.clock(0.0, 0.09);
  feed(streams, "A", 0, 10);
  a.clock(0.1, 0.19);
  feed(streams, "A", 10, 10);
  a.clock(0.0, 0.09);  // the second run
  feed(streams, "A", 0, 10);
  EXPECT_EQ(streams.source_restarts(), 1u);
  EXPECT_EQ(streams.backwards(), 0u);
  EXPECT_EQ(streams.lost(), 0u);
}

// A source started again restarts its clock: the chunk is cut where time goes back, against the
// tool's last sample before the chunk too; equal times are not a new run.
TEST(ToolStreams, NewRunStartsWhereTimeGoesBack) {
  auto samples = [](std::initializer_list<double> times) {
    std::vector<Sample> v;
    for (double t : times) {
      Sample s;
      s.t = t;
      v.push_back(s);
    }
    return v;
  };
  const auto steady = samples({1.0, 1.01, 1.02});
  EXPECT_EQ(new_run_start(steady, std::nullopt), 3u);
  EXPECT_EQ(new_run_start(steady, 0.99), 3u);
  EXPECT_EQ(new_run_start(steady, 1.0), 3u);
  EXPECT_EQ(new_run_start(steady, 5.0), 0u);
  EXPECT_EQ(new_run_start(samples({3.98, 3.99, 0.0, 0.01}), 3.97), 2u);
  EXPECT_EQ(new_run_start(samples({}), 1.0), 0u);
}

}  // namespace
}  // namespace plumb::estimator_component
