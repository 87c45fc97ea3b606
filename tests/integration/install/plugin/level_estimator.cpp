// "level": inclination from the mean specific force over each 100 samples, nothing else. The
// smallest useful estimator, to show that a plugin built outside plumb's tree loads in plumb's host.
#include <cmath>
#include <numbers>

#include "plumb/estimator/estimator.hpp"

namespace {

class LevelEstimator final : public plumb::estimator::Estimator {
 public:
  plumb::estimator::Info info() const override {
    return {"level", "inclination from the mean accelerometer over 100 samples", "1.0", {}, false};
  }
  void configure(const plumb::estimator::Parameters&) override { reset(); }
  void push(std::span<const plumb::Sample> samples, std::vector<plumb::Estimate>& out) override {
    for (const auto& s : samples) {
      if (n_ == 0) t_start_ = s.t;
      sum_ -= s.f;  // at rest f = -G
      t_end_ = s.t;
      if (++n_ == kWindow) emit(out);
    }
  }
  void flush(std::vector<plumb::Estimate>& out) override {
    if (n_ > 0) emit(out);
  }
  plumb::estimator::Counters counters() const override { return {{"windows", windows_}}; }

 private:
  static constexpr std::uint32_t kWindow = 100;
  void reset() {
    sum_.setZero();
    n_ = 0;
  }
  void emit(std::vector<plumb::Estimate>& out) {
    const Eigen::Vector3d g = sum_ / n_;
    plumb::Estimate e;
    e.estimator = "level";
    e.t_start = t_start_;
    e.t_end = t_end_;
    e.inclination_deg = std::atan2(std::hypot(g.x(), g.y()), g.z()) * 180.0 / std::numbers::pi;
    e.total_g = g.norm();
    e.samples_used = n_;
    e.valid = true;
    e.reason = "azimuth and toolface not estimated";
    out.push_back(e);
    ++windows_;
    reset();
  }
  Eigen::Vector3d sum_ = Eigen::Vector3d::Zero();
  std::uint32_t n_ = 0;
  double t_start_ = 0;
  double t_end_ = 0;
  std::uint64_t windows_ = 0;
};

}  // namespace

PLUMB_ESTIMATOR_PLUGIN(LevelEstimator, "inclination from the mean accelerometer (out-of-tree example)")
