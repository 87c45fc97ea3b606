// plumb's CDR against a DDS vendor's own: Fast DDS's generated type support (fastddsgen, fastcdr)
// serialises the same messages; the bytes must be identical, and Fast DDS must read plumb's bytes
// back to the same values. This is what makes a recording's messages the bytes on the wire.
#include <gtest/gtest.h>

#include <fastdds/rtps/common/SerializedPayload.h>

#include <cstring>
#include <vector>

#include "plumb/topics/all.hpp"
#include "plumb/topics/cdr.hpp"
#include "plumb_idl/attitudePubSubTypes.h"
#include "plumb_idl/sensorPubSubTypes.h"

namespace {

template <class PubSub, class Vendor> std::vector<std::uint8_t> fastdds_bytes(Vendor& message) {
  PubSub type;
  eprosima::fastrtps::rtps::SerializedPayload_t payload(type.getSerializedSizeProvider(&message)());
  EXPECT_TRUE(type.serialize(&message, &payload));
  return {payload.data, payload.data + payload.length};
}

template <class PubSub, class Vendor> Vendor fastdds_read(const std::vector<std::uint8_t>& bytes) {
  PubSub type;
  eprosima::fastrtps::rtps::SerializedPayload_t payload(static_cast<std::uint32_t>(bytes.size()));
  std::memcpy(payload.data, bytes.data(), bytes.size());
  payload.length = static_cast<std::uint32_t>(bytes.size());
  Vendor out;
  EXPECT_TRUE(type.deserialize(&payload, &out));
  return out;
}

TEST(CdrOnTheWire, SensorBatchIsWhatFastDdsWrites) {
  plumb::topics::SensorBatch ours;
  ours.tool_id = "T1";
  ours.calibration_id = "cal-7";
  plumb::msg::SensorBatch theirs;
  theirs.tool_id("T1");
  theirs.calibration_id("cal-7");
  for (int i = 0; i < 3; ++i) {
    plumb::topics::SensorSample s;
    s.seq = 100 + static_cast<std::uint64_t>(i);
    s.stamp_ns = -5 + i;
    s.fx = 0.25 * i;
    s.bz = 41.5;
    s.wz = -1e-3;
    s.temp_c = 25.5;
    s.flags = 0x180;
    ours.samples.push_back(s);
    plumb::msg::SensorSample v;
    v.seq(s.seq);
    v.stamp_ns(s.stamp_ns);
    v.fx(s.fx);
    v.bz(s.bz);
    v.wz(s.wz);
    v.temp_c(s.temp_c);
    v.flags(s.flags);
    theirs.samples().push_back(v);
  }
  std::vector<std::uint8_t> bytes;
  plumb::topics::cdr::serialize(ours, bytes);
  EXPECT_EQ(bytes, (fastdds_bytes<plumb::msg::SensorBatchPubSubType>(theirs)));
  const auto back = fastdds_read<plumb::msg::SensorBatchPubSubType, plumb::msg::SensorBatch>(bytes);
  EXPECT_EQ(back.calibration_id().to_string(), "cal-7");
  ASSERT_EQ(back.samples().size(), 3u);
  EXPECT_EQ(back.samples()[2].seq(), 102u);
  EXPECT_EQ(back.samples()[2].fx(), 0.5);
}

TEST(CdrOnTheWire, AttitudeIsWhatFastDdsWrites) {
  plumb::topics::Attitude ours;
  ours.tool_id = "tool";
  ours.estimator = "compensated";
  ours.window_start_ns = 1;
  ours.window_end_ns = 2000000000;
  ours.inclination_deg = 1.25;
  ours.azimuth_deg = 271.5;
  ours.samples_used = 1000;
  ours.flags = 7;
  ours.reason = "fine";
  plumb::msg::Attitude theirs;
  theirs.tool_id("tool");
  theirs.estimator("compensated");
  theirs.window_start_ns(1);
  theirs.window_end_ns(2000000000);
  theirs.inclination_deg(1.25);
  theirs.azimuth_deg(271.5);
  theirs.samples_used(1000);
  theirs.flags(7);
  theirs.reason("fine");
  std::vector<std::uint8_t> bytes;
  plumb::topics::cdr::serialize(ours, bytes);
  EXPECT_EQ(bytes, (fastdds_bytes<plumb::msg::AttitudePubSubType>(theirs)));
  EXPECT_EQ((fastdds_read<plumb::msg::AttitudePubSubType, plumb::msg::Attitude>(bytes).reason().to_string()), "fine");
}

}  // namespace
