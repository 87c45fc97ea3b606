#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "bench.hpp"
#include "plumb/bridge/protocol.hpp"
#include "plumb/bridge/pty.hpp"

namespace plumb::bench {
namespace {

using Clock = std::chrono::steady_clock;

struct Usage {
  double cpu_s = 0;
  double wall_s = 0;
  long max_rss_kb = 0;
  bool ok = false;
};

// Runs plumb-bridge on `link` for `seconds` while `feed` writes frames (or nothing), and measures
// the child's CPU time with getrusage on it alone (wait4).
Usage measure(const CpuOptions& o, const std::string& link, const std::string& calibration, bool feed_data) {
  bridge::PseudoTerminal pty;
  bridge::replace_symlink(pty.slave_path(), link);
  const std::string duration = std::to_string(o.seconds);
  const std::string domain = std::to_string(o.domain);
  const auto t0 = Clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int devnull = ::open("/dev/null", O_WRONLY);
    ::dup2(devnull, 1);
    std::vector<const char*> argv = {o.bridge.c_str(), "--device", link.c_str(), "--baud", "921600", "--mode", "binary",
                                     "--transport", o.transport.c_str(), "--domain", domain.c_str(),
                                     "--duration", duration.c_str(), "--no-calibration-topic",
                                     "--calibration", calibration.c_str(), nullptr};
    ::execv(o.bridge.c_str(), const_cast<char* const*>(argv.data()));
    std::perror("execv plumb-bridge");
    ::_exit(127);
  }
  std::atomic<bool> running{true};
  std::thread feeder([&] {
    if (!feed_data) return;
    std::uint64_t seq = 0;
    const auto start = Clock::now();
    while (running) {
      Sample s;
      s.seq = seq;
      s.t = static_cast<double>(seq) / o.rate_hz;
      s.f = {0.1, -0.2, -9.81};
      s.b = {20, 1, 40};
      const auto frame = bridge::encode_frame(s);
      pty.write_all(frame.data(), frame.size(), std::chrono::milliseconds(100));
      ++seq;
      std::this_thread::sleep_until(start + std::chrono::duration<double>(static_cast<double>(seq) / o.rate_hz));
    }
  });
  int status = 0;
  rusage ru{};
  ::wait4(pid, &status, 0, &ru);
  running = false;
  feeder.join();
  Usage u;
  u.wall_s = std::chrono::duration<double>(Clock::now() - t0).count();
  u.cpu_s = static_cast<double>(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
            static_cast<double>(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec) * 1e-6;
  u.max_rss_kb = ru.ru_maxrss;
  u.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  bridge::remove_symlink(link);
  return u;
}

}  // namespace

bool run_bridge_cpu(const CpuOptions& o) {
  char dir_template[] = "/tmp/plumb-bench-bridge-XXXXXX";
  const std::string dir = ::mkdtemp(dir_template);
  const std::string link = dir + "/board";
  // Coefficients, so that the calibrated topic is published too (the full per-sample work).
  const std::string calibration = dir + "/bench.cal";
  std::ofstream(calibration) << "format plumb-calibration 1\ncalibration_id bench\naccel.bias 0.01 0.02 0.03\n";
  std::printf("\nplumb-bridge CPU use (%s, %.0f s per row, getrusage of the bridge process)\n", o.transport.c_str(),
              o.seconds);
  const Usage idle = measure(o, link, calibration, false);
  const Usage busy = measure(o, link, calibration, true);
  std::remove(calibration.c_str());
  ::rmdir(dir.c_str());
  if (!idle.ok || !busy.ok) {
    std::printf("plumb-bridge did not run cleanly (is %s built, and the %s plugin?)\n", o.bridge.c_str(),
                o.transport.c_str());
    return false;
  }
  std::printf("| %-38s | %9s | %12s | %10s |\n", "bridge", "CPU s", "% of a core", "max RSS MB");
  std::printf("|%s|%s|%s|%s|\n", std::string(40, '-').c_str(), std::string(11, '-').c_str(),
              std::string(14, '-').c_str(), std::string(12, '-').c_str());
  auto row = [](const char* name, const Usage& u) {
    std::printf("| %-38s | %9.3f | %12.2f | %10.1f |\n", name, u.cpu_s, 100.0 * u.cpu_s / u.wall_s,
                static_cast<double>(u.max_rss_kb) / 1024.0);
  };
  row("idle (device open, no data)", idle);
  char name[64];
  std::snprintf(name, sizeof name, "%.0f Hz frames, raw + calibrated out", o.rate_hz);
  row(name, busy);
  std::printf("cost of the %.0f Hz stream: %.2f%% of a core (busy - idle); %.1f us of CPU per sample\n", o.rate_hz,
              100.0 * (busy.cpu_s / busy.wall_s - idle.cpu_s / idle.wall_s),
              1e6 * (busy.cpu_s - idle.cpu_s * busy.wall_s / idle.wall_s) / (o.rate_hz * o.seconds));
  return true;
}

}  // namespace plumb::bench
