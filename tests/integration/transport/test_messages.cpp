#include "test_messages.hpp"

namespace plumb::test {

double Distinct::real() {
  switch (reals_++) {
    case 0: return std::numeric_limits<double>::max();
    case 1: return std::numeric_limits<double>::lowest();
    case 2: return std::numeric_limits<double>::denorm_min();
    case 3: return -0.0;
    default: break;
  }
  ++k_;
  const double sign = (k_ % 2 == 0) ? 1.0 : -1.0;
  return sign * (static_cast<double>(k_) * 1.0009765625 + 1.0 / static_cast<double>(k_ + 2));  // not a short decimal
}

std::string pattern_string(std::size_t length, unsigned seed) {
  // Printable ASCII without space and quote characters, so that it survives shell and CSV output.
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_+.:;()[]";
  constexpr std::size_t n = sizeof kAlphabet - 1;
  std::string s(length, ' ');
  for (std::size_t i = 0; i < length; ++i) s[i] = kAlphabet[(seed * 7 + i * 13 + i / n) % n];
  return s;
}

std::string attitude_line(const topics::Attitude& a) {
  // Same format string as examples/c_attitude_listener/attitude_listener.c.
  char buffer[1024];
  std::snprintf(buffer, sizeof buffer,
                "tool=%s estimator=%s end_ns=%lld inclination=%.17g azimuth=%.17g toolface=%.17g "
                "rpm=%.17g flags=%u reason=%s",
                a.tool_id.c_str(), a.estimator.c_str(), static_cast<long long>(a.window_end_ns), a.inclination_deg,
                a.azimuth_deg, a.gravity_toolface_deg, a.rpm, a.flags, a.reason.c_str());
  return buffer;
}

}  // namespace plumb::test
