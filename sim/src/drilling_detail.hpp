// Internals of the drilling simulator shared between its source files (private to sim/src):
// the closed-form kinematics and the scenario checks.
#pragma once

#include <cmath>
#include <string>

#include <Eigen/Core>

#include "plumb/sim/drilling.hpp"
#include "scenario_checks.hpp"

namespace plumb::sim::detail {

// The drive factor r(tau) of a drilling phase of length `duration` with raised-cosine ramps of
// `ramp` s at both ends: r rises 0 -> 1, holds, falls 1 -> 0. `along` = integral of r from 0 to tau
// (s; distance / cruise speed), `rate` = r, `rate_dot` = dr/dtau. r and dr/dtau are continuous.
struct Drive {
  double along = 0, rate = 0, rate_dot = 0;
};
Drive raised_cosine_drive(double tau, double duration, double ramp);

// Unit vector along the hole in NED: (sinI cosA, sinI sinA, cosI).
Eigen::Vector3d hole_direction(double inc, double azi);

// Exact integral over x in [0, length] of hole_direction(inc0 + build x, azi0 + turn x), build and
// turn in rad/m: the displacement along a segment of constant build and turn rates.
Eigen::Vector3d along_hole(double inc0, double azi0, double build, double turn, double length);

// The checks every IMU scenario (drilling run, walk) shares: rate, site, field, grade and given
// biases. `require(ok, what)` throws with the scenario's own prefix.
template <class Scenario, class Require>
void validate_imu_site(const Scenario& s, const Require& require) {
  require(std::isfinite(s.sample_rate_hz) && s.sample_rate_hz > 0, "sample rate must be > 0 Hz");
  require(std::isfinite(s.latitude_deg) && std::abs(s.latitude_deg) <= 90, "latitude must be within [-90, 90] deg");
  require(std::isfinite(s.g) && s.g > 0, "g must be > 0");
  require(finite_nonneg(s.total_b), "total field must be >= 0 uT");
  require(std::isfinite(s.dip_deg) && std::abs(s.dip_deg) <= 90, "dip must be within [-90, 90] deg");
  require(finite_nonneg(s.earth_rate), "earth rate must be >= 0 rad/s");
  const ImuGrade& g = s.grade;
  require(finite_nonneg(g.gyro_bias_deg_h) && finite_nonneg(g.gyro_arw_deg_rt_h) && finite_nonneg(g.accel_bias_mg) &&
              finite_nonneg(g.accel_vrw_mps_rt_h),
          "IMU grade '" + g.name + "': biases and noise densities must be finite and >= 0");
  require(finite_nonneg(g.gyro_range_deg_s), "IMU grade '" + g.name + "': gyro range must be >= 0 deg/s (0: unlimited)");
  require(finite_nonneg(g.accel_range_g), "IMU grade '" + g.name + "': accelerometer range must be >= 0 g (0: unlimited)");
  require(!s.gyro_bias || s.gyro_bias->allFinite(), "gyro bias must be finite");
  require(!s.accel_bias || s.accel_bias->allFinite(), "accelerometer bias must be finite");
}

// Throws std::invalid_argument naming the bad parameter (the plan is checked by DrillingTrajectory).
void validate(const DrillingScenario& scenario, std::size_t stop_count);

}  // namespace plumb::sim::detail
