// Generic printing and setting of topic message fields, driven by plumb::topics::visit_fields:
// `plumb topic echo` prints with it, `plumb topic pub` sets fields by path ("samples.0.fx").
#pragma once

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "messages/flag_names.hpp"
#include "plumb/core/number.hpp"
#include "plumb/topics/all.hpp"

namespace plumb::cli {

template <class T> struct is_array : std::false_type {};
template <class T, std::size_t N> struct is_array<std::array<T, N>> : std::true_type {};
template <class T> struct is_vector : std::false_type {};
template <class T> struct is_vector<std::vector<T>> : std::true_type {};

std::string format_number(double v);
// Four significant digits, for measured figures (rates, periods) whose last digits are noise.
std::string format_measured(double v);

template <class T> std::string scalar_text(const T& v) {
  if constexpr (std::is_same_v<T, std::string>) {
    return v;
  } else if constexpr (std::is_floating_point_v<T>) {
    return format_number(v);
  } else {
    return std::to_string(v);
  }
}

// One flattened row: ("samples.3.fx", "0.25").
using Flat = std::vector<std::pair<std::string, std::string>>;

template <class M> void flatten(const M& m, const std::string& prefix, Flat& out) {
  topics::visit_fields(m, [&](const char* name, const auto& field) {
    using F = std::decay_t<decltype(field)>;
    const std::string path = prefix + name;
    if constexpr (is_array<F>::value) {
      for (std::size_t i = 0; i < field.size(); ++i) out.emplace_back(path + "." + std::to_string(i), scalar_text(field[i]));
    } else if constexpr (is_vector<F>::value) {
      for (std::size_t i = 0; i < field.size(); ++i) flatten(field[i], path + "." + std::to_string(i) + ".", out);
    } else if constexpr (std::is_class_v<F> && !std::is_same_v<F, std::string>) {
      flatten(field, path + ".", out);
    } else {
      out.emplace_back(path, scalar_text(field));
    }
  });
}

// YAML-like, one field a line, as `ros2 topic echo` prints.
template <class M> void print_yaml(std::ostream& os, const M& m, int indent = 0) {
  const std::string pad(static_cast<std::size_t>(indent), ' ');
  topics::visit_fields(m, [&](const char* name, const auto& field) {
    using F = std::decay_t<decltype(field)>;
    if constexpr (is_array<F>::value) {
      os << pad << name << ": [";
      for (std::size_t i = 0; i < field.size(); ++i) os << (i ? ", " : "") << scalar_text(field[i]);
      os << "]\n";
    } else if constexpr (is_vector<F>::value) {
      os << pad << name << ":" << (field.empty() ? " []" : "") << "\n";
      for (const auto& item : field) {
        os << pad << "- ";
        std::ostringstream inner;
        print_yaml(inner, item, indent + 2);
        os << inner.str().substr(static_cast<std::size_t>(indent) + 2);
      }
    } else if constexpr (std::is_class_v<F> && !std::is_same_v<F, std::string>) {
      os << pad << name << ":\n";
      print_yaml(os, field, indent + 2);
    } else if constexpr (std::is_same_v<F, std::string>) {
      os << pad << name << ": \"" << field << "\"\n";
    } else if constexpr (std::is_same_v<F, std::uint32_t>) {
      // A flags field is printed with the names of its bits (idl/ constants), not as a bare integer.
      const auto names = flag_names<std::remove_const_t<M>>();
      os << pad << name << ": " << scalar_text(field);
      if (std::string_view(name) == "flags" && !names.empty()) os << " (" << describe_flags(names, field) << ")";
      os << "\n";
    } else {
      os << pad << name << ": " << scalar_text(field) << "\n";
    }
  });
}

template <class T> void parse_scalar(const std::string& text, T& out, const std::string& path) {
  if constexpr (std::is_same_v<T, std::string>) {
    out = text;
  } else if constexpr (std::is_same_v<T, bool>) {
    if (text != "true" && text != "false" && text != "1" && text != "0")
      throw std::invalid_argument("field '" + path + "': '" + text + "' is not true, false, 1 or 0");
    out = text == "true" || text == "1";
  } else if constexpr (std::is_floating_point_v<T>) {
    const auto v = parse_number(text);
    if (!v) throw std::invalid_argument("field '" + path + "': '" + text + "' is not a number");
    out = static_cast<T>(*v);
  } else {
    T v{};
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || ptr != text.data() + text.size())
      throw std::invalid_argument("field '" + path + "': '" + text + "' is not a valid " +
                                  (std::is_signed_v<T> ? "integer" : "non-negative integer") + " of its range");
    out = v;
  }
}

std::vector<std::string> split(const std::string& s, char sep);

// Sets the field at `path` ("tool_id", "accelerometer.bias", "accelerometer.bias.1", "samples.2.fz")
// from text; arrays take comma-separated values. Throws std::invalid_argument naming the path.
template <class M> void set_field(M& m, const std::string& path, const std::string& value, const std::string& full = "") {
  const std::string shown = full.empty() ? path : full;
  const auto dot = path.find('.');
  const std::string head = path.substr(0, dot);
  const std::string rest = dot == std::string::npos ? "" : path.substr(dot + 1);
  bool found = false;
  topics::visit_fields(m, [&](const char* name, auto& field) {
    if (found || head != name) return;
    found = true;
    using F = std::decay_t<decltype(field)>;
    if constexpr (is_array<F>::value) {
      if (rest.empty()) {
        const auto parts = split(value, ',');
        if (parts.size() != field.size())
          throw std::invalid_argument("field '" + shown + "': expected " + std::to_string(field.size()) + " comma-separated values");
        for (std::size_t i = 0; i < parts.size(); ++i) parse_scalar(parts[i], field[i], shown);
      } else {
        std::size_t i = 0;
        parse_scalar(rest, i, shown);
        if (i >= field.size()) throw std::invalid_argument("field '" + shown + "': index out of range");
        parse_scalar(value, field[i], shown);
      }
    } else if constexpr (is_vector<F>::value) {
      const auto d2 = rest.find('.');
      if (rest.empty() || d2 == std::string::npos)
        throw std::invalid_argument("field '" + shown + "': name an element's field, e.g. " + head + ".0.<field>");
      std::size_t i = 0;
      parse_scalar(rest.substr(0, d2), i, shown);
      const std::size_t bound = M::max_size(head);  // the sequence's IDL bound
      if (i >= bound)
        throw std::invalid_argument("field '" + shown + "': index out of range (at most " + std::to_string(bound) + " elements)");
      if (field.size() <= i) field.resize(i + 1);
      set_field(field[i], rest.substr(d2 + 1), value, shown);
    } else if constexpr (std::is_class_v<F> && !std::is_same_v<F, std::string>) {
      if (rest.empty()) throw std::invalid_argument("field '" + shown + "' is a structure: name one of its fields");
      set_field(field, rest, value, shown);
    } else {
      if (!rest.empty()) throw std::invalid_argument("field '" + shown + "': '" + head + "' has no sub-fields");
      parse_scalar(value, field, shown);
    }
  });
  if (!found) throw std::invalid_argument("unknown field '" + shown + "'");
}

}  // namespace plumb::cli
