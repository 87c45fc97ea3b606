// [w x]: the matrix of the cross product with w, for the tests' finite-difference checks of
// rotation rates (dC/dt = -[w x] C).
#pragma once

#include <Eigen/Core>

namespace plumb::sim::test {

inline Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& w) {
  Eigen::Matrix3d m;
  m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return m;
}

}  // namespace plumb::sim::test
