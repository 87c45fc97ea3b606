// Text form of a rotation profile, as given on command lines: "60", "ramp:0:120:5",
// "stopgo:60:4", "stickslip:60:2".
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "plumb/core/number.hpp"
#include "plumb/sim/platform.hpp"

namespace plumb::sim {
namespace {

const char* const kAccepted =
    "accepted: RPM (constant), ramp:START_RPM:END_RPM:SECONDS, stopgo:MEAN_RPM:PERIOD_S, "
    "stickslip:MEAN_RPM:PERIOD_S";

[[noreturn]] void fail(const std::string& text, const std::string& why) {
  throw std::invalid_argument("bad rotation profile '" + text + "': " + why + " (" + kAccepted + ")");
}

double number(const std::string& text, const std::string& field, const std::string& what) {
  const auto v = parse_number(field, true);
  if (!v) fail(text, what + " '" + field + "' is not a number");
  if (!std::isfinite(*v)) fail(text, what + " must be finite");
  return *v;
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const auto colon = s.find(':', start);
    parts.push_back(s.substr(start, colon - start));
    if (colon == std::string::npos) return parts;
    start = colon + 1;
  }
}

}  // namespace

RotationProfile parse_profile(const std::string& text) {
  if (text.empty()) fail(text, "empty");
  const auto parts = split(text);
  RotationProfile p;
  const std::string& kind = parts[0];
  if (parts.size() == 1) {
    p.kind = ProfileKind::Constant;
    p.rpm = number(text, kind, "speed");
    return p;
  }
  auto expect = [&](std::size_t n) {
    if (parts.size() != n) fail(text, kind + " takes " + std::to_string(n - 1) + " values separated by ':'");
  };
  if (kind == "ramp") {
    expect(4);
    p.kind = ProfileKind::Ramp;
    p.rpm = number(text, parts[1], "start speed");
    p.rpm_end = number(text, parts[2], "end speed");
    p.ramp_s = number(text, parts[3], "ramp duration");
    if (p.ramp_s <= 0) fail(text, "ramp duration must be > 0 s");
  } else if (kind == "stopgo" || kind == "stickslip") {
    expect(3);
    p.kind = kind == "stopgo" ? ProfileKind::StopAndGo : ProfileKind::StickSlip;
    p.rpm = number(text, parts[1], "mean speed");
    p.period_s = number(text, parts[2], "period");
    if (p.period_s <= 0) fail(text, "period must be > 0 s");
  } else {
    fail(text, "unknown kind '" + kind + "'");
  }
  return p;
}

}  // namespace plumb::sim
