#include "plumb/bridge/replay_source.hpp"

#include <cmath>
#include <stdexcept>
#include <thread>

namespace plumb::bridge {

double parse_rate(const std::string& text) {
  if (text == "realtime") return 1.0;
  if (text == "max") return 0.0;
  std::string number = text;
  if (!number.empty() && (number.front() == 'x' || number.front() == 'X')) number.erase(0, 1);
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(number, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (number.empty() || used != number.size() || !std::isfinite(v) || v <= 0)
    throw std::invalid_argument("--rate: expected realtime, xN (N > 0 times faster) or max, got '" + text + "'");
  return v;
}

ReplaySource::ReplaySource(const std::string& path, double speed, Counters& counters, bool strict,
                           std::function<void(const csv::Error&)> on_bad_row)
    : path_(path), speed_(speed), c_(counters), strict_(strict), on_bad_row_(std::move(on_bad_row)), file_(path) {
  if (!file_) throw csv::Error(path, 0, "", "cannot open file");
  reader_ = std::make_unique<csv::SensorReader>(file_, path);
}

bool ReplaySource::read_next() {
  while (true) {
    try {
      Sample s;
      if (!reader_->next(s)) return false;
      ++c_.lines_ok;
      next_ = s;
      return true;
    } catch (const csv::Error& e) {
      ++c_.csv_errors;
      last_error_ = e.what();
      if (strict_) throw;
      if (on_bad_row_) on_bad_row_(e);
    }
  }
}

std::chrono::steady_clock::time_point ReplaySource::due(double t) const {
  if (speed_ <= 0 || !std::isfinite(t) || t <= t0_) return start_;
  return start_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                      std::chrono::duration<double>((t - t0_) / speed_));
}

bool ReplaySource::poll(std::vector<Sample>& out, std::chrono::milliseconds max_wait) {
  using clock = std::chrono::steady_clock;
  if (!next_ && !read_next()) return false;
  if (!started_) {
    started_ = true;
    start_ = clock::now();
    t0_ = std::isfinite(next_->t) ? next_->t : 0.0;
  }
  // Bounded per call so the caller's flush and status timers keep running at "max".
  constexpr std::size_t kMaxPerPoll = 256;
  const auto deadline = clock::now() + max_wait;
  for (std::size_t n = 0; n < kMaxPerPoll; ++n) {
    const auto when = due(next_->t);
    if (when > clock::now()) {
      if (!out.empty() || when > deadline) {
        if (out.empty()) std::this_thread::sleep_until(deadline);
        return true;
      }
      std::this_thread::sleep_until(when);
    }
    out.push_back(*next_);
    next_.reset();
    if (!read_next()) return !out.empty();
  }
  return true;
}

std::string ReplaySource::describe() const {
  return "replay of " + path_ + " " +
         (speed_ <= 0 ? std::string("as fast as possible")
                      : speed_ == 1 ? std::string("in real time") : "at x" + std::to_string(speed_));
}

}  // namespace plumb::bridge
