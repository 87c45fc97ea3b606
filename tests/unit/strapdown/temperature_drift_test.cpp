// The navigator's temperature part (temperature_drift.hpp) against what it must do: readings
// corrected by exactly the stated coefficient times the change since the first reading; the bias
// noise it adds at least the coefficient's uncertainty times the change, squared, whatever the path,
// and nothing while the temperature holds; without coefficients no correction, the grade's typical
// one as the uncertainty, and one notice naming the parameters to give.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/strapdown/parameters.hpp"
#include "plumb/strapdown/temperature_drift.hpp"

namespace plumb::strapdown {
namespace {

constexpr double kTempDegPerHour = 3.14159265358979323846 / 180.0 / 3600.0;  // deg/h -> rad/s

TemperatureDrift drift_part_for(const NavigatorConfig& config) {
  TemperatureDrift part;
  part.reset(config);
  return part;
}

InputReading warm_reading(double t, double temp_c) {
  InputReading in;
  in.t = t;
  in.f = Eigen::Vector3d(0.1, -0.2, -9.8);
  in.w = Eigen::Vector3d(1e-5, 2e-5, -3e-5);
  in.temp_c = temp_c;
  return in;
}

// A ramp of the temperature from `from` to `to` over `seconds` at 100 Hz, epochs at 20 Hz: the
// bias variance the part adds (gyro, accelerometer).
std::pair<double, double> added_variance(TemperatureDrift& part, Counters& counters, double& t, double from, double to,
                                         double seconds) {
  double gyro = 0, accel = 0;
  const int n = static_cast<int>(seconds * 100);
  for (int k = 1; k <= n; ++k) {
    t += 0.01;
    InputReading in = warm_reading(t, from + (to - from) * k / n);
    part.correct(in, counters);
    if (k % 5 == 0) {
      const ProcessNoise noise = part.widen(ProcessNoise{}, 0.05);
      gyro += noise.gyro_bias_walk * noise.gyro_bias_walk * 0.05;
      accel += noise.accel_bias_walk * noise.accel_bias_walk * 0.05;
    }
  }
  return {gyro, accel};
}

TEST(TemperatureDrift, CorrectsByTheStatedCoefficient) {
  TemperatureDrift part = drift_part_for(parse_parameters(
      {{"imu_grade", "mems"}, {"gyro_bias_temp_dph_per_c", "0.2"}, {"accel_bias_temp_mg_per_c", "0.05"}}));
  Counters counters;
  InputReading first = warm_reading(0, 61.5);
  part.correct(first, counters);
  EXPECT_EQ(first.w, warm_reading(0, 0).w);  // the reference: nothing to correct
  InputReading later = warm_reading(1, 81.5);
  part.correct(later, counters);
  const InputReading raw = warm_reading(1, 81.5);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(raw.w[i] - later.w[i], 20 * 0.2 * kTempDegPerHour, 1e-18);
    EXPECT_NEAR(raw.f[i] - later.f[i], 20 * 0.05 * 9.80665e-3, 1e-13);
  }
  EXPECT_EQ(counters["temperature_readings"], 2u);
  EXPECT_EQ(counters["temperature_corrected"], 2u);
  const std::vector<std::string> notices = part.take_notices();
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_NE(notices[0].find("corrected"), std::string::npos);
}

TEST(TemperatureDrift, BiasNoiseCoversTheChangeSquaredAndNothingWhileItHolds) {
  TemperatureDrift part = drift_part_for(parse_parameters(
      {{"gyro_bias_temp_dph_per_c", "0.1"}, {"accel_bias_temp_mg_per_c", "0.02"}, {"bias_temp_sd", "0.3"}}));
  Counters counters;
  double t = 0;
  InputReading first = warm_reading(t, 60);
  part.correct(first, counters);
  const double sd_gyro = 0.3 * 0.1 * kTempDegPerHour, sd_accel = 0.3 * 0.02 * 9.80665e-3;
  // Warming by 30 degC: the error k' x 30 has variance sd^2 30^2; the part adds that (within the
  // mean's lag and its 0.1 degC steps) and not much more.
  const auto [gyro_up, accel_up] = added_variance(part, counters, t, 60, 90, 120);
  EXPECT_GT(gyro_up, sd_gyro * sd_gyro * 29.0 * 29.0);
  EXPECT_LT(gyro_up, sd_gyro * sd_gyro * 30.0 * 30.0 * 1.001);
  EXPECT_NEAR(accel_up / gyro_up, (sd_accel * sd_accel) / (sd_gyro * sd_gyro), 1e-6 * accel_up / gyro_up);
  // Holding (the mean settles within seconds, then nothing).
  added_variance(part, counters, t, 90, 90, 20);
  const auto [gyro_hold, accel_hold] = added_variance(part, counters, t, 90, 90, 60);
  EXPECT_EQ(gyro_hold, 0.0);
  EXPECT_EQ(accel_hold, 0.0);
  // Back down: the error returns to zero, but the filter may have learnt the bias at 90 degC, from
  // which it is off by k' x 30 again: the part adds the same again.
  const auto [gyro_down, accel_down] = added_variance(part, counters, t, 90, 60, 120);
  EXPECT_GT(gyro_down, sd_gyro * sd_gyro * 29.0 * 29.0);
  (void)accel_down;
}

TEST(TemperatureDrift, WithoutCoefficientsTheGradesWidenAndANoticeNamesTheParameters) {
  TemperatureDrift part = drift_part_for(parse_parameters({{"imu_grade", "mems"}}));
  Counters counters;
  double t = 0;
  InputReading first = warm_reading(t, 60);
  part.correct(first, counters);
  const auto [gyro, accel] = added_variance(part, counters, t, 60, 80, 60);
  const double sd_gyro = 0.2 * kTempDegPerHour;  // mems: the coefficient itself is the uncertainty
  EXPECT_GT(gyro, sd_gyro * sd_gyro * 19.0 * 19.0);
  EXPECT_LT(gyro, sd_gyro * sd_gyro * 20.0 * 20.0 * 1.001);
  (void)accel;
  InputReading last = warm_reading(t + 0.01, 80);
  part.correct(last, counters);
  EXPECT_EQ(last.w, warm_reading(0, 0).w);  // not corrected
  EXPECT_EQ(counters["temperature_corrected"], 0u);
  const std::vector<std::string> notices = part.take_notices();
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_NE(notices[0].find("gyro_bias_temp_dph_per_c"), std::string::npos);
  EXPECT_NE(notices[0].find("accel_bias_temp_mg_per_c"), std::string::npos);
  EXPECT_FALSE(part.row_warning().empty());
}

TEST(TemperatureDrift, IgnoredWhenAskedOrAbsent) {
  for (const bool ask_off : {true, false}) {
    NavigatorConfig config = parse_parameters({{"gyro_bias_temp_dph_per_c", "0.2"}});
    config.use_temperature = !ask_off;
    TemperatureDrift part = drift_part_for(config);
    Counters counters;
    for (int k = 0; k < 1000; ++k) {
      InputReading in = warm_reading(0.01 * k, 60 + 0.03 * k);
      if (!ask_off) in.temp_c.reset();
      part.correct(in, counters);
      EXPECT_EQ(in.w, warm_reading(0, 0).w);
      EXPECT_EQ(part.widen(ProcessNoise{}, 0.01).gyro_bias_walk, 0.0);
    }
    EXPECT_EQ(counters["temperature_readings"], 0u);
    EXPECT_TRUE(part.take_notices().empty());
  }
}

}  // namespace
}  // namespace plumb::strapdown
