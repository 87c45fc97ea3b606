#pragma once
// What every scenario checks of its fields before it simulates anything. A refusal is a
// std::invalid_argument whose message starts with the input it refuses ("invalid drilling plan: ...").
#include <cmath>
#include <stdexcept>
#include <string>

namespace plumb::sim {

inline bool finite_nonneg(double v) { return std::isfinite(v) && v >= 0; }

class Refusal {
 public:
  explicit constexpr Refusal(const char* subject) : subject_(subject) {}
  void operator()(bool ok, const std::string& what) const {
    if (!ok) throw std::invalid_argument(std::string(subject_) + ": " + what);
  }

 private:
  const char* subject_;
};

}  // namespace plumb::sim
