// Copies between plumb's vendor-neutral topic types (messages.hpp) and the classes fastddsgen
// generates from idl/. to_fast() rejects what the IDL cannot carry (strings longer than their bound,
// more than kMaxSamplesPerBatch samples) with transport::Error instead of truncating silently.
#pragma once

#include "plumb/transport/messages.hpp"
#include "plumb_idl/attitude.h"
#include "plumb_idl/calibration.h"
#include "plumb_idl/sensor.h"
#include "plumb_idl/status.h"
#include "plumb_idl/truth.h"

namespace plumb::transport::fastdds {

void to_fast(const topics::SensorBatch& in, plumb::msg::SensorBatch& out);
void to_fast(const topics::Attitude& in, plumb::msg::Attitude& out);
void to_fast(const topics::CalibrationCoefficients& in, plumb::msg::CalibrationCoefficients& out);
void to_fast(const topics::ComponentStatus& in, plumb::msg::ComponentStatus& out);
void to_fast(const topics::Truth& in, plumb::msg::Truth& out);

void from_fast(const plumb::msg::SensorBatch& in, topics::SensorBatch& out);
void from_fast(const plumb::msg::Attitude& in, topics::Attitude& out);
void from_fast(const plumb::msg::CalibrationCoefficients& in, topics::CalibrationCoefficients& out);
void from_fast(const plumb::msg::ComponentStatus& in, topics::ComponentStatus& out);
void from_fast(const plumb::msg::Truth& in, topics::Truth& out);

}  // namespace plumb::transport::fastdds
