// The process noise of one filter epoch beyond the figures': what the readings could not show
// (unseen_motion.hpp, sensor_range.hpp, stream_faults.hpp) and a turning tool's unresolved
// vibration (filter_state.cpp). add_noise (error_state_filter.hpp) adds it to the covariance; the
// smoother keeps it to predict again.
#pragma once

#include <Eigen/Core>

namespace plumb::strapdown {

struct UnseenMotionNoise {
  // Velocity (m^2/s^2 over the epoch, NED).
  Eigen::Matrix3d velocity = Eigen::Matrix3d::Zero();
  // The position and the along-hole distance together: u u' is added to their 4 x 4 block.
  Eigen::Vector4d displacement = Eigen::Vector4d::Zero();
  // The attitude (rad, NED) and the velocity it moved: u u' is added to their 6 x 6 block (a turn
  // about one direction the readings did not show: a gap's, stream_faults.hpp; a clipped axial
  // gyro's whose spin was followed, navigator.cpp).
  Eigen::Matrix<double, 6, 1> turn = Eigen::Matrix<double, 6, 1>::Zero();
  // The attitude alone (rad^2, NED): turns about several axes, each its own unknown (the clipped
  // gyros', sensor_range.hpp).
  Eigen::Matrix3d attitude = Eigen::Matrix3d::Zero();
};

}  // namespace plumb::strapdown
