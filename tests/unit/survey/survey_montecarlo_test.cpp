// Survey accuracy on simulated runs with known truth: the simulator's stop-and-go drilling run
// (six 1.5 m rotary segments, 30 s stops) through the static estimator (5 s windows) and the station
// detector into a survey, over many seeds. Station inclination and azimuth errors against the
// truth must match the estimator's own sigma (RMS of error/sigma in [0.7, 1.5]), and the end of the
// survey must lie inside its reported 95 % ellipse in about 95 % of the runs. Label `montecarlo`.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "plumb/core/attitude.hpp"
#include "plumb/estimator/loader.hpp"
#include "plumb/sim/drilling.hpp"
#include "plumb/survey/station_detector.hpp"
#include "plumb/survey/survey.hpp"

namespace plumb::survey {
namespace {

struct RunResult {
  std::vector<double> normalized;  // error / sigma of every station's inclination and azimuth
  bool inside95 = false;
  std::size_t stations = 0;
};

RunResult run_once(std::uint64_t seed) {
  sim::DrillingScenario scenario = sim::DrillingScenario::survey_stop_and_go(sim::ImuGrade::tactical(), 100, seed);
  // Noisier magnetometers than the default so that the azimuth sigma is well above round-off. No
  // accelerometer bias: a static estimator's sigma covers the noise of its window, and a constant
  // bias is a calibration error (the error model's systematic terms), not noise.
  scenario.magnetometer.sigma_uT = 0.5;
  scenario.accel_bias = Eigen::Vector3d::Zero();
  sim::DrillingSimulator simulator(scenario);
  std::vector<TruthSample> truth;
  const std::vector<Sample> samples = simulator.run(&truth);

  SurveyOptions options;
  options.checks = {false, false, false};
  Survey survey(options);
  StationDetector detector({}, [&](const Station& s) { survey.add(s); });
  estimator::Runner runner = estimator::load_runner({"static"});
  runner.configure({}, 5.0);
  const auto take = [&](const estimator::Runner::Slot&, Estimate& e) { detector.add_attitude(e, ""); };
  std::vector<Sample> chunk;
  for (const auto& s : samples) {
    detector.add_depth({s.t, s.depth_m, 0, false});
    chunk.push_back(s);
    if (chunk.size() == 100) {
      runner.push(chunk, take);
      chunk.clear();
    }
  }
  runner.push(chunk, take);
  runner.flush(take);
  detector.flush();

  RunResult r;
  r.stations = survey.rows().size();
  if (survey.rows().empty()) {
    const auto& c = detector.counters();
    ADD_FAILURE() << "no station: " << c.windows << " windows, " << c.invalid_windows << " invalid, " << c.moving_windows
                  << " moving, " << c.no_depth_windows << " without depth";
    return r;
  }
  for (const auto& row : survey.rows()) {
    // The sample at the window's end: the tool stands still through the window.
    const auto it = std::lower_bound(truth.begin(), truth.end(), row.station.t_s - 1e-9,
                                     [](const TruthSample& t, double v) { return t.t < v; });
    const TruthSample& t = it == truth.end() ? truth.back() : *it;
    r.normalized.push_back((row.station.inclination_deg - t.inclination_deg) / row.station.inclination_sd_deg);
    r.normalized.push_back(wrap_deg_180(row.station.magnetic_azimuth_deg - t.azimuth_deg) / row.station.azimuth_sd_deg);
  }
  const TruthSample& end = truth.back();
  const auto& last = survey.rows().back();
  r.inside95 = inside_ellipse(last.uncertainty, last.point.north_m - end.north_m, last.point.east_m - end.east_m,
                              kEllipse95Factor);
  return r;
}

TEST(SurveyMonteCarlo, StationsWithinTheirSigmaAndEndInsideThe95Ellipse) {
  const int runs = 100;
  double sum_sq = 0;
  std::size_t n = 0, inside = 0;
  for (int seed = 1; seed <= runs; ++seed) {
    const RunResult r = run_once(static_cast<std::uint64_t>(seed));
    ASSERT_EQ(r.stations, 7u) << "seed " << seed << ": one station for the alignment and each of the six stops";
    for (double v : r.normalized) sum_sq += v * v;
    n += r.normalized.size();
    inside += r.inside95 ? 1 : 0;
  }
  const double rms = std::sqrt(sum_sq / static_cast<double>(n));
  const double coverage = static_cast<double>(inside) / runs;
  std::printf("%d runs, %zu station angles: RMS(error/sigma) %.3f; end inside the 95 %% ellipse in %.1f %% of runs\n", runs,
              n, rms, 100 * coverage);
  EXPECT_GT(rms, 0.7);
  EXPECT_LT(rms, 1.5);
  // 100 runs at p = 0.95: binomial sd 2.2 %; below 88 % is over 3 sd away.
  EXPECT_GE(coverage, 0.88);
  EXPECT_LE(coverage, 0.995);  // an ellipse far too large would hold every run
}

}  // namespace
}  // namespace plumb::survey
