// The survey (bad stations, flagged QC), the survey file (round trip, truncation, damage, atomic
// rewrite) and the station detector (one station per stop, repeats, restarts, pipe tally).
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <random>

#include <gtest/gtest.h>

#include "plumb/survey/detector_report.hpp"
#include "plumb/survey/station_detector.hpp"
#include "plumb/survey/survey.hpp"
#include "plumb/survey/survey_file.hpp"

namespace plumb::survey {
namespace {

SurveyOptions options() {
  SurveyOptions o;
  o.field.gravity_mps2 = 9.80665;
  o.field.total_b_uT = 50;
  o.field.dip_deg = 60;
  return o;
}

Station station(double md, double inc, double az, double b = 50) {
  Station s;
  s.md_m = md;
  s.inclination_deg = inc;
  s.magnetic_azimuth_deg = az;
  s.inclination_sd_deg = 0.05;
  s.azimuth_sd_deg = 0.3;
  s.total_g_mps2 = 9.80665;
  s.total_b_uT = b;
  s.dip_deg = 60;
  s.source = "static";
  s.tool_id = "t1";
  return s;
}

TEST(Survey, BadStationsAreRefusedWithTheirReasonAndLeaveTheSurveyAsItWas) {
  Survey s(options());
  s.add(station(100, 10, 20));
  s.add(station(110, 11, 21));
  const auto refused = [&](const Station& st, const char* what) {
    try {
      s.add(st);
      ADD_FAILURE() << "accepted: " << what;
    } catch (const StationError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  refused(station(105, 11, 21), "goes backwards");
  refused(station(110, 11, 21), "duplicate");
  refused(station(120, 181, 21), "outside [0, 180]");
  refused(station(120, -1, 21), "outside [0, 180]");
  refused(station(120, 10, std::nan("")), "azimuth");
  EXPECT_EQ(s.rows().size(), 2u);
}

TEST(Survey, FailedQcIsKeptAndFlagged) {
  Survey s(options());
  s.add(station(100, 10, 20));
  const auto& row = s.add(station(110, 11, 21, 51));
  EXPECT_FALSE(row.qc.pass);
  EXPECT_NE(row.qc.reason.find("|B|"), std::string::npos);
  EXPECT_EQ(s.rows().size(), 2u);
  EXPECT_EQ(s.failed_qc(), 1u);
}

TEST(Survey, TrueSurveyNeedsDeclinationAndSaysSo) {
  auto o = options();
  o.reference = AzimuthReference::True;
  EXPECT_THROW(Survey{o}, std::invalid_argument);
  o.north.declination_known = true;
  o.north.declination_deg = 10;
  Survey s(o);
  EXPECT_NEAR(s.add(station(0, 30, 355)).azimuth_deg, 5, 1e-12);
  EXPECT_EQ(s.rows()[0].reference, AzimuthReference::True);
}

// Issue 36: the vertical section defaulted to azimuth 0 while the well went to 120, and ran off to
// -4 m. Without --section-azimuth it is along the well's closure: the last station's section is its
// closure distance, and every row follows the newest station; a given azimuth still wins.
TEST(Survey, SectionAzimuthDefaultsToTheClosureOfTheLastStation) {
  Survey s(options());
  for (int k = 0; k < 8; ++k) s.add(station(100 + 30 * k, 5 * k, 120 + k));
  const auto& last = s.rows().back().point;
  ASSERT_GT(last.closure_distance_m, 10);
  EXPECT_TRUE(s.section_azimuth_is_closure());
  EXPECT_DOUBLE_EQ(s.section_azimuth_deg(), last.closure_azimuth_deg);
  EXPECT_NEAR(last.vertical_section_m, last.closure_distance_m, 1e-9);
  const double a = last.closure_azimuth_deg * 3.14159265358979323846 / 180;
  for (const auto& r : s.rows())
    EXPECT_NEAR(r.point.vertical_section_m, r.point.north_m * std::cos(a) + r.point.east_m * std::sin(a), 1e-9);
  const std::string text = survey_text(s);
  EXPECT_NE(text.find(" (closure)\n"), std::string::npos) << text.substr(0, 300);

  auto given = options();
  given.section_azimuth_deg = 0;
  Survey north(given);
  for (int k = 0; k < 8; ++k) north.add(station(100 + 30 * k, 5 * k, 120 + k));
  EXPECT_FALSE(north.section_azimuth_is_closure());
  EXPECT_NEAR(north.rows().back().point.vertical_section_m, north.rows().back().point.north_m, 1e-12);
  EXPECT_LT(north.rows().back().point.vertical_section_m, 0);
  EXPECT_EQ(survey_text(north).find("(closure)"), std::string::npos);
}

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("plumb_survey_test_" + std::to_string(::getpid()) + name)).string();
}

TEST(SurveyFile, AppendedRowsReadBackIntoTheSameSurvey) {
  const std::string path = temp_path("append.csv");
  std::filesystem::remove(path);
  Survey a(options());
  {
    SurveyAppender out(path, a.options());
    for (int k = 0; k < 5; ++k) out.append(a.add(station(100 + 10 * k, 10 + k, 20 + 2 * k)));
  }
  const auto loaded = read_survey_file(path);
  EXPECT_TRUE(loaded.problem.empty()) << loaded.problem;
  ASSERT_EQ(loaded.stations.size(), 5u);
  Survey b(options());
  for (const auto& st : loaded.stations) b.add(st);
  EXPECT_EQ(survey_text(a), survey_text(b));
  std::filesystem::remove(path);
}

// Issue 36: 17-digit values (`md_sd_m 2.6e-16`). Each column now has the precision fit for it
// (0.001 m, 0.001 deg, sigmas to 3 significant digits, arithmetic noise 0), and a station enters the
// survey rounded the same way, so the file still reads back as the same survey, digit for digit.
TEST(SurveyFile, ColumnsHaveTheirPrecisionAndStillReadBackExactly) {
  const std::string path = temp_path("precision.csv");
  std::filesystem::remove(path);
  Survey a(options());
  {
    SurveyAppender out(path, a.options());
    for (int k = 0; k < 4; ++k) {
      Station st = station(100.123456789 + 10.0 / 3 * k, 10.987654321 + k / 7.0, 20.0 / 3 + k);
      st.md_sd_m = 2.6e-16;
      st.inclination_sd_deg = 0.0123456;
      st.t_s = 1700000000.0 + k / 3.0;
      out.append(a.add(st));
    }
  }
  std::ifstream in(path);
  std::string line, header, first;
  while (std::getline(in, line) && line[0] == '#') {
  }
  header = line;
  std::getline(in, first);
  const auto value = [&](const std::string& row, const std::string& column) {
    std::vector<std::string> names, values;
    std::stringstream h(header), r(row);
    for (std::string f; std::getline(h, f, ',');) names.push_back(f);
    for (std::string f; std::getline(r, f, ',');) values.push_back(f);
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == column) return values.at(i);
    return std::string("(no column)");
  };
  EXPECT_EQ(value(first, "md_m"), "100.123");
  EXPECT_EQ(value(first, "md_sd_m"), "0");
  EXPECT_EQ(value(first, "inclination_deg"), "10.988");
  EXPECT_EQ(value(first, "inclination_sd_deg"), "0.0123");
  EXPECT_EQ(value(first, "magnetic_azimuth_deg"), "6.667");
  EXPECT_EQ(value(first, "t"), "1700000000.000");
  EXPECT_LE(value(first, "inclination_total_sd_deg").size(), 6u) << value(first, "inclination_total_sd_deg");
  const auto loaded = read_survey_file(path);
  ASSERT_TRUE(loaded.problem.empty()) << loaded.problem;
  Survey b(options());
  for (const auto& st : loaded.stations) b.add(st);
  EXPECT_EQ(survey_text(a), survey_text(b));
  for (std::size_t k = 0; k < a.rows().size(); ++k) {
    EXPECT_EQ(a.rows()[k].station.md_m, b.rows()[k].station.md_m);
    EXPECT_EQ(a.rows()[k].point.north_m, b.rows()[k].point.north_m);
    EXPECT_EQ(a.rows()[k].uncertainty.covariance, b.rows()[k].uncertainty.covariance);
  }
  std::filesystem::remove(path);
}

TEST(SurveyFile, TruncatedOrDamagedRowsKeepTheValidPartAndSayWhere) {
  const std::string path = temp_path("damaged.csv");
  Survey a(options());
  for (int k = 0; k < 4; ++k) a.add(station(100 + 10 * k, 10 + k, 20));
  const std::string text = survey_text(a);
  // Cut in the middle of the last row: the writer died while writing it.
  write_file_atomically(path, text.substr(0, text.size() - 20));
  auto loaded = read_survey_file(path);
  EXPECT_EQ(loaded.stations.size(), 3u);
  EXPECT_NE(loaded.problem.find("truncated"), std::string::npos) << loaded.problem;
  // A damaged row in the middle: what is above it is kept.
  std::string damaged = text;
  const auto third_row = damaged.find("\n2,");
  damaged.replace(third_row + 3, 5, "xx,yy");
  write_file_atomically(path, damaged);
  loaded = read_survey_file(path);
  EXPECT_EQ(loaded.stations.size(), 2u);
  EXPECT_NE(loaded.problem.find("damaged row"), std::string::npos) << loaded.problem;
  // Not a survey file at all: an error, not an empty survey.
  write_file_atomically(path, "t,inclination_deg\n1,2\n");
  EXPECT_THROW(read_survey_file(path), std::runtime_error);
  std::filesystem::remove(path);
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
}

// A stop-and-go run: depth reports every 0.5 s; attitude windows of 2 s every 2 s, valid only
// while the depth stands (a static estimator); stops at 0, 9.5, 19 m, then a resurvey at 19 m.
struct StopAndGo {
  std::vector<Station> stations;
  std::vector<std::string> notes;
  StationDetector detector{DetectorOptions{}, [this](const Station& s) { stations.push_back(s); },
                           [this](const std::string& n) { notes.push_back(n); }};
};

double depth_at(double t) {
  // stand 0-20 s at 0; drill to 9.5 by 40 s; stand to 60; drill to 19 by 80; stand to 100;
  // pull up to 17 by 110; run back to 19 by 120; stand to 140.
  const auto ramp = [](double t0, double t1, double d0, double d1, double t) { return d0 + (d1 - d0) * (t - t0) / (t1 - t0); };
  if (t < 20) return 0;
  if (t < 40) return ramp(20, 40, 0, 9.5, t);
  if (t < 60) return 9.5;
  if (t < 80) return ramp(60, 80, 9.5, 19, t);
  if (t < 100) return 19;
  if (t < 110) return ramp(100, 110, 19, 17, t);
  if (t < 120) return ramp(110, 120, 17, 19, t);
  return 19;
}

Estimate window(double t0, double t1, bool still) {
  Estimate e;
  e.estimator = "static";
  e.t_start = t0;
  e.t_end = t1;
  e.valid = still;
  e.azimuth_valid = still;
  e.inclination_deg = 30 + t0 / 100;
  e.azimuth_deg = 120;
  e.total_g = 9.80665;
  e.total_b = 50;
  e.dip_deg = 60;
  return e;
}

void feed(StopAndGo& run, double from, double to) {
  for (double t = from; t < to; t += 2) {
    for (double td = t; td < t + 2; td += 0.5) run.detector.add_depth({td, depth_at(td), 0.01, false});
    // Static estimates are valid when the tool stands; here also while it moves slowly (sliding),
    // so that only the depth tells a stop from drilling.
    run.detector.add_attitude(window(t, t + 2, true), "t1");
  }
}

TEST(StationDetector, OneStationPerStopAndARepeatIsSaid) {
  StopAndGo run;
  feed(run, 0, 140);
  run.detector.flush();
  ASSERT_EQ(run.stations.size(), 3u);
  EXPECT_EQ(run.stations[0].md_m, 0);
  EXPECT_EQ(run.stations[1].md_m, 9.5);
  EXPECT_EQ(run.stations[2].md_m, 19);
  EXPECT_GE(run.stations[1].t_s - 2, 40);  // the whole window inside the stop
  EXPECT_EQ(run.detector.counters().repeat_stops, 1u);
  ASSERT_EQ(run.notes.size(), 1u);
  EXPECT_GT(run.detector.counters().moving_windows, 20u);
}

TEST(StationDetector, EveryWindowOfAStopMakesItsStation) {
  // Each window reads the true 30 deg plus an error of +-0.1 deg, alternating, with sigma 0.1 deg:
  // the station is their mean, its sigma 0.1 / sqrt(windows).
  std::vector<Station> got;
  StationDetector d({}, [&](const Station& s) { got.push_back(s); });
  int k = 0;
  for (double t = 0; t < 60; t += 2) {
    for (double td = t; td < t + 2; td += 0.5) d.add_depth({td, t < 40 ? 5.0 : 5.0 + (t - 40) * 0.1, 0.01, false});
    Estimate e = window(t, t + 2, true);
    e.inclination_deg = 30 + (k++ % 2 ? 0.1 : -0.1);
    e.inclination_sd_deg = 0.1;
    e.azimuth_deg = k % 2 ? 359.9 : 0.1;  // across north
    e.azimuth_sd_deg = 0.1;
    d.add_attitude(e, "t1");
  }
  d.flush();
  ASSERT_EQ(got.size(), 1u);
  // Windows ending at 4 s (the depth log starts with the first) to 40 s: 19 of them, ten at +0.1.
  EXPECT_EQ(got[0].windows, 19u);
  EXPECT_NEAR(got[0].inclination_deg, 30 + 0.1 / 19, 1e-9);
  // 1 / sqrt(sum of weights), widened by the scatter about the mean (chi2 / (n - 1) = 19.9 / 18).
  const double chi2 = 10 * std::pow(0.1 - 0.1 / 19, 2) / 0.01 + 9 * std::pow(0.1 + 0.1 / 19, 2) / 0.01;
  EXPECT_NEAR(got[0].inclination_sd_deg, 0.1 / std::sqrt(19.0) * std::sqrt(chi2 / 18), 1e-9);
  const double az = got[0].magnetic_azimuth_deg > 180 ? got[0].magnetic_azimuth_deg - 360 : got[0].magnetic_azimuth_deg;
  EXPECT_NEAR(az, 0.1 / 19, 1e-9);
  EXPECT_EQ(d.counters().combined_windows, 19u);
}

TEST(StationDetector, NoisyQuantizedDepthHeldBetweenReportsFindsEveryStop) {
  // The rig's depth: 1 Hz reports with 4 cm of noise, quantized to 1 cm; a window of 2 s every 2 s.
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0, 0.04);
  StopAndGo run;
  for (double t = 0; t < 140; t += 2) {
    for (double td = t; td < t + 2; td += 1) run.detector.add_depth({td, std::round((depth_at(td) + noise(rng)) * 100) / 100, 0, false});
    run.detector.add_attitude(window(t, t + 2, true), "t1");
  }
  run.detector.flush();
  ASSERT_EQ(run.stations.size(), 3u);
  EXPECT_NEAR(run.stations[1].md_m, 9.5, 0.05);
  EXPECT_NEAR(run.stations[2].md_m, 19, 0.05);
  // The tolerance follows the measured noise (6.5 sigma, about 0.26 m), not the 0.02 m floor.
  EXPECT_GT(run.detector.still_tolerance_m(), 0.15);
  EXPECT_LT(run.detector.still_tolerance_m(), 0.4);
}

