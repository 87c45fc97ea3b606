// The serial device over real pseudo-terminals: raw bytes arrive intact, the device vanishing
// is noticed and counted, and it is reopened (with back-off) when it comes back.
#include "plumb/bridge/serial_port.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <thread>

#include "plumb/bridge/frame_parser.hpp"
#include "plumb/bridge/protocol.hpp"
#include "plumb/bridge/pty.hpp"
#include "test_samples.hpp"

namespace plumb::bridge {
namespace {

using namespace std::chrono_literals;
namespace fs = std::filesystem;

struct TempDir {
  fs::path path;
  TempDir() {
    char tmpl[] = "/tmp/plumb-serial-test-XXXXXX";
    path = ::mkdtemp(tmpl);
  }
  ~TempDir() { fs::remove_all(path); }
};

// Reads until `want` samples came out or the guard deadline passed (a guard against hanging,
// not a timing check).
std::vector<Sample> read_samples(SerialPort& port, FrameParser& parser, std::size_t want,
                                 std::vector<SerialPort::Event>* events = nullptr) {
  std::vector<Sample> out;
  std::uint8_t buf[256];
  const auto guard = std::chrono::steady_clock::now() + 10s;
  while (out.size() < want && std::chrono::steady_clock::now() < guard) {
    const auto r = port.read(buf, sizeof buf, 20ms);
    if (events && (r.event == SerialPort::Event::Opened || r.event == SerialPort::Event::Closed)) events->push_back(r.event);
    if (r.bytes) parser.feed(std::span(buf, r.bytes), out);
    if (r.event == SerialPort::Event::Closed) parser.finish();
  }
  return out;
}

void write_frames(PseudoTerminal& pty, std::uint64_t first, std::size_t count) {
  std::vector<std::uint8_t> bytes;
  for (const auto& s : test::make_samples(first, count)) append_frame(bytes, s);
  ASSERT_TRUE(pty.write_all(bytes.data(), bytes.size(), 5s));
}

TEST(SerialPort, ReadsFramesThroughAPseudoTerminalByItsSymlink) {
  TempDir dir;
  const std::string link = (dir.path / "board").string();
  PseudoTerminal pty;
  replace_symlink(pty.slave_path(), link);
  Counters c;
  SerialPort port({link, 921600, 10ms, 80ms}, c);
  FrameParser parser(c);
  // Bytes of every value, including the ones a cooked tty would translate (CR, NL, XON, ^C).
  // More than the pty buffers hold: the writer waits for the reader, from its own thread.
  std::thread writer([&] { write_frames(pty, 0, 200); });
  const auto got = read_samples(port, parser, 200);
  writer.join();
  ASSERT_EQ(got.size(), 200u);
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i].seq, i);
  EXPECT_EQ(c.opens, 1u);
  EXPECT_EQ(c.reopens, 0u);
  EXPECT_EQ(c.bytes_read, 200 * kFrameSizeV1);
  EXPECT_EQ(c.bytes_skipped, 0u);
}

TEST(SerialPort, DeviceThatDisappearsIsReopenedWhenItComesBack) {
  TempDir dir;
  const std::string link = (dir.path / "board").string();
  Counters c;
  SerialPort port({link, 115200, 10ms, 40ms}, c);
  FrameParser parser(c);
  std::vector<SerialPort::Event> events;

  auto pty = std::make_unique<PseudoTerminal>();
  replace_symlink(pty->slave_path(), link);
  write_frames(*pty, 0, 10);
  // Half a frame, then the board goes away.
  const auto partial = encode_frame(test::make_sample(10));
  ASSERT_TRUE(pty->write_all(partial.data(), 30, 1s));
  ASSERT_EQ(read_samples(port, parser, 10, &events).size(), 10u);
  // The half frame may come in a later read than the tenth frame; it must be in the parser before
  // the board goes away (a hang-up discards what the line still holds).
  std::vector<Sample> none;
  std::uint8_t chunk[64];
  for (const auto until = std::chrono::steady_clock::now() + 5s;
       parser.pending_bytes() < 30 && std::chrono::steady_clock::now() < until;) {
    const auto r = port.read(chunk, sizeof chunk, 20ms);
    if (r.bytes) parser.feed(std::span(chunk, r.bytes), none);
  }
  ASSERT_EQ(parser.pending_bytes(), 30u);
  ASSERT_TRUE(none.empty());
  pty->close();
  remove_symlink(link);
  // Reading notices the hang-up.
  std::uint8_t buf[64];
  const auto guard = std::chrono::steady_clock::now() + 10s;
  while (port.is_open() && std::chrono::steady_clock::now() < guard) {
    const auto r = port.read(buf, sizeof buf, 20ms);
    if (r.event == SerialPort::Event::Closed) {
      events.push_back(r.event);
      parser.finish();
    }
  }
  EXPECT_FALSE(port.is_open());
  EXPECT_GE(c.read_errors, 1u);
  EXPECT_FALSE(port.last_error().empty());
  EXPECT_EQ(c.truncated, 1u);  // the half frame, flushed when the device closed

  pty = std::make_unique<PseudoTerminal>();
  replace_symlink(pty->slave_path(), link);
  write_frames(*pty, 11, 10);
  const auto got = read_samples(port, parser, 10, &events);
  ASSERT_EQ(got.size(), 10u);
  EXPECT_EQ(got.front().seq, 11u);
  EXPECT_EQ(c.opens, 2u);
  EXPECT_EQ(c.reopens, 1u);
  ASSERT_GE(events.size(), 3u);
  EXPECT_EQ(events[0], SerialPort::Event::Opened);
  EXPECT_EQ(events[1], SerialPort::Event::Closed);
  EXPECT_EQ(events[2], SerialPort::Event::Opened);
}

