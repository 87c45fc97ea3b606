#include "scenario_options.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace plumb::sim_component {
namespace {

bool given(const CLI::App& app, const std::string& name) { return app.count(name) > 0; }

double parse_number(const std::string& option, const std::string& text) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(v))
    throw std::invalid_argument(option + ": '" + text + "' is not a number");
  return v;
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const auto at = text.find(sep, start);
    parts.push_back(text.substr(start, at - start));
    if (at == std::string::npos) return parts;
    start = at + 1;
  }
}

// "x,y,z" -> vector.
Eigen::Vector3d parse_triple(const std::string& option, const std::string& text) {
  const auto parts = split(text, ',');
  if (parts.size() != 3) throw std::invalid_argument(option + ": expected X,Y,Z, got '" + text + "'");
  return {parse_number(option, parts[0]), parse_number(option, parts[1]), parse_number(option, parts[2])};
}

void set_triple(const CLI::App& app, const std::string& option, const std::string& text, Eigen::Vector3d& out) {
  if (given(app, option)) out = parse_triple(option, text);
}

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

}  // namespace

void add_scenario_options(CLI::App& app, ScenarioOptions& o) {
  app.add_option("--preset", o.preset, "start from: default, or reference (the paper's case: g 10, B 48.4 uT, dip 45.5, "
                                       "100 Hz, 10 s, SNR_a 20 dB, SNR_m 20 dB)")
      ->check(CLI::IsMember({"default", "reference"}));
  app.add_option("--inclination", o.inclination_deg, "inclination, deg (0..180)")->capture_default_str();
  app.add_option("--azimuth", o.azimuth_deg, "magnetic azimuth, deg")->capture_default_str();
  app.add_option("--toolface", o.toolface_deg, "gravity toolface at t = 0, deg")->capture_default_str();
  auto* rpm = app.add_option("--rpm", o.rpm, "constant platform speed, rev/min (positive: toolface increases)")
                  ->capture_default_str();
  app.add_option("--profile", o.profile, "rotation profile: RPM, ramp:START:END:SECONDS, stopgo:MEAN:PERIOD_S, "
                                         "stickslip:MEAN:PERIOD_S")
      ->excludes(rpm);
  app.add_option("--g", o.g, "gravity, m/s^2")->capture_default_str();
  app.add_option("--field", o.field, "total magnetic field, uT")->capture_default_str();
  app.add_option("--dip", o.dip, "magnetic dip, deg, positive down")->capture_default_str();
  app.add_option("--latitude", o.latitude, "latitude for the earth rate the gyros see, deg")->capture_default_str();
  app.add_option("--rate-hz", o.rate_hz, "sample rate, Hz")->capture_default_str();
  auto* duration = app.add_option("--duration", o.duration_s, "record length, s")->capture_default_str();
  app.add_option("--count", o.count, "number of samples (instead of --duration)")->excludes(duration);
  auto* snr_a = app.add_option("--snr-accel", o.snr_accel, "accelerometer SNR, dB (CONVENTIONS.md); default: no noise (reference preset: 20)");
  auto* snr_m = app.add_option("--snr-mag", o.snr_mag, "magnetometer SNR, dB; default: no noise (reference preset: 20)");
  app.add_option("--sigma-accel", o.sigma_accel, "accelerometer noise sigma, m/s^2")->excludes(snr_a);
  app.add_option("--sigma-mag", o.sigma_mag, "magnetometer noise sigma, uT")->excludes(snr_m);
  app.add_option("--sigma-gyro", o.sigma_gyro, "gyro noise sigma, rad/s");
  app.add_option("--accel-bias", o.accel_bias, "accelerometer bias X,Y,Z, m/s^2");
  app.add_option("--accel-scale", o.accel_scale, "accelerometer relative scale error X,Y,Z (e.g. 0.001,0,0)");
  app.add_option("--accel-bias-temp", o.accel_bias_temp, "accelerometer bias change X,Y,Z per degC from 25 degC");
  app.add_option("--mag-bias", o.mag_bias, "magnetometer bias X,Y,Z, uT");
  app.add_option("--mag-scale", o.mag_scale, "magnetometer relative scale error X,Y,Z");
  app.add_option("--mag-bias-temp", o.mag_bias_temp, "magnetometer bias change X,Y,Z per degC from 25 degC");
  app.add_option("--gyro-bias", o.gyro_bias, "gyro bias X,Y,Z, rad/s");
  app.add_option("--gyro-scale", o.gyro_scale, "gyro relative scale error X,Y,Z");
  app.add_option("--vibration", o.vibration_rms, "lateral vibration rms on x and y, m/s^2");
  app.add_option("--vibration-hz", o.vibration_hz, "vibration centre frequency, Hz")->capture_default_str();
  app.add_option("--shock-rate", o.shock_rate, "mean rate of lateral half-sine shocks, 1/s");
  app.add_option("--shock-peak", o.shock_peak, "shock peak, m/s^2");
  app.add_option("--temp", o.temp, "temperature, degC: T (constant) or START:END (linear over the duration)");
  app.add_option("--seed", o.seed, "random seed (same seed, same samples)")->capture_default_str();
  app.add_option("--tool-id", o.tool_id, "tool id in the published messages (at most 31 characters)")
      ->capture_default_str();
  app.add_flag("--no-gyro", o.no_gyro, "simulate no gyros (samples without the has-gyro flag)");
}

