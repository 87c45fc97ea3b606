// Stillness detection for zero-velocity updates. Two detectors over a short sliding window:
// - Magnitude (docs/methods.md section 4, the source's test): every sample of the window has
//   | |f| - g | < accel_tol and, when a magnetometer is used, | |B| - B0 | < field_tol; plus gyro
//   quiet (below).
// - GLRT (foot-mounted INS, Skog et al. 2010 / OpenShoe; no magnetometer):
//   T = 1/W sum_k ( |f_k - g f_mean/|f_mean||^2 / sigma_a^2 + |w_k - w_expected|^2 / sigma_w^2 ),
//   still when T < glrt_threshold. Under stillness T is about 6 (3 + 3 degrees of freedom).
// Gyro quiet, for both: the mean of w - w_expected over the window, and over the quiet stretch so
// far (an exponential mean over up to rate_memory_s, restarted only when a window is not quiet, so
// a failed period does not start afresh at the next sample), is below gyro_tol + 4 sigma_w / sqrt(N). w_expected is the earth rate in the tool frame
// plus the gyro bias estimate; the caller widens gyro_tol by what it does not know of them. The
// period-long test catches a slow steady turn (a sliding build of 8 deg/30 m at 0.05 m/s turns at
// 2.3e-4 rad/s, below one sample's noise of a MEMS gyro) that a short window cannot see.
// Specific-force steadiness, for both: the window mean of f stays within 4 sigma (plus
// accel_drift_tol) of the period's mean; a slow start along a near-horizontal axis changes the
// direction of f long before it changes |f| (which moves by a^2 / 2g only).
// With a measured depth, the depth must also stay within depth_tol over depth_window (a tool
// sliding straight at constant speed is otherwise indistinguishable from a still one), and, when
// its noise is known, the mean of the last depth_window_s within kDepthMeanSigmas of the noise of
// the period's mean before it (2 cm of noise at 100 Hz hides a slow start from the range's 8 sigma,
// 0.16 m, not from means: 0.013 m after 5 s). A period the depth ended while its own reports
// show motion is followed by none until the depth's trend is flat (DepthTrend): a steady slide
// passes the one-second tests again at once.
// The period starts at the oldest sample of the first quiet window and is confirmed once it has
// lasted min_still; once confirmed, it ends only when a test fails by `hysteresis` times its
// threshold.
// Magnitude detector: the long means are held while windows are not quite quiet (a slide that
// builds turns the gyros just past their limit), so at the stop that follows they still hold the
// force of the slide's start (0.27 m/s^2 after 2 deg of build) and would keep the stop unseen for
// their time constants (40 s at 10 s). A quiet window after such a hold that disagrees with the
// held means starts them afresh when the hold lasted rate_memory_s / 2 (a noisy sensor's windows
// flicker: short holds are noise, not a slide), and that stop is confirmed only after
// rate_memory_s / 2.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include "plumb/strapdown/depth_trend.hpp"
#include "plumb/strapdown/ring_queue.hpp"

namespace plumb::strapdown {

struct StillnessConfig {
  enum class Mode { Magnitude, Glrt };
  Mode mode = Mode::Magnitude;
  double window_s = 0.05;      // statistics window (at least kMinWindowSamples samples)
  double min_still_s = 0.5;    // a still period counts from this duration on
  double hysteresis = 1.5;     // exit thresholds = entry thresholds x this
  double accel_tol = 0.05;     // m/s^2 (magnitude)
  double field_tol_uT = 5;     // uT (magnitude, with magnetometer)
  double gyro_tol = 1e-5;      // rad/s beyond the noise allowance
  double sigma_a = 0.01;       // m/s^2 per sample (GLRT; also the magnitude noise allowance)
  double sigma_w = 1e-4;       // rad/s per sample
  double glrt_threshold = 15;
  double accel_drift_tol = 0.002;  // m/s^2 beyond the noise allowance
  double rate_memory_s = 10.0;
  double depth_window_s = 1.0;
  double depth_tol_m = 0.01;
  // The depth's white noise (m; 0: not known, no test on means): the mean of the last depth_window_s
  // must stay within kDepthMeanSigmas of its noise of the period's mean before it.
  double depth_sd_m = 0;
  static constexpr double kDepthMeanSigmas = 6;
  static constexpr std::size_t kMinWindowSamples = 3;
};

struct StillnessInput {
  double t = 0;
  Eigen::Vector3d f = Eigen::Vector3d::Zero();
  Eigen::Vector3d w_minus_expected = Eigen::Vector3d::Zero();  // rad/s
  double g = 9.80665;
  std::optional<double> field_deviation_uT;  // |B| - B0, when the field is to be checked
  std::optional<double> depth_m;
  double extra_gyro_tol = 0;                 // rad/s, what the caller does not know of w_expected
  double extra_accel_tol = 0;                // m/s^2, what the caller does not know of |f| - g (a bias not yet estimated)
};

// One of the detector's tests at the last sample, as its statistic against its limit (the window
// is not still when statistic > limit): the one furthest from passing is what a user needs to read
// when no still period is found.
struct StillnessCheck {
  enum class Test { None, Acceleration, Field, Glrt, GyroWindow, GyroStretch, ForceSteadiness, Depth };
  Test test = Test::None;
  double statistic = 0;  // SI units: m/s^2, uT, rad/s, m (the GLRT's is dimensionless)
  double limit = 0;
  double ratio() const { return limit > 0 ? statistic / limit : 0.0; }
};
const char* test_name(StillnessCheck::Test test);

// Which test kept the detector from a still period over a stretch of data: each failing sample's
// binding test is counted; the one counted most is the answer, shown at its closest approach.
class StillnessTally {
 public:
  void add(const StillnessCheck& check);
  void clear() { *this = StillnessTally(); }
  // The most frequent failing test at its smallest statistic/limit; Test::None when none failed.
  StillnessCheck most_frequent() const;

