#include "plumb/sim/turntable.hpp"

#include <cmath>
#include <cstdio>
#include <random>

#include <Eigen/LU>

#include "plumb/core/attitude.hpp"

namespace plumb::sim {

namespace {

// Inverse of TriadModel::apply: the raw output whose calibration is the physical value x.
Eigen::Vector3d raw_of(const TriadModel& t, const Eigen::Vector3d& x, double dT) {
  const Eigen::Vector3d w = x + t.second_order.cwiseProduct(x.cwiseAbs2());
  const Eigen::Vector3d scale = Eigen::Vector3d::Ones() + t.scale_temp * dT;
  const Eigen::Vector3d v = t.sensitivity.inverse() * w.cwiseQuotient(scale);
  return (v + t.bias_at(dT)).cwiseProduct(t.sensor_scale_at(dT));
}

Eigen::Matrix3d small_matrix(std::mt19937_64& rng, double sigma) {
  std::normal_distribution<double> n(0.0, sigma);
  Eigen::Matrix3d m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = i == j ? 0.0 : n(rng);
  return m;
}

Eigen::Vector3d small_vector(std::mt19937_64& rng, double sigma) {
  std::normal_distribution<double> n(0.0, sigma);
  return {n(rng), n(rng), n(rng)};
}

std::string run_name(double temperature_c) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%gC", temperature_c);
  return buf;
}

}  // namespace

Eigen::Vector3d SensorPackage::raw_accel(const Eigen::Vector3d& f, double T) const {
  return raw_of(truth.accelerometer, f, T - truth.reference_temp_c);
}

Eigen::Vector3d SensorPackage::raw_mag(const Eigen::Vector3d& b, double T) const {
  return raw_of(truth.magnetometer, b, T - truth.reference_temp_c);
}

double SensorPackage::raw_temperature(double T) const {
  // Newton on the (monotonic) correction polynomial.
  double t = T;
  for (int i = 0; i < 50; ++i) {
    const auto& c = truth.thermometer;
    const double value = truth.corrected_temperature(t) - T;
    const double slope = c[1] + t * (2 * c[2] + t * 3 * c[3]);
    const double step = value / slope;
    t -= step;
    if (std::abs(step) < 1e-13 * (1 + std::abs(t))) break;
  }
  return t;
}

SensorPackage SensorPackage::typical(AccelOutput output, std::uint64_t seed, bool temperature_effects) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  SensorPackage p;
  p.accel_output = output;
  const double raw_per_unit = output == AccelOutput::Voltage ? 0.25 : 1000.0;  // per m/s^2

  CalibrationModel& t = p.truth;
  t.tool_id = "sim-package";
  t.calibration_id = "truth";
  t.reference_temp_c = 25;
  t.temp_min_c = -40;
  t.temp_max_c = 250;
  // Accelerometers: raw = bias + A (a + k2 a^2), A = diag(scale) (I + misalignment).
  Eigen::Vector3d scale;
  for (int i = 0; i < 3; ++i) scale[i] = raw_per_unit * (1 + 0.01 * n(rng));
  const Eigen::Matrix3d A = scale.asDiagonal() * (Eigen::Matrix3d::Identity() + small_matrix(rng, 0.003));
  t.accelerometer.sensitivity = A.inverse();
  t.accelerometer.bias = raw_per_unit * small_vector(rng, 0.05);
  t.accelerometer.second_order = small_vector(rng, 2e-5);
  // Magnetometers: 10 counts per microtesla; hard iron of a few microtesla, soft iron ~1 %.
  const Eigen::Matrix3d Am = 10.0 * (Eigen::Matrix3d::Identity() + small_matrix(rng, 0.005));
  Eigen::Matrix3d soft = Am;
  for (int i = 0; i < 3; ++i) soft(i, i) *= 1 + 0.01 * n(rng);
  t.magnetometer.sensitivity = soft.inverse();
  t.magnetometer.bias = 10.0 * small_vector(rng, 2.0);
  if (temperature_effects) {
    t.accelerometer.bias_temp = raw_per_unit * small_vector(rng, 2e-4);
    // Each accelerometer's scale factor drifts on its own output (version 2 of the model).
    t.accelerometer.sensor_scale_temp1 = small_vector(rng, 2e-5);
    t.magnetometer.bias_temp = 10.0 * small_vector(rng, 2e-3);
    t.magnetometer.scale_temp = small_vector(rng, 1e-5);
    // Thermometer: an offset and gain error, and a cubic term that matters above about 175 degC:
    // T = (1 + gain) (t + offset) + k3 (t - 25)^3.
    const double offset = 1.5 + 0.3 * n(rng), gain = 0.002 + 0.001 * n(rng), k3 = 3.75e-7 * (1 + 0.1 * n(rng));
    t.thermometer = {(1 + gain) * offset - 15625 * k3, (1 + gain) + 1875 * k3, -75 * k3, k3};
  }

  CalibrationModel& nom = p.nominal;
  nom.tool_id = t.tool_id;
  nom.calibration_id = "nominal";
  nom.temp_min_c = t.temp_min_c;
  nom.temp_max_c = t.temp_max_c;
  nom.accelerometer.sensitivity = Eigen::Matrix3d::Identity() / raw_per_unit;
  nom.magnetometer.sensitivity = Eigen::Matrix3d::Identity() / 10.0;
  return p;
}

