// One rule for every number plumb reads from text: command-line options, parameter values, CSV
// fields, coefficient and station files, profiles. Before this each reader had its own (stod took
// leading blanks and hexadecimal, strtod took "inf", from_chars refused "+1"), so the same text
// was a number to one tool and an error to another.
#pragma once

#include <optional>
#include <string_view>

namespace plumb {

// The whole text is one decimal number: optional sign ('+' or '-'), digits, optional fraction and
// exponent. No blanks, no hexadecimal, nothing outside double's range. "nan" and "inf" are
// accepted only with allow_non_finite (CSV fields, where they are counted as bad samples later).
std::optional<double> parse_number(std::string_view text, bool allow_non_finite = false);

// The pace of a replay or simulation: "realtime" -> 1, "xN", "Nx" or "N" -> N (> 0 times faster),
// "max" -> 0 (as fast as possible). Empty when the text is none of these.
std::optional<double> parse_pace(std::string_view text);

}  // namespace plumb
