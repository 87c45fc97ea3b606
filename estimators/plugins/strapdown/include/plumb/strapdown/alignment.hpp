// Initial alignment from a still period: sums of the raw readings, and the coarse attitude from
// them. The filter refines the coarse attitude with the same means (tilt, heading, earth rate) as
// its first measurements, which also gives it the right correlations between attitude and biases.
#pragma once

#include <optional>

#include <Eigen/Core>

namespace plumb::strapdown {

// Running means and spreads of raw f, w and B over a stretch of stillness.
class StillStats {
 public:
  void add(const Eigen::Vector3d& f, const Eigen::Vector3d& w, const std::optional<Eigen::Vector3d>& b, double t);
  void clear() { *this = StillStats(); }
  double count() const { return n_; }
  double mag_count() const { return nb_; }
  double duration() const { return n_ > 0 ? t_last_ - t_first_ : 0.0; }
  Eigen::Vector3d mean_f() const { return sf_ / n_; }
  Eigen::Vector3d mean_w() const { return sw_ / n_; }
  Eigen::Vector3d mean_b() const { return sb_ / nb_; }
  // Per-axis standard deviation of one sample (pooled over the three axes).
  double sample_sd_f() const { return pooled(sf_, sff_, n_); }
  double sample_sd_w() const { return pooled(sw_, sww_, n_); }
  double sample_sd_b() const { return pooled(sb_, sbb_, nb_); }

 private:
  static double pooled(const Eigen::Vector3d& s, double ss, double n);
  double n_ = 0, nb_ = 0, t_first_ = 0, t_last_ = 0;
  Eigen::Vector3d sf_ = Eigen::Vector3d::Zero(), sw_ = Eigen::Vector3d::Zero(), sb_ = Eigen::Vector3d::Zero();
  double sff_ = 0, sww_ = 0, sbb_ = 0;
};

// C_b^n from the down direction (gravity, -f) and a second vector whose horizontal part points at
// azimuth `azimuth_of_reference` (rad) in the navigation frame: the field B (magnetic north, or
// declination in a true frame) or the earth rate (true north, gyrocompassing). Exact at any
// attitude (TRIAD); nullopt when the two are parallel or zero.
std::optional<Eigen::Matrix3d> triad_attitude(const Eigen::Vector3d& mean_f, const Eigen::Vector3d& reference_b,
                                              double azimuth_of_reference);

// C_b^n from the tilt of -f and a given tool azimuth (rad). At I = 0 or 180 deg, where the
// azimuth means nothing, the toolface is set to 0.
Eigen::Matrix3d tilt_and_azimuth_attitude(const Eigen::Vector3d& mean_f, double azimuth);

}  // namespace plumb::strapdown
