#include "plumb/survey/uncertainty.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>

#include "plumb/core/attitude.hpp"

namespace plumb::survey {
namespace {

using Jacobian = Eigen::Matrix3d;  // columns: d/d md, d/d inclination (rad), d/d azimuth (rad)

// Derivatives of one course's displacement with respect to the parameters of its start (a) and
// its end (b). Displacement is linear in the course length, so the depth columns are exact; the
// angle columns are central differences (step 1e-6 rad: truncation ~1e-12, round-off ~1e-10 of the
// course length, far below any sigma this propagates).
void course_jacobians(const StationGeometry& a, const StationGeometry& b, Jacobian& d_start, Jacobian& d_end) {
  const double course = b.md_m - a.md_m;
  const double i1 = a.inclination_deg * kDeg, a1 = a.azimuth_deg * kDeg;
  const double i2 = b.inclination_deg * kDeg, a2 = b.azimuth_deg * kDeg;
  const Eigen::Vector3d r = course_displacement(course, i1, a1, i2, a2);
  constexpr double h = 1e-6;
  const auto f = [&](double di1, double da1, double di2, double da2) {
    return course_displacement(course, i1 + di1, a1 + da1, i2 + di2, a2 + da2);
  };
  d_start.col(0) = -r / course;
  d_end.col(0) = r / course;
  d_start.col(1) = (f(h, 0, 0, 0) - f(-h, 0, 0, 0)) / (2 * h);
  d_start.col(2) = (f(0, h, 0, 0) - f(0, -h, 0, 0)) / (2 * h);
  d_end.col(1) = (f(0, 0, h, 0) - f(0, 0, -h, 0)) / (2 * h);
  d_end.col(2) = (f(0, 0, 0, h) - f(0, 0, 0, -h)) / (2 * h);
}

// Systematic sources: their change of (md, inc, azi) at one station.
constexpr int kSystematic = 4;  // DEC, DSF, AMIL, ABZ

// ABZ: how the closed-form attitude (docs/conventions.md) moves with a bias on the axial accelerometer,
// at this station's attitude in the reference field (central difference; the effect does not
// depend on the toolface, the bias lying on the axis the tool turns about).
Eigen::Vector3d axial_accelerometer_weight(const StationGeometry& s, const StationSigma& sigma, const ErrorModel& m) {
  if (m.axial_accel_bias_sd_mps2 == 0) return Eigen::Vector3d::Zero();
  const double inc = s.inclination_deg * kDeg, az = sigma.magnetic_azimuth_deg * kDeg;
  const Eigen::Vector3d G = gravity_tool(inc, 0, m.gravity_mps2);
  const Eigen::Vector3d B = field_tool(inc, az, 0, m.total_b_uT, m.dip_deg * kDeg);
  const double h = 1e-4 * m.gravity_mps2;
  const ClosedForm up = closed_form_attitude(G + Eigen::Vector3d(0, 0, h), B);
  const ClosedForm down = closed_form_attitude(G - Eigen::Vector3d(0, 0, h), B);
  const double d_inc = (up.inclination_deg - down.inclination_deg) / (2 * h) * kDeg;
  // Near vertical the azimuth is ill-conditioned: its share is left out rather than blown up.
  const double d_az = std::sin(inc) > 1e-3 ? wrap_deg_180(up.azimuth_deg - down.azimuth_deg) / (2 * h) * kDeg : 0.0;
  return {0, d_inc * m.axial_accel_bias_sd_mps2, d_az * m.axial_accel_bias_sd_mps2};
}

Eigen::Vector3d systematic_weight(int source, const StationGeometry& s, const StationSigma& sigma, const ErrorModel& m) {
  switch (source) {
    case 0: return {0, 0, m.declination_sd_deg * kDeg};
    case 1: return {s.md_m * m.depth_scale_sd, 0, 0};
    case 2: {
      const double horizontal = m.total_b_uT * std::cos(m.dip_deg * kDeg);
      if (m.axial_bias_sd_uT == 0 || horizontal <= 0) return Eigen::Vector3d::Zero();
      return {0, 0,
              m.axial_bias_sd_uT * std::sin(s.inclination_deg * kDeg) * std::sin(sigma.magnetic_azimuth_deg * kDeg) /
                  horizontal};
    }
    default: return axial_accelerometer_weight(s, sigma, m);
  }
}

// Random sources at one station: a diagonal covariance of (md, inc, azi).
Eigen::Matrix3d random_covariance(const StationSigma& s) {
  Eigen::Vector3d sd(s.md_sd_m, s.inclination_sd_deg * kDeg, s.azimuth_sd_deg * kDeg);
  return sd.cwiseAbs2().asDiagonal();
}

}  // namespace

void describe_covariance(PositionUncertainty& u) {
  const Eigen::Matrix3d& c = u.covariance;
  u.north_sd_m = std::sqrt(std::max(0.0, c(0, 0)));
  u.east_sd_m = std::sqrt(std::max(0.0, c(1, 1)));
  u.tvd_sd_m = std::sqrt(std::max(0.0, c(2, 2)));
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(c.topLeftCorner<2, 2>());
  const Eigen::Vector2d values = eig.eigenvalues();  // ascending
  u.minor_sd_m = std::sqrt(std::max(0.0, values(0)));
  u.major_sd_m = std::sqrt(std::max(0.0, values(1)));
  const Eigen::Vector2d axis = eig.eigenvectors().col(1);
  double az = std::atan2(axis(1), axis(0)) / kDeg;
  az = std::fmod(az + 360.0, 180.0);
  u.major_azimuth_deg = az;
}

std::vector<PositionUncertainty> propagate_uncertainty(const std::vector<StationGeometry>& st,
                                                       const std::vector<StationSigma>& sigma, const ErrorModel& m) {
  if (st.size() != sigma.size()) throw std::invalid_argument("propagate_uncertainty: one sigma per station");
  const std::size_t n = st.size();
  std::vector<PositionUncertainty> out(n);
  if (n == 0) return out;
  // d_end[k]: derivative of the course (k-1 -> k) with respect to station k's parameters (k >= 1);
  // d_start[k]: of the course (k -> k+1) with respect to station k's (k + 1 < n).
  std::vector<Jacobian> d_start(n, Jacobian::Zero()), d_end(n, Jacobian::Zero());
  for (std::size_t k = 0; k + 1 < n; ++k) {
    if (!(st[k + 1].md_m > st[k].md_m)) throw std::invalid_argument("propagate_uncertainty: measured depths must increase");
    course_jacobians(st[k], st[k + 1], d_start[k], d_end[k + 1]);
  }
  // Sums over the stations above k, whose courses on both sides are in the path to k.
  Eigen::Matrix3d random_above = Eigen::Matrix3d::Zero();
  std::array<Eigen::Vector3d, kSystematic> systematic_above;
  systematic_above.fill(Eigen::Vector3d::Zero());
  for (std::size_t k = 1; k < n; ++k) {
    // Station k-1 is now fully above k: both its courses lie on the path to k.
    const Jacobian full = d_end[k - 1] + d_start[k - 1];
    random_above += full * random_covariance(sigma[k - 1]) * full.transpose();
    for (int s = 0; s < kSystematic; ++s) systematic_above[s] += full * systematic_weight(s, st[k - 1], sigma[k - 1], m);
    // Station k itself: only the course that ends at it.
    Eigen::Matrix3d c = random_above + d_end[k] * random_covariance(sigma[k]) * d_end[k].transpose();
    for (int s = 0; s < kSystematic; ++s) {
      const Eigen::Vector3d v = systematic_above[s] + d_end[k] * systematic_weight(s, st[k], sigma[k], m);
      c += v * v.transpose();
    }
    out[k].covariance = c;
    describe_covariance(out[k]);
  }
  return out;
}

bool inside_ellipse(const PositionUncertainty& u, double dn, double de, double factor) {
  const Eigen::Matrix2d c = u.covariance.topLeftCorner<2, 2>();
  const Eigen::Vector2d e(dn, de);
  Eigen::LDLT<Eigen::Matrix2d> ldlt(c);
  if (ldlt.info() != Eigen::Success || c.determinant() <= 0) return e.norm() == 0;
  return e.dot(ldlt.solve(e)) <= factor * factor;
}

}  // namespace plumb::survey
