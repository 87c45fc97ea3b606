// The simulators' runs with every sensor error off (perfect IMU, no magnetometer noise, no
// vibration): what an exact integration of their IMU must turn back into the truth.
#pragma once

#include "plumb/sim/drilling.hpp"
#include "plumb/sim/walk.hpp"

namespace plumb::sim::test {

inline WalkScenario error_free(WalkScenario s) {
  s.grade = ImuGrade::perfect();
  s.mag_sigma_uT = 0;
  return s;
}

inline DrillingScenario error_free(DrillingScenario s) {
  s.grade = ImuGrade::perfect();
  s.magnetometer.sigma_uT = 0;
  s.vibration = Vibration{};
  return s;
}

}  // namespace plumb::sim::test
