// A sensor package written for the tests in the source documents' own form, independent of
// plumb's calibration model and simulator (docs/methods.md section 3, each accelerometer i):
//   output_i = k_i(T) (a_i + b_i(T) + q_i a_i^2 + sum_j m_ij a_j)
// with k_i(T) = k_i (1 + sum_p alpha_ip dT^p) and b_i(T) = b_i + sum_p beta_ip dT^p, dT = T - 25.
// Outputs in volts or counted pulses per sample interval; a thermometer with its own
// non-linearity (raw reading as a function of the true temperature, not plumb's polynomial); a
// table top that is not level; an orientation that moves smoothly between stations; a first-order
// settling response of every channel; white noise; and disturbances inside stations.
#pragma once

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "plumb/calibration/types.hpp"
#include "plumb/core/attitude.hpp"
#include "plumb/core/sample.hpp"

namespace plumb::test::source {

struct Package {
  bool pulses = false;
  double nominal_k = 0.25;                  // volts (or pulses/s) per m/s^2: the datasheet value
  Eigen::Vector3d k = Eigen::Vector3d::Constant(0.25);
  Eigen::Vector3d b = Eigen::Vector3d::Zero();       // m/s^2
  Eigen::Vector3d q = Eigen::Vector3d::Zero();       // per m/s^2
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();       // misalignment, zero diagonal
  Eigen::Matrix3d alpha = Eigen::Matrix3d::Zero();   // row i: sensor i's scale drift, orders 1..3 (per degC^p)
  Eigen::Matrix3d beta = Eigen::Matrix3d::Zero();    // row i: bias drift, orders 1..3 (m/s^2 per degC^p)
  double therm_offset = 0, therm_gain = 0, therm_cubic = 0;   // raw = T (1 - gain) - offset - cubic (T - 25)^3
  double noise = 1e-3;                      // m/s^2 per sample, white, at the sensor's input
  double tau_s = 1.0;                       // settling response of every output
  double mag_per_ut = 10;                   // magnetometer counts per microtesla (not calibrated here)

  // Noise-free output of the three accelerometers for specific force a at true temperature T.
  Eigen::Vector3d output(const Eigen::Vector3d& a, double T) const {
    const double d = T - 25;
    Eigen::Vector3d u;
    for (int i = 0; i < 3; ++i) {
      const double ki = k[i] * (1 + alpha(i, 0) * d + alpha(i, 1) * d * d + alpha(i, 2) * d * d * d);
      const double bi = b[i] + beta(i, 0) * d + beta(i, 1) * d * d + beta(i, 2) * d * d * d;
      double inner = a[i] + bi + q[i] * a[i] * a[i];
      for (int j = 0; j < 3; ++j) inner += m(i, j) * a[j];
      u[i] = ki * inner;
    }
    return u;
  }
  double raw_thermometer(double T) const {
    return T * (1 - therm_gain) - therm_offset - therm_cubic * std::pow(T - 25, 3);
  }

