#include "machine_load.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

namespace plumb::bench {
namespace {

std::string loadavg_text() {
  std::ifstream in("/proc/loadavg");
  std::string one, five, fifteen;
  in >> one >> five >> fifteen;
  return one + " " + five + " " + fifteen;
}

double loadavg_1min() {
  std::ifstream in("/proc/loadavg");
  double one = 0;
  in >> one;
  return one;
}

// Busy and total jiffies of all CPUs from the first line of /proc/stat.
void cpu_times(unsigned long long& busy, unsigned long long& total) {
  std::ifstream in("/proc/stat");
  std::string cpu;
  unsigned long long user = 0, nice = 0, system = 0, idle = 0, iowait = 0, irq = 0, softirq = 0, steal = 0;
  in >> cpu >> user >> nice >> system >> idle >> iowait >> irq >> softirq >> steal;
  busy = user + nice + system + irq + softirq + steal;
  total = busy + idle + iowait;
}

}  // namespace

MachineLoad::MachineLoad() : loadavg_at_start_(loadavg_text()) {
  cpu_times(busy_at_start_, total_at_start_);
  sample();
}

void MachineLoad::sample() {
  const double one = loadavg_1min();
  lowest_1min_ = std::min(lowest_1min_, one);
  highest_1min_ = std::max(highest_1min_, one);
}

void MachineLoad::print_summary(std::ostream& out) {
  sample();
  unsigned long long busy = 0, total = 0;
  cpu_times(busy, total);
  const double busy_percent =
      total > total_at_start_ ? 100.0 * static_cast<double>(busy - busy_at_start_) / static_cast<double>(total - total_at_start_) : 0;
  char text[256];
  std::snprintf(text, sizeof text, "%.1f-%.1f", lowest_1min_, highest_1min_);
  out << "- load average (1, 5, 15 min) before the run: " << loadavg_at_start_ << "; after: " << loadavg_text()
      << "; 1-min load between measurements: " << text << " on " << std::thread::hardware_concurrency()
      << " hardware threads\n";
  std::snprintf(text, sizeof text, "%.0f", busy_percent);
  out << "- CPU busy over the run (all processes, this benchmark's included): " << text << " %\n";
}

}  // namespace plumb::bench
