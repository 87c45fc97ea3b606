// The six-face fit at the heart of the 6- and 24-position procedures (docs/methods.md section 3), done
// directly in the form of plumb::TriadModel, which makes it exact:
//   raw u = bias + A (a + k2 .* a^2),  A = S^-1.
// With axis j up (a = +g e_j) and down (a = -g e_j):
//   (u+j - u-j) / 2g = A e_j                      column j of A
//   (u+j + u-j) / 2  = bias + k2_j g^2 A e_j      9 equations in bias and k2 (3 redundant)
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "plumb/calibration/types.hpp"

namespace plumb::calibration {

inline constexpr int kTriadParams = 15;  // bias (3), S row-major (9), k2 (3)
using TriadVector = Eigen::Matrix<double, kTriadParams, 1>;
using TriadCovariance = Eigen::Matrix<double, kTriadParams, kTriadParams>;

struct FaceAverages {
  std::array<Eigen::Vector3d, 6> mean;   // raw, per face +x -x +y -y +z -z
  std::array<Eigen::Vector3d, 6> se;     // standard error of each component
};

struct TriadFit {
  TriadVector params = TriadVector::Zero();
  TriadCovariance covariance = TriadCovariance::Zero();
  double chi2 = 0;   // of the 3 redundant equations (3 degrees of freedom)
  // The same in the form of docs/methods.md section 3: output_i = k_i (a_i + b_i + k2_i a_i^2 + sum_j m_ij a_j),
  // order k (3), b (3, m/s^2), k2 (3), m (6: xy xz yx yz zx zy).
  Eigen::Matrix<double, 15, 1> method_params = Eigen::Matrix<double, 15, 1>::Zero();
  Eigen::Matrix<double, 15, 15> method_covariance = Eigen::Matrix<double, 15, 15>::Zero();
};

TriadFit fit_six_faces(const FaceAverages& faces, double g);

TriadModel triad_from_vector(const TriadVector& p);
TriadVector vector_from_triad(const TriadModel& t);
// "bias.x", "sensitivity.xy", "second_order.z" ...
std::vector<std::string> triad_parameter_names();
std::vector<std::string> method_parameter_names();

// The robust orientation check: from the raw averages alone (medians, so that one misplaced station
// cannot hide), each station's reading direction against its nominal one. Throws CalibrationError
// naming the station when one is further than max_angle_deg from where it should be. With too few
// stations to estimate each axis's offset and scale (each axis needs one station with it vertical
// and two with it horizontal: the live procedure checks every station as it comes), the raw
// reading's direction is judged as it is.
void check_orientations(const std::vector<const StationAverage*>& stations, double max_angle_deg);

// Inclination (deg) of a specific force f (G = -f).
double inclination_of_specific_force(const Eigen::Vector3d& f);

}  // namespace plumb::calibration
