#include "rotation_average.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/QR>

#include "procedure_common.hpp"

namespace plumb::calibration::detail {

namespace {

// Beyond this many standard deviations a disagreement is no noise (a few in 10^9 for Gaussian
// noise: no false alarm over many calibrations).
constexpr double kSigmas = 6;

double median4(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return 0.5 * (v[1] + v[2]);
}

// How much of raw channel h's change shows in raw channel a (the cross-axis coupling A_ah / A_hh),
// from the run's faces with axis h up and down, rotations averaged.
double coupling(const std::vector<const StationAverage*>& slots, int a, int h) {
  Eigen::Vector3d up = Eigen::Vector3d::Zero(), down = Eigen::Vector3d::Zero();
  for (int r = 0; r < 4; ++r) {
    up += slots[static_cast<std::size_t>((2 * h) * 4 + r)]->accel / 4;
    down += slots[static_cast<std::size_t>((2 * h + 1) * 4 + r)]->accel / 4;
  }
  const double span = up[h] - down[h];
  return span != 0 ? (up[a] - down[a]) / span : 0.0;
}

}  // namespace

RotationAverage robust_rotation_average(const std::vector<const StationAverage*>& slots, const std::string& context,
                                        const std::vector<const StationAverage*>& suspects) {
  RotationAverage out;
  for (int f = 0; f < 6; ++f) {
    std::vector<const StationAverage*> st;
    for (int r = 0; r < 4; ++r) st.push_back(slots[static_cast<std::size_t>(f * 4 + r)]);
    const int axis = f / 2;
    const std::string face = context + "face " + face_label(f);
    const std::string names = "'" + st[0]->station.name + "', '" + st[1]->station.name + "', '" +
                              st[2]->station.name + "', '" + st[3]->station.name + "'";

    // The tilt-free combination, per channel.
    double worst_e = 0;
    for (int c = 0; c < 3; ++c) {
      const double e = st[0]->accel[c] - st[1]->accel[c] + st[2]->accel[c] - st[3]->accel[c];
      double var = 0;
      for (const auto* s : st) var += s->accel_se[c] * s->accel_se[c];
      worst_e = std::max(worst_e, std::abs(e) / std::max(std::sqrt(var), 1e-300));
    }
    // Along the up axis: each station against the median of the four. The up channel sees the
    // table's tilt too, through the sensor's cross-axis terms (0.5 deg of misalignment times a
    // 0.05 deg tilt is several standard errors): that part is the horizontal channels' variation
    // times their coupling into the up channel, taken from the run's own faces.
    std::vector<double> up;
    for (int r = 0; r < 4; ++r) {
      const auto* s = st[static_cast<std::size_t>(r)];
      double v = s->accel[axis];
      for (int h = 0; h < 3; ++h)
        if (h != axis) {
          double mean_h = 0;
          for (const auto* q : st) mean_h += q->accel[h] / 4;
          v -= coupling(slots, axis, h) * (s->accel[h] - mean_h);
        }
      up.push_back(v);
    }
    const double mid = median4(up);
    std::vector<int> off;
    for (int r = 0; r < 4; ++r) {
      const double se = std::max(st[static_cast<std::size_t>(r)]->accel_se[axis], 1e-300);
      // 2 se: the median itself has the noise of the others.
      if (std::abs(up[static_cast<std::size_t>(r)] - mid) / (2 * se) > kSigmas) off.push_back(r);
    }

    std::vector<int> keep{0, 1, 2, 3};
    if (off.size() == 1) {
      const int bad = off.front();
      const auto* s = st[static_cast<std::size_t>(bad)];
      out.dropped.push_back(face + ": station '" + s->station.name + "' left out: its reading along the up axis is " +
                            format(std::abs(up[static_cast<std::size_t>(bad)] - mid) /
                                   std::max(s->accel_se[axis], 1e-300)) +
                            " standard errors from the other rotations' (misplaced or moved); the face's mean comes "
                            "from the other three and the table's tilt");
      keep.erase(keep.begin() + bad);
    } else if (off.size() > 1) {
      throw CalibrationError(face + ": stations " + names + " disagree along the up axis (" +
                             std::to_string(off.size()) + " of 4 off): too few agreeing rotations remain; "
                             "repeat the face");
    } else if (const auto n_suspect = std::count_if(st.begin(), st.end(), [&](const StationAverage* s) {
                 return std::find(suspects.begin(), suspects.end(), s) != suspects.end();
               });
               worst_e > kSigmas && n_suspect == 1) {
      const auto bad = std::find_if(st.begin(), st.end(), [&](const StationAverage* s) {
        return std::find(suspects.begin(), suspects.end(), s) != suspects.end();
      });
      out.dropped.push_back(face + ": station '" + (*bad)->station.name + "' left out: the rotations disagree by " +
                            format(worst_e) + " standard deviations and it is the one off the run's temperature");
      keep.erase(keep.begin() + (bad - st.begin()));
    } else if (worst_e > kSigmas) {
      throw CalibrationError(face + ": the four rotations (stations " + names + ") disagree by " + format(worst_e) +
                             " standard deviations, more than a tilt of the table explains, and the station at fault "
                             "cannot be told: repeat the face");
    }

    // The face's mean: with all four the plain average (the tilt's sinusoid averages out); with
    // three, the least-squares constant of m + alpha cos r + beta sin r through them.
    Eigen::MatrixXd H(static_cast<Eigen::Index>(keep.size()), 3);
    for (std::size_t k = 0; k < keep.size(); ++k) {
      const double r = keep[k] * M_PI / 2;
      H.row(static_cast<Eigen::Index>(k)) << 1, std::cos(r), std::sin(r);
    }
    // Row 0 of the pseudo-inverse: the weights of the constant.
    const Eigen::MatrixXd pinv = H.completeOrthogonalDecomposition().pseudoInverse();
    Eigen::Vector3d mean = Eigen::Vector3d::Zero(), var = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < keep.size(); ++k) {
      const double w = pinv(0, static_cast<Eigen::Index>(k));
      const auto* s = st[static_cast<std::size_t>(keep[k])];
      mean += w * s->accel;
      var += w * w * s->accel_se.cwiseAbs2();
    }
    out.faces.mean[static_cast<std::size_t>(f)] = mean;
    out.faces.se[static_cast<std::size_t>(f)] = var.cwiseSqrt().cwiseMax(1e-12 * mean.cwiseAbs().maxCoeff());
  }
  return out;
}

}  // namespace plumb::calibration::detail
