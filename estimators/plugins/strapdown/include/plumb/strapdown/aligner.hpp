// The navigator's initial alignment: the means of its first still period (up to align_s), the check
// that the accelerometers read m/s^2, the reference field it learns, the coarse attitude
// (gyrocompass, a given azimuth, the magnetometer, or relative), which sets the azimuth reference
// and whether the magnetometer serves azimuth, and the filter's covariance before its first
// measurements (stop_updates.hpp gives those, from the same means).
#pragma once

#include <optional>
#include <string>

#include <Eigen/Core>

#include "plumb/strapdown/alignment.hpp"
#include "plumb/strapdown/error_state_filter.hpp"
#include "plumb/strapdown/navigator_common.hpp"
#include "plumb/strapdown/navigator_config.hpp"
#include "plumb/strapdown/stillness.hpp"

namespace plumb::strapdown {

class Aligner {
 public:
  void reset(const NavigatorConfig& config);
  // A reading before alignment and the detector's verdict on it: true when the alignment is due
  // (the still period has lasted align_s, or has ended with enough readings).
  bool take(const InputReading& in, const StillnessState& still);
  // A recording that ends inside its first still period aligns on what it has.
  bool can_align_at_end(bool still) const {
    return still && stats_.count() >= StillnessConfig::kMinWindowSamples;
  }
  struct Coarse {
    StillStats stats;  // the means aligned on
    Eigen::Matrix3d c_bn;
    double heading_sd = 0;
    double g = 0;      // given, or |mean f|
  };
  // The coarse alignment from the means so far, which it forgets; none when the accelerometers
  // look like g units (counted, and said on the rows).
  std::optional<Coarse> coarse(Counters& counters);
  // The filter's covariance at alignment, before its first measurements.
  StateMatrix initial_covariance(const Eigen::Vector3d& f, double heading_sd, double sd_mean_f, double depth_sd,
                                 bool lever_model, bool drilling_tool) const;

  const FieldReference& field() const { return field_; }
  bool use_mag() const { return use_mag_; }  // the magnetometer serves azimuth
  const std::string& azimuth_reference() const { return azimuth_reference_; }
  bool accel_in_g() const { return accel_in_g_; }
  double accel_in_g_level() const { return accel_in_g_level_; }

 private:
  Eigen::Matrix3d initial_attitude(const Eigen::Vector3d& f, const Eigen::Vector3d& w, const Eigen::Vector3d& b,
                                   bool mag, double& heading_sd);

  NavigatorConfig config_;
  StillStats stats_;
  bool accel_in_g_ = false;
  double accel_in_g_level_ = 0;
  FieldReference field_;
  bool use_mag_ = false;
  std::string azimuth_reference_ = "magnetic";
};

}  // namespace plumb::strapdown
