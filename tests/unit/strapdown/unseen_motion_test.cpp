// Without depth or a pipe tally, a slide that starts smoothly and runs straight looks still to the
// sensors (unseen_motion.hpp): the position's sigma must grow as the slide it cannot rule out, and
// the attitude's must allow for the speed-up a stop hides; the rows and the log say that the pipe
// tally is the remedy. With depth or a tally, nothing changes.
#include <gtest/gtest.h>

#include "drilling_support.hpp"

namespace plumb::strapdown::test {
namespace {

// Four straight 8 m slides at 0.05 m/s (180 m/h) from I 60 deg, each starting and ending over
// ramp_s, with 60 s stops: no build, no turn, no vibration, so neither the accelerometers nor the
// gyros see the tool move once the ramp is too gentle for the stillness detector.
sim::DrillingScenario straight_slides(const char* grade, std::uint64_t seed, double ramp_s) {
  auto s = sim::DrillingScenario::reference(sim::ImuGrade::named(grade), 100, seed);
  s.plan.inclination_deg = 60;
  s.plan.ramp_s = ramp_s;
  s.plan.segments.clear();
  for (int k = 0; k < 4; ++k) {
    s.plan.segments.push_back(sim::DrillSegment::drill(8, 0.05, 0, 0));
    s.plan.segments.push_back(sim::DrillSegment::stop(60));
  }
  return s;
}

std::vector<Sample> without_depth(std::vector<Sample> samples) {
  for (Sample& x : samples) x.flags &= ~flags::kHasDepth;
  return samples;
}

std::vector<Estimate> navigate_unseen(const std::vector<Sample>& samples, const estimator::Parameters& params,
                               std::vector<std::string>* notices = nullptr) {
  Navigator nav(parse_parameters(params));
  std::vector<Estimate> rows;
  for (const Sample& s : samples) {
    nav.push(s, rows);
    if (notices != nullptr) {
      for (std::string& n : nav.take_notices()) notices->push_back(std::move(n));
    }
  }
  nav.flush(rows);
  return rows;
}

// Before (max_rop_m_per_h=0): the whole run one stop, the end 100 % of the 32 m off with
// RMS(error/sigma) 2637-2650, MEMS inclination 0.30-0.31 deg off with RMS(error/sigma) 1.99-2.04.
// After: the end as far off with RMS(error/sigma) 0.66, MEMS inclination 0.18-0.19 deg and 1.32-1.37.
TEST(StrapdownUnseenMotion, SmoothStraightSlidesWithoutDepth) {
  for (const char* grade : {"tactical", "mems"}) {
    for (std::uint64_t seed : {1, 2}) {
      const auto scenario = straight_slides(grade, seed, 15);
      const auto [samples, truth] = simulate(scenario);
      const std::vector<Sample> blind = without_depth(samples);
      const double drilled = sim::DrillingTrajectory(scenario.plan).drilled_length_m();
      estimator::Parameters params = parameters_for(scenario);
      const std::string label = std::string(grade) + " seed " + std::to_string(seed);
      params["max_rop_m_per_h"] = "0";
      const RunMetrics before = score_drilling(blind, truth, 100, drilled, params);
      params.erase("max_rop_m_per_h");
      std::map<std::string, std::uint64_t> counters;
      const RunMetrics after = score_drilling(blind, truth, 100, drilled, params, &counters);
      print((label + ", no allowance").c_str(), before);
      print((label + ", max_rop 180 m/h").c_str(), after);
      std::printf("  end RMS(error/sigma) %.1f -> %.2f\n", before.end_position_rms_z(), after.end_position_rms_z());
      EXPECT_EQ(counters.at("still_periods"), 1u) << label;  // every slide unseen
      EXPECT_GT(before.end_position_rms_z(), 100.0) << label;  // the fault
      EXPECT_GT(after.end_position_pct(), 90.0) << label;      // the slides stay unseen...
      EXPECT_LE(after.end_position_rms_z(), 3.0) << label;     // ...and the sigma says so
      for (int a = 0; a < 3; ++a) EXPECT_LE(after.rms_z_angle(a), 2.0) << label << " angle " << a;
      EXPECT_LE(after.max_attitude_err_deg(), std::string(grade) == "mems" ? 0.5 : 0.2) << label;
    }
  }
}

// The rows say so, and the log once, with the remedy.
TEST(StrapdownUnseenMotion, RowsAndNoticeNameThePipeTally) {
  const auto scenario = straight_slides("tactical", 1, 15);
  const auto [samples, truth] = simulate(scenario);
  std::vector<std::string> notices;
  const std::vector<Estimate> rows = navigate_unseen(without_depth(samples), parameters_for(scenario), &notices);
  ASSERT_FALSE(rows.empty());
  EXPECT_NE(rows.back().reason.find("pipe_joint_m or pipe_tally_m"), std::string::npos) << rows.back().reason;
  int said = 0;
  for (const std::string& n : notices) said += n.find("The remedy is the pipe tally") != std::string::npos ? 1 : 0;
  EXPECT_EQ(said, 1);
}

// Depth, or a pipe tally, measures the along-hole motion: every row as without the allowance.
TEST(StrapdownUnseenMotion, NothingChangesWithDepthOrATally) {
  const auto scenario = straight_slides("mems", 3, 15);
  const auto [samples, truth] = simulate(scenario);
  estimator::Parameters with_tally = parameters_for(scenario);
  with_tally["pipe_joint_m"] = "8";
  for (const auto& [input, params] : {std::pair{samples, parameters_for(scenario)}, std::pair{without_depth(samples), with_tally}}) {
    estimator::Parameters off = params;
    off["max_rop_m_per_h"] = "0";
    const std::vector<Estimate> a = navigate_unseen(input, params), b = navigate_unseen(input, off);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
      ASSERT_EQ(a[k].valid, b[k].valid) << k;
      if (!a[k].valid) continue;
      EXPECT_EQ(a[k].inclination_deg, b[k].inclination_deg) << k;
      EXPECT_EQ(a[k].navigation->position_m, b[k].navigation->position_m) << k;
      EXPECT_EQ(a[k].navigation->position_sd_m, b[k].navigation->position_sd_m) << k;
      EXPECT_EQ(a[k].reason, b[k].reason) << k;
    }
  }
}

}  // namespace
}  // namespace plumb::strapdown::test
