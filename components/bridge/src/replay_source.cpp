#include "plumb/bridge/replay_source.hpp"

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <thread>

namespace plumb::bridge {

ReplaySource::ReplaySource(const std::string& path, double speed, Counters& counters, bool strict,
                           std::function<void(const csv::Error&)> on_bad_row, const csv::Import& import,
                           const std::function<void(const std::string&)>& on_warning)
    : path_(path),
      import_(import),
      speed_(speed),
      c_(counters),
      strict_(strict),
      on_bad_row_(std::move(on_bad_row)),
      file_(path) {
  if (!file_) throw csv::Error(path, 0, "", "cannot open file");
  reader_ = std::make_unique<csv::SensorReader>(file_, path, import_);
  if (on_warning) check_units(on_warning);
}

// A second, private read of the file's first seconds: at "realtime" the replay itself would
// reach them only seconds later, after publishing wrong numbers.
void ReplaySource::check_units(const std::function<void(const std::string&)>& on_warning) const {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path_, ec)) return;  // a FIFO cannot be read twice
  std::ifstream head(path_);
  std::vector<Sample> first;
  try {
    csv::SensorReader reader(head, path_, import_);
    Sample s;
    while (first.size() < 4096 && (first.empty() || !(s.t - first.front().t > 5.0))) {
      try {
        if (!reader.next(s)) break;
        first.push_back(s);
      } catch (const csv::Error&) {
        // Counted and reported by the replay itself.
      }
    }
  } catch (const csv::Error&) {
    return;
  }
  for (const auto& warning : csv::check_units(first, import_)) on_warning(warning);
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
                      : speed_ == 1 ? std::string("in real time") : "at x" + std::to_string(speed_)) +
         (csv::is_default(import_) ? std::string() : " (" + csv::describe(import_) + ")");
}

}  // namespace plumb::bridge
