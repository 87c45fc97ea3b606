// `strapdown`: the gyro inclinometer's navigator (docs/methods.md section 4) behind
// the estimator plugin API. The math lives in the plumb_strapdown library (navigator.hpp).
#include <memory>

#include "plumb/estimator/estimator.hpp"
#include "plumb/strapdown/navigator.hpp"
#include "plumb/strapdown/parameters.hpp"

namespace plumb::strapdown {
namespace {

class StrapdownEstimator final : public estimator::Estimator {
 public:
  estimator::Info info() const override {
    estimator::Info i;
    i.name = "strapdown";
    i.description = "strapdown navigator: attitude, velocity and position with zero-velocity Kalman updates at stops";
    i.version = "1.0.0";
    i.parameters = parameter_specs();
    i.uses_gyro = true;
    return i;
  }
  void configure(const estimator::Parameters& params) override { navigator_.configure(parse_parameters(params)); }
  void push(std::span<const Sample> samples, std::vector<Estimate>& out) override {
    for (const Sample& s : samples) navigator_.push(s, out);
  }
  void flush(std::vector<Estimate>& out) override { navigator_.flush(out); }
  std::vector<std::string> take_notices() override { return navigator_.take_notices(); }
  estimator::Counters counters() const override {
    estimator::Counters c;
    for (const auto& [name, value] : navigator_.counters()) c[name] = value;
    return c;
  }

 private:
  Navigator navigator_;
};

}  // namespace
}  // namespace plumb::strapdown

PLUMB_ESTIMATOR_PLUGIN(plumb::strapdown::StrapdownEstimator,
                       "strapdown navigator with zero-velocity updates (gyros required)")
