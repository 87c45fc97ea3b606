#include "plumb/core/attitude.hpp"

#include <algorithm>
#include <cmath>

namespace plumb {

double wrap_deg_360(double deg) {
  double r = std::fmod(deg, 360.0);
  if (r < 0) r += 360.0;
  return r >= 360.0 ? 0.0 : r;
}

double wrap_deg_180(double deg) {
  double r = wrap_deg_360(deg);
  return r > 180.0 ? r - 360.0 : r;
}

Eigen::Matrix3d rot1(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Eigen::Matrix3d r;
  r << 1, 0, 0, 0, c, s, 0, -s, c;
  return r;
}

Eigen::Matrix3d rot2(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Eigen::Matrix3d r;
  r << c, 0, -s, 0, 1, 0, s, 0, c;
  return r;
}

Eigen::Matrix3d rot3(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Eigen::Matrix3d r;
  r << c, s, 0, -s, c, 0, 0, 0, 1;
  return r;
}

Eigen::Matrix3d c_nb(double inc, double azi, double tf) { return rot3(tf) * rot2(inc) * rot3(azi); }

Eigen::Vector3d field_ned(double total_b, double dip_rad) {
  return {total_b * std::cos(dip_rad), 0.0, total_b * std::sin(dip_rad)};
}

Eigen::Vector3d gravity_tool(double inc, double tf, double g) {
  return {-g * std::sin(inc) * std::cos(tf), g * std::sin(inc) * std::sin(tf), g * std::cos(inc)};
}

Eigen::Vector3d field_tool(double inc, double azi, double tf, double total_b, double dip_rad) {
  return c_nb(inc, azi, tf) * field_ned(total_b, dip_rad);
}

ClosedForm closed_form_attitude(const Eigen::Vector3d& G, const Eigen::Vector3d& B) {
  ClosedForm out;
  if (!G.allFinite() || !B.allFinite()) {
    out.reason = "non-finite input";
    return out;
  }
  out.total_g = G.norm();
  out.total_b = B.norm();
  if (out.total_g <= 0.0) {
    out.reason = "zero gravity";
    return out;
  }
  const double radial = std::hypot(G.x(), G.y());
  out.inclination_deg = std::atan2(radial, G.z()) / kDeg;
  out.valid = true;
  out.toolface_valid = radial > out.total_g * std::sin(kMinInclinationForToolfaceDeg * kDeg);
  out.gravity_toolface_deg = out.toolface_valid ? wrap_deg_360(std::atan2(G.y(), -G.x()) / kDeg) : 0.0;
  if (out.total_b <= 0.0) {
    out.reason = "zero magnetic field";
    out.valid = false;
    return out;
  }
  out.magnetic_toolface_deg = wrap_deg_360(std::atan2(-B.y(), B.x()) / kDeg);
  out.dip_deg = std::asin(std::clamp(G.dot(B) / (out.total_g * out.total_b), -1.0, 1.0)) / kDeg;
  const double num = out.total_g * (G.x() * B.y() - G.y() * B.x());
  const double den = B.z() * radial * radial - G.z() * (G.x() * B.x() + G.y() * B.y());
  out.azimuth_valid = out.toolface_valid && std::hypot(num, den) > 0.0;
  out.azimuth_deg = out.azimuth_valid ? wrap_deg_360(std::atan2(num, den) / kDeg) : 0.0;
  if (!out.toolface_valid) out.reason = "near vertical: toolface and azimuth undefined";
  return out;
}

}  // namespace plumb