TEST(StationDetector, NoStationSaysWhyAndWhatToTry) {
  // A static estimator on a turning platform: every window invalid, with its reason.
  std::vector<Station> got;
  StationDetector d({}, [&](const Station& s) { got.push_back(s); });
  for (double t = 0; t < 60; t += 2) {
    d.add_depth({t, 100, 0.01, false});
    Estimate e = window(t, t + 2, false);
    e.reason = "platform rotating (31.2 rpm)";
    d.add_attitude(e, "t1");
  }
  d.flush();
  EXPECT_TRUE(got.empty());
  const std::string advice = no_station_advice(d.counters(), "static", d.still_tolerance_m());
  EXPECT_NE(advice.find("30 invalid (30 platform rotating)"), std::string::npos) << advice;
  EXPECT_NE(advice.find("try -e compensated"), std::string::npos) << advice;
}

TEST(Survey, IscwsaModelGivesEachStationItsRandomAndTotalSigma) {
  SurveyOptions o;
  o.checks = {false, false, false};
  o.tool_code = iscwsa::builtin_tool_code("MWD");
  Survey magnetic(o);
  o.reference = AzimuthReference::True;
  o.north.declination_known = true;
  Survey true_north(o);
  for (int k = 0; k < 5; ++k) {
    Station s;
    s.md_m = 100 + 30 * k;
    s.inclination_deg = 10 + 5 * k;
    s.magnetic_azimuth_deg = 60;
    s.inclination_sd_deg = 0.01;
    s.azimuth_sd_deg = 0.05;
    magnetic.add(s);
    true_north.add(s);
  }
  const SurveyRow& m = magnetic.rows().back();
  const SurveyRow& t = true_north.rows().back();
  EXPECT_GT(m.inclination_total_sd_deg, m.inclination_random_sd_deg);
  EXPECT_GE(m.inclination_random_sd_deg, 0.01);
  EXPECT_GT(m.uncertainty.major_sd_m, m.random_uncertainty.major_sd_m);
  // The declination terms belong to a true (or grid) survey only.
  EXPECT_GT(t.azimuth_total_sd_deg, m.azimuth_total_sd_deg);
  EXPECT_EQ(m.error_model.rfind("MWD", 0), 0u);
}

