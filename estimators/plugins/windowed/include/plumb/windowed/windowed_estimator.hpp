// Base of the windowed plugins (static, integral, compensated): cuts the stream into back-to-back
// windows of `window` seconds (0: the whole stream until flush()), rejects and counts bad samples,
// splits at gaps, checks |G|, |B| and dip against the reference (reference_check.hpp), and
// guarantees finite outputs. Subclasses only turn one window into an estimate.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "plumb/estimator/estimator.hpp"
#include "plumb/estimator/parameter_reader.hpp"
#include "plumb/windowed/reference_check.hpp"
#include "plumb/windowed/window.hpp"

namespace plumb::windowed {

using estimator::ParameterReader;

class WindowedEstimator : public estimator::Estimator {
 public:
  estimator::Info info() const final;
  void configure(const estimator::Parameters& params) final;
  void push(std::span<const Sample> samples, std::vector<Estimate>& out) final;
  void flush(std::vector<Estimate>& out) final;
  estimator::Counters counters() const final;

  // Windows shorter than this many samples are reported invalid.
  static constexpr std::size_t kMinSamples = 10;
  // A spacing above this multiple of the nominal one is a gap: the window is closed there.
  static constexpr double kGapFactor = 3.0;

 protected:
  WindowedEstimator();
  // Name, description, version and the plugin's own parameters (the base adds `window`).
  virtual estimator::Info describe() const = 0;
  virtual void configure_plugin(const ParameterReader& params) = 0;
  // One window (at least kMinSamples samples) to one estimate; the base fills the bookkeeping
  // fields (estimator, times, samples_used, partial_window) afterwards.
  virtual Estimate estimate_window(const WindowData& window) = 0;

 private:
  void accept(const Sample& s, std::vector<Estimate>& out);
  bool usable(const Sample& s);
  void close_window(bool partial, const std::string& note, std::vector<Estimate>& out);
  // Plain fields, not map entries: counting runs once per sample.
  struct Counts {
    std::uint64_t accepted = 0, non_finite = 0, saturated = 0, out_of_range = 0, time_backwards = 0, gaps = 0;
    std::uint64_t windows = 0, invalid_windows = 0;
  };
  void reset();

  void grow();

  double window_s_ = 10;
  ReferenceCheck reference_;  // |G|, |B|, dip against the reference; sigma limits
  WindowData window_;     // columns sized ahead; the first count_ rows are the window
  std::size_t count_ = 0;
  std::optional<double> last_t_;
  std::vector<double> first_spacings_;  // to learn the nominal spacing
  double nominal_dt_ = 0;
  Counts counts_;
};

// Replaces every non-finite number by 0 and marks the estimate invalid: the last line of defence
// behind "never NaN in an output".
void make_finite(Estimate& e);

}  // namespace plumb::windowed
