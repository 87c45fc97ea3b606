// Readings at the sensors' range: a shock of tens of g on a +-16 g accelerometer, stick-slip that
// turns a MEMS gyro past its range. The part beyond the range is unknown, bounded by what the tool
// can plausibly meet (accel_shock_max_g, gyro_rate_max_dps): this part turns it into process
// noise along the clipped axes, says so once in a notice, and on the rows that hold such readings.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "plumb/strapdown/navigator_common.hpp"
#include "plumb/strapdown/navigator_config.hpp"
#include "plumb/strapdown/unseen_motion.hpp"

namespace plumb::strapdown {

class SensorRange {
 public:
  void reset(const NavigatorConfig& config);
  // Every sample taken, before or after alignment: the notice.
  void seen(const InputReading& in);
  // A reading the filter integrates over dt, the tool frame to NED c_bn: what its clipped axes
  // could hide, gathered for the epoch. spin_followed_by: the sensors its axial rate was followed
  // from (clipped_spin.hpp, which says what that axis could hide), or none.
  void integrate(const InputReading& in, double dt, const Eigen::Matrix3d& c_bn, const char* spin_followed_by = nullptr);
  // The epoch's extra noise: the gathered attitude and velocity, each clipped axis its own unknown.
  void add_to(UnseenMotionNoise& noise);
  // What the row since the last one says (empty when nothing was clipped); row_done() starts anew.
  std::string row_warning() const;
  void row_done() { row_accel_ = row_gyro_ = row_followed_ = 0; }
  std::vector<std::string> take_notices();

 private:
  NavigatorConfig config_;
  // Column i: what tool axis i could hide in the epoch, NED. Summed linearly within the epoch,
  // whatever the side clipped: a slip's samples err the same way, and a shock that rebounds clips
  // both sides by excesses that need not cancel. Two axes clipped at once are two unknowns, not
  // one turn about their diagonal.
  Eigen::Matrix3d attitude_ = Eigen::Matrix3d::Zero(), velocity_ = Eigen::Matrix3d::Zero();
  std::uint64_t row_accel_ = 0, row_gyro_ = 0, row_followed_ = 0;
  const char* followed_by_ = "";
  bool accel_said_ = false, gyro_said_ = false;
  std::vector<std::string> notices_;
};

}  // namespace plumb::strapdown
