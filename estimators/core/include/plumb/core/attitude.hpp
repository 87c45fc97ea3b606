// Frames and closed-form attitude of docs/conventions.md: C_n^b = R3(T) R2(I) R3(A).
#pragma once

#include <string>

#include <Eigen/Core>

namespace plumb {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDeg = kPi / 180.0;
inline constexpr double kRpm = kPi / 30.0;  // rad/s of one revolution per minute

// Wraps an angle to [0, 360).
double wrap_deg_360(double deg);
// Wraps an angle difference to (-180, 180].
double wrap_deg_180(double deg);

Eigen::Matrix3d rot1(double a);  // frame rotations (docs/conventions.md)
Eigen::Matrix3d rot2(double a);
Eigen::Matrix3d rot3(double a);

// C_n^b for inclination, azimuth, toolface in radians.
Eigen::Matrix3d c_nb(double inc, double azi, double tf);

// Earth field in the navigation frame (NED, magnetic north): B (cos dip, 0, sin dip).
Eigen::Vector3d field_ned(double total_b, double dip_rad);

// Gravity G and field B in the tool frame for an attitude (radians) and environment.
Eigen::Vector3d gravity_tool(double inc, double tf, double g);
Eigen::Vector3d field_tool(double inc, double azi, double tf, double total_b, double dip_rad);

// Closed-form attitude from one (G, B) pair; G is gravity in the tool frame (= -specific force
// at rest). Angles in degrees. Toolface and azimuth are flagged invalid near vertical.
struct ClosedForm {
  double inclination_deg = 0;
  double azimuth_deg = 0;
  double gravity_toolface_deg = 0;
  double magnetic_toolface_deg = 0;
  double dip_deg = 0;
  double total_g = 0;
  double total_b = 0;
  bool valid = false;           // inclination usable (finite, non-zero G and B)
  bool azimuth_valid = false;
  bool toolface_valid = false;
  std::string reason;           // why not valid
};

// Below this inclination the toolface (and hence azimuth from a single pair) is reported invalid.
inline constexpr double kMinInclinationForToolfaceDeg = 0.05;

ClosedForm closed_form_attitude(const Eigen::Vector3d& G, const Eigen::Vector3d& B);

}  // namespace plumb
