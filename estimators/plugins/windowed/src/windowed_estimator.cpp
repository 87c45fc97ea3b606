#include "plumb/windowed/windowed_estimator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace plumb::windowed {

namespace {

std::string format(const char* fmt, double value) {
  char text[64];
  std::snprintf(text, sizeof text, fmt, value);
  return text;
}

}  // namespace

WindowedEstimator::WindowedEstimator() = default;

estimator::Info WindowedEstimator::info() const {
  estimator::Info info = describe();
  info.parameters.insert(info.parameters.begin(),
                         {"window", "10", "window length in seconds, windows back to back; 0 = the whole stream until flush"});
  for (auto& spec : reference_parameter_specs()) info.parameters.push_back(std::move(spec));
  return info;
}

void WindowedEstimator::configure(const estimator::Parameters& params) {
  const estimator::Info spec = info();
  ParameterReader reader(params, spec.parameters);
  window_s_ = reader.number("window", 0.0, 1e7);
  configure_plugin(reader);
  reference_.configure(read_reference_options(reader, params));
  reset();
}

estimator::Counters WindowedEstimator::counters() const {
  // Only what happened: an empty map for a fresh estimator.
  estimator::Counters c;
  const std::pair<const char*, std::uint64_t> all[] = {
      {"samples_accepted", counts_.accepted},       {"rejected_non_finite", counts_.non_finite},
      {"rejected_saturated", counts_.saturated},    {"rejected_out_of_range", counts_.out_of_range},
      {"rejected_time_backwards", counts_.time_backwards}, {"gaps", counts_.gaps},
      {"windows", counts_.windows},                 {"invalid_windows", counts_.invalid_windows}};
  for (const auto& [name, value] : all) {
    if (value > 0) c[name] = value;
  }
  return c;
}

void WindowedEstimator::reset() {
  window_.clear();
  count_ = 0;
  last_t_.reset();
  first_spacings_.clear();
  nominal_dt_ = 0;
  counts_ = {};
  reference_.reset();
}

bool WindowedEstimator::usable(const Sample& s) {
  if ((s.flags & (flags::kAccelSaturated | flags::kMagSaturated)) != 0) {
    ++counts_.saturated;
    return false;
  }
  if ((s.flags & flags::kOutOfRange) != 0) {
    ++counts_.out_of_range;
    return false;
  }
  // x * 0 is 0 for every finite x and NaN for inf or NaN: one test for all seven numbers.
  const double zero = s.t * 0 + s.f.x() * 0 + s.f.y() * 0 + s.f.z() * 0 + s.b.x() * 0 + s.b.y() * 0 + s.b.z() * 0;
  if ((s.flags & flags::kNotFinite) != 0 || zero != 0) {
    ++counts_.non_finite;
    return false;
  }
  if ((s.flags & flags::kTimeBackwards) != 0 || (last_t_ && s.t <= *last_t_)) {
    ++counts_.time_backwards;
    return false;
  }
  return true;
}

void WindowedEstimator::push(std::span<const Sample> samples, std::vector<Estimate>& out) {
  // Room for the rest of the window up front: push_back then never reallocates mid-window.
  for (const Sample& s : samples) accept(s, out);
}

