// A walk with the IMU strapped to one foot, around a closed loop: the classic check of a
// zero-velocity-update navigator's accuracy, also how users check a gyro tool on the
// surface. The foot swings from footprint to footprint and stands perfectly still on each one.
//
// Mounting (docs/conventions.md frames): the tool z axis points forward along the foot, the tool x axis
// up out of the instep, the tool y axis to the right of the foot. With the foot's heading psi,
// pitch theta (toes up positive) and roll phi (right side down positive) this gives exactly
//   C_n^b = R3(phi) R2(90 deg + theta) R3(psi):  I = 90 deg + theta, A = psi, T = phi,
// so a flat foot reads I = 90 deg, T = 0, A = its heading: far from vertical, unlike a drilling tool.
//
// Kinematics, all closed form in the time tau in [0, 1] across each swing of duration D:
//   position: footprint k + (footprint k+1 - footprint k) s(tau) - clearance b(tau) (down),
//   heading:  psi_k + (psi_k+1 - psi_k) s(tau)  (turns at corners happen in the air),
//   pitch:    -pitch_deg w(tau) (toes down after toe-off, toes up before heel strike),
//   roll:     roll_deg b(tau),
// with s = 35 tau^4 - 84 tau^5 + 70 tau^6 - 20 tau^7 (septic smoothstep), b = 256 tau^4 (1-tau)^4
// and w = (19683/16) tau^4 (1-tau)^4 (1 - 2 tau) (peak |w| = 1): velocity, acceleration, jerk and
// the angular rate and its derivative are zero at both ends of every swing, so the stance is exactly
// still and the sensors are continuous into it. Sensors as in drilling.hpp: w_ib = w_nb + C_n^b w_ie,
// f = C_n^b (dv/dt + 2 w_ie x v - g_n), B = C_n^b B_n, instantaneous values at t = k / rate.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "plumb/core/sample.hpp"
#include "plumb/sim/imu_model.hpp"

namespace plumb::sim {

// One straight stretch of the loop. Its strides are equal: round(length / stride) of them.
struct WalkLeg {
  double length_m = 0;    // horizontal, > 0
  double climb_m = 0;     // height gained over the leg (negative: down), shared evenly by its strides
  double stride_m = 0;    // horizontal stride on this leg (stairs: two treads); 0: WalkScenario::stride_m
  double turn_deg = 0;    // heading change at the end of the leg, positive to the right (clockwise from above)
};

struct WalkScenario {
  std::string tool_id = "walk";
  // The loop, from the start point; it must return there (checked to 1e-6 m, then closed exactly).
  std::vector<WalkLeg> legs;
  double heading_deg = 0;         // of the first leg, magnetic; a footprint at a corner points halfway
  double stride_m = 1.4;          // one foot's step: the distance between its successive footprints
  double cadence_hz = 1.0;        // strides per second of the instrumented foot (swing + stance)
  double stance_min_s = 0.05;     // each stance lasts a uniform draw in [min, max] from the seed
  double stance_max_s = 0.3;
  double clearance_m = 0.12;      // peak lift of the foot above the straight line between footprints
  double pitch_deg = 30;          // peak pitch during a swing
  double roll_deg = 5;            // peak roll during a swing
  double initial_still_s = 10;    // standing before the first stride (initial alignment)
  double final_still_s = 5;       // standing after the last stride
  ImuGrade grade = ImuGrade::mems();
  std::optional<Eigen::Vector3d> gyro_bias;    // rad/s; default: drawn from the grade and the seed
  std::optional<Eigen::Vector3d> accel_bias;   // m/s^2; default: drawn from the grade and the seed
  double sample_rate_hz = 400;
  double latitude_deg = 35;
  double g = 9.80665;             // m/s^2
  double total_b = 50;            // microtesla
  double dip_deg = 60;
  double earth_rate = 7.292115e-5;  // rad/s
  bool magnetometer = true;       // false: Sample::b stays zero
  double mag_sigma_uT = 0.1;      // white noise per axis per sample
  std::uint64_t seed = 1;

