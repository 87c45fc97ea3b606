#include "plumb/core/number.hpp"

#include <charconv>
#include <cmath>

namespace plumb {

std::optional<double> parse_number(std::string_view text, bool allow_non_finite) {
  const char* first = text.data();
  const char* last = first + text.size();
  // from_chars takes '-' but not '+'; "+-1" must still fail.
  if (first != last && *first == '+' && last - first > 1 && first[1] != '-') ++first;
  double value = 0;
  const auto r = std::from_chars(first, last, value);
  if (text.empty() || r.ec != std::errc() || r.ptr != last) return std::nullopt;
  if (!allow_non_finite && !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<double> parse_pace(std::string_view text) {
  if (text == "realtime") return 1.0;
  if (text == "max") return 0.0;
  if (!text.empty() && (text.front() == 'x' || text.front() == 'X')) text.remove_prefix(1);
  else if (!text.empty() && (text.back() == 'x' || text.back() == 'X')) text.remove_suffix(1);
  const auto speed = parse_number(text);
  if (!speed || *speed <= 0) return std::nullopt;
  return speed;
}

}  // namespace plumb