sim::Scenario make_scenario(const CLI::App& app, const ScenarioOptions& o) {
  sim::Scenario s;
  if (o.preset == "reference") s = sim::Scenario::reference(o.inclination_deg, o.azimuth_deg, o.rpm, o.snr_accel);
  s.tool_id = o.tool_id;
  s.inclination_deg = o.inclination_deg;
  s.azimuth_deg = o.azimuth_deg;
  s.toolface0_deg = o.toolface_deg;
  s.seed = o.seed;
  s.with_gyro = !o.no_gyro;
  if (given(app, "--profile")) {
    s.rotation = sim::parse_profile(o.profile);
  } else {
    s.rotation = sim::RotationProfile{};
    s.rotation.rpm = o.rpm;
  }
  if (given(app, "--g")) s.g = o.g;
  if (given(app, "--field")) s.total_b = o.field;
  if (given(app, "--dip")) s.dip_deg = o.dip;
  s.latitude_deg = o.latitude;
  if (given(app, "--rate-hz")) s.sample_rate_hz = o.rate_hz;
  require(std::isfinite(s.sample_rate_hz) && s.sample_rate_hz > 0, "--rate-hz must be > 0");
  if (given(app, "--duration")) s.duration_s = o.duration_s;
  if (given(app, "--count")) {
    require(o.count > 0, "--count must be > 0");
    s.duration_s = static_cast<double>(o.count) / s.sample_rate_hz;
  }
  if (given(app, "--snr-accel")) s.noise.snr_accel_db = o.snr_accel;
  if (given(app, "--snr-mag")) s.noise.snr_mag_db = o.snr_mag;
  if (given(app, "--sigma-accel")) {
    s.noise.sigma_accel = o.sigma_accel;
    s.noise.snr_accel_db.reset();
  }
  if (given(app, "--sigma-mag")) {
    s.noise.sigma_mag = o.sigma_mag;
    s.noise.snr_mag_db.reset();
  }
  s.noise.sigma_gyro = o.sigma_gyro;
  set_triple(app, "--accel-bias", o.accel_bias, s.accel_errors.bias);
  set_triple(app, "--accel-scale", o.accel_scale, s.accel_errors.scale);
  set_triple(app, "--accel-bias-temp", o.accel_bias_temp, s.accel_errors.bias_temp);
  set_triple(app, "--mag-bias", o.mag_bias, s.mag_errors.bias);
  set_triple(app, "--mag-scale", o.mag_scale, s.mag_errors.scale);
  set_triple(app, "--mag-bias-temp", o.mag_bias_temp, s.mag_errors.bias_temp);
  set_triple(app, "--gyro-bias", o.gyro_bias, s.gyro_errors.bias);
  set_triple(app, "--gyro-scale", o.gyro_scale, s.gyro_errors.scale);
  s.vibration.lateral_rms = o.vibration_rms;
  s.vibration.frequency_hz = o.vibration_hz;
  s.vibration.shock_rate_hz = o.shock_rate;
  s.vibration.shock_peak = o.shock_peak;
  if (given(app, "--temp")) {
    const auto parts = split(o.temp, ':');
    require(parts.size() <= 2, "--temp: expected T or START:END, got '" + o.temp + "'");
    s.temp_start_c = parse_number("--temp", parts[0]);
    s.temp_end_c = parts.size() == 2 ? parse_number("--temp", parts[1]) : s.temp_start_c;
  }
  require(s.tool_id.size() <= 31, "--tool-id: at most 31 characters");
  return s;
}

}  // namespace plumb::sim_component
