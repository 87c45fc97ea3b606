#include "plumb/calibration/triad_fit.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/LU>
#include <Eigen/QR>

#include "plumb/calibration/fit.hpp"
#include "plumb/core/attitude.hpp"

namespace plumb::calibration {

namespace {

using Inputs = Eigen::Matrix<double, 18, 1>;

Inputs pack(const FaceAverages& f) {
  Inputs x;
  for (int k = 0; k < 6; ++k) x.segment<3>(3 * k) = f.mean[static_cast<std::size_t>(k)];
  return x;
}

// The fit as a function of the 18 face means (weights fixed), so that its covariance follows by
// propagation.
TriadVector solve(const Inputs& x, const Inputs& se, double g, double* chi2) {
  Eigen::Matrix3d A;
  std::array<Eigen::Vector3d, 3> sum;
  std::array<Eigen::Vector3d, 3> sum_se;
  for (int j = 0; j < 3; ++j) {
    const Eigen::Vector3d up = x.segment<3>(6 * j), down = x.segment<3>(6 * j + 3);
    A.col(j) = (up - down) / (2 * g);
    sum[static_cast<std::size_t>(j)] = (up + down) / 2;
    sum_se[static_cast<std::size_t>(j)] =
        0.5 * (se.segment<3>(6 * j).cwiseAbs2() + se.segment<3>(6 * j + 3).cwiseAbs2()).cwiseSqrt();
  }
  Eigen::Matrix<double, 9, 6> H = Eigen::Matrix<double, 9, 6>::Zero();
  Eigen::Matrix<double, 9, 1> y;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const int row = 3 * j + i;
      const double w = 1 / std::max(sum_se[static_cast<std::size_t>(j)][i], 1e-300);
      H(row, i) = w;
      H(row, 3 + j) = w * g * g * A(i, j);
      y[row] = w * sum[static_cast<std::size_t>(j)][i];
    }
  const Eigen::Matrix<double, 6, 1> bk = H.colPivHouseholderQr().solve(y);
  if (chi2) *chi2 = (H * bk - y).squaredNorm();
  const Eigen::Matrix3d S = A.inverse();
  TriadVector p;
  p.segment<3>(0) = bk.head<3>();
  for (int r = 0; r < 3; ++r) p.segment<3>(3 + 3 * r) = S.row(r).transpose();
  p.segment<3>(12) = bk.tail<3>();
  return p;
}

Eigen::Matrix<double, 15, 1> to_method_form(const TriadVector& p) {
  // A = K (I + M): k_i = A_ii, m_ij = A_ij / A_ii; bias = K b; and K k2_m = A k2 (first order in
  // the product of misalignment and second-order terms, which the model form keeps exactly).
  const TriadModel t = triad_from_vector(p);
  const Eigen::Matrix3d A = t.sensitivity.inverse();
  Eigen::Matrix<double, 15, 1> m;
  const Eigen::Vector3d k = A.diagonal();
  m.segment<3>(0) = k;
  m.segment<3>(3) = t.bias.cwiseQuotient(k);
  m.segment<3>(6) = (A * t.second_order).cwiseQuotient(k);
  int idx = 9;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (i != j) m[idx++] = A(i, j) / A(i, i);
  return m;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  if (n == 0) return 0;
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

TriadModel triad_from_vector(const TriadVector& p) {
  TriadModel t;
  t.bias = p.segment<3>(0);
  for (int r = 0; r < 3; ++r) t.sensitivity.row(r) = p.segment<3>(3 + 3 * r).transpose();
  t.second_order = p.segment<3>(12);
  return t;
}

TriadVector vector_from_triad(const TriadModel& t) {
  TriadVector p;
  p.segment<3>(0) = t.bias;
  for (int r = 0; r < 3; ++r) p.segment<3>(3 + 3 * r) = t.sensitivity.row(r).transpose();
  p.segment<3>(12) = t.second_order;
  return p;
}

std::vector<std::string> triad_parameter_names() {
  std::vector<std::string> n;
  const char* const ax = "xyz";
  for (int i = 0; i < 3; ++i) n.push_back(std::string("bias.") + ax[i]);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) n.push_back(std::string("sensitivity.") + ax[r] + ax[c]);
  for (int i = 0; i < 3; ++i) n.push_back(std::string("second_order.") + ax[i]);
  return n;
}

std::vector<std::string> method_parameter_names() {
  std::vector<std::string> n;
  const char* const ax = "xyz";
  for (int i = 0; i < 3; ++i) n.push_back(std::string("method.k.") + ax[i]);
  for (int i = 0; i < 3; ++i) n.push_back(std::string("method.b.") + ax[i]);
  for (int i = 0; i < 3; ++i) n.push_back(std::string("method.k2.") + ax[i]);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (i != j) n.push_back(std::string("method.m.") + ax[i] + ax[j]);
  return n;
}

TriadFit fit_six_faces(const FaceAverages& faces, double g) {
  Inputs se;
  for (int k = 0; k < 6; ++k) se.segment<3>(3 * k) = faces.se[static_cast<std::size_t>(k)];
  const Inputs x = pack(faces);
  TriadFit fit;
  fit.params = solve(x, se, g, &fit.chi2);
  Eigen::MatrixXd cov_x = Eigen::MatrixXd::Zero(18, 18);
  cov_x.diagonal() = se.cwiseAbs2();
  Eigen::VectorXd typical = x.cwiseAbs().cwiseMax(1e-3 * x.cwiseAbs().maxCoeff());
  const VectorFn f = [&](const Eigen::VectorXd& in) -> Eigen::VectorXd { return solve(in, se, g, nullptr); };
  fit.covariance = propagate(f, x, cov_x, typical);
  const VectorFn fm = [&](const Eigen::VectorXd& in) -> Eigen::VectorXd {
    return to_method_form(solve(in, se, g, nullptr));
  };
  fit.method_params = to_method_form(fit.params);
  fit.method_covariance = propagate(fm, x, cov_x, typical);
  return fit;
}

void check_orientations(const std::vector<const StationAverage*>& stations, double max_angle_deg) {
  Eigen::Vector3d bias, amplitude = Eigen::Vector3d::Zero();
  bool estimable = true;
  for (int i = 0; i < 3; ++i) {
    std::vector<double> horizontal;
    bool vertical = false;
    for (const auto* s : stations) {
      if (!s->station.orientation.known()) continue;
      if (s->station.orientation.axis != i) horizontal.push_back(s->accel[i]);
      else vertical = true;
    }
    estimable = estimable && vertical && horizontal.size() >= 2;
    bias[i] = median(horizontal);
    for (const auto* s : stations) amplitude[i] = std::max(amplitude[i], std::abs(s->accel[i] - bias[i]));
  }
  // Too few stations to tell each axis's offset and scale (a live procedure checks every station
  // before recording it, the first one alone): judge the raw reading's direction as it is. An
  // accelerometer's offset is small against its output at 1 g, so this catches a wrong face.
  if (!estimable) bias.setZero(), amplitude.setOnes();
  for (const auto* s : stations) {
    const Orientation& o = s->station.orientation;
    if (!o.known()) continue;
    const Eigen::Vector3d n = (s->accel - bias).cwiseQuotient(amplitude.cwiseMax(1e-300));
    const double angle = std::acos(std::clamp(n.normalized().dot(o.up()), -1.0, 1.0)) / kDeg;
    if (angle > max_angle_deg) {
      int axis = 0;
      n.cwiseAbs().maxCoeff(&axis);
      Orientation seen;
      seen.axis = axis;
      seen.sign = n[axis] >= 0 ? 1 : -1;
      std::ostringstream msg;
      msg.precision(3);
      msg << "station '" << s->station.name << "' (" << o.label() << "): the tool reads as if at "
          << face_label(seen.face()) << ", " << angle << " deg from where the station list puts it; check the tool's "
          << "orientation";
      throw CalibrationError(msg.str());
    }
  }
}

double inclination_of_specific_force(const Eigen::Vector3d& f) {
  const Eigen::Vector3d G = -f;
  return std::atan2(std::hypot(G.x(), G.y()), G.z()) / kDeg;
}

}  // namespace plumb::calibration
