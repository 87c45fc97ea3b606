// Which coefficients a bridge applies (tool id and units, docs/calibration.md "Binding") and the
// |G| check that stops a calibrated stream whose coefficients were made for other units.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "calibration_binding.hpp"

namespace plumb::bridge_component {
namespace {

CalibrationModel coefficients(const std::string& tool, const std::string& accel_units = "",
                              const std::string& mag_units = "") {
  CalibrationModel m;
  m.tool_id = tool;
  m.calibration_id = "cal-1";
  m.accel_units = accel_units;
  m.mag_units = mag_units;
  return m;
}

TEST(CalibrationBinding, SameToolIsApplied) {
  EXPECT_EQ(binding_problem(coefficients("T1"), BindingRule{"T1"}), "");
}

TEST(CalibrationBinding, OtherToolIsRefusedNamingBothIds) {
  const auto p = binding_problem(coefficients("sim-turntable"), BindingRule{"board"});
  EXPECT_NE(p.find("'sim-turntable'"), std::string::npos) << p;
  EXPECT_NE(p.find("'board'"), std::string::npos) << p;
  EXPECT_NE(p.find("refused"), std::string::npos) << p;
  EXPECT_EQ(p.find('\n'), std::string::npos) << "one line";
}

TEST(CalibrationBinding, CoefficientsWithoutToolNeverMatchSilently) {
  const auto p = binding_problem(coefficients(""), BindingRule{"board"});
  EXPECT_NE(p.find("names no tool"), std::string::npos) << p;
  EXPECT_NE(p.find("--calibration-any-tool"), std::string::npos) << p;
}

TEST(CalibrationBinding, AnyToolIsAnExplicitOptIn) {
  BindingRule rule{"board"};
  rule.any_tool = true;
  EXPECT_EQ(binding_problem(coefficients(""), rule), "");
  EXPECT_EQ(binding_problem(coefficients("T9"), rule), "");
}

TEST(CalibrationBinding, StatedUnitsMustBeTheStreams) {
  EXPECT_EQ(binding_problem(coefficients("T1", "m/s2", "uT"), BindingRule{"T1"}), "");
  const auto p = binding_problem(coefficients("T1", "V", "counts"), BindingRule{"T1"});
  EXPECT_NE(p.find("V"), std::string::npos) << p;
  EXPECT_NE(p.find("m/s2"), std::string::npos) << p;
  // any_tool does not lift the units rule.
  BindingRule any{"T1"};
  any.any_tool = true;
  EXPECT_NE(binding_problem(coefficients("T1", "V"), any), "");
  BindingRule volts{"T1", false, "V", "counts"};
  EXPECT_EQ(binding_problem(coefficients("T1", "V", "counts"), volts), "");
  EXPECT_NE(binding_problem(coefficients("T1", "V", "uT"), volts), "");
}

TEST(CalibrationBinding, UnstatedUnitsAreLeftToTheGravityCheck) {
  EXPECT_EQ(binding_problem(coefficients("T1"), BindingRule{"T1"}), "");
}

std::vector<Sample> samples_with_norm(double norm, int n, double rpm = 0) {
  std::vector<Sample> out;
  for (int i = 0; i < n; ++i) {
    Sample s;
    const double a = 2 * M_PI * rpm / 60 * i * 0.01;  // turning about z at 100 Hz
    const Eigen::Vector3d f(0.3 * std::cos(a), 0.3 * std::sin(a), std::sqrt(1 - 0.09));
    s.f = norm * f;
    out.push_back(s);
  }
  return out;
}

TEST(GravityCheck, PendingUntilAWindowIsFull) {
  GravityCheck check(9.80665, 0.2, 100);
  EXPECT_EQ(check.add(samples_with_norm(9.8, 99)), GravityCheck::Verdict::Pending);
  EXPECT_EQ(check.add(samples_with_norm(9.8, 1)), GravityCheck::Verdict::Ok);
}

TEST(GravityCheck, VoltsCoefficientsOnAMetresPerSecondSquaredStreamFail) {
  GravityCheck check;
  EXPECT_EQ(check.add(samples_with_norm(38.8, 100)), GravityCheck::Verdict::Failed);
  EXPECT_NEAR(check.measured(), 38.8, 1e-9);
  EXPECT_NE(check.reason().find("38.8"), std::string::npos) << check.reason();
  // Final until new coefficients reset it.
  EXPECT_EQ(check.add(samples_with_norm(9.8, 200)), GravityCheck::Verdict::Failed);
  check.reset();
  EXPECT_EQ(check.add(samples_with_norm(9.8, 100)), GravityCheck::Verdict::Ok);
}

TEST(GravityCheck, TheOtherWayRoundFailsToo) {
  GravityCheck check;
  EXPECT_EQ(check.add(samples_with_norm(9.80665 * 0.25, 100)), GravityCheck::Verdict::Failed);
}

TEST(GravityCheck, RotationDoesNotChangeTheNorm) {
  GravityCheck check;
  EXPECT_EQ(check.add(samples_with_norm(9.80665, 500, 120)), GravityCheck::Verdict::Ok);
}

TEST(GravityCheck, ShocksAndUnusableSamplesDoNotDecide) {
  GravityCheck check;
  auto s = samples_with_norm(9.80665, 100);
  for (int i = 0; i < 30; ++i) s[static_cast<std::size_t>(3 * i)].f *= 5;  // shocks in 30 % of the samples
  auto bad = samples_with_norm(100, 50);
  for (auto& b : bad) b.flags |= flags::kAccelSaturated;
  EXPECT_EQ(check.add(bad), GravityCheck::Verdict::Pending);
  EXPECT_EQ(check.add(s), GravityCheck::Verdict::Ok);
}

TEST(GravityCheck, FinishJudgesAShortStream) {
  GravityCheck check;
  check.add(samples_with_norm(38.8, 10));
  EXPECT_EQ(check.finish(), GravityCheck::Verdict::Failed);
}

}  // namespace
}  // namespace plumb::bridge_component
