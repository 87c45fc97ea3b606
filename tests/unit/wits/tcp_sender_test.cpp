// The rig's TCP client against real sockets on 127.0.0.1: frames arrive whole, a closed port fails
// within the deadline saying which and why, and a reader that starts late is reached.
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

#include "loopback_listener.hpp"
#include "plumb/wits/frame_writer.hpp"
#include "plumb/wits/tcp_sender.hpp"

namespace plumb::wits {
namespace {

using namespace std::chrono_literals;
using SenderTestClock = std::chrono::steady_clock;

// Accepts one connection (within 5 s) and reads it to its end.
std::string sender_test_read_all(int listen_fd) {
  pollfd p{listen_fd, POLLIN, 0};
  if (::poll(&p, 1, 5000) != 1) return "(no connection)";
  const int fd = ::accept(listen_fd, nullptr, nullptr);
  std::string got;
  char buffer[512];
  for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;) got.append(buffer, static_cast<std::size_t>(n));
  ::close(fd);
  return got;
}

TEST(WitsTcpSender, FramesArriveWhole) {
  int port = 0;
  const int listener = test::loopback_listen(port);
  ASSERT_GE(listener, 0);
  TcpSender sender("127.0.0.1", port);
  EXPECT_EQ(sender.address(), "127.0.0.1:" + std::to_string(port));
  ASSERT_TRUE(sender.connect(2s)) << sender.last_error();
  std::string sent;
  for (int k = 0; k < 50; ++k) {
    const std::string frame = record01_frame(1000 + 0.25 * k, 1000 + 0.25 * k, 1.0, 1700000000 + k);
    ASSERT_TRUE(sender.send(frame)) << sender.last_error();
    sent += frame;
  }
  sender.close_when_sent();
  EXPECT_FALSE(sender.is_open());
  EXPECT_EQ(sender_test_read_all(listener), sent);
  ::close(listener);
}

TEST(WitsTcpSender, ClosedPortFailsWithinTheDeadlineSayingWhy) {
  const int port = test::loopback_closed_port();
  TcpSender sender("127.0.0.1", port);
  const auto start = SenderTestClock::now();
  EXPECT_FALSE(sender.connect(500ms));
  const auto took = SenderTestClock::now() - start;
  EXPECT_GE(took, 500ms);  // it retried while the deadline lasted
  EXPECT_LT(took, 500ms + 2500ms);  // the wait, and at most one bounded handshake past it
  const std::string& why = sender.last_error();
  EXPECT_NE(why.find("cannot connect to 127.0.0.1:" + std::to_string(port)), std::string::npos) << why;
  EXPECT_NE(why.find("Connection refused"), std::string::npos) << why;
  EXPECT_FALSE(sender.send("frame"));  // nothing to send on
  EXPECT_NE(sender.last_error().find("not connected"), std::string::npos);
}

TEST(WitsTcpSender, OneAttemptWhenNotWaiting) {
  TcpSender sender("127.0.0.1", test::loopback_closed_port());
  const auto start = SenderTestClock::now();
  EXPECT_FALSE(sender.connect(0ms));
  EXPECT_LT(SenderTestClock::now() - start, 1s);
  EXPECT_EQ(sender.last_error().find("attempts"), std::string::npos) << sender.last_error();
}

TEST(WitsTcpSender, StopEndsTheWait) {
  TcpSender sender("127.0.0.1", test::loopback_closed_port());
  int asked = 0;
  const auto start = SenderTestClock::now();
  EXPECT_FALSE(sender.connect(60s, [&] { return ++asked >= 3; }));
  EXPECT_EQ(asked, 3);
  EXPECT_LT(SenderTestClock::now() - start, 10s);
}

TEST(WitsTcpSender, AListenerThatAppearsLateIsReached) {
  int port = test::loopback_closed_port();
  std::atomic<int> listener{-1};
  std::thread late([&] {
    std::this_thread::sleep_for(400ms);
    int p = port;
    listener = test::loopback_listen(p);
  });
  TcpSender sender("127.0.0.1", port);
  const bool connected = sender.connect(10s);
  late.join();
  ASSERT_GE(listener.load(), 0) << "the port was taken meanwhile";
  ASSERT_TRUE(connected) << sender.last_error();
  const std::string frame = record01_frame(1234.5, 1234.5, 1.0, 1700000000);
  ASSERT_TRUE(sender.send(frame));
  sender.close_when_sent();
  EXPECT_EQ(sender_test_read_all(listener), frame);
  ::close(listener);
}

TEST(WitsTcpSender, ALostReaderIsAFailedSendThenANewConnection) {
  int port = 0;
  const int listener = test::loopback_listen(port);
  ASSERT_GE(listener, 0);
  TcpSender sender("127.0.0.1", port);
  ASSERT_TRUE(sender.connect(2s));
  ::close(::accept(listener, nullptr, nullptr));  // the reader goes away
  bool failed = false;
  // The first send after the close may still be taken by the kernel; a reset follows.
  for (int i = 0; i < 50 && !failed; ++i) {
    failed = !sender.send(std::string(4096, 'x'));
    std::this_thread::sleep_for(10ms);
  }
  ASSERT_TRUE(failed);
  EXPECT_FALSE(sender.is_open());
  EXPECT_NE(sender.last_error().find("the connection to 127.0.0.1:" + std::to_string(port) + " was lost"),
            std::string::npos)
      << sender.last_error();
  ASSERT_TRUE(sender.connect(2s)) << sender.last_error();
  ASSERT_TRUE(sender.send("again"));
  sender.close_when_sent();
  EXPECT_EQ(sender_test_read_all(listener), "again");
  ::close(listener);
}

}  // namespace
}  // namespace plumb::wits
