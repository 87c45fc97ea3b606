// The named walks (the 25 m and 60 m loops the navigator is checked on) and the checks of a walk's loop, timing,
// sensors and environment.
#include <cmath>
#include <stdexcept>
#include <string>

#include "plumb/core/attitude.hpp"
#include "drilling_detail.hpp"
#include "walk_detail.hpp"
#include "scenario_checks.hpp"

namespace plumb::sim {
namespace {

constexpr Refusal require_walk{"invalid walk scenario"};

// Two stairs of 0.3 m tread and 0.17 m rise per stride: a common flight taken normally.
constexpr double kStairStride = 0.6;
constexpr double kStairRise = 0.34;

}  // namespace

WalkScenario WalkScenario::loop(double length_m, double climb_m, const ImuGrade& grade, double rate_hz,
                                std::uint64_t seed) {
  require_walk(std::isfinite(length_m) && length_m > 0, "loop length must be > 0 m");
  require_walk(finite_nonneg(climb_m), "stair climb must be >= 0 m");
  WalkScenario s;
  s.grade = grade;
  s.sample_rate_hz = rate_hz;
  s.seed = seed;
  const double long_side = length_m / 3.0, short_side = length_m / 6.0;
  const auto side = [&](double length, double climb) {
    if (climb == 0) {
      s.legs.push_back({length, 0.0, 0.0, 90.0});
      return;
    }
    const double strides = std::ceil(std::abs(climb) / kStairRise - 1e-9);
    const double flight = strides * kStairStride;
    require_walk(flight < length, "a flight of " + std::to_string(flight) + " m for " + std::to_string(std::abs(climb)) +
                                 " m of stairs does not fit a " + std::to_string(length) + " m side");
    const double flat = 0.5 * (length - flight);
    s.legs.push_back({flat, 0.0, 0.0, 0.0});
    s.legs.push_back({flight, climb, kStairStride, 0.0});
    s.legs.push_back({flat, 0.0, 0.0, 90.0});
  };
  side(long_side, climb_m);
  side(short_side, 0.0);
  side(long_side, -climb_m);
  side(short_side, 0.0);
  return s;
}

WalkScenario WalkScenario::loop_25m(const ImuGrade& grade, double rate_hz, std::uint64_t seed) {
  WalkScenario s = loop(25.0, 0.0, grade, rate_hz, seed);
  s.tool_id = "walk-25m";
  return s;
}

WalkScenario WalkScenario::loop_60m(const ImuGrade& grade, double rate_hz, std::uint64_t seed) {
  WalkScenario s = loop(60.0, 3.0, grade, rate_hz, seed);
  s.tool_id = "walk-60m";
  return s;
}

double WalkScenario::duration_s() const { return WalkPath(*this).duration_s(); }

namespace detail {

void validate_walk_path(const WalkScenario& s) {
  require_walk(!s.legs.empty(), "the loop has no legs");
  for (std::size_t k = 0; k < s.legs.size(); ++k) {
    const WalkLeg& leg = s.legs[k];
    const std::string name = "leg " + std::to_string(k + 1);
    require_walk(std::isfinite(leg.length_m) && leg.length_m > 0, name + ": length must be > 0 m");
    require_walk(std::isfinite(leg.climb_m), name + ": climb must be finite");
    require_walk(finite_nonneg(leg.stride_m), name + ": stride must be >= 0 m (0: the scenario's)");
    require_walk(std::isfinite(leg.turn_deg) && std::abs(leg.turn_deg) <= 180,
            name + ": turn must be within [-180, 180] deg");
  }
  require_walk(std::isfinite(s.heading_deg), "heading must be finite");
  require_walk(std::isfinite(s.stride_m) && s.stride_m > 0, "stride must be > 0 m");
  require_walk(std::isfinite(s.cadence_hz) && s.cadence_hz > 0, "cadence must be > 0 strides/s");
  require_walk(std::isfinite(s.stance_min_s) && s.stance_min_s > 0 && std::isfinite(s.stance_max_s) &&
              s.stance_max_s >= s.stance_min_s,
          "stance must satisfy 0 < min <= max s");
  require_walk(1.0 / s.cadence_hz - 0.5 * (s.stance_min_s + s.stance_max_s) >= 0.2,
          "the swing (1 / cadence - mean stance) must last at least 0.2 s");
  require_walk(finite_nonneg(s.clearance_m), "clearance must be >= 0 m");
  require_walk(std::isfinite(s.pitch_deg) && std::abs(s.pitch_deg) < 90, "pitch must be within (-90, 90) deg");
  require_walk(std::isfinite(s.roll_deg) && std::abs(s.roll_deg) <= 180, "roll must be within [-180, 180] deg");
  require_walk(finite_nonneg(s.initial_still_s) && finite_nonneg(s.final_still_s), "still periods must be >= 0 s");
}

void validate_walk_sensors(const WalkScenario& s) {
  validate_imu_site(s, require_walk);
  require_walk(finite_nonneg(s.mag_sigma_uT), "magnetometer noise must be finite and >= 0 uT");
  require_walk(s.tool_id.size() <= 31, "tool id: at most 31 characters");
}

}  // namespace detail
}  // namespace plumb::sim
