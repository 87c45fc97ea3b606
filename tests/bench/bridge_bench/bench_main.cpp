// plumb-bench-bridge: how fast the bridge parses, and what it costs to run at 1 kHz.
#include <unistd.h>

#include <climits>
#include <cstdio>
#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

#include "bench.hpp"

int main(int argc, char** argv) {
  CLI::App app{"plumb-bench-bridge: frame parser throughput (MB/s, frames/s) beside memcpy and CRC-only over the "
               "same bytes, and plumb-bridge's CPU use at 1 kHz (getrusage)"};
  app.name("plumb-bench-bridge");
  std::size_t frames = 200000;
  int repeats = 5;
  plumb::bench::CpuOptions cpu;
  cpu.transport = "cyclonedds";
  bool no_cpu = false;
  app.add_option("--frames", frames, "frames in the throughput test")->capture_default_str();
  app.add_option("--repeats", repeats, "runs per row (best is shown)")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--transport", cpu.transport, "transport of the CPU test")->capture_default_str();
  app.add_option("--domain", cpu.domain, "DDS domain of the CPU test")->capture_default_str();
  app.add_option("--seconds", cpu.seconds, "seconds per CPU row")->capture_default_str();
  app.add_option("--rate", cpu.rate_hz, "frame rate of the CPU test, Hz")->capture_default_str();
  app.add_option("--bridge", cpu.bridge, "path of plumb-bridge (default: next to this program)");
  app.add_flag("--no-cpu", no_cpu, "skip the CPU test");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  if (frames == 0) {
    std::fprintf(stderr, "plumb-bench-bridge: --frames must be > 0\n");
    return 1;
  }
  if (cpu.bridge.empty()) {
    std::error_code ec;
    const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
    cpu.bridge = (self.parent_path() / "plumb-bridge").string();
  }
  plumb::bench::run_parser_throughput(frames, repeats);
  if (!no_cpu && !plumb::bench::run_bridge_cpu(cpu)) return 1;
  return 0;
}
