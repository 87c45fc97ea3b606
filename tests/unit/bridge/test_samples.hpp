// Samples with float32-exact values, so a frame round trip must give them back bit for bit.
#pragma once

#include <cstdint>
#include <vector>

#include "plumb/core/sample.hpp"

namespace plumb::bridge::test {

inline Sample make_sample(std::uint64_t seq) {
  Sample s;
  s.seq = seq;
  s.t = static_cast<double>(seq) * 0.001;  // 1 kHz; 1e-3 s is a whole number of ns
  const double k = static_cast<double>(seq % 97);
  s.f = {0.25 * k - 3.0, -0.5, -9.75};
  s.b = {20.5, -0.125 * k, 40.0};
  s.w = {0.0, 0.5, 6.25};
  s.temp_c = 25.5;
  s.flags = flags::kHasGyro | flags::kHasTemperature;
  return s;
}

inline std::vector<Sample> make_samples(std::uint64_t first, std::size_t count) {
  std::vector<Sample> v;
  for (std::size_t i = 0; i < count; ++i) v.push_back(make_sample(first + i));
  return v;
}

}  // namespace plumb::bridge::test
