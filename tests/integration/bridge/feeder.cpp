// plumb-test-serial-feeder: a scripted sensor board on a pseudo-terminal. Writes COUNT frames
// (sequence 0..COUNT-1, 1 ms apart) at RATE Hz into a pty linked at PATH, with the faults given
// by --fault injected at fixed places, so a test knows exactly what the bridge must count.
#include <chrono>
#include <iostream>
#include <map>
#include <thread>

#include <CLI/CLI.hpp>

#include "plumb/bridge/protocol.hpp"
#include "plumb/bridge/pty.hpp"

namespace {
constexpr const char* kProgram = "plumb-test-serial-feeder";
using Clock = std::chrono::steady_clock;
using Bytes = std::vector<std::uint8_t>;

plumb::Sample sample(std::uint64_t seq) {
  plumb::Sample s;
  s.seq = seq;
  s.t = static_cast<double>(seq) * 1e-3;
  s.f = {0.1, -0.2, -9.81};
  s.b = {20.0, 1.0, 40.0};
  s.w = {0.0, 0.0, 6.28};
  s.temp_c = 30.0;
  s.flags = plumb::flags::kHasGyro | plumb::flags::kHasTemperature;
  return s;
}
}  // namespace

int main(int argc, char** argv) {
  using namespace plumb;
  CLI::App app{"scripted sensor board on a pseudo-terminal, for the bridge's integration tests"};
  app.name(kProgram);
  std::string link;
  std::uint64_t count = 1000;
  double rate_hz = 1000, start_delay_s = 0, gone_s = 1.0;
  std::vector<std::string> faults;
  std::uint64_t vanish_at = 0;
  app.add_option("--link", link, "symbolic link to create at the pty slave")->required();
  app.add_option("--count", count, "frames (sequence numbers 0..count-1)")->capture_default_str();
  app.add_option("--rate", rate_hz, "frames per second (0: as fast as the reader takes them)")->capture_default_str();
  app.add_option("--start-delay", start_delay_s, "seconds to wait after creating the pty")->capture_default_str();
  app.add_option("--fault", faults,
                 "SEQ:KIND, KIND one of garbage, crc, truncated, version, duplicate, drop, nan, range, backwards; "
                 "applied to the frame with that sequence number");
  app.add_option("--vanish-at", vanish_at, "before this sequence number the device disappears and comes back");
  app.add_option("--gone", gone_s, "seconds the device stays away")->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  std::map<std::uint64_t, std::string> fault_at;
  for (const auto& f : faults) {
    const auto colon = f.find(':');
    if (colon == std::string::npos) {
      std::cerr << kProgram << ": --fault " << f << ": expected SEQ:KIND" << std::endl;
      return 1;
    }
    fault_at[std::stoull(f.substr(0, colon))] = f.substr(colon + 1);
  }
  try {
    auto pty = std::make_unique<bridge::PseudoTerminal>();
    bridge::replace_symlink(pty->slave_path(), link);
    std::cout << kProgram << ": " << link << " -> " << pty->slave_path() << std::endl;
    std::this_thread::sleep_for(std::chrono::duration<double>(start_delay_s));
    const auto start = Clock::now();
    auto write = [&](const Bytes& b) {
      if (!pty->write_all(b.data(), b.size(), std::chrono::seconds(30))) throw std::runtime_error("write timed out");
    };
    for (std::uint64_t seq = 0; seq < count; ++seq) {
      if (rate_hz > 0) std::this_thread::sleep_until(start + std::chrono::duration<double>(static_cast<double>(seq) / rate_hz));
      if (vanish_at && seq == vanish_at) {
        pty->drain(std::chrono::seconds(10));
        pty.reset();
        bridge::remove_symlink(link);
        std::this_thread::sleep_for(std::chrono::duration<double>(gone_s));
        pty = std::make_unique<bridge::PseudoTerminal>();
        bridge::replace_symlink(pty->slave_path(), link);
      }
      Sample s = sample(seq);
      const auto it = fault_at.find(seq);
      const std::string kind = it == fault_at.end() ? "" : it->second;
      if (kind == "drop") continue;
      if (kind == "nan") s.f.y() = std::numeric_limits<double>::quiet_NaN();
      if (kind == "range") s.b.x() = 5000;
      if (kind == "backwards") s.t -= 0.5;
      Bytes frame = bridge::encode_frame(s);
      if (kind == "garbage") write(Bytes{0x00, 0x11, 0x22, 0x33, 0x44});
      if (kind == "crc") frame[40] ^= 0x10;
      if (kind == "truncated") frame.resize(35);
      if (kind == "version") frame = bridge::encode_raw_frame(2, Bytes(60, 0x55));
      write(frame);
      if (kind == "duplicate") write(frame);
    }
    pty->drain(std::chrono::seconds(30));
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    bridge::remove_symlink(link);
    std::cout << kProgram << ": wrote " << count << " frames" << std::endl;
    return 0;
  } catch (const std::exception& e) {
    std::cerr << kProgram << ": " << e.what() << std::endl;
    return 1;
  }
}
