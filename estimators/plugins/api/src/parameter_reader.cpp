#include "plumb/estimator/parameter_reader.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "plumb/core/number.hpp"

namespace plumb::estimator {

using estimator::ParameterError;

ParameterReader::ParameterReader(const estimator::Parameters& given, const std::vector<estimator::ParameterSpec>& specs)
    : given_(given), specs_(specs) {
  for (const auto& [name, value] : given_) {
    bool known = false;
    std::string names;
    for (const auto& spec : specs_) {
      known = known || spec.name == name;
      names += (names.empty() ? "" : ", ") + spec.name;
    }
    if (!known) throw ParameterError("unknown parameter '" + name + "' (accepted: " + names + ")");
  }
}

const std::string& ParameterReader::text(const std::string& name) const {
  if (auto it = given_.find(name); it != given_.end()) return it->second;
  for (const auto& spec : specs_) {
    if (spec.name == name) return spec.default_value;
  }
  throw ParameterError("parameter '" + name + "' has no specification");
}

double ParameterReader::number(const std::string& name, double min, double max) const {
  const std::string& value = text(name);
  const auto parsed = parse_number(value);
  const double x = parsed.value_or(0);
  if (!parsed || x < min || x > max) {
    std::ostringstream range;  // shortest form: [-90, 90], not [-90.000000, 90.000000]
    range << "[" << min << ", " << max << "]";
    throw ParameterError("parameter '" + name + "': '" + value + "' is not a number in " + range.str());
  }
  return x;
}

bool ParameterReader::boolean(const std::string& name) const {
  const std::string& value = text(name);
  if (value == "true" || value == "yes" || value == "on" || value == "1") return true;
  if (value == "false" || value == "no" || value == "off" || value == "0") return false;
  throw ParameterError("parameter '" + name + "': '" + value + "' is not true/false");
}

}  // namespace plumb::estimator
