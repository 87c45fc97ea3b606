// Measurement models of the navigator: residual r = h(estimate) - z, Jacobian H with respect to
// the error state (error_state_filter.hpp), noise covariance R. Each function is pure: the caller
// decides when a measurement applies (stillness, drilling, depth) and feeds it to the filter.
#pragma once

#include <Eigen/Core>

#include "plumb/strapdown/error_state_filter.hpp"
#include "plumb/strapdown/mechanization.hpp"

namespace plumb::strapdown {

template <int M>
struct Measurement {
  Eigen::Matrix<double, M, 1> r = Eigen::Matrix<double, M, 1>::Zero();
  Eigen::Matrix<double, M, kStates> h = Eigen::Matrix<double, M, kStates>::Zero();
  Eigen::Matrix<double, M, M> noise = Eigen::Matrix<double, M, M>::Zero();
};

// Still: the velocity is zero. sd: the real velocity of a "still" tool (rig sway, pumps).
Measurement<3> zero_velocity(const NavState& x, double sd_mps);

// Still: the gyros' mean over a stretch of stillness sees only the earth rate plus their bias:
// z = mean raw w = C_n^b w_ie + b_g + G(mean raw f) (g_s, g_a). sd_mean: standard deviation of that
// mean per axis.
Measurement<3> zero_rate(const NavState& x, const Eigen::Vector3d& gyro_bias, const Eigen::Vector2d& gyro_g,
                         const Eigen::Vector3d& w_ie, const Eigen::Vector3d& mean_raw_w,
                         const Eigen::Vector3d& mean_raw_f, double sd_mean);

// Still: the accelerometers' mean sees only gravity plus their bias: z = mean raw f = -C_n^b g_n + b_a.
// (Tilt and the horizontal accelerometer biases are one measurement: the filter keeps them correlated.)
Measurement<3> tilt(const NavState& x, const Eigen::Vector3d& accel_bias, double g, const Eigen::Vector3d& mean_raw_f,
                    double sd_mean);

// Still: magnetic heading. The mean field in the tool frame, turned into the navigation frame by
// the estimated attitude, must point at the reference field's azimuth `field_azimuth` (0 in a
// magnetic frame, the declination in a true one): r = heading of (C_b^n B) - field_azimuth.
// sd_heading: its standard deviation (rad), noise and model error together. mean_b has the
// estimated axial bias taken out; the bias state's column is how its error turns the heading.
Measurement<1> magnetic_heading(const NavState& x, const Eigen::Vector3d& mean_b, double field_azimuth,
                                double sd_heading);

// Drilling: the tool moves along its own z axis only, so the tool-frame velocity has x = y = 0.
// For a drilling string (drilling_string = true) the constraint is on the string's advance, which
// is along the axis; what the velocity holds across the axis is vibration (real, zero-mean,
// centimetres per second) and error. So the attitude's column comes from the speed along the axis
// alone: with the whole velocity the constraint read the attitude off the vibration's own velocity
// (quadratic in it), which rectified into an azimuth drift of a turning tool read at 10 Hz.
Measurement<2> lateral_velocity(const NavState& x, double sd_mps, bool drilling_string = false);

// Drilling: over a filter epoch of dt the string's acceleration along the tool axis is about zero
// (the rate of penetration changes slowly). dv: the velocity change the mechanization made over the
// epoch (no filter correction in it); phi: the epoch's transition, whose velocity rows less the
// identity are how the error state made dv wrong; axis: the tool axis in the navigation frame.
// sd: of the epoch's mean acceleration along the axis (the string's and the accelerometers' noise).
// dv_turned: the part of dv an attitude error turns against the axis, as phi took it (dv, or its
// part along the axis where phi left the force across the axis out: filter_state.cpp).
Measurement<1> axial_acceleration(const Eigen::Vector3d& axis, const Eigen::Vector3d& dv,
                                  const Eigen::Vector3d& dv_turned, const StateMatrix& phi, double dt, double sd);

// Measured depth: the distance travelled along the tool axis since alignment.
Measurement<1> along_hole_distance(const NavState& x, double measured_distance_m, double sd_m);

}  // namespace plumb::strapdown
