// One message of every topic type with every field set to a distinct, deterministic value
// (strings at their IDL bound, full sequences, negative and extreme finite numbers), so that a
// field lost, swapped or rounded on the way through a transport shows up as a difference.
#pragma once

#include <string>

#include "plumb/transport/messages.hpp"

namespace plumb::test {

topics::SensorBatch full_sensor_batch();   // 32 samples, strings at their bound
topics::SensorBatch empty_sensor_batch();  // no samples, empty strings: the other edge
topics::Attitude full_attitude();
topics::CalibrationCoefficients full_calibration();
topics::ComponentStatus full_status();  // 32 counters
topics::Truth full_truth();

// A printable string of exactly `length` characters, different for each `seed`.
std::string pattern_string(std::size_t length, unsigned seed);

// "field: expected X, got Y" for the first field (in IDL order, recursively) that differs; empty if equal.
std::string first_difference(const topics::SensorBatch& expected, const topics::SensorBatch& got);
std::string first_difference(const topics::Attitude& expected, const topics::Attitude& got);
std::string first_difference(const topics::CalibrationCoefficients& expected, const topics::CalibrationCoefficients& got);
std::string first_difference(const topics::ComponentStatus& expected, const topics::ComponentStatus& got);
std::string first_difference(const topics::Truth& expected, const topics::Truth& got);

// One line describing an attitude exactly as examples/c_attitude_listener prints it.
std::string attitude_line(const topics::Attitude& a);

}  // namespace plumb::test
