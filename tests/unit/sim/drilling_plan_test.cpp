// Drilling plans: lengths and durations, the named scenarios, and the refusal of bad parameters
// with a message that names them.
#include <string>

#include <gtest/gtest.h>

#include "plumb/sim/drilling.hpp"

namespace plumb::sim {
namespace {

TEST(DrillingPlan, LengthOrDurationIncludesTheRamps) {
  DrillingPlan p;
  p.alignment_s = 10;
  p.ramp_s = 4;
  DrillSegment by_duration = DrillSegment::drill(0, 0.1);
  by_duration.duration_s = 24;
  p.segments = {DrillSegment::drill(2, 0.1), DrillSegment::stop(5), by_duration};
  const DrillingTrajectory tr(p);
  // 2 m at 0.1 m/s: 20 s cruising-equivalent plus one ramp length; 24 s: (24 - 4) x 0.1 = 2 m.
  EXPECT_DOUBLE_EQ(tr.duration_s(), 10 + 24 + 5 + 24);
  EXPECT_NEAR(tr.drilled_length_m(), 4.0, 1e-12);
  EXPECT_TRUE(tr.still_at(5));
  EXPECT_FALSE(tr.still_at(20));
  EXPECT_TRUE(tr.still_at(36));
  EXPECT_TRUE(tr.still_at(1000));  // past the end the tool stays
  EXPECT_NEAR(tr.at(1000).depth_m, 4.0, 1e-12);
}

TEST(DrillingPlan, NamedScenarios) {
  const DrillingScenario ref = DrillingScenario::reference(ImuGrade::tactical(), 10, 3);
  EXPECT_DOUBLE_EQ(ref.duration_s(), 960.0);
  EXPECT_EQ(DrillingSimulator(ref).sample_count(), 9600u);
  EXPECT_EQ(ref.grade.name, "tactical");
  EXPECT_EQ(ref.seed, 3u);
  const DrillingScenario survey = DrillingScenario::survey_stop_and_go(ImuGrade::mems());
  EXPECT_DOUBLE_EQ(survey.duration_s(), 60 + 6 * (35 + 30));
  const std::string line = describe(ref);
  for (const char* part : {"drilling-reference", "960 s", "10 Hz", "4 drilling segment(s) (2 rotary)", "32 m",
                           "4 stop(s)", "tactical", "seed 3"})
    EXPECT_NE(line.find(part), std::string::npos) << part << " not in: " << line;
}

void expect_refused(const DrillingScenario& s, const std::string& words) {
  try {
    DrillingSimulator sim(s);
    ADD_FAILURE() << "accepted a scenario that should fail with '" << words << "'";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(DrillingPlan, BadParametersAreRefusedReadably) {
  const DrillingScenario good = DrillingScenario::reference(ImuGrade::tactical());
  auto with = [&](auto change) {
    DrillingScenario s = good;
    change(s);
    return s;
  };
  expect_refused(with([](auto& s) { s.plan.ramp_s = 0; }), "speed ramp");
  expect_refused(with([](auto& s) { s.plan.inclination_deg = 190; }), "inclination");
  expect_refused(with([](auto& s) { s.plan.segments[0].rop_mps = 0; }), "segment 1 (drill): rate of penetration");
  expect_refused(with([](auto& s) { s.plan.segments[0].length_m = 0.1; }), "segment 1 (drill): too short");
  expect_refused(with([](auto& s) { s.plan.segments[0].duration_s = 100; }), "not both");
  expect_refused(with([](auto& s) { s.plan.segments[1].duration_s = 0; }), "segment 2 (stop): duration");
  expect_refused(with([](auto& s) { s.plan.segments[0].rpm = 60; }), "rotary");
  expect_refused(with([](auto& s) { s.plan.segments[0].build_deg_per_30m = 400; }), "leaves [0, 180]");
  expect_refused(with([](auto& s) { s.plan.segments.clear(); s.plan.alignment_s = 0; }), "empty");
  expect_refused(with([](auto& s) { s.sample_rate_hz = 0; }), "sample rate");
  expect_refused(with([](auto& s) { s.latitude_deg = 95; }), "latitude");
  expect_refused(with([](auto& s) { s.grade.gyro_arw_deg_rt_h = -1; }), "noise densities");
  expect_refused(with([](auto& s) { s.grade.gyro_range_deg_s = NAN; }), "gyro range");
  expect_refused(with([](auto& s) { s.magnetometer.sigma_uT = -0.1; }), "magnetometer noise");
  expect_refused(with([](auto& s) { s.depth.quantum_m = -1; }), "depth");
  expect_refused(with([](auto& s) { s.vibration.frequency_hz = 0; }), "vibration frequency");
  expect_refused(with([](auto& s) { s.gyro_bias = Eigen::Vector3d(0, NAN, 0); }), "gyro bias");
}

}  // namespace
}  // namespace plumb::sim
