// The machine's load during a benchmark run: the load averages of /proc/loadavg sampled before every
// measurement, and the share of CPU time (/proc/stat) the whole machine spent busy over the run
// (this benchmark's own processes included: it keeps at most two of them busy at a time).
#pragma once

#include <ostream>
#include <string>

namespace plumb::bench {

class MachineLoad {
 public:
  MachineLoad();
  void sample();  // call before every measurement
  void print_summary(std::ostream& out);

 private:
  std::string loadavg_at_start_;
  double lowest_1min_ = 1e9, highest_1min_ = 0;
  unsigned long long busy_at_start_ = 0, total_at_start_ = 0;
};

}  // namespace plumb::bench
