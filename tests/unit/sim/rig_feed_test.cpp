// plumb-sim --wits's rig feed against real sockets on 127.0.0.1: it says once that it waits for
// plumb-wits and once whether it came, reaches a plumb-wits that starts late, sends a frame per
// interval of the run, and counts the frames nobody took.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>

#include "../wits/loopback_listener.hpp"
#include "rig_feed.hpp"

namespace plumb::sim_component {
namespace {

using namespace std::chrono_literals;

std::size_t rig_feed_test_count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

TEST(RigFeed, WaitsForALatePlumbWitsSayingSoThenSendsAFramePerInterval) {
  const int port = test::loopback_closed_port();
  const std::string address = "127.0.0.1:" + std::to_string(port);
  std::atomic<int> listener{-1};
  std::thread late([&] {
    std::this_thread::sleep_for(300ms);
    int p = port;
    listener = test::loopback_listen(p);
  });
  RigFeed feed(address, 1.0);
  testing::internal::CaptureStdout();
  const bool connected = feed.connect(10);
  const std::string said = testing::internal::GetCapturedStdout();
  late.join();
  ASSERT_GE(listener.load(), 0) << "the port was taken meanwhile";
  ASSERT_TRUE(connected) << said;
  EXPECT_EQ(said, "plumb-sim: waiting for plumb-wits on " + address + " (up to 10 s)\n"
                  "plumb-sim: the rig's WITS feed connected to " + address + "\n");
  for (double t = 0; t < 3.95; t += 0.5) feed.at(t, 1000 + t);  // frames at 0, 1, 2 and 3 s
  EXPECT_EQ(feed.frames_sent(), 4u);
  EXPECT_EQ(feed.frames_lost(), 0u);
  const int peer = ::accept(listener, nullptr, nullptr);
  std::string got;
  char buffer[1024];
  pollfd p{peer, POLLIN, 0};
  while (rig_feed_test_count(got, "!!\r\n") < 4 && ::poll(&p, 1, 3000) == 1) {
    const ssize_t n = ::read(peer, buffer, sizeof buffer);
    if (n <= 0) break;
    got.append(buffer, static_cast<std::size_t>(n));
  }
  EXPECT_EQ(rig_feed_test_count(got, "&&\r\n"), 4u) << got;
  EXPECT_NE(got.find("01081002.00\r\n"), std::string::npos) << got;  // the bit depth at 2 s
  ::close(peer);
  ::close(listener);
}

TEST(RigFeed, GivesUpWithTheReasonAndCountsTheFramesLost) {
  const std::string address = "127.0.0.1:" + std::to_string(test::loopback_closed_port());
  RigFeed feed(address, 1.0);
  testing::internal::CaptureStdout();
  EXPECT_FALSE(feed.connect(0.3));
  const std::string said = testing::internal::GetCapturedStdout();
  EXPECT_EQ(rig_feed_test_count(said, "\n"), 2u) << said;
  EXPECT_EQ(said.rfind("plumb-sim: waiting for plumb-wits on " + address + " (up to 0.3 s)\n", 0), 0u) << said;
  EXPECT_NE(said.find("plumb-sim: gave up waiting for plumb-wits: cannot connect to " + address +
                      ": Connection refused"), std::string::npos)
      << said;
  feed.at(0, 1000);
  feed.at(1, 1001);
  EXPECT_EQ(feed.frames_sent(), 0u);
  EXPECT_EQ(feed.frames_lost(), 2u);
}

TEST(RigFeed, ABadAddressIsAUsageError) {
  EXPECT_THROW(RigFeed("127.0.0.1", 1.0), std::invalid_argument);
  EXPECT_THROW(RigFeed("127.0.0.1:99999", 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace plumb::sim_component
