#include "plumb/strapdown/alignment.hpp"

#include <cmath>

#include <Eigen/Geometry>

#include "plumb/core/attitude.hpp"

namespace plumb::strapdown {

void StillStats::add(const Eigen::Vector3d& f, const Eigen::Vector3d& w, const std::optional<Eigen::Vector3d>& b,
                     double t) {
  if (n_ == 0) t_first_ = t;
  t_last_ = t;
  n_ += 1;
  sf_ += f;
  sw_ += w;
  sff_ += f.squaredNorm();
  sww_ += w.squaredNorm();
  if (b) {
    nb_ += 1;
    sb_ += *b;
    sbb_ += b->squaredNorm();
  }
}

double StillStats::pooled(const Eigen::Vector3d& s, double ss, double n) {
  if (n < 2) return 0.0;
  const double var = (ss - s.squaredNorm() / n) / (3.0 * (n - 1.0));
  return std::sqrt(std::max(0.0, var));
}

std::optional<Eigen::Matrix3d> triad_attitude(const Eigen::Vector3d& mean_f, const Eigen::Vector3d& reference_b,
                                              double azimuth_of_reference) {
  if (mean_f.norm() <= 0 || !mean_f.allFinite() || !reference_b.allFinite()) return std::nullopt;
  const Eigen::Vector3d down = -mean_f.normalized();
  const Eigen::Vector3d east_raw = down.cross(reference_b);
  if (east_raw.norm() < 1e-9 * reference_b.norm() || east_raw.norm() == 0) return std::nullopt;
  // Axes of the frame whose north is the reference's horizontal direction, in tool coordinates.
  const Eigen::Vector3d east = east_raw.normalized();
  const Eigen::Vector3d north = east.cross(down);
  Eigen::Matrix3d c_ref_b;  // columns: that frame's axes in the tool frame, i.e. C_ref^b
  c_ref_b.col(0) = north;
  c_ref_b.col(1) = east;
  c_ref_b.col(2) = down;
  // C_n^b = C_ref^b C_n^ref with C_n^ref = R3(azimuth_of_reference).
  const Eigen::Matrix3d c_nb = c_ref_b * rot3(azimuth_of_reference);
  return c_nb.transpose();
}

Eigen::Matrix3d tilt_and_azimuth_attitude(const Eigen::Vector3d& mean_f, double azimuth) {
  const Eigen::Vector3d g = -mean_f;
  const double inc = std::atan2(std::hypot(g.x(), g.y()), g.z());
  const double tf = std::hypot(g.x(), g.y()) > 0 ? std::atan2(g.y(), -g.x()) : 0.0;
  return c_nb(inc, azimuth, tf).transpose();
}

}  // namespace plumb::strapdown
