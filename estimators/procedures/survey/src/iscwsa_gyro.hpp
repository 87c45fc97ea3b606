// The gyro terms of the ISCWSA gyro error model (Torkildsen, Havardstein, Weston and Ekseth, SPE
// 90408; the weighting functions as the OWSG gyro tool codes state them): a gyrocompass at each
// station (stationary mode), a gyro run continuously from one initialisation (continuous mode),
// and the initialisation carried over into the continuous section. Internal to iscwsa.cpp.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "plumb/survey/iscwsa.hpp"

namespace plumb::survey::iscwsa::detail {

// One station as the gyro terms see it: radians, azi the true azimuth; t_s the station's time (NaN when
// not known).
struct GyroStation {
  double md = 0, inc = 0, azi = 0, t_s = 0;
};

enum class GyroKind {
  None,        // not a gyro term
  Stationary,  // GXY-*, GXYZ-* (B, G, RN, SF, MIS): a gyrocompass at the station
  Drift,       // GXY-GD, GXYZ-GD, GZ-GD: a gyro bias integrated over the time run since the initialisation
  RandomWalk,  // GXY-GRW, GXYZ-GRW, GZ-GRW: the gyro's random walk over that time
  Reference    // EXT-REF, EXT-TIE: the azimuth a continuous run was initialised from
};
GyroKind gyro_kind(const std::string& weight_function);

// A term's change of (MD, I, A) at each station (per the magnitude given, in SI: rad/h, rad/sqrt(h),
// rad) and which stations share one draw of it: stations of the same group (contiguous) share
// one, groups are independent. A random term is one group per station, except that the
// gyrocompass initialising a continuous run is one draw of its own, held by every station of the run.
struct GyroEffect {
  std::vector<Eigen::Vector3d> dia;
  std::vector<int> group;
};

// Throws std::invalid_argument when a gyrocompass term has no latitude or the continuous terms'
// time cannot be had (no running speed and station times that do not increase).
GyroEffect gyro_term(const std::vector<GyroStation>& stations, const Term& term, double magnitude,
                     const GyroRunning& running, const Field& field);

}  // namespace plumb::survey::iscwsa::detail