TEST(SerialPort, MissingDeviceIsRetriedWithCappedExponentialBackoff) {
  Counters c;
  SerialPort port({"/nonexistent/plumb-board", 9600, 10ms, 40ms}, c);
  std::uint8_t buf[16];
  std::vector<long> backoffs;  // each new value the back-off takes
  const auto until = std::chrono::steady_clock::now() + 300ms;  // several attempts at 10..40 ms
  std::size_t failed_opens = 0;
  while (std::chrono::steady_clock::now() < until) {
    failed_opens += port.read(buf, sizeof buf, 5ms).event == SerialPort::Event::OpenFailed;
    const long b = port.current_backoff().count();
    if (backoffs.empty() || backoffs.back() != b) backoffs.push_back(b);
  }
  EXPECT_EQ(backoffs, (std::vector<long>{20, 40}));  // doubled after each failure, then capped
  // Attempts at 0, 10, 30, 70, 110, ... ms: one per back-off period, no spinning.
  EXPECT_GE(failed_opens, 3u);
  EXPECT_LE(failed_opens, 300u / 40u + 3u);
  EXPECT_NE(port.last_error().find("cannot open"), std::string::npos) << port.last_error();
  EXPECT_EQ(c.opens, 0u);
}

TEST(SerialPort, NonStandardBaudRateIsRefused) {
  Counters c;
  EXPECT_THROW(SerialPort({"/dev/null", 12345}, c), std::invalid_argument);
  EXPECT_TRUE(baud_constant(115200).has_value());
}

TEST(SerialPort, RegularFileIsNotATerminal) {
  TempDir dir;
  const auto file = dir.path / "not-a-tty";
  std::ofstream(file) << "hello";
  Counters c;
  SerialPort port({file.string(), 9600, 10ms, 20ms}, c);
  std::uint8_t buf[16];
  port.read(buf, sizeof buf, 1ms);
  EXPECT_FALSE(port.is_open());
  EXPECT_NE(port.last_error().find("not a terminal"), std::string::npos) << port.last_error();
}

TEST(PseudoTerminal, DrainWaitsForTheReaderAndGivesUpWithoutOne) {
  PseudoTerminal pty;
  const auto frame = encode_frame(test::make_sample(0));
  ASSERT_TRUE(pty.write_all(frame.data(), frame.size(), 1s));
  EXPECT_FALSE(pty.drain(300ms));  // nobody reads: the bytes stay
  Counters c;
  SerialPort port({pty.slave_path(), 9600, 10ms, 20ms}, c);
  FrameParser parser(c);
  std::thread reader([&] { read_samples(port, parser, 1); });
  EXPECT_TRUE(pty.drain(10s));
  reader.join();
  EXPECT_EQ(c.frames_ok, 1u);
}

TEST(Symlink, ReplaceRefusesToClobberARealFile) {
  TempDir dir;
  const auto file = dir.path / "device";
  std::ofstream(file) << "x";
  EXPECT_THROW(replace_symlink("/dev/null", file.string()), std::runtime_error);
  remove_symlink(file.string());
  EXPECT_TRUE(fs::exists(file));
}

}  // namespace
}  // namespace plumb::bridge
