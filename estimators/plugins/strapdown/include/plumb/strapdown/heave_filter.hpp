// A floating rig's heave on the depth reports: the heave compensator's residual, a swell of
// decimetres at periods of 6-16 s on the measured depth only (the tool does not move with it).
// The filter takes it for white noise of its rms, so each depth update pulls the along-hole
// distance towards the swell's phase of the moment: the end of a run off by up to the swell's
// amplitude. Here each report is explained by a bank of models, each the tool's depth (a trend whose
// speed wanders as drilling starts and stops, held still where the inertial sensors say the tool
// is) plus a swell of one period (a lightly damped oscillator), beside one model without a swell.
// Their likelihoods over the last minutes weigh them; where the best swell does not explain the
// reports better than no swell by a clear margin (a likelihood-ratio test), nothing is taken out.
// What is taken out of a report is the models' weighted swell as predicted from the reports before
// it, and the depth update's variance becomes the reports' own noise plus what that prediction is
// not sure of (independent of each other). The navigator takes it out at stops only (StopUpdates),
// where a standing tool's depth is all the reports say, and the end of a run is a stop; while
// drilling the trend and the swell share the reports' change, and taken out there too the MEMS
// family's worst axis went from 0.475 to 0.55 deg (depth trusted 3-5 times more, its errors in the
// along-axis acceleration read as tilt) for no better end.
#pragma once

#include <array>
#include <optional>

#include <Eigen/Core>

namespace plumb::strapdown {

class HeaveFilter {
 public:
  // A new depth report at t; still: the inertial sensors say the tool stands; depth_sd: the
  // reports' noise as the navigator takes it (stated or measured: a swell's rms when there is one).
  void report(double t, double depth, bool still, double depth_sd);
  void reset() { *this = HeaveFilter(); }
  // The swell in the latest report, m (0 where no swell is found).
  double swell() const { return swell_; }
  // The swell at t, at or after the latest report: predicted from the reports before it (between
  // reports the models see: they take one a second at most, where the swell's period shows).
  double swell_at(double t) const;
  // The variance of a report with the swell taken out, m^2 (depth_sd^2 where none is found).
  double residual_var(double depth_sd) const { return found_ ? residual_var_ : depth_sd * depth_sd; }
  bool found() const { return found_; }
  // The tool's depth at the latest report, swell and noise averaged out (a still tool's reports
  // over its stop), from the best model; none before a report.
  std::optional<double> depth() const;
  // The period of the best swell model, s (none while no swell is found).
  std::optional<double> period_s() const;

  static constexpr int kModels = 21;              // swell periods 6, 6.5, ... 16 s
  static constexpr double kShortestPeriodS = 6;
  static constexpr double kPeriodStepS = 0.5;
  static constexpr double kDamping = 0.1;         // a swell's band: about a tenth of its frequency
  static constexpr double kMemoryS = 180;         // the likelihoods' memory: a few minutes of sea
  static constexpr double kClearMargin = 10;      // log-likelihood a swell must win by
  static constexpr double kWhiteShare = 0.3;      // of depth_sd, the reports' own noise in a swell model
  static constexpr double kMinWhiteSdM = 0.01;
  static constexpr double kStillSpeedSd = 0.001;  // m/s: a standing string, as the stops' updates take it
  static constexpr double kSpeedWanderS = 2;      // the trend's speed changes by rop_sd over this
  static constexpr double kRestartAfterS = 60;    // reports this far apart start the bank again
  static constexpr double kReportIntervalS = 0.9; // a depth read at the IMU's rate: a report a second
  static constexpr double kMinSwellSdM = 0.005;   // a swell's rms below this is no swell worth a model

 private:
  using Vec4 = Eigen::Matrix<double, 4, 1>;
  using Mat4 = Eigen::Matrix<double, 4, 4>;
  // [depth, speed, swell, swell rate]; the no-swell model keeps its swell states at zero.
  struct Model {
    Vec4 x = Vec4::Zero();
    Mat4 p = Mat4::Zero();
    double log_likelihood = 0;
  };
  void start(double depth, double depth_sd);
  void predict(Model& m, double dt, int model, double swell_sd);
  static double update(Model& m, double z, const Eigen::Matrix<double, 1, 4>& h, double r);
  void take_out_predicted_swell(double white);

  std::array<Model, kModels + 1> models_;  // [0]: no swell
  // No swell either, with the swell models' own white noise: reports quieter than the depth's
  // stated noise are not a swell (a land rig's reports of 2 cm against 5 cm stated made the slowest
  // swell, 16 s, win by its smaller white noise alone).
  Model quiet_;
  std::array<double, kModels + 1> weight_{};  // of the swell models, while one is found
  bool swell_models_awake_ = false;
  std::array<Eigen::Matrix2d, kModels + 1> oscillators_{};  // their transitions over oscillator_dt_
  double oscillator_dt_ = -1;
  std::optional<double> last_t_;
  double swell_ = 0, residual_var_ = 0;
  bool found_ = false;
  int best_ = 0;
};

}  // namespace plumb::strapdown
