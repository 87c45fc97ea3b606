#include "scenario_options.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "plumb/core/number.hpp"

namespace plumb::sim_component {
namespace {

bool given(const CLI::App& app, const std::string& name) { return app.count(name) > 0; }

double option_number(const std::string& option, const std::string& text) {
  const auto v = parse_number(text);
  if (!v) throw std::invalid_argument(option + ": '" + text + "' is not a number");
  return *v;
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
  return {option_number(option, parts[0]), option_number(option, parts[1]), option_number(option, parts[2])};
}

void set_triple(const CLI::App& app, const std::string& option, const std::string& text, Eigen::Vector3d& out) {
  if (given(app, option)) out = parse_triple(option, text);
}

std::string format_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// "platform 48.4; drilling and drilling-survey 50; walk 50": a default each scenario keeps.
std::string per_scenario(double platform, double drilling, double walk) {
  return "platform " + format_number(platform) + "; drilling and drilling-survey " + format_number(drilling) + "; walk " +
         format_number(walk);
}

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

}  // namespace

void add_scenario_options(CLI::App& app, ScenarioOptions& o) {
  app.add_option("--scenario", o.scenario,
                 "what to simulate: platform (the rotating sensor platform), drilling (a 16-minute drilling run with "
                 "four pipe connections, the navigator's accuracy case), drilling-survey (stop-and-go rotary drilling "
                 "with short survey stops) or walk (an IMU on a foot walking a closed loop, the classic check of a "
                 "zero-velocity-update navigator: tool z forward along the foot, x up); drilling runs carry gyros, "
                 "measured depth and truth position, walks gyros and truth position")
      ->capture_default_str()
      ->check(CLI::IsMember({"platform", "drilling", "drilling-survey", "walk"}));
  app.add_option("--preset", o.preset, "start from: default, or reference (the paper's case: g 10, B 48.4 uT, dip 45.5, "
                                       "100 Hz, 10 s, SNR_a 20 dB, SNR_m 20 dB)")
      ->check(CLI::IsMember({"default", "reference"}));
  app.add_option("--inclination", o.inclination_deg, "inclination, deg (0..180); drilling: at the start of the run (not for walks)")->capture_default_str();
  app.add_option("--azimuth", o.azimuth_deg, "magnetic azimuth, deg; drilling: at the start of the run; walk: heading of the first side")->capture_default_str();
  app.add_option("--toolface", o.toolface_deg, "gravity toolface at t = 0, deg (not for walks)")->capture_default_str();
  auto* rpm = app.add_option("--rpm", o.rpm, "constant platform speed, rev/min (positive: toolface increases)")
                  ->capture_default_str();
  app.add_option("--profile", o.profile, "rotation profile: RPM, ramp:START:END:SECONDS, stopgo:MEAN:PERIOD_S, "
                                         "stickslip:MEAN:PERIOD_S")
      ->excludes(rpm);
  app.add_option("--g", o.g, "gravity, m/s^2")->capture_default_str();
  // (Each scenario keeps its own field and latitude unless given: a default shown here would be the
  // platform's only, and a gyrocompass run told the wrong latitude looks degrees off. The defaults
  // quoted are the scenarios' own, read from them.)
  const sim::Scenario platform;
  const sim::DrillingScenario drilling = sim::DrillingScenario::reference(sim::ImuGrade::perfect(), 100, 1);
  const sim::WalkScenario walk = sim::WalkScenario::loop_25m();
  app.add_option("--field", o.field,
                 "total magnetic field, uT (default: " + per_scenario(platform.total_b, drilling.total_b, walk.total_b) + ")");
  app.add_option("--dip", o.dip,
                 "magnetic dip, deg, positive down (default: " + per_scenario(platform.dip_deg, drilling.dip_deg, walk.dip_deg) + ")");
  // The platform takes the option's own value (o.latitude before parsing) whether given or not.
  app.add_option("--latitude", o.latitude,
                 "latitude for the earth rate the gyros see, deg (default: " +
                     per_scenario(o.latitude, drilling.latitude_deg, walk.latitude_deg) + ")");
  app.add_option("--rate-hz", o.rate_hz, "sample rate, Hz (drilling: the IMU rate, default 100; walk: default 400)")->capture_default_str();
  auto* duration = app.add_option("--duration", o.duration_s, "record length, s")->capture_default_str();
  app.add_option("--count", o.count, "number of samples (instead of --duration)")->excludes(duration);
  auto* snr_a = app.add_option("--snr-accel", o.snr_accel, "accelerometer SNR, dB (docs/conventions.md); default: no noise (reference preset: 20)");
  auto* snr_m = app.add_option("--snr-mag", o.snr_mag, "magnetometer SNR, dB; default: no noise (reference preset: 20)");
  app.add_option("--sigma-accel", o.sigma_accel, "accelerometer noise sigma, m/s^2")->excludes(snr_a);
  app.add_option("--sigma-mag", o.sigma_mag, "magnetometer noise sigma, uT (drilling and walk default 0.1)")->excludes(snr_m);
  app.add_option("--sigma-gyro", o.sigma_gyro, "gyro noise sigma, rad/s");
  app.add_option("--accel-bias", o.accel_bias, "accelerometer bias X,Y,Z, m/s^2 (drilling, walk: instead of the one drawn from --grade)");
  app.add_option("--accel-scale", o.accel_scale, "accelerometer relative scale error X,Y,Z (e.g. 0.001,0,0)");
  app.add_option("--accel-bias-temp", o.accel_bias_temp, "accelerometer bias change X,Y,Z per degC from 25 degC");
  app.add_option("--mag-bias", o.mag_bias, "magnetometer bias X,Y,Z, uT");
  app.add_option("--mag-scale", o.mag_scale, "magnetometer relative scale error X,Y,Z");
  app.add_option("--mag-bias-temp", o.mag_bias_temp, "magnetometer bias change X,Y,Z per degC from 25 degC");
  app.add_option("--gyro-bias", o.gyro_bias, "gyro bias X,Y,Z, rad/s (drilling, walk: instead of the one drawn from --grade)");
  app.add_option("--gyro-scale", o.gyro_scale, "gyro relative scale error X,Y,Z");
  app.add_option("--vibration", o.vibration_rms, "lateral vibration rms on x and y, m/s^2 (drilling: while drilling only)");
  app.add_option("--vibration-hz", o.vibration_hz, "vibration centre frequency, Hz")->capture_default_str();
  app.add_option("--vibration-band", o.vibration_band,
                 "vibration bandwidth about the centre frequency, Hz: 64 tones spread across it, as a bit's broadband "
                 "excitation (--vibration-hz 24 --vibration-band 32: 8-40 Hz); default 0: four tones within 25 % of the "
                 "centre");
  app.add_option("--shock-rate", o.shock_rate, "mean rate of lateral half-sine shocks, 1/s");
  app.add_option("--shock-peak", o.shock_peak, "shock peak, m/s^2");
  app.add_option("--temp", o.temp, "temperature, degC: T (constant) or START:END (linear over the duration)");
  app.add_option("--seed", o.seed, "random seed (same seed, same samples)")->capture_default_str();
  app.add_option("--tool-id", o.tool_id, "tool id in the published messages (at most 31 characters)")
      ->capture_default_str();
  app.add_flag("--no-gyro", o.no_gyro, "simulate no gyros (samples without the has-gyro flag)");
  app.add_option("--grade", o.grade, "drilling, walk: IMU grade, navigation, tactical, mems or perfect "
                                     "(sim/drilling.hpp tables their biases, noise and range); default tactical for "
                                     "drilling, mems for a walk");
  app.add_option("--gyro-range", o.gyro_range, "drilling, walk: gyro saturation range, deg/s (default: the grade's)");
  app.add_flag("--no-mag", o.no_mag, "drilling, walk: no magnetometer on the tool (bx,by,bz written as 0)");
  app.add_option("--mag-disturbance", o.mag_disturbances,
                 "drilling: STOP:DELTA_UT:DELTA_DIP_DEG shifts |B| and dip while the tool stands at that pipe "
                 "connection (0 = first); repeatable");
  app.add_flag("--no-depth", o.no_depth, "drilling: no measured depth in the samples");
  app.add_option("--circulation-temp", o.circulation_temp,
                 "drilling: MUD_C:FORMATION_C, the tool's temperature on the samples (temp_c): it cools toward the "
                 "mud's while drilling (90 s time constant) and warms toward the formation's at stops (120 s), from "
                 "the mud's; the biases follow it by the grade's coefficients (sim/tool_temperature.hpp)");
  app.add_option("--depth-noise", o.depth_noise, "drilling: measured-depth noise sigma, m");
  app.add_option("--depth-step", o.depth_step, "drilling: measured-depth reading step, m (0: none)");
  app.add_option("--walk-length", o.walk_length,
                 "walk: length of the closed loop, m (a rectangle, long sides twice the short ones); 25 (flat) and "
                 "60 (with 3 m of stairs up and back down) are the navigator's test walks")
      ->capture_default_str();
  app.add_option("--walk-climb", o.walk_climb,
                 "walk: height of the flight of stairs on the first long side, walked back down on the other, m "
                 "(default: 3 for a 60 m loop, else 0)");
}

sim::Scenario make_scenario(const CLI::App& app, const ScenarioOptions& o) {
  for (const char* option : {"--grade", "--gyro-range", "--no-mag"})
    require(!given(app, option),
            std::string(option) + " applies to drilling runs and walks only (--scenario drilling or walk)");
  for (const char* option : {"--mag-disturbance", "--no-depth", "--depth-noise", "--depth-step", "--circulation-temp"})
    require(!given(app, option), std::string(option) + " applies to drilling runs only (--scenario drilling)");
  for (const char* option : {"--walk-length", "--walk-climb"})
    require(!given(app, option), std::string(option) + " applies to walks only (--scenario walk)");
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
  s.vibration.band_hz = o.vibration_band;
  s.vibration.shock_rate_hz = o.shock_rate;
  s.vibration.shock_peak = o.shock_peak;
  if (given(app, "--temp")) {
    const auto parts = split(o.temp, ':');
    require(parts.size() <= 2, "--temp: expected T or START:END, got '" + o.temp + "'");
    s.temp_start_c = option_number("--temp", parts[0]);
    s.temp_end_c = parts.size() == 2 ? option_number("--temp", parts[1]) : s.temp_start_c;
  }
  require(s.tool_id.size() <= 31, "--tool-id: at most 31 characters");
  return s;
}

bool is_drilling(const ScenarioOptions& o) { return o.scenario == "drilling" || o.scenario == "drilling-survey"; }

sim::DrillingScenario make_drilling_scenario(const CLI::App& app, const ScenarioOptions& o) {
  // A drilling run's length comes from its plan, its noise from its grade: these would be ignored.
  for (const char* option : {"--preset", "--rpm", "--profile", "--duration", "--count", "--snr-accel", "--snr-mag",
                             "--sigma-accel", "--sigma-gyro", "--accel-scale", "--accel-bias-temp", "--mag-bias",
                             "--mag-scale", "--mag-bias-temp", "--gyro-scale", "--temp", "--no-gyro", "--walk-length",
                             "--walk-climb"})
    require(!given(app, option), std::string(option) + " does not apply to --scenario " + o.scenario);
  sim::ImuGrade grade;
  try {
    grade = sim::ImuGrade::named(o.grade);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--grade: ") + e.what());
  }
  if (given(app, "--gyro-range")) {
    require(std::isfinite(o.gyro_range) && o.gyro_range > 0, "--gyro-range must be > 0 deg/s");
    grade.gyro_range_deg_s = o.gyro_range;
  }
  const double rate = given(app, "--rate-hz") ? o.rate_hz : 100.0;
  require(std::isfinite(rate) && rate > 0, "--rate-hz must be > 0");
  const auto seed = static_cast<std::uint64_t>(o.seed);
  sim::DrillingScenario s = o.scenario == "drilling" ? sim::DrillingScenario::reference(grade, rate, seed)
                                                     : sim::DrillingScenario::survey_stop_and_go(grade, rate, seed);
  if (given(app, "--tool-id")) s.tool_id = o.tool_id;
  if (given(app, "--inclination")) s.plan.inclination_deg = o.inclination_deg;
  if (given(app, "--azimuth")) s.plan.azimuth_deg = o.azimuth_deg;
  if (given(app, "--toolface")) s.plan.toolface_deg = o.toolface_deg;
  if (given(app, "--g")) s.g = o.g;
  if (given(app, "--field")) s.total_b = o.field;
  if (given(app, "--dip")) s.dip_deg = o.dip;
  if (given(app, "--latitude")) s.latitude_deg = o.latitude;
  if (given(app, "--sigma-mag")) s.magnetometer.sigma_uT = o.sigma_mag;
  if (given(app, "--gyro-bias")) s.gyro_bias = parse_triple("--gyro-bias", o.gyro_bias);
  if (given(app, "--accel-bias")) s.accel_bias = parse_triple("--accel-bias", o.accel_bias);
  s.magnetometer.present = !o.no_mag;
  for (const auto& text : o.mag_disturbances) {
    const auto parts = split(text, ':');
    require(parts.size() == 3, "--mag-disturbance: expected STOP:DELTA_UT:DELTA_DIP_DEG, got '" + text + "'");
    const double stop = option_number("--mag-disturbance", parts[0]);
    require(stop >= 0 && stop == std::floor(stop) && stop < 1e6, "--mag-disturbance: stop index '" + parts[0] +
                                                                      "' is not a whole number >= 0");
    s.magnetometer.disturbances.push_back({static_cast<std::size_t>(stop), option_number("--mag-disturbance", parts[1]),
                                           option_number("--mag-disturbance", parts[2])});
  }
  require(!o.no_mag || o.mag_disturbances.empty(), "--mag-disturbance needs a magnetometer (drop --no-mag)");
  s.depth.present = !o.no_depth;
  if (given(app, "--depth-noise")) s.depth.sigma_m = o.depth_noise;
  if (given(app, "--depth-step")) s.depth.quantum_m = o.depth_step;
  if (given(app, "--circulation-temp")) {
    const auto parts = split(o.circulation_temp, ':');
    require(parts.size() == 2, "--circulation-temp: expected MUD_C:FORMATION_C, got '" + o.circulation_temp + "'");
    s.temperature.enabled = true;
    s.temperature.circulating_c = s.temperature.start_c = option_number("--circulation-temp", parts[0]);
    s.temperature.formation_c = option_number("--circulation-temp", parts[1]);
  }
  s.vibration.lateral_rms = o.vibration_rms;
  s.vibration.frequency_hz = o.vibration_hz;
  s.vibration.band_hz = o.vibration_band;
  s.vibration.shock_rate_hz = o.shock_rate;
  s.vibration.shock_peak = o.shock_peak;
  require(s.tool_id.size() <= 31, "--tool-id: at most 31 characters");
  // The simulator's own checks (plan, grade, disturbances against the stops) with their message.
  const sim::DrillingSimulator checked(s);
  (void)checked;
  return s;
}

bool is_walk(const ScenarioOptions& o) { return o.scenario == "walk"; }

sim::WalkScenario make_walk_scenario(const CLI::App& app, const ScenarioOptions& o) {
  // A walk's length comes from its loop, its motion from the foot, its noise from its grade.
  for (const char* option : {"--preset", "--inclination", "--toolface", "--rpm", "--profile", "--duration", "--count",
                             "--snr-accel", "--snr-mag", "--sigma-accel", "--sigma-gyro", "--accel-scale",
                             "--accel-bias-temp", "--mag-bias", "--mag-scale", "--mag-bias-temp", "--gyro-scale",
                             "--temp", "--no-gyro", "--vibration", "--vibration-hz", "--shock-rate", "--shock-peak",
                             "--mag-disturbance", "--no-depth", "--depth-noise", "--depth-step", "--circulation-temp"})
    require(!given(app, option), std::string(option) + " does not apply to --scenario walk");
  sim::ImuGrade grade;
  try {
    grade = sim::ImuGrade::named(given(app, "--grade") ? o.grade : "mems");
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--grade: ") + e.what());
  }
  if (given(app, "--gyro-range")) {
    require(std::isfinite(o.gyro_range) && o.gyro_range > 0, "--gyro-range must be > 0 deg/s");
    grade.gyro_range_deg_s = o.gyro_range;
  }
  const double rate = given(app, "--rate-hz") ? o.rate_hz : 400.0;
  require(std::isfinite(rate) && rate > 0, "--rate-hz must be > 0");
  require(std::isfinite(o.walk_length) && o.walk_length > 0, "--walk-length must be > 0 m");
  require(!given(app, "--walk-climb") || (std::isfinite(o.walk_climb) && o.walk_climb >= 0),
          "--walk-climb must be >= 0 m");
  const auto seed = static_cast<std::uint64_t>(o.seed);
  sim::WalkScenario s;
  try {
    if (!given(app, "--walk-climb") && o.walk_length == 25)
      s = sim::WalkScenario::loop_25m(grade, rate, seed);
    else if (!given(app, "--walk-climb") && o.walk_length == 60)
      s = sim::WalkScenario::loop_60m(grade, rate, seed);
    else
      s = sim::WalkScenario::loop(o.walk_length, o.walk_climb, grade, rate, seed);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--walk-length/--walk-climb: ") + e.what());
  }
  if (given(app, "--tool-id")) s.tool_id = o.tool_id;
  if (given(app, "--azimuth")) s.heading_deg = o.azimuth_deg;
  if (given(app, "--g")) s.g = o.g;
  if (given(app, "--field")) s.total_b = o.field;
  if (given(app, "--dip")) s.dip_deg = o.dip;
  if (given(app, "--latitude")) s.latitude_deg = o.latitude;
  if (given(app, "--sigma-mag")) s.mag_sigma_uT = o.sigma_mag;
  if (given(app, "--gyro-bias")) s.gyro_bias = parse_triple("--gyro-bias", o.gyro_bias);
  if (given(app, "--accel-bias")) s.accel_bias = parse_triple("--accel-bias", o.accel_bias);
  s.magnetometer = !o.no_mag;
  require(s.tool_id.size() <= 31, "--tool-id: at most 31 characters");
  // The simulator's own checks (loop, grade, environment) with their message.
  const sim::WalkSimulator checked(s);
  (void)checked;
  return s;
}

}  // namespace plumb::sim_component
