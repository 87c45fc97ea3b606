#include "payloads.hpp"

namespace native_fastdds {

void fill(plumb::msg::SensorBatch& batch) {
  batch.tool_id("bench-tool");
  batch.calibration_id("bench-calibration-0001");
  batch.samples().resize(plumb::msg::MAX_SAMPLES_PER_BATCH);
  for (std::size_t i = 0; i < batch.samples().size(); ++i) {
    auto& s = batch.samples()[i];
    s.seq(i);
    s.stamp_ns(static_cast<std::int64_t>(i) * 1'000'000);
    s.fx(0.1); s.fy(-0.2); s.fz(9.8);
    s.bx(20.0); s.by(5.0); s.bz(45.0);
    s.wx(0.001); s.wy(0.002); s.wz(6.28);
    s.temp_c(85.0);
    s.flags(plumb::msg::SAMPLE_HAS_GYRO | plumb::msg::SAMPLE_HAS_TEMPERATURE);
  }
}

void fill(plumb::msg::Attitude& attitude) {
  attitude.tool_id("bench-tool");
  attitude.estimator("bench-estimator");
  attitude.inclination_deg(30);
  attitude.azimuth_deg(120);
  attitude.samples_used(400);
  attitude.flags(plumb::msg::ATTITUDE_VALID);
}

}  // namespace native_fastdds
