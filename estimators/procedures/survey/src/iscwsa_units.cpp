// The units of a tool code's magnitudes: each weighting function takes its magnitude in one unit
// (the one ISCWSA's and OWSG's tables use); a user's tool code may give another unit of the same
// quantity, never one of another quantity (a magnitude in furlongs, or in nT for a sag term, would
// otherwise be taken as if it were in the model's unit, and the survey priced with it in silence).
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "plumb/survey/iscwsa.hpp"

namespace plumb::survey::iscwsa {
namespace {

struct UnitFactor {
  const char* unit;
  double to_model;  // magnitude in the model's unit per magnitude in `unit`
};

constexpr double kPi = 3.14159265358979323846;
constexpr double kStandardGravity = 9.80665;

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }
bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The accepted spellings of each model unit, the model unit first.
const std::vector<UnitFactor>& spellings(const std::string& model) {
  static const std::vector<std::pair<std::string, std::vector<UnitFactor>>> table{
      {"m", {{"m", 1}, {"ft", 0.3048}}},
      {"1/m", {{"1/m", 1}, {"1/ft", 1 / 0.3048}}},
      {"-", {{"-", 1}, {"ppm", 1e-6}, {"%", 1e-2}}},
      {"m/s2", {{"m/s2", 1}, {"m/s^2", 1}, {"mg", kStandardGravity * 1e-3}, {"ug", kStandardGravity * 1e-6}}},
      {"nT", {{"nT", 1}, {"uT", 1e3}}},
      {"deg", {{"deg", 1}, {"rad", 180 / kPi}, {"mrad", 0.18 / kPi}}},
      {"deg.nT", {{"deg.nT", 1}}},
      {"deg/hr", {{"deg/hr", 1}, {"deg/h", 1}}},
      {"deg/sqrt(hr)", {{"deg/sqrt(hr)", 1}, {"deg/sqr(hr)", 1}, {"deg/sqrt(h)", 1}}},
  };
  for (const auto& [name, units] : table)
    if (name == model) return units;
  throw std::logic_error("no spellings for unit " + model);
}

}  // namespace

std::string model_unit(const std::string& wf) {
  if (!known_weight_function(wf)) return {};
  if (wf == "DREF") return "m";
  if (wf == "DST") return "1/m";
  if (wf == "DBH") return "deg.nT";
  if (ends_with(wf, "-MIS")) return "deg";  // the gyro model's misalignments
  // The gyro model's accelerometer terms (AXY-, AXYZ-): biases, unless a scale factor.
  if (starts_with(wf, "AB") || ((starts_with(wf, "AXY-") || starts_with(wf, "AXYZ-")) && !ends_with(wf, "-SF")))
    return "m/s2";
  if (starts_with(wf, "MB") || wf == "AMIL") return "nT";
  if (wf == "DSF" || starts_with(wf, "AS") || starts_with(wf, "MS") || ends_with(wf, "-SF") || wf == "XCLA" ||
      wf == "XCLH")
    return "-";
  if (ends_with(wf, "-GRW")) return "deg/sqrt(hr)";
  if (starts_with(wf, "GXY") || starts_with(wf, "GZ")) return "deg/hr";
  return "deg";  // AZ, SAG, SAGE, XYM*, EXT-REF, EXT-TIE and the declinations
}

double to_model_unit(const std::string& wf, double magnitude, const std::string& unit) {
  const std::string model = model_unit(wf);
  if (model.empty()) throw std::invalid_argument("unknown weighting function '" + wf + "'");
  std::string accepted;
  for (const UnitFactor& u : spellings(model)) {
    if (unit == u.unit) return magnitude * u.to_model;
    accepted += (accepted.empty() ? "" : ", ") + std::string(u.unit);
  }
  throw std::invalid_argument("unit '" + unit + "' for " + wf + ": its magnitude is in " + model + " (accepted: " +
                              accepted + ")");
}

}  // namespace plumb::survey::iscwsa