 private:
  static constexpr int kTests = 8;
  std::uint64_t count_[kTests] = {};
  StillnessCheck closest_[kTests];
};

struct StillnessState {
  bool still = false;    // confirmed still period in progress (this sample included)
  bool started = false;  // confirmed at this sample
  bool ended = false;    // the period that was confirmed ended at this sample (this sample moves)
  double period_start = 0;
};

class StillnessDetector {
 public:
  explicit StillnessDetector(const StillnessConfig& config = {}) : config_(config) {}
  void configure(const StillnessConfig& config) { config_ = config; reset(); }
  const StillnessConfig& config() const { return config_; }
  void set_noise(double sigma_a, double sigma_w) { config_.sigma_a = sigma_a; config_.sigma_w = sigma_w; }
  void set_depth_tolerance(double tol_m) { config_.depth_tol_m = tol_m; }
  void set_depth_noise(double sd_m) { config_.depth_sd_m = sd_m; }
  // The test furthest from passing at the last sample (entry thresholds); Test::None before the
  // window holds kMinWindowSamples readings.
  StillnessCheck binding_check(double extra_gyro_tol) const;
  StillnessState update(const StillnessInput& in);
  // Forgets the window and any period (after a gap or a saturated sample).
  void reset();
  // Restarts the long rate and force means (when w_expected changes meaning, at alignment).
  void restart_stretch();
  bool still() const { return confirmed_; }
  double last_statistic() const { return last_statistic_; }

 private:
  struct Entry {
    double t;
    Eigen::Vector3d f, w;
    double f_dev, b_dev;
    double w_norm;
    std::uint64_t sequence;
  };
  // The window's statistics from running sums (O(1) per sample); window_quiet then compares at any
  // threshold factor.
  void measure_window(double g, double extra_gyro_tol);
  void add_to_sums(const Entry& e);
  void remove_from_sums(const Entry& e);
  void resum(double extra_gyro_tol);
  static double rate_excess(double w_norm, double tol) {
    const double x = std::max(0.0, w_norm - tol);
    return x * x;
  }
  bool window_quiet(double factor) const;
  bool period_quiet(double factor, double extra_gyro_tol) const;

  StillnessConfig config_;
  RingQueue<Entry> window_;
  // Running sums over window_; the rate energy counts what exceeds excess_tol_ (re-summed when the
  // caller's tolerance changes, at filter epochs), and every kResumEvery samples all are re-summed
  // so that rounding cannot build up. Largest |f_dev| and |b_dev| by monotonic queues of
  // (sequence, value).
  Eigen::Vector3d f_sum_ = Eigen::Vector3d::Zero(), w_sum_ = Eigen::Vector3d::Zero();
  double f_square_sum_ = 0, w_excess_square_sum_ = 0, excess_tol_ = -1;
  RingQueue<std::pair<std::uint64_t, double>> f_dev_max_, b_dev_max_;
  std::uint64_t entry_count_ = 0, since_resum_ = 0;
  static constexpr std::uint64_t kResumEvery = 4096;
  // The depths of the last depth_window_s (time, depth) and, for their range in O(1) per sample,
  // monotonic queues of (sequence number, depth): the largest and smallest still in the window.
  RingQueue<std::pair<double, double>> depths_;
  RingQueue<std::pair<std::uint64_t, double>> depth_max_, depth_min_;
  std::uint64_t depth_count_ = 0;
  // Depth reports (a value that differs from the row before: a held report counts once) of the
  // last depth_window_s, and the sum and count of those since the period began (the last
  // depth_window_s included): a slow start that noisy depth hides from the range test shows in
  // the means.
  void add_depth_report(double t, double depth);
  bool depth_means_steady(double factor) const;
  RingQueue<std::pair<double, double>> recent_reports_;
  double recent_sum_ = 0, period_sum_ = 0, period_n_ = 0;
  std::optional<double> last_depth_;
  // Set when the depth ended a still period whose own reports show motion: the inertial tests may
  // still pass (a steady slide), and a new period waits until the depth's trend is flat.
  DepthTrend trend_;
  bool depth_moved_ = false;
  bool candidate_ = false, confirmed_ = false;
  double period_start_ = 0;
  void extend_stretch(const StillnessInput& in);
  // The quiet stretch: exponential means of w and f and their effective sample count.
  Eigen::Vector3d stretch_w_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d stretch_f_ = Eigen::Vector3d::Zero();
  double stretch_n_ = 0;
  // The stretch is held (neither extended nor restarted) by windows that are not quite quiet, since
  // held_since_: the tool may have moved on since. A stretch restarted for that is confirmed no
  // sooner than fresh_until_ (its long tests need time to see a slow turn or a slow start).
  bool stretch_held_ = false;
  double held_since_ = 0;
  double fresh_until_ = -1e300;
  double last_dt_ = 0, last_t_ = 0;
  Eigen::Vector3d window_f_mean_ = Eigen::Vector3d::Zero();
  double window_w_mean_norm_ = 0, window_gyro_allowance_ = 0, window_b_dev_ = 0;
  std::size_t root_n_of_ = 0;  // the window size whose square root root_n_ is
  double root_n_ = 0;
  double extra_accel_tol_ = 0;  // the last input's
  double last_statistic_ = 0;
  std::optional<double> last_depth_range_;
};

}  // namespace plumb::strapdown
