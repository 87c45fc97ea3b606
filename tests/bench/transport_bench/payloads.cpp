#include "payloads.hpp"

namespace plumb::bench {
namespace {

// XCDR1 (plain CDR) sizes: every primitive aligned to its own size, counted from the start of the
// serialized body; a string is a 4-byte length, its characters and a terminating NUL.
class CdrSize {
 public:
  void primitive(std::size_t size) {
    bytes_ = (bytes_ + size - 1) / size * size;
    bytes_ += size;
  }
  void string(const std::string& text) {
    primitive(4);
    bytes_ += text.size() + 1;
  }
  std::size_t bytes() const { return bytes_; }

 private:
  std::size_t bytes_ = 0;
};

}  // namespace

template <> topics::SensorBatch make_payload<topics::SensorBatch>() {
  topics::SensorBatch batch;
  batch.tool_id = "bench-tool";
  batch.calibration_id = "bench-calibration-0001";
  batch.samples.resize(topics::SensorBatch::kSamplesMax);
  for (std::size_t i = 0; i < batch.samples.size(); ++i) {
    auto& s = batch.samples[i];
    s.seq = i;
    s.stamp_ns = static_cast<std::int64_t>(i) * 1'000'000;
    s.fx = 0.1; s.fy = -0.2; s.fz = 9.8;
    s.bx = 20.0; s.by = 5.0; s.bz = 45.0;
    s.wx = 0.001; s.wy = 0.002; s.wz = 6.28;
    s.temp_c = 85.0;
    s.flags = topics::SAMPLE_HAS_GYRO | topics::SAMPLE_HAS_TEMPERATURE;
  }
  return batch;
}

template <> topics::Attitude make_payload<topics::Attitude>() {
  topics::Attitude attitude;
  attitude.tool_id = "bench-tool";
  attitude.estimator = "bench-estimator";
  attitude.inclination_deg = 30;
  attitude.azimuth_deg = 120;
  attitude.samples_used = 400;
  attitude.flags = topics::ATTITUDE_VALID;
  return attitude;
}

// The sequence number rides in the first sample's seq (batch) or in window_start_ns (attitude).
void set_seq(topics::SensorBatch& batch, std::uint64_t seq) { batch.samples.at(0).seq = seq; }
void set_seq(topics::Attitude& attitude, std::uint64_t seq) { attitude.window_start_ns = static_cast<std::int64_t>(seq); }
std::uint64_t get_seq(const topics::SensorBatch& batch) { return batch.samples.empty() ? 0 : batch.samples[0].seq; }
std::uint64_t get_seq(const topics::Attitude& attitude) { return static_cast<std::uint64_t>(attitude.window_start_ns); }

std::size_t serialized_size(const topics::SensorBatch& batch) {
  CdrSize size;
  size.string(batch.tool_id);
  size.string(batch.calibration_id);
  size.primitive(4);  // sequence length
  for (std::size_t i = 0; i < batch.samples.size(); ++i) {
    size.primitive(8);                                // seq
    size.primitive(8);                                // stamp_ns
    for (int d = 0; d < 10; ++d) size.primitive(8);   // f, b, w, temp_c
    size.primitive(4);                                // flags
  }
  return size.bytes();
}

std::size_t serialized_size(const topics::Attitude& attitude) {
  CdrSize size;
  size.string(attitude.tool_id);
  size.string(attitude.estimator);
  size.primitive(8);                               // window_start_ns
  size.primitive(8);                               // window_end_ns
  for (int d = 0; d < 11; ++d) size.primitive(8);  // inclination .. total_b
  size.primitive(4);                               // samples_used
  size.primitive(4);                               // flags
  size.string(attitude.reason);
  return size.bytes();
}

}  // namespace plumb::bench
