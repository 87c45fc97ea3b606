#include "plumb/bridge/sample_checker.hpp"

#include <cmath>

namespace plumb::bridge {
namespace {

// The bits the bridge decides itself; whatever the board sent in them is replaced.
constexpr std::uint32_t kBridgeOwned =
    flags::kCalibrated | flags::kGapBefore | flags::kTimeBackwards | flags::kNotFinite | flags::kOutOfRange |
    flags::kTemperatureOutOfRange;

bool all_finite(const Eigen::Vector3d& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

// |v_i| compared per axis; non-finite axes are counted as such, never as out of range too.
bool at_least(double x, double limit) { return std::isfinite(x) && std::abs(x) >= limit; }
bool above(double x, double limit) { return std::isfinite(x) && std::abs(x) > limit; }
bool any_at_least(const Eigen::Vector3d& v, double limit) {
  return at_least(v.x(), limit) || at_least(v.y(), limit) || at_least(v.z(), limit);
}
bool any_above(const Eigen::Vector3d& v, double limit) {
  return above(v.x(), limit) || above(v.y(), limit) || above(v.z(), limit);
}

}  // namespace

bool SampleChecker::check(Sample& s) {
  s.flags &= ~kBridgeOwned;
  if (have_last_) {
    if (s.seq > last_seq_) {
      if (s.seq - last_seq_ > 1) {
        ++c_.seq_gaps;
        c_.samples_missing += s.seq - last_seq_ - 1;
        s.flags |= flags::kGapBefore;
      }
    } else if (!new_stream_ && last_seq_ - s.seq <= limits_.duplicate_window) {
      ++c_.duplicates;
      return false;
    } else {
      ++c_.seq_restarts;
      s.flags |= flags::kGapBefore;
    }
    if (s.t < last_t_) {
      ++c_.time_backwards;
      s.flags |= flags::kTimeBackwards;
    }
  }
  have_last_ = true;
  new_stream_ = false;
  last_seq_ = s.seq;
  if (std::isfinite(s.t)) last_t_ = s.t;

  const bool has_gyro = s.flags & flags::kHasGyro;
  const bool has_temp = s.flags & flags::kHasTemperature;
  const bool finite = std::isfinite(s.t) && all_finite(s.f) && all_finite(s.b) && (!has_gyro || all_finite(s.w)) &&
                      (!has_temp || std::isfinite(s.temp_c));
  if (!finite) {
    ++c_.not_finite;
    s.flags |= flags::kNotFinite;
  }
  if (any_at_least(s.f, limits_.accel_full_scale)) s.flags |= flags::kAccelSaturated;
  if (any_at_least(s.b, limits_.mag_full_scale)) s.flags |= flags::kMagSaturated;
  if (has_gyro && any_at_least(s.w, limits_.gyro_full_scale)) s.flags |= flags::kGyroSaturated;
  if (s.flags & (flags::kAccelSaturated | flags::kMagSaturated | flags::kGyroSaturated)) ++c_.saturated;
  const bool out_of_range = any_above(s.f, limits_.accel_max) || any_above(s.b, limits_.mag_max) ||
                            (has_gyro && any_above(s.w, limits_.gyro_max)) ||
                            (has_temp && std::isfinite(s.temp_c) && (s.temp_c < limits_.temp_min_c || s.temp_c > limits_.temp_max_c));
  if (out_of_range) {
    ++c_.out_of_range;
    s.flags |= flags::kOutOfRange;
  }
  return true;
}

}  // namespace plumb::bridge