void axis_up_attitude(int axis, int sign, double& inclination_deg, double& toolface_deg) {
  // f = sign g e_axis, i.e. G = -sign g e_axis, with G = (-g sinI cosT, g sinI sinT, g cosI).
  if (axis == 2) {
    inclination_deg = sign > 0 ? 180 : 0;
    toolface_deg = 0;
  } else if (axis == 0) {
    inclination_deg = 90;
    toolface_deg = sign > 0 ? 0 : 180;
  } else {
    inclination_deg = 90;
    toolface_deg = sign > 0 ? 270 : 90;
  }
}

std::vector<StationPlan> six_position_plan(double duration_s, double temperature_c) {
  std::vector<StationPlan> out;
  const char* const ax = "xyz";
  for (int axis = 0; axis < 3; ++axis)
    for (int sign : {1, -1}) {
      StationPlan p;
      p.orientation = std::string(sign > 0 ? "+" : "-") + ax[axis];
      p.name = "p" + p.orientation;
      axis_up_attitude(axis, sign, p.inclination_deg, p.toolface_deg);
      p.temperature_c = temperature_c;
      p.duration_s = duration_s;
      out.push_back(p);
    }
  return out;
}

std::vector<StationPlan> twenty_four_position_plan(const std::vector<double>& temperatures_c, double duration_s) {
  std::vector<StationPlan> out;
  for (double T : temperatures_c)
    for (auto base : six_position_plan(duration_s, T))
      for (int rot = 0; rot < 360; rot += 90) {
        StationPlan p = base;
        p.run = run_name(T);
        p.orientation = base.orientation + "@" + std::to_string(rot);
        p.name = p.run + "/" + p.orientation;
        p.azimuth_deg = rot;
        out.push_back(p);
      }
  return out;
}

std::vector<StationPlan> random_static_plan(int n, std::uint64_t seed, double duration_s, double temperature_c) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<StationPlan> out;
  for (int i = 0; i < n; ++i) {
    StationPlan p;
    p.name = "s" + std::to_string(i + 1);
    p.inclination_deg = std::acos(1 - 2 * u(rng)) / kDeg;  // uniform over the sphere
    p.azimuth_deg = 360 * u(rng);
    p.toolface_deg = 360 * u(rng);
    p.temperature_c = temperature_c;
    p.duration_s = duration_s;
    out.push_back(p);
  }
  return out;
}

