// The truth row of a moving simulator (drilling run, walk) from its kinematic state: both states
// carry the same named angles, rates, position and velocity, so one writer serves both.
#pragma once

#include "plumb/core/attitude.hpp"
#include "plumb/core/sample.hpp"

namespace plumb::sim {

constexpr double kRadPerSToRpm = 60.0 / (2.0 * kPi);

template <class State>
void fill_truth(const State& st, double t, double depth_m, TruthSample& truth) {
  truth.t = t;
  truth.inclination_deg = st.inclination / kDeg;
  truth.azimuth_deg = wrap_deg_360(st.azimuth / kDeg);
  truth.toolface_deg = wrap_deg_360(st.toolface / kDeg);
  truth.rpm = st.toolface_rate * kRadPerSToRpm;
  truth.has_position = true;
  truth.north_m = st.position.x();
  truth.east_m = st.position.y();
  truth.down_m = st.position.z();
  truth.vn_mps = st.velocity.x();
  truth.ve_mps = st.velocity.y();
  truth.vd_mps = st.velocity.z();
  truth.depth_m = depth_m;
}

}  // namespace plumb::sim
