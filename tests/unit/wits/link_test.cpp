// The links over real sockets on 127.0.0.1 and a real pseudo-terminal: bytes arrive, a closed
// connection is an event, and the link comes back by itself.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <string>

#include "plumb/bridge/pty.hpp"
#include "plumb/wits/link.hpp"

namespace plumb::wits {
namespace {

using namespace std::chrono_literals;

// Reads until `want` bytes came or 3 s passed; the events seen on the way are counted. With
// `closed`, it stops at the first Closed event; with `want` 0, at the first Opened one.
std::string read_some(Link& link, std::size_t want, int* closed = nullptr) {
  std::string got;
  std::uint8_t buffer[256];
  const auto until = std::chrono::steady_clock::now() + 3s;
  while ((want == 0 || got.size() < want) && std::chrono::steady_clock::now() < until) {
    const auto r = link.read(buffer, sizeof buffer, 20ms);
    got.append(reinterpret_cast<char*>(buffer), r.bytes);
    if (closed && r.event == Link::Event::Closed) {
      ++*closed;
      break;
    }
    if (want == 0 && r.event == Link::Event::Opened) break;
  }
  return got;
}

int connect_to(int port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<std::uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  return ::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0 ? fd : -1;
}

// A listening socket on a free port of 127.0.0.1.
int listen_any(int& port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a);
  ::listen(fd, 4);
  socklen_t size = sizeof a;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &size);
  port = ntohs(a.sin_port);
  return fd;
}

TEST(WitsLink, ServerTakesAConnectionThenTheNext) {
  int port = 0;
  ::close(listen_any(port));  // a port that was free a moment ago
  auto server = make_tcp_server("127.0.0.1", port);
  int first = connect_to(port);
  ASSERT_GE(first, 0);
  ASSERT_EQ(::write(first, "abc", 3), 3);
  EXPECT_EQ(read_some(*server, 3), "abc");
  ::close(first);
  int closed = 0;
  read_some(*server, 1, &closed);
  EXPECT_EQ(closed, 1);  // the end of the first connection is an event
  int second = connect_to(port);
  ASSERT_EQ(::write(second, "def", 3), 3);
  EXPECT_EQ(read_some(*server, 3), "def");
  EXPECT_EQ(server->counters().connects, 2u);
  EXPECT_EQ(server->counters().reconnects, 1u);
  ::close(second);
}

TEST(WitsLink, ClientReconnectsByItself) {
  int port = 0;
  const int listener = listen_any(port);
  auto client = make_tcp_client("127.0.0.1", port, {10ms, 50ms});
  read_some(*client, 0);  // connects
  int peer = ::accept(listener, nullptr, nullptr);
  ASSERT_GE(peer, 0);
  ASSERT_EQ(::write(peer, "one", 3), 3);
  ::close(peer);
  int closed = 0;
  EXPECT_EQ(read_some(*client, 3, &closed), "one");
  if (closed == 0) read_some(*client, 1, &closed);
  EXPECT_EQ(closed, 1);
  read_some(*client, 0);  // connects again, after its back-off
  peer = ::accept(listener, nullptr, nullptr);
  ASSERT_GE(peer, 0);
  ASSERT_EQ(::write(peer, "two", 3), 3);
  EXPECT_EQ(read_some(*client, 3), "two");
  EXPECT_EQ(client->counters().reconnects, 1u);
  ::close(peer);
  ::close(listener);
}

TEST(WitsLink, ClientWithNobodyListeningSaysWhy) {
  int port = 0;
  ::close(listen_any(port));
  auto client = make_tcp_client("127.0.0.1", port, {10ms, 50ms});
  std::uint8_t buffer[8];
  EXPECT_EQ(client->read(buffer, sizeof buffer, 10ms).event, Link::Event::OpenFailed);
  EXPECT_NE(client->last_event().find("cannot connect"), std::string::npos);
}

TEST(WitsLink, SerialPortOverAPseudoTerminal) {
  bridge::PseudoTerminal pty;
  auto link = make_serial_link(pty.slave_path(), 9600, {10ms, 50ms});
  read_some(*link, 0);  // opens
  const std::string text = "&&\r\n0108100\r\n!!\r\n";
  ASSERT_TRUE(pty.write_all(reinterpret_cast<const std::uint8_t*>(text.data()), text.size(), 1s));
  EXPECT_EQ(read_some(*link, text.size()), text);
  EXPECT_EQ(link->counters().connects, 1u);
}

TEST(WitsLink, HostPortOption) {
  std::string host;
  int port = 0;
  split_host_port("10.0.0.5:5000", "--connect", host, port);
  EXPECT_EQ(host, "10.0.0.5");
  EXPECT_EQ(port, 5000);
  EXPECT_THROW(split_host_port("10.0.0.5", "--connect", host, port), std::invalid_argument);
  EXPECT_THROW(split_host_port("h:70000", "--connect", host, port), std::invalid_argument);
  EXPECT_THROW(split_host_port(":5000", "--connect", host, port), std::invalid_argument);
}

// A server's [ADDRESS:]PORT: each mistake named for what it is (a port out of range, an address
// that is not one), never as another option's.
TEST(WitsLink, ListenOption) {
  std::string address;
  int port = 0;
  split_listen_address("5000", "--listen", address, port);
  EXPECT_EQ(address, "0.0.0.0");
  EXPECT_EQ(port, 5000);
  split_listen_address("127.0.0.1:5001", "--listen", address, port);
  EXPECT_EQ(address, "127.0.0.1");
  EXPECT_EQ(port, 5001);
  const auto message = [&](const std::string& text) {
    try {
      split_listen_address(text, "--listen", address, port);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(message("99999"), "--listen: port '99999' is not a number in 1-65535");
  EXPECT_EQ(message("0"), "--listen: port '0' is not a number in 1-65535");
  EXPECT_EQ(message("50x"), "--listen: port '50x' is not a number in 1-65535");
  EXPECT_EQ(message("foo:5000"), "--listen: 'foo' is not an IPv4 address of this computer (e.g. 0.0.0.0:5000 for every interface)");
  EXPECT_EQ(message(":5000"), "--listen: expected [ADDRESS:]PORT (e.g. 5000 or 10.0.0.5:5000), got ':5000'");
}

}  // namespace
}  // namespace plumb::wits