TEST(StationDetector, WithoutDepthWindowsWaitNoLongerThanTheDepthHistory) {
  StopAndGo run;
  const double history = 600;  // the default depth_history_s
  for (double t = 0; t < 1000; t += 2) run.detector.add_attitude(window(t, t + 2, true), "t1");
  // Windows more than the history older than the newest were decided, without depth; the rest wait.
  EXPECT_NEAR(static_cast<double>(run.detector.counters().no_depth_windows), (1000 - history) / 2, 2);
  EXPECT_TRUE(run.stations.empty());
}

TEST(StationDetector, ResumedDetectorNeitherRepeatsNorLosesStations) {
  StopAndGo first;
  feed(first, 0, 66);  // killed while drilling on from the second stop, after its station
  ASSERT_EQ(first.stations.size(), 2u);
  StopAndGo second;
  second.detector.resume(first.stations.back().t_s, first.stations.back().md_m, 2);
  feed(second, 44, 100);  // restarted: the windows of the stop come again, then the next stop
  second.detector.flush();
  ASSERT_EQ(second.stations.size(), 1u);
  EXPECT_EQ(second.stations[0].md_m, 19);
  EXPECT_GT(second.detector.counters().old_windows + second.detector.counters().same_stop_windows, 0u);
}

TEST(StationDetector, PipeTallyNumbersTheStops) {
  DetectorOptions o;
  o.tally = PipeTally{100, {9.6, 9.4}, {0, 0.02}, 0.05};
  std::vector<Station> got;
  StationDetector d(o, [&](const Station& s) { got.push_back(s); });
  const bool pattern[] = {true, true, false, false, true, false, true, true, true};
  double t = 0;
  for (bool still : pattern) {
    d.add_attitude(window(t, t + 2, still), "t1");
    t += 2;
  }
  d.flush();  // the last stop is still open: its station comes with the end of the input
  ASSERT_EQ(got.size(), 3u);
  EXPECT_NEAR(got[0].md_m, 100, 1e-12);
  EXPECT_NEAR(got[1].md_m, 109.62, 1e-12);
  EXPECT_NEAR(got[2].md_m, 119.0, 1e-12);
  EXPECT_EQ(got[2].md_sd_m, 0.05);
}

}  // namespace
}  // namespace plumb::survey