  // Errors of the sizes the issue's packages had: biases to 0.05 m/s^2, scale to 1 %,
  // misalignment to 0.5 deg, second-order terms, drifts over 25..225 degC of up to 1 % in scale
  // and 0.05 m/s^2 in bias, up to `order` in temperature.
  static Package random(std::mt19937_64& rng, bool pulses, int order) {
    std::uniform_real_distribution<double> u(-1, 1);
    Package p;
    p.pulses = pulses;
    p.nominal_k = pulses ? 1000.0 : 0.25;
    for (int i = 0; i < 3; ++i) {
      p.k[i] = p.nominal_k * (1 + 0.01 * u(rng));
      p.b[i] = 0.05 * u(rng);
      p.q[i] = 2e-5 * u(rng);
      for (int j = 0; j < 3; ++j)
        if (i != j) p.m(i, j) = 0.5 * kDeg * u(rng);
      // Drift over a 200 degC span: each order up to its share of the total.
      for (int o = 1; o <= order; ++o) {
        p.alpha(i, o - 1) = 0.004 * u(rng) / std::pow(200.0, o);
        p.beta(i, o - 1) = 0.02 * u(rng) / std::pow(200.0, o);
      }
    }
    p.therm_offset = 1.5 * u(rng);
    p.therm_gain = 0.003 * u(rng);
    p.therm_cubic = 3e-7 * (1 + 0.2 * u(rng));   // ~2 degC at 225 degC: the non-linear range
    return p;
  }
};

// A position on the turntable: axis (0..2) up (+1) or down (-1), turned by rotation_deg about the
// table's normal.
struct Position {
  std::string name, label, run;
  int axis = 0, sign = 1;
  double rotation_deg = 0;
  double temperature_c = 25;
  double duration_s = 60;
  // Extra rotation of the tool (tool frame) at time s into the station: the disturbances.
  std::function<Eigen::Matrix3d(double)> disturbance;
  std::vector<double> reference_temps_c;
};

struct Rig {
  double g = 9.80665;
  double rate_hz = 50;
  double move_s = 10;                      // the tool turns smoothly from one position to the next
  double tilt_x_deg = 0, tilt_y_deg = 0;   // table top
  Eigen::Vector3d field_table{20, 5, 40};  // microtesla, in table coordinates
  double rest_s = 0;                       // after the last station, the tool is moved to rest here
};

struct Recording {
  std::vector<Sample> samples;
  std::vector<calibration::Station> stations;
};

// Table coordinates (z = table normal, up) to tool coordinates for a position, without the tilt.
inline Eigen::Matrix3d table_to_tool(int axis, int sign, double rotation_deg) {
  const int j = (axis + 1) % 3, k = (axis + 2) % 3;
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();   // columns: table x, y, z in tool coordinates
  M(j, 0) = 1;
  M(k, 1) = sign;
  M(axis, 2) = sign;
  const double r = rotation_deg * kDeg;
  Eigen::Matrix3d Rz;
  Rz << std::cos(r), std::sin(r), 0, -std::sin(r), std::cos(r), 0, 0, 0, 1;
  return M * Rz;
}

inline std::vector<Position> six_positions(double duration_s, double T = 25) {
  std::vector<Position> out;
  const char* const ax = "xyz";
  for (int a = 0; a < 3; ++a)
    for (int s : {1, -1}) {
      Position p;
      p.label = std::string(s > 0 ? "+" : "-") + ax[a];
      p.name = "p" + p.label;
      p.axis = a;
      p.sign = s;
      p.temperature_c = T;
      p.duration_s = duration_s;
      out.push_back(p);
    }
  return out;
}

inline std::vector<Position> twenty_four_positions(const std::vector<double>& temps, double duration_s) {
  std::vector<Position> out;
  for (double T : temps)
    for (const auto& face : six_positions(duration_s, T))
      for (int r = 0; r < 360; r += 90) {
        Position p = face;
        p.run = std::to_string(static_cast<int>(T)) + "C";
        p.rotation_deg = r;
        p.label = face.label + "@" + std::to_string(r);
        p.name = p.run + "/" + p.label;
        out.push_back(p);
      }
  return out;
}

// Records the positions in order: a smooth move, then the station; every output follows its
// input with a first-order response (the settling transient after every move).
inline Recording record(const Package& pkg, const Rig& rig, const std::vector<Position>& positions, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n01(0, 1);
  Recording rec;
  const double dt = 1 / rig.rate_hz;
  const double a = 1 - std::exp(-dt / pkg.tau_s);
  // The true vertical in table coordinates (specific force direction at rest: up).
  const Eigen::Vector3d up = (Eigen::Vector3d(rig.tilt_x_deg * kDeg, rig.tilt_y_deg * kDeg, 1)).normalized();
  Eigen::Vector3d lag_a = Eigen::Vector3d::Zero(), lag_m = Eigen::Vector3d::Zero(), phase = Eigen::Vector3d::Zero();
  bool first = true;
  double t = 0;
  Eigen::Quaterniond from = Eigen::Quaterniond::Identity();
  const auto emit = [&](const Eigen::Matrix3d& R, double T) {
    const Eigen::Vector3d f = R * (rig.g * up), bfield = R * rig.field_table;
    const Eigen::Vector3d target = pkg.output(f, T);
    const Eigen::Vector3d target_m = pkg.mag_per_ut * bfield;
    if (first) lag_a = target, lag_m = target_m, first = false;
    lag_a += a * (target - lag_a);
    lag_m += a * (target_m - lag_m);
    // White noise at the sensors' input, after the settling response.
    const Eigen::Vector3d out = lag_a + pkg.noise * pkg.k.cwiseProduct(Eigen::Vector3d(n01(rng), n01(rng), n01(rng)));
    Sample s;
    s.t = t;
    if (pkg.pulses) {
      // Pulses counted over the sample interval: the output is the count divided by dt.
      for (int i = 0; i < 3; ++i) {
        phase[i] += out[i] * dt;
        const double count = std::floor(phase[i]);
        phase[i] -= count;
        s.f[i] = count / dt;
      }
    } else {
      s.f = out;
    }
    s.b = lag_m + 0.2 * Eigen::Vector3d(n01(rng), n01(rng), n01(rng));
    s.temp_c = pkg.raw_thermometer(T + 0.05 * n01(rng));
    s.flags = flags::kHasTemperature;
    rec.samples.push_back(s);
    t += dt;
  };
  for (const auto& p : positions) {
    const Eigen::Matrix3d target = table_to_tool(p.axis, p.sign, p.rotation_deg);
    const Eigen::Quaterniond to(target);
    if (!rec.samples.empty())
      for (double s = 0; s < rig.move_s; s += dt) {
        const double x = 0.5 - 0.5 * std::cos(M_PI * s / rig.move_s);   // smooth start and stop
        emit(from.slerp(x, to).toRotationMatrix(), p.temperature_c);
      }
    calibration::Station st;
    st.name = p.name;
    st.orientation = calibration::parse_orientation(p.label);
    st.run = p.run;
    st.start_s = t;
    for (double s = 0; s < p.duration_s; s += dt)
      emit((p.disturbance ? p.disturbance(s) : Eigen::Matrix3d::Identity()) * target, p.temperature_c);
    st.end_s = t - dt;
    for (int r = 0; r < 3; ++r) st.reference_temps_c.push_back(p.temperature_c + 0.02 * n01(rng));
    rec.stations.push_back(st);
    from = to;
  }
  if (rig.rest_s > 0) {
    // Taken off the table: turned 90 deg about a horizontal axis, then still.
    const Eigen::Matrix3d rest = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix() *
                                 from.toRotationMatrix();
    const Eigen::Quaterniond to(rest);
    for (double s = 0; s < rig.move_s; s += dt)
      emit(from.slerp(0.5 - 0.5 * std::cos(M_PI * s / rig.move_s), to).toRotationMatrix(), positions.back().temperature_c);
    for (double s = 0; s < rig.rest_s; s += dt) emit(rest, positions.back().temperature_c);
  }
  return rec;
}

// Worst inclination error (deg) of `model` on the package's noise-free outputs at the given
// orientations (inclination, toolface deg) and true temperatures.
inline double worst_inclination_error(const Package& pkg, const CalibrationModel& model,
                                      const std::vector<Eigen::Vector2d>& orientations,
                                      const std::vector<double>& temperatures, double g = 9.80665) {
  double worst = 0;
  for (std::size_t k = 0; k < orientations.size(); ++k) {
    const double inc = orientations[k][0], tf = orientations[k][1];
    const double T = temperatures[k % temperatures.size()];
    Sample s;
    s.f = pkg.output(-gravity_tool(inc * kDeg, tf * kDeg, g), T);
    s.temp_c = pkg.raw_thermometer(T);
    s.flags = flags::kHasTemperature;
    model.apply(s);
    worst = std::max(worst, std::abs(std::atan2(std::hypot(s.f.x(), s.f.y()), -s.f.z()) / kDeg - inc));
  }
  return worst;
}

// The datasheet conversion: what "before calibration" means.
inline CalibrationModel nominal_model(const Package& pkg) {
  CalibrationModel m;
  m.accelerometer.sensitivity = Eigen::Matrix3d::Identity() / pkg.nominal_k;
  m.magnetometer.sensitivity = Eigen::Matrix3d::Identity() / pkg.mag_per_ut;
  return m;
}

// Orientations that are not calibration stations: inclination uniform in [0, max], toolface uniform.
inline std::vector<Eigen::Vector2d> random_orientations(std::mt19937_64& rng, int n, double max_inclination_deg) {
  std::uniform_real_distribution<double> inc(0, max_inclination_deg), tf(0, 360);
  std::vector<Eigen::Vector2d> out;
  for (int i = 0; i < n; ++i) out.emplace_back(inc(rng), tf(rng));
  return out;
}

}  // namespace plumb::test::source
