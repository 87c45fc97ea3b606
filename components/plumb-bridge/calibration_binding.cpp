#include "calibration_binding.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace plumb::bridge_component {

namespace {
std::string id_of(const CalibrationModel& m) { return m.calibration_id.empty() ? "unnamed" : m.calibration_id; }

std::string units_problem(const CalibrationModel& m, const char* what, const std::string& stated,
                          const std::string& stream, const char* option) {
  if (stated.empty() || stated == stream) return {};
  return "calibration '" + id_of(m) + "' was made for a package whose " + what + " send " + stated +
         ", this bridge's stream is in " + stream + ": refused (use coefficients made for this package, or state the "
         "stream's units with " + option + ")";
}
}  // namespace

std::string binding_problem(const CalibrationModel& m, const BindingRule& rule) {
  if (!rule.any_tool) {
    if (m.tool_id.empty())
      return "calibration '" + id_of(m) + "' names no tool, this bridge is tool '" + rule.tool_id +
             "': refused (write the tool id into the coefficients, plumb-calibrate --tool-id " + rule.tool_id +
             ", or pass --calibration-any-tool)";
    if (m.tool_id != rule.tool_id)
      return "calibration '" + id_of(m) + "' is for tool '" + m.tool_id + "', this bridge is tool '" + rule.tool_id +
             "': refused (start the bridge with --tool-id " + m.tool_id + " if it reads that tool)";
  }
  if (auto p = units_problem(m, "accelerometers", m.accel_units, rule.accel_units, "--accel-units"); !p.empty()) return p;
  return units_problem(m, "magnetometers", m.mag_units, rule.mag_units, "--mag-units");
}

std::string describe_coefficients(const CalibrationModel& m, const std::string& source) {
  return "calibration '" + id_of(m) + "' (tool '" + m.tool_id + "', accel " +
         (m.accel_units.empty() ? "units not stated" : m.accel_units) + ", mag " +
         (m.mag_units.empty() ? "units not stated" : m.mag_units) + ") from " + source;
}

GravityCheck::GravityCheck(double g, double tolerance, std::size_t window)
    : g_(g), tolerance_(tolerance), window_(std::max<std::size_t>(window, 1)) {}

GravityCheck::Verdict GravityCheck::add(const std::vector<Sample>& calibrated) {
  for (const auto& s : calibrated) {
    if (verdict_ == Verdict::Failed) break;
    if ((s.flags & flags::kUnusable) || !s.f.allFinite()) continue;
    norms_.push_back(s.f.norm());
    if (norms_.size() >= window_) judge();
  }
  return verdict_;
}

GravityCheck::Verdict GravityCheck::finish() {
  if (verdict_ != Verdict::Failed && !norms_.empty()) judge();
  return verdict_;
}

void GravityCheck::reset() {
  norms_.clear();
  verdict_ = Verdict::Pending;
  measured_ = 0;
}

GravityCheck::Verdict GravityCheck::judge() {
  auto mid = norms_.begin() + static_cast<std::ptrdiff_t>(norms_.size() / 2);
  std::nth_element(norms_.begin(), mid, norms_.end());
  measured_ = *mid;
  norms_.clear();
  verdict_ = std::abs(measured_ - g_) <= tolerance_ * g_ ? Verdict::Ok : Verdict::Failed;
  return verdict_;
}

std::string GravityCheck::reason() const {
  if (verdict_ != Verdict::Failed) return {};
  std::ostringstream out;
  out.precision(3);
  out << "calibrated |G| = " << measured_ << " m/s^2, expected " << g_ << " +- " << tolerance_ * 100
      << " %: coefficients do not fit this stream's units; calibrated stream stopped";
  return out.str();
}

}  // namespace plumb::bridge_component
