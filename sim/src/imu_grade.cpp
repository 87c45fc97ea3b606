// The named IMU grades (values tabled in imu_model.hpp, read from the vocabulary's table that the
// navigator's imu_grade presets and the survey's model of its stations read too:
// plumb/core/imu_grade.hpp), their conversion to SI units and their one-line description.
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "plumb/core/attitude.hpp"
#include "plumb/core/imu_grade.hpp"
#include "plumb/sim/imu_model.hpp"

namespace plumb::sim {
namespace {

constexpr double kSecondsPerHour = 3600.0;
constexpr double kMilliG = 9.80665e-3;  // m/s^2, standard gravity / 1000

ImuGrade make(const char* name, double gyro_bias, double arw, double accel_bias, double vrw, double range,
              double gyro_temp = 0, double accel_temp = 0) {
  ImuGrade g;
  g.name = name;
  g.gyro_bias_deg_h = gyro_bias;
  g.gyro_arw_deg_rt_h = arw;
  g.accel_bias_mg = accel_bias;
  g.accel_vrw_mps_rt_h = vrw;
  g.gyro_range_deg_s = range;
  g.gyro_bias_temp_dph_per_c = gyro_temp;
  g.accel_bias_temp_mg_per_c = accel_temp;
  return g;
}

ImuGrade from_table(const char* name) {
  const ImuGradeFigures& f = *find_imu_grade(name);
  return make(f.name, f.gyro_bias_dph, f.gyro_arw_deg_rt_h, f.accel_bias_mg, f.accel_vrw_mps_rt_h, f.gyro_range_dps,
              f.gyro_temp_dph_c, f.accel_temp_mg_c);
}

}  // namespace

// The temperature coefficients are the residuals a datasheet states after the part's own
// compensation: a few thousandths of a deg/h and of a mg per degC for navigation-grade parts;
// 0.05 deg/h/degC for a survey tool's fibre-optic gyro and 10 ug/degC for a quartz accelerometer;
// 0.2 deg/h/degC and 0.05 mg/degC for an industrial MEMS unit (the order of ADIS1649x-class sheets).
// Ring-laser / high-end fibre-optic gyros and servo accelerometers: enough to gyrocompass.
ImuGrade ImuGrade::navigation() { return from_table("navigation"); }
// Fibre-optic gyros and quartz accelerometers of gyro survey and MWD tools.
ImuGrade ImuGrade::tactical() { return from_table("tactical"); }
// Industrial MEMS (the source's class of sensor).
ImuGrade ImuGrade::mems() { return from_table("mems"); }
ImuGrade ImuGrade::perfect() { return make("perfect", 0, 0, 0, 0, 0); }

ImuGrade ImuGrade::named(const std::string& name) {
  if (name == "navigation") return navigation();
  if (name == "tactical") return tactical();
  if (name == "mems") return mems();
  if (name == "perfect") return perfect();
  throw std::invalid_argument("unknown IMU grade '" + name + "' (navigation, tactical, mems or perfect)");
}

double ImuGrade::gyro_bias_sigma() const { return gyro_bias_deg_h * kDeg / kSecondsPerHour; }

double ImuGrade::accel_bias_sigma() const { return accel_bias_mg * kMilliG; }

// A density per sqrt(hour) is density / 60 per sqrt(second); white noise of that density sampled
// every dt has sigma = density / sqrt(dt).
double ImuGrade::gyro_bias_temp() const { return gyro_bias_temp_dph_per_c * kDeg / kSecondsPerHour; }

double ImuGrade::accel_bias_temp() const { return accel_bias_temp_mg_per_c * kMilliG; }

double ImuGrade::gyro_noise_sigma(double dt) const {
  return gyro_arw_deg_rt_h * kDeg / std::sqrt(kSecondsPerHour) / std::sqrt(dt);
}

double ImuGrade::accel_noise_sigma(double dt) const {
  return accel_vrw_mps_rt_h / std::sqrt(kSecondsPerHour) / std::sqrt(dt);
}

double ImuGrade::gyro_range() const {
  return gyro_range_deg_s > 0 ? gyro_range_deg_s * kDeg : std::numeric_limits<double>::infinity();
}

double ImuGrade::accel_range() const {
  return accel_range_g > 0 ? accel_range_g * kMilliG * 1000.0 : std::numeric_limits<double>::infinity();
}

std::string describe(const ImuGrade& g) {
  std::ostringstream out;
  out << g.name << " IMU (gyro bias " << g.gyro_bias_deg_h << " deg/h, ARW " << g.gyro_arw_deg_rt_h
      << " deg/sqrt(h), accel bias " << g.accel_bias_mg << " mg, VRW " << g.accel_vrw_mps_rt_h << " m/s/sqrt(h), ";
  if (g.gyro_range_deg_s > 0)
    out << "range " << g.gyro_range_deg_s << " deg/s)";
  else
    out << "unlimited range)";
  if (g.accel_range_g > 0) out << ", accelerometers +-" << g.accel_range_g << " g";
  return out.str();
}

}  // namespace plumb::sim