void WindowedEstimator::accept(const Sample& s, std::vector<Estimate>& out) {
  if (!usable(s)) return;
  if (last_t_) {
    const double dt = s.t - *last_t_;
    const bool gap = (s.flags & flags::kGapBefore) != 0 || (nominal_dt_ > 0 && dt > kGapFactor * nominal_dt_);
    if (gap) {
      ++counts_.gaps;
      close_window(true, "window cut short by a gap of " + format("%.3g", dt) + " s", out);
      first_spacings_.clear();
      nominal_dt_ = 0;
    } else if (nominal_dt_ == 0) {
      // The median of the first spacings: robust to one odd spacing at start-up.
      first_spacings_.push_back(dt);
      if (first_spacings_.size() == 9) {
        auto copy = first_spacings_;
        std::nth_element(copy.begin(), copy.begin() + 4, copy.end());
        nominal_dt_ = copy[4];
      }
    }
  }
  if (window_s_ > 0 && count_ > 0 && s.t >= window_.t[0] + window_s_ * (1 - 1e-9)) {
    close_window(false, {}, out);
  }
  last_t_ = s.t;
  // Columns are kept sized ahead of the fill level and written by index: seven push_backs per
  // sample cost more than the whole platform-angle tracker.
  if (count_ == window_.t.size()) grow();
  const std::size_t i = count_++;
  window_.t[i] = s.t;
  window_.gx[i] = -s.f.x();
  window_.gy[i] = -s.f.y();
  window_.gz[i] = -s.f.z();
  window_.bx[i] = s.b.x();
  window_.by[i] = s.b.y();
  window_.bz[i] = s.b.z();
  ++counts_.accepted;
  // The window is complete once its last sample is in: emit now instead of on the next sample,
  // which would add one sample period (a whole batch over DDS) to the latency. The same windows
  // as the rule above; that one still closes windows when the spacing is not yet known.
  if (window_s_ > 0 && nominal_dt_ > 0 && s.t + nominal_dt_ >= window_.t[0] + window_s_ * (1 - 1e-9)) {
    close_window(false, {}, out);
  }
}

void WindowedEstimator::flush(std::vector<Estimate>& out) {
  if (count_ == 0) return;
  // A window that spans its full length (first sample to one spacing past the last) is complete.
  const double dt = nominal_dt_ > 0 ? nominal_dt_ : 0.0;
  const double covered = window_.t[count_ - 1] - window_.t[0] + dt;
  const bool partial = window_s_ > 0 && covered < window_s_ * (1 - 1e-6);
  close_window(partial, {}, out);
}

void WindowedEstimator::close_window(bool partial, const std::string& note, std::vector<Estimate>& out) {
  if (count_ == 0) return;
  for (auto* column : {&window_.t, &window_.gx, &window_.gy, &window_.gz, &window_.bx, &window_.by, &window_.bz}) {
    column->resize(count_);  // shrinking keeps the capacity
  }
  window_.nominal_dt = nominal_dt_;
  Estimate e;
  if (window_.size() < kMinSamples) {
    e.reason = "too few samples in window (" + std::to_string(window_.size()) + ", need " +
               std::to_string(kMinSamples) + ")";
  } else {
    e = estimate_window(window_);
    reference_.apply(e);
  }
  e.estimator = describe().name;
  e.t_start = window_.t.front();
  e.t_end = window_.t.back();
  e.samples_used = static_cast<std::uint32_t>(std::min<std::size_t>(e.samples_used ? e.samples_used : window_.size(),
                                                                   window_.size()));
  e.partial_window = partial;
  if (!note.empty()) e.reason = e.reason.empty() ? note : e.reason + "; " + note;
  make_finite(e);
  if (!e.valid) ++counts_.invalid_windows;
  ++counts_.windows;
  out.push_back(std::move(e));
  count_ = 0;
}

void WindowedEstimator::grow() {
  // Back to the full capacity after a window was handed out, or double it.
  const std::size_t size = window_.t.size() < window_.t.capacity() ? window_.t.capacity()
                                                                   : std::max<std::size_t>(1024, 2 * window_.t.size());
  for (auto* column : {&window_.t, &window_.gx, &window_.gy, &window_.gz, &window_.bx, &window_.by, &window_.bz}) {
    column->resize(size);
  }
}

void make_finite(Estimate& e) {
  bool fixed = false;
  for (double* v : {&e.t_start, &e.t_end, &e.inclination_deg, &e.azimuth_deg, &e.gravity_toolface_deg,
                    &e.magnetic_toolface_deg, &e.rpm, &e.inclination_sd_deg, &e.azimuth_sd_deg, &e.toolface_sd_deg,
                    &e.dip_deg, &e.total_g, &e.total_b}) {
    if (!std::isfinite(*v)) {
      *v = 0;
      fixed = true;
    }
  }
  if (fixed) {
    e.valid = e.azimuth_valid = e.toolface_valid = false;
    e.reason = e.reason.empty() ? "numerical failure (non-finite result)" : e.reason + "; numerical failure";
  }
}

}  // namespace plumb::windowed
