// Which coefficients a bridge may apply (docs/calibration.md "Binding"), and the check of the
// calibrated stream that catches coefficients made for a package with other output units.
// Pure logic, no DDS: the publisher asks, the unit tests call it directly.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "plumb/core/calibration_model.hpp"
#include "plumb/core/sample.hpp"

namespace plumb::bridge_component {

struct BindingRule {
  std::string tool_id;          // the bridge's own tool id (never empty)
  bool any_tool = false;        // --calibration-any-tool: apply coefficients of any tool, or of none
  std::string accel_units = "m/s2";  // units of the stream's f channels (docs/protocol.md: m/s2)
  std::string mag_units = "uT";      // units of the stream's b channels
};

// Empty when `m` may be applied; otherwise one line naming what is wrong and what to do.
// Coefficients that name no tool are refused unless any_tool: an empty id on either side must
// never match silently. Stated units must equal the stream's; unstated units (files written
// before the units lines) pass here and are left to the GravityCheck.
std::string binding_problem(const CalibrationModel& m, const BindingRule& rule);

// "calibration 'ID' (tool 'T', accel V, mag counts) from SOURCE": how every log line names them.
std::string describe_coefficients(const CalibrationModel& m, const std::string& source);

// |f| of the calibrated stream against g. |f| of the accelerometer triad does not change when the
// tool turns, so the check holds on the rotating platform: the centripetal acceleration at the
// sensors (w^2 r: 1.6 m/s^2 at 120 rpm and 1 cm from the axis) is radial and adds to g in
// quadrature in a near-vertical hole (+1.3 %), and the median of |f| over the window ignores
// shocks. A units mismatch is a factor (0.25 V per m/s^2 gives 38.8 instead of 9.8), far beyond
// the default tolerance of 20 %.
class GravityCheck {
 public:
  enum class Verdict { Pending, Ok, Failed };
  GravityCheck(double g = 9.80665, double tolerance = 0.2, std::size_t window = 100);
  // Feeds calibrated samples (unusable ones are skipped). Every full window is judged; a failure
  // is final until reset().
  Verdict add(const std::vector<Sample>& calibrated);
  // End of stream: judges what the open window holds, if anything.
  Verdict finish();
  void reset();
  Verdict verdict() const { return verdict_; }
  double measured() const { return measured_; }  // median |f| of the last judged window
  // One line: "calibrated |G| = 38.8 m/s^2, expected 9.81 +- 20 %: ..." (empty unless Failed).
  std::string reason() const;

 private:
  Verdict judge();
  double g_, tolerance_;
  std::size_t window_;
  std::vector<double> norms_;
  Verdict verdict_ = Verdict::Pending;
  double measured_ = 0;
};

}  // namespace plumb::bridge_component
