// A field or a line of a text file without the blanks around it (spaces, tabs, and the line ends
// of files written on another system), for every reader of plumb's text files.
#pragma once

#include <string>
#include <string_view>

namespace plumb {

inline std::string trim(std::string_view s) {
  constexpr std::string_view kBlanks = " \t\r\n";
  const auto b = s.find_first_not_of(kBlanks);
  if (b == std::string_view::npos) return {};
  return std::string(s.substr(b, s.find_last_not_of(kBlanks) - b + 1));
}

}  // namespace plumb
