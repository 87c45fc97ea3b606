#include "messages/flag_names.hpp"

#include <cstdio>

namespace plumb::cli {

namespace {
// The prefix of each IDL constant (ATTITUDE_, SAMPLE_, NAVIGATION_) is left out: the field says whose.
constexpr FlagName kAttitude[] = {{topics::ATTITUDE_VALID, "VALID"},
                                  {topics::ATTITUDE_AZIMUTH_VALID, "AZIMUTH_VALID"},
                                  {topics::ATTITUDE_TOOLFACE_VALID, "TOOLFACE_VALID"},
                                  {topics::ATTITUDE_ROTATING, "ROTATING"},
                                  {topics::ATTITUDE_PARTIAL_WINDOW, "PARTIAL_WINDOW"}};
constexpr FlagName kSample[] = {{topics::SAMPLE_ACCEL_SATURATED, "ACCEL_SATURATED"},
                                {topics::SAMPLE_MAG_SATURATED, "MAG_SATURATED"},
                                {topics::SAMPLE_GYRO_SATURATED, "GYRO_SATURATED"},
                                {topics::SAMPLE_OUT_OF_RANGE, "OUT_OF_RANGE"},
                                {topics::SAMPLE_NOT_FINITE, "NOT_FINITE"},
                                {topics::SAMPLE_GAP_BEFORE, "GAP_BEFORE"},
                                {topics::SAMPLE_TIME_BACKWARDS, "TIME_BACKWARDS"},
                                {topics::SAMPLE_HAS_GYRO, "HAS_GYRO"},
                                {topics::SAMPLE_HAS_TEMPERATURE, "HAS_TEMPERATURE"},
                                {topics::SAMPLE_CALIBRATED, "CALIBRATED"},
                                {topics::SAMPLE_TEMPERATURE_OUT_OF_RANGE, "TEMPERATURE_OUT_OF_RANGE"},
                                {topics::SAMPLE_NO_MAGNETOMETER, "NO_MAGNETOMETER"}};
constexpr FlagName kNavigation[] = {{topics::NAVIGATION_VALID, "VALID"},
                                    {topics::NAVIGATION_STILL, "STILL"},
                                    {topics::NAVIGATION_ALIGNED, "ALIGNED"},
                                    {topics::NAVIGATION_AZIMUTH_VALID, "AZIMUTH_VALID"},
                                    {topics::NAVIGATION_DEPTH_AIDED, "DEPTH_AIDED"}};
}  // namespace

template <> std::span<const FlagName> flag_names<topics::Attitude>() { return kAttitude; }
template <> std::span<const FlagName> flag_names<topics::SensorSample>() { return kSample; }
template <> std::span<const FlagName> flag_names<topics::Navigation>() { return kNavigation; }

std::string describe_flags(std::span<const FlagName> names, std::uint32_t flags) {
  if (flags == 0) return "none";
  std::string text;
  std::uint32_t known = 0;
  for (const auto& f : names) {
    known |= f.bit;
    if (flags & f.bit) text += (text.empty() ? "" : ", ") + std::string(f.name);
  }
  if (const std::uint32_t rest = flags & ~known) {
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%x", rest);
    text += (text.empty() ? "" : ", ") + std::string(hex);
  }
  return text;
}

}  // namespace plumb::cli
