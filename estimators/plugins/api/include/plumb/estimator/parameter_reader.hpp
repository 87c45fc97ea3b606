// Reads estimator parameters against their specs: unknown names and bad values throw
// ParameterError naming the parameter and what it accepts; missing ones take their defaults.
#pragma once

#include <string>
#include <vector>

#include "plumb/estimator/estimator.hpp"

namespace plumb::estimator {

class ParameterReader {
 public:
  ParameterReader(const estimator::Parameters& given, const std::vector<estimator::ParameterSpec>& specs);
  // A number in [min, max].
  double number(const std::string& name, double min, double max) const;
  // true/false, yes/no, on/off, 1/0.
  bool boolean(const std::string& name) const;

 private:
  const std::string& text(const std::string& name) const;
  const estimator::Parameters& given_;
  const std::vector<estimator::ParameterSpec>& specs_;
};

}  // namespace plumb::estimator