void true_vectors(const Rig& rig, const StationPlan& plan, Eigen::Vector3d& f, Eigen::Vector3d& b) {
  const Eigen::Matrix3d table = rot1(rig.table_tilt_x_deg * kDeg) * rot2(rig.table_tilt_y_deg * kDeg);
  const Eigen::Matrix3d C = c_nb(plan.inclination_deg * kDeg, plan.azimuth_deg * kDeg, plan.toolface_deg * kDeg) * table;
  f = -(C * Eigen::Vector3d(0, 0, rig.g));
  b = C * field_ned(rig.total_b, rig.dip_deg * kDeg);
}

Recording record(const SensorPackage& package, const Rig& rig, const std::vector<StationPlan>& plans) {
  Recording rec;
  std::mt19937_64 rng(rig.seed);
  std::normal_distribution<double> n(0.0, 1.0);
  const double dt = 1.0 / rig.sample_rate_hz;
  const TriadModel& acc = package.truth.accelerometer;
  Eigen::Vector3d accel_noise_raw, mag_noise_raw;
  const Eigen::Matrix3d A = acc.sensitivity.inverse(), Am = package.truth.magnetometer.sensitivity.inverse();
  for (int i = 0; i < 3; ++i) {
    accel_noise_raw[i] = package.accel_noise * A.row(i).norm();
    mag_noise_raw[i] = package.mag_noise * Am.row(i).norm();
  }
  double t = 0;
  std::uint64_t seq = 0;
  bool first = true;
  Eigen::Vector3d prev_a = Eigen::Vector3d::Zero(), prev_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d phase = Eigen::Vector3d::Zero();  // pulse counters
  for (const auto& plan : plans) {
    RecordedStation st;
    st.plan = plan;
    true_vectors(rig, plan, st.true_f, st.true_b);
    const double T = plan.temperature_c;
    const Eigen::Vector3d target_a = package.raw_accel(st.true_f, T);
    const Eigen::Vector3d target_m = package.raw_mag(st.true_b, T);
    const double raw_T = package.raw_temperature(T);
    if (first) prev_a = target_a, prev_m = target_m, first = false;
    const double tau = plan.settle_tau_s >= 0 ? plan.settle_tau_s : package.settle_tau_s;
    st.start_s = t;
    const auto count = static_cast<long>(std::llround(plan.duration_s * rig.sample_rate_hz));
    Eigen::Vector3d last_a = prev_a, last_m = prev_m;
    for (long k = 0; k < count; ++k) {
      const double since = k * dt;
      const double decay = tau > 0 ? std::exp(-since / tau) : 0.0;
      last_a = target_a + (prev_a - target_a) * decay;
      last_m = target_m + (prev_m - target_m) * decay;
      Sample s;
      s.seq = seq++;
      s.t = t + since;
      Eigen::Vector3d ua = last_a;
      for (int i = 0; i < 3; ++i) ua[i] += accel_noise_raw[i] * n(rng);
      if (package.accel_output == AccelOutput::PulseRate) {
        // Pulses counted over the sample interval: rate = whole pulses / interval.
        for (int i = 0; i < 3; ++i) {
          const double before = std::floor(phase[i]);
          phase[i] += ua[i] * dt;
          ua[i] = (std::floor(phase[i]) - before) / dt;
        }
      }
      s.f = ua;
      s.b = last_m;
      for (int i = 0; i < 3; ++i) s.b[i] += mag_noise_raw[i] * n(rng);
      s.temp_c = raw_T + package.thermometer_noise * n(rng);
      s.flags = flags::kHasTemperature;
      rec.samples.push_back(s);
    }
    st.end_s = t + (count - 1) * dt;
    for (int r = 0; r < rig.reference_thermometers; ++r) st.reference_temps_c.push_back(T + rig.reference_noise_c * n(rng));
    rec.stations.push_back(st);
    prev_a = last_a;
    prev_m = last_m;
    t += count * dt + rig.move_s;
  }
  return rec;
}

}  // namespace plumb::sim