  // A rectangle of the given perimeter (long sides twice the short ones), walked clockwise from its
  // south-west corner, first north. climb_m > 0 puts a flight of stairs in the middle of the first
  // long side (up) and of the other (down): strides of 0.6 m rising at most 0.34 m (two stairs of
  // 0.3 m x 0.17 m), so the foot returns to its start height.
  static WalkScenario loop(double length_m, double climb_m, const ImuGrade& grade = ImuGrade::mems(),
                           double rate_hz = 400, std::uint64_t seed = 1);
  // The navigator's test walks: a flat 25 m loop (18 strides), and a 60 m loop with 3 m of stairs up and down.
  static WalkScenario loop_25m(const ImuGrade& grade = ImuGrade::mems(), double rate_hz = 400, std::uint64_t seed = 1);
  static WalkScenario loop_60m(const ImuGrade& grade = ImuGrade::mems(), double rate_hz = 400, std::uint64_t seed = 1);

  double duration_s() const;
};

// The true state of the foot at one instant.
struct WalkState {
  double t = 0;
  bool still = true;               // exactly zero velocity and constant attitude
  std::size_t stride = 0;          // strides begun by t (the one in the air, or the last landed)
  double inclination = 0, azimuth = 0, toolface = 0;  // rad; azimuth unwrapped
  double inclination_rate = 0, azimuth_rate = 0, toolface_rate = 0;  // rad/s
  Eigen::Matrix3d c_nb = Eigen::Matrix3d::Identity();
  Eigen::Vector3d w_nb = Eigen::Vector3d::Zero();      // rad/s, tool frame
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // NED from the start footprint, m
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // NED, m/s
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();  // dv/dt, NED, m/s^2
};

// The loop compiled into footprints and timed swings (stance lengths drawn from the seed), evaluated
// in closed form at any t.
class WalkPath {
 public:
  struct Footprint {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  // NED, m
    double heading = 0;                                  // rad, unwrapped
  };
  struct Swing {
    double t0 = 0, t1 = 0;         // lift-off and landing, s
    std::size_t from = 0;          // footprint index; lands on from + 1
  };
  // Throws std::invalid_argument with a readable message for a bad loop or timing.
  explicit WalkPath(const WalkScenario& scenario);
  double duration_s() const { return duration_; }
  const std::vector<Footprint>& footprints() const { return footprints_; }
  const std::vector<Swing>& swings() const { return swings_; }
  double horizontal_length_m() const;   // sum of the strides' horizontal lengths
  double length_m() const;              // sum of the 3-D footprint-to-footprint distances
  // Before 0 the foot stands on the first footprint, past the end on the last.
  WalkState at(double t) const;
  bool still_at(double t) const;

 private:
  std::vector<Footprint> footprints_;
  std::vector<Swing> swings_;
  double duration_ = 0;
  double clearance_ = 0, pitch_ = 0, roll_ = 0;  // m, rad, rad
};

// Produces the samples of a walk one at a time, deterministic for a seed.
class WalkSimulator {
 public:
  // Throws std::invalid_argument with a readable message for bad parameters.
  explicit WalkSimulator(const WalkScenario& scenario);
  std::size_t sample_count() const;   // duration x rate, rounded
  bool done() const;
  // Next sample (gyros flagged kHasGyro, saturation kGyroSaturated) and its truth (with position;
  // depth_m stays 0). Past sample_count() the foot stands on its last footprint.
  Sample next(TruthSample* truth = nullptr);
  std::vector<Sample> run(std::vector<TruthSample>* truth = nullptr);
  // True while the foot stands perfectly still: the truth for a zero-velocity detector.
  bool still_at(double t) const { return path_.still_at(t); }
  double time_of(std::size_t index) const;
  const WalkScenario& scenario() const { return scenario_; }
  const WalkPath& path() const { return path_; }
  const Eigen::Vector3d& gyro_bias() const { return imu_.gyro_bias(); }    // the biases in use (truth)
  const Eigen::Vector3d& accel_bias() const { return imu_.accel_bias(); }
  std::size_t index() const { return index_; }

 private:
  WalkScenario scenario_;
  WalkPath path_;
  ImuModel imu_;
  Eigen::Vector3d field_ned_ = Eigen::Vector3d::Zero();
  std::size_t index_ = 0;
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
};

// One readable line: loop, strides, timing, grade, environment, rate, seed.
std::string describe(const WalkScenario& scenario);

}  // namespace plumb::sim
