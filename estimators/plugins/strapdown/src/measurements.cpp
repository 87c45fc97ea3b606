#include "plumb/strapdown/measurements.hpp"

#include <cmath>

#include "plumb/strapdown/rotation.hpp"

namespace plumb::strapdown {

using namespace index;

namespace {
template <int M>
void set_noise(Measurement<M>& m, double sd) {
  m.noise.diagonal().setConstant(sd * sd);
}
}  // namespace

Measurement<3> zero_velocity(const NavState& x, double sd_mps) {
  Measurement<3> m;
  m.r = x.v;
  m.h.block<3, 3>(0, kVel).setIdentity();
  set_noise(m, sd_mps);
  return m;
}

// C_n^b(est) w = C_n^b w + C_n^b [w x] phi to first order.
Measurement<3> zero_rate(const NavState& x, const Eigen::Vector3d& gyro_bias, const Eigen::Vector2d& gyro_g,
                         const Eigen::Vector3d& w_ie, const Eigen::Vector3d& mean_raw_w,
                         const Eigen::Vector3d& mean_raw_f, double sd_mean) {
  Measurement<3> m;
  const Eigen::Matrix3d c_nb = x.q.toRotationMatrix().transpose();
  const Eigen::Matrix<double, 3, 2> g_of_f = gyro_g_matrix(mean_raw_f);
  m.r = c_nb * w_ie + gyro_bias + g_of_f * gyro_g - mean_raw_w;
  m.h.block<3, 3>(0, kAtt) = c_nb * skew(w_ie);
  m.h.block<3, 3>(0, kGyroBias).setIdentity();
  m.h.block<3, 2>(0, kGyroG) = g_of_f;
  set_noise(m, sd_mean);
  return m;
}

Measurement<3> tilt(const NavState& x, const Eigen::Vector3d& accel_bias, double g, const Eigen::Vector3d& mean_raw_f,
                    double sd_mean) {
  Measurement<3> m;
  const Eigen::Matrix3d c_nb = x.q.toRotationMatrix().transpose();
  const Eigen::Vector3d g_n(0.0, 0.0, g);
  m.r = -c_nb * g_n + accel_bias - mean_raw_f;
  m.h.block<3, 3>(0, kAtt) = -c_nb * skew(g_n);
  m.h.block<3, 3>(0, kAccelBias).setIdentity();
  m.h.block<3, 1>(0, kGravity) = -c_nb.col(2);
  set_noise(m, sd_mean);
  return m;
}

// In the frame turned by field_azimuth the reference field is (Bh, 0, Bv); the attitude error adds
// phi x B, whose east part is phi_d Bh - phi_n Bv, so the heading error is phi_d - phi_n Bv/Bh.
Measurement<1> magnetic_heading(const NavState& x, const Eigen::Vector3d& mean_b, double field_azimuth,
                                double sd_heading) {
  Measurement<1> m;
  const double c = std::cos(field_azimuth), s = std::sin(field_azimuth);
  Eigen::Matrix3d turn;  // frame rotation R3(field_azimuth)
  turn << c, s, 0, -s, c, 0, 0, 0, 1;
  const Eigen::Vector3d b = turn * (x.q * mean_b);
  const double bh = std::hypot(b.x(), b.y());
  m.r[0] = std::atan2(b.y(), b.x());
  const Eigen::RowVector3d d(-b.z() / bh, 0.0, 1.0);
  m.h.block<1, 3>(0, kAtt) = d * turn;
  // An axial bias error dm adds -dm C e_z to the field in the navigation frame: its east part turns
  // the heading by that over Bh.
  m.h(0, kMagAxial) = -(turn * (x.q * Eigen::Vector3d::UnitZ())).y() / bh;
  m.noise(0, 0) = sd_heading * sd_heading;
  return m;
}

// C_n^b(est) v(est) = C_n^b v + C_n^b [v x] phi + C_n^b dv to first order.
Measurement<2> lateral_velocity(const NavState& x, double sd_mps, bool drilling_string) {
  Measurement<2> m;
  const Eigen::Matrix3d c_nb = x.q.toRotationMatrix().transpose();
  const Eigen::Vector3d v_b = c_nb * x.v;
  m.r = v_b.head<2>();
  if (drilling_string) {
    // C_n^b [(s e_z^n) x] = s [e_z x] C_n^b, s the speed along the axis: its top rows are
    // s (-row y, row x) of C_n^b.
    m.h.block<1, 3>(0, kAtt) = -v_b.z() * c_nb.row(1);
    m.h.block<1, 3>(1, kAtt) = v_b.z() * c_nb.row(0);
  } else {
    m.h.block<2, 3>(0, kAtt) = (c_nb * skew(x.v)).topRows<2>();
  }
  m.h.block<2, 3>(0, kVel) = c_nb.topRows<2>();
  set_noise(m, sd_mps);
  return m;
}

Measurement<1> axial_acceleration(const Eigen::Vector3d& axis, const Eigen::Vector3d& dv,
                                  const Eigen::Vector3d& dv_turned, const StateMatrix& phi, double dt, double sd) {
  Measurement<1> m;
  m.r[0] = axis.dot(dv) / dt;
  m.h = axis.transpose() * phi.middleRows<3>(kVel) / dt;
  m.h.middleCols<3>(kVel) -= axis.transpose() / dt;
  // The axis itself is the estimate's: an attitude error turns it against the epoch's mean
  // acceleration (vibration, whirl), as in lateral_velocity.
  m.h.middleCols<3>(kAtt) += axis.transpose() * skew(Eigen::Vector3d(dv_turned / dt));
  m.noise(0, 0) = sd * sd;
  return m;
}

Measurement<1> along_hole_distance(const NavState& x, double measured_distance_m, double sd_m) {
  Measurement<1> m;
  m.r[0] = x.s - measured_distance_m;
  m.h(0, kDistance) = 1.0;
  m.noise(0, 0) = sd_m * sd_m;
  return m;
}

}  // namespace plumb::strapdown
