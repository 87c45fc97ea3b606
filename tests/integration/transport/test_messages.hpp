// One message of any topic type with every field set to a distinct, deterministic value (strings
// at their IDL bound, full sequences, extreme finite numbers), filled through visit_fields so that
// a type added to idl/ is covered without code here. A field lost, swapped or rounded on the way
// through a transport shows up as a difference.
#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "plumb/topics/all.hpp"

namespace plumb::test {

// A printable string of exactly `length` characters, different for each `seed`.
std::string pattern_string(std::size_t length, unsigned seed);

// Each call returns a value no other call returns. The first reals are the extremes of the
// double range, which must cross bit for bit as well.
class Distinct {
 public:
  double real();
  template <class T> T integer() {
    ++k_;
    if constexpr (std::is_same_v<T, bool>) {
      return k_ % 2 == 0;
    } else {
      // Near the ends of the range, where a narrowing or a sign mix-up shows.
      const long step = k_ % (sizeof(T) >= 4 ? 1000000 : 64);
      if constexpr (std::is_signed_v<T>) return static_cast<T>(std::numeric_limits<T>::min() + static_cast<T>(step));
      else return static_cast<T>(std::numeric_limits<T>::max() - static_cast<T>(step));
    }
  }
  unsigned seed() { return static_cast<unsigned>(++k_); }

 private:
  long k_ = 0;
  int reals_ = 0;
};

template <class T> struct IsArray : std::false_type {};
template <class E, std::size_t N> struct IsArray<std::array<E, N>> : std::true_type {};
template <class T> struct IsVector : std::false_type {};
template <class E> struct IsVector<std::vector<E>> : std::true_type {};

template <class M> void fill(M& m, Distinct& d);

// `bound`: the IDL bound of a string or sequence (0 for anything else).
template <class F> void fill_field(F& f, std::size_t bound, Distinct& d) {
  if constexpr (std::is_same_v<F, std::string>) {
    f = pattern_string(bound, d.seed());
  } else if constexpr (std::is_floating_point_v<F>) {
    f = static_cast<F>(d.real());
  } else if constexpr (std::is_integral_v<F>) {
    f = d.integer<F>();
  } else if constexpr (IsArray<F>::value) {
    for (auto& e : f) fill_field(e, 0, d);
  } else if constexpr (IsVector<F>::value) {
    f.resize(bound);
    for (auto& e : f) fill_field(e, 0, d);
  } else {
    fill(f, d);
  }
}

template <class M> void fill(M& m, Distinct& d) {
  topics::visit_fields(m, [&](const char* name, auto& field) { fill_field(field, M::max_size(name), d); });
}

// Every field set, every sequence full, every string at its bound.
template <class M> M full() {
  Distinct d;
  M m{};
  fill(m, d);
  return m;
}

// Flattens a message into (path, exact text) pairs in IDL order.
class Flattener {
 public:
  std::vector<std::pair<std::string, std::string>> fields;

  template <class M> void message(const std::string& prefix, const M& m) {
    topics::visit_fields(m, [&](const char* name, const auto& value) { this->value(prefix + name, value); });
  }

 private:
  template <class F> void value(const std::string& path, const F& v) {
    if constexpr (std::is_same_v<F, std::string>) {
      fields.emplace_back(path, '"' + v + '"');
    } else if constexpr (std::is_floating_point_v<F>) {
      char buffer[64];
      std::snprintf(buffer, sizeof buffer, "%a", static_cast<double>(v));
      fields.emplace_back(path, buffer);
    } else if constexpr (std::is_integral_v<F>) {
      fields.emplace_back(path, std::to_string(v));
    } else if constexpr (IsArray<F>::value) {
      for (std::size_t i = 0; i < v.size(); ++i) value(path + "[" + std::to_string(i) + "]", v[i]);
    } else if constexpr (IsVector<F>::value) {
      fields.emplace_back(path + ".length", std::to_string(v.size()));
      for (std::size_t i = 0; i < v.size(); ++i) value(path + "[" + std::to_string(i) + "]", v[i]);
    } else {
      message(path + ".", v);
    }
  }
};

// "field: expected X, got Y" for the first field (in IDL order, recursively) that differs; empty if equal.
template <class M> std::string first_difference(const M& expected, const M& got) {
  Flattener e, g;
  e.message("", expected);
  g.message("", got);
  for (std::size_t i = 0; i < e.fields.size() && i < g.fields.size(); ++i) {
    if (e.fields[i] != g.fields[i]) {
      return e.fields[i].first + ": expected " + e.fields[i].second + ", got " + g.fields[i].second;
    }
  }
  if (e.fields.size() != g.fields.size()) return "different number of fields";
  return expected == got ? "" : "operator== differs but no field does";
}

inline topics::SensorBatch full_sensor_batch() { return full<topics::SensorBatch>(); }  // 32 samples
inline topics::SensorBatch empty_sensor_batch() { return {}; }  // no samples, empty strings: the other edge
inline topics::Attitude full_attitude() { return full<topics::Attitude>(); }
inline topics::CalibrationCoefficients full_calibration() { return full<topics::CalibrationCoefficients>(); }
inline topics::ComponentStatus full_status() { return full<topics::ComponentStatus>(); }  // 32 counters
inline topics::Truth full_truth() { return full<topics::Truth>(); }

// One line describing an attitude exactly as examples/c_attitude_listener prints it.
std::string attitude_line(const topics::Attitude& a);

}  // namespace plumb::test
