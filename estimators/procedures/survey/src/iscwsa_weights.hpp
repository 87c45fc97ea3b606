// The weighting functions of the ISCWSA MWD model: the change of (MD, I, A) per unit of a term's
// magnitude at one station (SPE 67616 Table 1, SPE 63275 for the toolface-independent x-y terms,
// the revision 5 sheets for SAGE, XYM3E and XYM4E; the gyro model's accelerometer triad). Internal
// to iscwsa.cpp; the gyro's own terms are in iscwsa_gyro.hpp.
#pragma once

#include <string>

#include <Eigen/Core>

namespace plumb::survey::iscwsa::detail {

struct WeightContext {
  double md = 0, tvd = 0;
  double inc = 0, azi = 0, azm = 0;  // radians: inclination, azimuth of the position frame, magnetic azimuth
  double gravity = 9.80665, total_b_nT = 50000, dip = 0;  // dip in radians
  double course_m = 0;               // length of the course ending here (0 at the first station)
  double cant = 0;                   // x-y accelerometers canted to the tool axis (rad; SPE 90408's Model #4)
};

// How a weighting function behaves near vertical.
enum class Vertical { Regular, AccelerometerXY, MisalignmentNorth, MisalignmentEast };

struct WeightFunction {
  Eigen::Vector3d (*weight)(const WeightContext&) = nullptr;
  Vertical vertical = Vertical::Regular;
  bool course_coefficient = false;   // XYM3E, XYM4E: times max(1, sqrt(10 m / course))
};

// nullptr weight for an unknown name and for the XCL terms (which act on position directly).
WeightFunction weight_function(const std::string& name);
bool is_course_length_term(const std::string& name, const std::string& code);
bool is_azimuth_reference_term(const std::string& name);  // AZ, DBH: declination terms

}  // namespace plumb::survey::iscwsa::detail
