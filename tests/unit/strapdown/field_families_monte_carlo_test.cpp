// The navigator on what the field does to its input, each over a Monte Carlo of seeds (ctest
// label `montecarlo`): samples lost for 0.1-3 s and samples sent twice; shocks clipped
// at the accelerometers' range; stick-slip past the gyros' range. Each family must answer on every
// run, keep each angle's RMS(error/sigma) within 2 and the end position's within 3, and with depth
// meet the field targets: the tool axis within 0.2 deg (tactical) or 0.5 deg (MEMS), the end
// position within 1 % of MD. What is not met yet is bounded at its measured level (said where).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <tuple>

#include "families_support.hpp"
#include "plumb/sim/logger_clock.hpp"
#include "plumb/sim/logger_faults.hpp"

namespace plumb::strapdown::test {
namespace {

// The field targets (tool axis, end position, honest sigma) for one family and grade.
// (Where a family misses a target today, its measured level is the bound: a regression fails.)
void expect_field_targets(const FamilyResult& f, const std::string& grade, double max_axis_deg,
                          double end_rms_z = 3.0, double end_pct = 1.0, double angle_rms_z = 2.0) {
  EXPECT_GT(f.fewest_valid_rows, 850u) << grade;  // every run answered
  for (int a = 0; a < 3; ++a) EXPECT_LE(f.angle_rms_z[a], angle_rms_z) << grade << " angle " << a;
  EXPECT_LE(f.end_position_rms_z, end_rms_z) << grade;
  EXPECT_LE(f.worst_axis_deg, max_axis_deg) << grade;
  EXPECT_LE(f.worst_end_pct, end_pct) << grade;
}

sim::LoggerFaults field_logger_faults(std::uint64_t seed) {
  sim::LoggerFaults faults;
  faults.dropouts_per_minute = 1.5;
  faults.dropout_min_s = 0.1;
  faults.dropout_max_s = 3.0;
  faults.repeats_per_minute = 3;
  faults.repeats_restamped = seed % 2 == 1;
  return faults;
}

// The reference run with 1 m/s^2 of lateral vibration while drilling (so that what a gap hides
// while the bit works is not nothing), through a logger that loses 0.1-3 s about every 40 s and
// sends a sample twice every 20 s (the same stamp on even seeds, re-stamped on odd ones).
Family dropouts_and_repeats() {
  Family family;
  family.scenario = [](std::uint64_t, sim::DrillingScenario& s) { s.vibration.lateral_rms = 1.0; };
  family.input = [](std::uint64_t seed, std::vector<Sample>& s, estimator::Parameters&) {
    s = sim::through_logger(s, field_logger_faults(seed), 100, seed);
  };
  return family;
}

// Met: every run answers, each angle's sigma and the end position's are honest, the axis within
// 0.2 deg (tactical) and 0.5 (MEMS: 0.465; 0.54 while the turn a gap hid across the axis was one
// direction, 0.79 while one reading's rate across the axis was held through a gap), the end
// position within 1 % of MD (0.21-0.23 %; 6.2 % before the gaps' readings were made up in the
// navigation frame).
// A gap across a rotary segment's spin-up left the toolface 24 deg off (the rate's path through
// the ramp is not the line the made-up readings take) until the field across the axis measured the
// gap's turn: the worst attitude 0.26 deg tactical, 0.79 MEMS.
TEST(StrapdownFieldFamilies, DropoutsAndRepeats) {
  for (const auto& [grade, max_axis, worst] :
       {std::tuple{sim::ImuGrade::tactical(), 0.2, 0.5}, std::tuple{sim::ImuGrade::mems(), 0.5, 1.0}}) {
    const FamilyResult f = sweep(("dropouts and repeats, " + grade.name).c_str(), grade, 100, dropouts_and_repeats());
    expect_field_targets(f, grade.name, max_axis, 3.0, 0.5);
    EXPECT_LE(f.worst_attitude_deg, worst) << grade.name;
  }
}

// The same logger while the string sticks and slips (the 30 rpm spin swinging by +-30 rpm every
// 4 s, within the gyros' range): a gap's ends may read the same rate while the tool turned tens of
// degrees off the line between them. The spin's wander over the last seconds is what the gap may
// hide about the axis, and the field across the axis after it takes that back. (Before, the
// allowance was the line's own, nothing where both ends read alike; and the field's part across
// the axis had to be a fifth of it to be read: outside runs at 60-95 rpm +-60 % ended 7-10 % of MD
// off, toolface RMS(error/sigma) 4-16; here, the worst axis 87 deg off and ends 74-8470 % of MD.)
// The turn a gap hid across the axis is every direction across it alike: as one direction, the
// tilt the gravity shows after the gap named the azimuth with it (tactical azimuth RMS(error/sigma)
// 2.27, axis 0.30 deg; MEMS axis 0.54). Met: MEMS (axis 0.465 deg, ends within 0.6 % of MD), every
// angle's sigma honest (azimuth 1.18 tactical). Not met (docs/navigator.md, "Samples lost and sent
// twice"): the tactical axis, 0.211 deg against 0.2; the bound here.
TEST(StrapdownFieldFamilies, DropoutsWhileTheStringSticksAndSlips) {
  Family family = dropouts_and_repeats();
  family.scenario = [](std::uint64_t, sim::DrillingScenario& s) {
    s.vibration.lateral_rms = 1.0;
    s.plan.stick_slip_rpm = 30;
    s.plan.stick_slip_period_s = 4;
  };
  for (const auto& grade : {sim::ImuGrade::tactical(), sim::ImuGrade::mems()}) {
    const bool mems = grade.name == "mems";
    const FamilyResult f = sweep(("dropouts while sticking and slipping, " + grade.name).c_str(), grade, 100, family);
    expect_field_targets(f, grade.name, mems ? 0.5 : 0.22);
  }
}

// What the logger did, the navigator counts and says: every gap and every repeat of one run, and
// one notice of each kind.
TEST(StrapdownFieldFamilies, DropoutsAndRepeatsAreCountedAndSaidOnce) {
  for (bool restamped : {false, true}) {
    auto scenario = sim::DrillingScenario::reference(sim::ImuGrade::tactical(), 100, 5);
    sim::DrillingSimulator simulator(scenario);
    const std::vector<Sample> clean = simulator.run();
    sim::LoggerFaults faults = field_logger_faults(restamped ? 1 : 2);
    sim::LoggerFaultLog log;
    const std::vector<Sample> fed = sim::through_logger(clean, faults, 100, 9, &log);
    ASSERT_GT(log.gaps.size(), 5u);
    ASSERT_GT(log.repeats, 10u);
    Navigator nav(parse_parameters(parameters_for(scenario)));
    std::vector<Estimate> rows;
    std::vector<std::string> notices;
    for (const Sample& s : fed) {
      nav.push(s, rows);
      for (std::string& n : nav.take_notices()) notices.push_back(std::move(n));
    }
    nav.flush(rows);
    const auto& c = nav.counters();
    std::size_t lost = 0, gaps_in_a_second = 0;
    for (const auto& g : log.gaps) {
      lost += g.lost;
      if (g.first_after - g.last_before > 1.0) ++gaps_in_a_second;  // also max_gap_s's "gaps"
    }
    // Gaps before the alignment are counted too (the input checks see every sample).
    EXPECT_EQ(c.at("dropouts"), log.gaps.size());
    EXPECT_EQ(c.at("missing_samples"), lost);
    EXPECT_EQ(c.at("gaps"), gaps_in_a_second);
    EXPECT_EQ(c.at(restamped ? "repeated_samples" : "repeated_time"), log.repeats);
    int gap_notices = 0, repeat_notices = 0;
    for (const std::string& n : notices) {
      gap_notices += n.find("samples lost") != std::string::npos;
      repeat_notices += n.find("sent twice") != std::string::npos;
    }
    EXPECT_EQ(gap_notices, 1);
    EXPECT_EQ(repeat_notices, 1);
    std::size_t rows_saying_gap = 0;
    for (const Estimate& e : rows) rows_saying_gap += e.reason.find("gap bridged") != std::string::npos;
    EXPECT_GT(rows_saying_gap, 0u);
  }
}

// Shocks of 30 g on accelerometers of +-16 g, and stick-slip (the 30 rpm spin swinging by +-30 rpm
// every 4 s) past gyros of +-300 deg/s, as a file carries them: at the range, no flags. The user
// states the datasheet's ranges. The shocks rebound (no net velocity change: the half-sine's would
// be a velocity the truth does not have).
Family clipped_shocks_and_stick_slip(bool shocks = true, bool stick_slip = true) {
  Family family;
  family.scenario = [shocks, stick_slip](std::uint64_t, sim::DrillingScenario& s) {
    if (shocks) {
      s.vibration.shock_rate_hz = 0.3;
      s.vibration.shock_peak = 30 * 9.80665;
      s.vibration.shock_rebounds = true;
      s.grade.accel_range_g = 16;
    }
    if (stick_slip) {
      s.grade.gyro_range_deg_s = 300;
      s.plan.stick_slip_rpm = 30;
      s.plan.stick_slip_period_s = 4;
    }
  };
  family.input = [](std::uint64_t, std::vector<Sample>& s, estimator::Parameters& p) {
    for (Sample& x : s) x.flags &= ~(flags::kAccelSaturated | flags::kGyroSaturated);
    p["accel_range_g"] = "16";
    p["gyro_range_dps"] = "300";
  };
  return family;
}

// Each effect alone. The clipped shocks' end position is within 1 % of MD since a shock's velocity
// and displacement across the axis are taken back at its end (shock_rebound.hpp; 1.4 % before, and
// 3.5 % while the simulator's shocks left 7.5 cm of displacement each that its truth did not have).
// Not met (docs/navigator.md, "Clipped readings"): the MEMS axis with shocks (0.63 deg), its
// measured level the bound. The stick-slip meets the targets since the spin through the clipped
// readings is followed from the magnetometers (clipped_spin.hpp; before, toolface RMS(error/sigma)
// 2.2 tactical, end position's 3.8).
TEST(StrapdownFieldFamilies, ClippedShocks) {
  for (const auto& [grade, max_axis, end_pct] :
       {std::tuple{sim::ImuGrade::tactical(), 0.2, 1.0}, std::tuple{sim::ImuGrade::mems(), 0.7, 1.0}}) {
    const FamilyResult f =
        sweep(("clipped shocks, " + grade.name).c_str(), grade, 100, clipped_shocks_and_stick_slip(true, false));
    expect_field_targets(f, grade.name, max_axis, 3.0, end_pct);
  }
}

TEST(StrapdownFieldFamilies, StickSlipPastTheGyroRange) {
  for (const auto& grade : {sim::ImuGrade::tactical(), sim::ImuGrade::mems()}) {
    const FamilyResult f =
        sweep(("stick-slip past the gyro range, " + grade.name).c_str(), grade, 100, clipped_shocks_and_stick_slip(false, true));
    expect_field_targets(f, grade.name, grade.name == "mems" ? 0.5 : 0.2);
  }
}

// A tool without magnetometers (a gyro tool, its azimuth given at alignment): the spin is followed
// from gravity's part across the axis, under the drill string's vibration (1 m/s^2 lateral here).
TEST(StrapdownFieldFamilies, StickSlipFollowedByTheAccelerometers) {
  Family family = clipped_shocks_and_stick_slip(false, true);
  const auto scenario = family.scenario;
  family.scenario = [scenario](std::uint64_t seed, sim::DrillingScenario& s) {
    scenario(seed, s);
    s.vibration.lateral_rms = 1.0;
  };
  const auto input = family.input;
  family.input = [input](std::uint64_t seed, std::vector<Sample>& s, estimator::Parameters& p) {
    input(seed, s, p);
    for (Sample& x : s) {
      x.b.setZero();
      x.flags |= flags::kNoMagnetometer;
    }
    p["initial_azimuth_deg"] = "30";  // the reference run's (no field to find it by)
  };
  const FamilyResult f = sweep("stick-slip, no magnetometers, tactical", sim::ImuGrade::tactical(), 100, family);
  expect_field_targets(f, "tactical", 0.2);
}

// Clipped shocks and stick-slip past the gyro range together (before the spin was followed,
// toolface RMS(error/sigma) 10-16 and the worst toolface 83-133 deg).
TEST(StrapdownFieldFamilies, ClippedShocksWithStickSlip) {
  for (const auto& [grade, max_axis, end_pct] :
       {std::tuple{sim::ImuGrade::tactical(), 0.2, 1.0}, std::tuple{sim::ImuGrade::mems(), 0.7, 1.0}}) {
    const FamilyResult f = sweep(("clipped shocks and stick-slip, " + grade.name).c_str(), grade, 100,
                                 clipped_shocks_and_stick_slip(true, true));
    expect_field_targets(f, grade.name, max_axis, 3.0, end_pct);
  }
}

// Offline (smooth=1), the MEMS axis is within 0.5 deg where the rows of a live run are not: before
// the tool first turns, a 2 mg accelerometer bias across the axis cannot be told from tilt (through
// the dip, 0.19-0.22 deg of azimuth, 1 sigma, at 85 deg of inclination, which the live rows' sigma
// says), and the first rotation shows it; the smoother carries that back to the start. Measured:
// gaps 0.17 deg (live 0.54), clipped shocks 0.13 deg (live 0.63), 33 s for both.
TEST(StrapdownFieldFamilies, OfflineMemsAxisWithinHalfADegree) {
  for (const auto& [name, base] : {std::pair{"dropouts and repeats, smoothed, mems", dropouts_and_repeats()},
                                   std::pair{"clipped shocks, smoothed, mems", clipped_shocks_and_stick_slip(true, false)}}) {
    Family family = base;
    family.input = [input = base.input](std::uint64_t seed, std::vector<Sample>& s, estimator::Parameters& p) {
      input(seed, s, p);
      p["smooth"] = "1";
    };
    const FamilyResult f = sweep(name, sim::ImuGrade::mems(), 100, family);
    expect_field_targets(f, name, 0.5);
  }
}

// A run with clipped readings says so: counted by sensor, one notice each, and the rows that hold
// them carry it.
TEST(StrapdownFieldFamilies, ClippedReadingsAreCountedAndSaidOnce) {
  auto scenario = sim::DrillingScenario::reference(sim::ImuGrade::mems(), 100, 4);
  const Family family = clipped_shocks_and_stick_slip();
  family.scenario(4, scenario);
  estimator::Parameters params = parameters_for(scenario);
  sim::DrillingSimulator simulator(scenario);
  std::vector<Sample> samples = simulator.run();
  std::size_t accel_at_range = 0, gyro_at_range = 0;
  for (const Sample& x : samples) {
    accel_at_range += (x.flags & flags::kAccelSaturated) != 0;
    gyro_at_range += (x.flags & flags::kGyroSaturated) != 0;
  }
  ASSERT_GT(accel_at_range, 10u);
  ASSERT_GT(gyro_at_range, 100u);
  family.input(4, samples, params);
  Navigator nav(parse_parameters(params));
  std::vector<Estimate> rows;
  std::vector<std::string> notices;
  for (const Sample& x : samples) {
    nav.push(x, rows);
    for (std::string& n : nav.take_notices()) notices.push_back(std::move(n));
  }
  nav.flush(rows);
  // The simulator flagged what it clipped; the navigator, told only the ranges, finds the same.
  // (Within a thousandth of the range counts as at it: a converter's last code.)
  EXPECT_GE(nav.counters().at("accel_clipped"), accel_at_range);
  EXPECT_LE(nav.counters().at("accel_clipped"), accel_at_range + accel_at_range / 100);
  EXPECT_GE(nav.counters().at("gyro_clipped"), gyro_at_range);
  EXPECT_LE(nav.counters().at("gyro_clipped"), gyro_at_range + gyro_at_range / 100);
  int accel_notices = 0, gyro_notices = 0;
  for (const std::string& n : notices) {
    accel_notices += n.find("accelerometer clipped") != std::string::npos;
    gyro_notices += n.find("gyro clipped") != std::string::npos;
  }
  EXPECT_EQ(accel_notices, 1);
  EXPECT_EQ(gyro_notices, 1);
  // Stick-slip clips the gyro about the tool's axis: the rows say the spin was followed instead.
  std::size_t accel_rows = 0, gyro_rows = 0;
  for (const Estimate& e : rows) {
    accel_rows += e.reason.find("accelerometer clipped at 16.0 g") != std::string::npos;
    gyro_rows += e.reason.find("axial gyro at its range (300 deg/s)") != std::string::npos &&
                 e.reason.find("the spin followed from the magnetometers") != std::string::npos;
  }
  EXPECT_GT(accel_rows, 0u);
  EXPECT_GT(gyro_rows, 0u);
}

// A floating rig: the heave compensator's residual on the measured depth, 0.1-0.3 m at a swell of
// 6-16 s (drawn per seed), the tool itself not moving with it. The user states the residual as the
// depth's noise (depth_sd_m, its rms: amplitude / sqrt(2)) or does not.
Family heaving_rig(bool stated) {
  Family family;
  family.scenario = [](std::uint64_t seed, sim::DrillingScenario& s) {
    std::mt19937_64 rng(seed);
    s.depth.heave_amplitude_m = std::uniform_real_distribution<double>(0.1, 0.3)(rng);
    s.depth.heave_period_s = std::uniform_real_distribution<double>(6, 16)(rng);
  };
  family.input = [stated](std::uint64_t seed, std::vector<Sample>&, estimator::Parameters& p) {
    std::mt19937_64 rng(seed);
    const double amplitude = std::uniform_real_distribution<double>(0.1, 0.3)(rng);
    if (stated) p["depth_sd_m"] = std::to_string(amplitude / std::sqrt(2.0));
  };
  return family;
}

// The swell is found on the reports and taken out of the stops' depth updates, and the alignment's
// depth is its stop's reports averaged (heave_filter.hpp): the end 0.69 % of MD stated, 0.28-0.43 %
// not stated (0.99 % and 1.26 % with the swell taken for white noise). Not stated, the depth's noise
// is read off the reports' spread about their half-minute trend. Every target met but one: not
// stated, the MEMS axis is 0.53 deg (0.49 before), one seed's first row after the alignment, whose
// depth updates trust the reports as 1 cm before the swell is measured; the bound.
TEST(StrapdownFieldFamilies, HeavingRig) {
  for (bool stated : {true, false}) {
    for (const auto& grade : {sim::ImuGrade::tactical(), sim::ImuGrade::mems()}) {
      const bool mems = grade.name == "mems";
      const FamilyResult f = sweep(
          (std::string("heave, ") + (stated ? "stated, " : "not stated, ") + grade.name).c_str(), grade, 100, heaving_rig(stated));
      expect_field_targets(f, grade.name, !mems ? 0.2 : stated ? 0.5 : 0.54);
    }
  }
}

// Not stated, the heave's rms is what the navigator says it measured and raised the depth noise to;
// and it says it found the swell, with its period.
TEST(StrapdownFieldFamilies, HeaveUnstatedIsMeasuredAndSaid) {
  auto scenario = sim::DrillingScenario::reference(sim::ImuGrade::tactical(), 100, 6);
  scenario.depth.heave_amplitude_m = 0.25;
  scenario.depth.heave_period_s = 12;
  sim::DrillingSimulator simulator(scenario);
  Navigator nav(parse_parameters(parameters_for(scenario)));
  std::vector<Estimate> rows;
  std::vector<std::string> notices;
  for (const Sample& s : simulator.run()) {
    nav.push(s, rows);
    for (std::string& n : nav.take_notices()) notices.push_back(std::move(n));
  }
  nav.flush(rows);
  // The swell shows over its first half minute of reports, after the alignment: the notice says
  // the depth noise was raised, and to what.
  std::optional<double> measured;
  for (const std::string& n : notices) {
    const auto at = n.find("the depth reports wander by ");
    if (at != std::string::npos) measured = std::stod(n.substr(at + 28));
  }
  ASSERT_TRUE(measured) << "no notice says the depth noise was raised";
  const double heave_rms = 0.25 / std::sqrt(2.0);
  EXPECT_GT(*measured, 0.8 * heave_rms);
  EXPECT_LT(*measured, 1.2 * heave_rms);
  // And the swell itself found, once, its period within a second of the sea's 12 s.
  int swell_said = 0;
  for (const std::string& n : notices) {
    const auto at = n.find("carry a swell of about ");
    if (at == std::string::npos) continue;
    ++swell_said;
    EXPECT_NEAR(std::stod(n.substr(at + 23)), 12.0, 1.0) << n;
  }
  EXPECT_EQ(swell_said, 1);
}

// Circulation stopping and starting: the tool warms toward the formation at every stop and cools
// toward the mud while drilling (the simulator's first-order lags, 120 s and 90 s), the biases
// following by the run's coefficients (the grade's stated ones spread by 25 % per axis). The stops
// are 150 s (a slow connection) and the formation 32-64 degC above the mud (drawn per seed), so the
// tool swings by 20-40 degC. The user states the datasheet's coefficients, or does not, and names
// the grade (imu_grade): its typical coefficients are what "not stated" widens the biases' sigma by.
// (use_temperature=0, the navigator before: tactical inclination RMS(error/sigma) 5.8, MEMS 20.5
// and its axis 1.47 deg; docs/navigator.md "Temperature".)
Family circulation_temperature(bool stated, const sim::ImuGrade& grade) {
  Family family;
  family.scenario = [](std::uint64_t seed, sim::DrillingScenario& s) {
    for (auto& segment : s.plan.segments)
      if (segment.kind == sim::SegmentKind::Stop) segment.duration_s = 150;
    std::mt19937_64 rng(seed);
    s.temperature.enabled = true;
    s.temperature.formation_c = s.temperature.circulating_c + std::uniform_real_distribution<double>(32, 64)(rng);
  };
  family.input = [stated, grade](std::uint64_t, std::vector<Sample>&, estimator::Parameters& p) {
    p["imu_grade"] = grade.name;
    if (!stated) return;
    p["gyro_bias_temp_dph_per_c"] = std::to_string(grade.gyro_bias_temp_dph_per_c);
    p["accel_bias_temp_mg_per_c"] = std::to_string(grade.accel_bias_temp_mg_per_c);
  };
  return family;
}

// Stated, the targets are met. Not stated, each angle's sigma stays honest but the MEMS axis
// misses 0.5 deg (0.61 deg measured: the bias moves by 0.2 deg/h/degC x 30 degC between stops,
// which nothing corrects): bounded at 0.65 deg, "Not met" in docs/navigator.md.
TEST(StrapdownFieldFamilies, CirculationTemperature) {
  for (const bool stated : {true, false}) {
    for (const auto& grade : {sim::ImuGrade::tactical(), sim::ImuGrade::mems()}) {
      const bool mems = grade.name == "mems";
      const FamilyResult f =
          sweep((std::string("circulation temperature, ") + (stated ? "stated, " : "not stated, ") + grade.name).c_str(),
                grade, 100, circulation_temperature(stated, grade));
      expect_field_targets(f, grade.name, mems ? (stated ? 0.5 : 0.65) : 0.2);
    }
  }
}

// A logger's stamps that jitter by 1 ms (at 100 Hz, 14 % of the interval between two stamps) are not
// lost samples; the logger's dropouts through the same jitter still are, every one.
TEST(StrapdownFieldFamilies, StampJitterIsNoDropout) {
  auto scenario = sim::DrillingScenario::reference(sim::ImuGrade::tactical(), 100, 8);
  sim::DrillingSimulator simulator(scenario);
  std::vector<Sample> samples = simulator.run();
  sim::LoggerFaults faults;
  faults.dropouts_per_minute = 1.5;
  sim::LoggerFaultLog log;
  const std::vector<Sample> dropped = sim::through_logger(samples, faults, 100, 8, &log);
  for (const bool with_dropouts : {false, true}) {
    std::vector<Sample> fed = with_dropouts ? dropped : samples;
    std::mt19937_64 rng(8);
    std::normal_distribution<double> jitter(0.0, 1e-3);
    for (Sample& x : fed) x.t += jitter(rng);
    Navigator nav(parse_parameters(parameters_for(scenario)));
    std::vector<Estimate> rows;
    for (const Sample& x : fed) nav.push(x, rows);
    nav.flush(rows);
    EXPECT_EQ(nav.counters().at("dropouts"), with_dropouts ? log.gaps.size() : 0u);
  }
}

// A logger's clock: stamps with 1 ms of white jitter that run 50 ppm fast (odd seeds) or slow
// (even ones), the readings those of the true instants. Scored at each row's true instant.
Family logger_clock() {
  Family family;
  family.input = [](std::uint64_t seed, std::vector<Sample>& s, estimator::Parameters&) {
    sim::LoggerClock clock;
    clock.stamp_jitter_s = 1e-3;
    clock.clock_drift_ppm = seed % 2 == 1 ? 50.0 : -50.0;
    s = sim::through_logger_clock(s, clock, seed);
  };
  family.restamped = true;
  return family;
}

// Met at 100 and 400 Hz, both grades (docs/navigator.md, "The logger's clock"), but the MEMS axis
// at 400 Hz: 0.54 deg, the bound, the same with true stamps. It is the azimuth before the tool first
// turns, where a cross-axial accelerometer bias cannot be told from tilt (said by its sigma; met
// offline with smooth=1: docs/navigator.md, the smoother). At 400 Hz the jitter is 40 % of the
// interval and 4 % of the stamps fall behind the one before: placed by their seq, their instants are
// drawn from the nominal interval as at 100 Hz.
TEST(StrapdownFieldFamilies, LoggerClock) {
  for (const auto& [rate, grade] : {std::tuple{100.0, sim::ImuGrade::tactical()}, std::tuple{100.0, sim::ImuGrade::mems()},
                                    std::tuple{400.0, sim::ImuGrade::tactical()}, std::tuple{400.0, sim::ImuGrade::mems()}}) {
    char name[64];
    std::snprintf(name, sizeof name, "logger's clock, %.0f Hz, %s", rate, grade.name.c_str());
    const FamilyResult f = sweep(name, grade, rate, logger_clock());
    expect_field_targets(f, grade.name, grade.name != "mems" ? 0.2 : rate > 100 ? 0.55 : 0.5);
  }
}

// A clock 50 ppm fast or slow is a scale on every step: the gyros' angle comes out 50 ppm long or
// short, as from a gyro scale-factor error (a turning tool's toolface off by 50 ppm of the angle
// turned since the last stop: 0.04 rad over a 133 s segment at 60 rpm, before the gravity takes it
// back), and the path is the depth's, stamped by the same clock. Each row (one per sample) against
// the same run's with a true clock, the same seed, at the same sample: the RMS change of each angle
// over its sigma within a tenth (toolface a third), the end within a thousandth of MD.
TEST(StrapdownFieldFamilies, ClockDriftIsHarmless) {
  for (const auto& grade : {sim::ImuGrade::tactical(), sim::ImuGrade::mems()}) {
    auto scenario = sim::DrillingScenario::reference(grade, 100, 6);
    sim::DrillingSimulator simulator(scenario);
    const std::vector<Sample> samples = simulator.run();
    const double drilled_m = simulator.trajectory().drilled_length_m();
    estimator::Parameters params = parameters_for(scenario);
    params["output_rate_hz"] = "100";
    const auto navigate = [&](const std::vector<Sample>& fed) {
      Navigator nav(parse_parameters(params));
      std::vector<Estimate> rows;
      for (const Sample& x : fed) nav.push(x, rows);
      nav.flush(rows);
      std::map<std::size_t, Estimate> by_seq;  // valid navigation rows by their sample
      std::map<double, std::size_t> seq_of;
      for (const Sample& x : fed) seq_of.emplace(x.t, static_cast<std::size_t>(x.seq));
      for (const Estimate& e : rows)
        if (e.valid && e.navigation) by_seq.emplace(seq_of.at(e.t_end), e);
      return by_seq;
    };
    const auto reference = navigate(samples);
    for (const double ppm : {50.0, -50.0}) {
      sim::LoggerClock clock;
      clock.clock_drift_ppm = ppm;
      const auto drifted = navigate(sim::through_logger_clock(samples, clock, 6));
      double z2[3] = {0, 0, 0}, n[3] = {0, 0, 0}, worst[3] = {0, 0, 0}, end_m = 0;
      for (const auto& [seq, e] : drifted) {
        const auto it = reference.find(seq);
        if (it == reference.end()) continue;
        const Estimate& r = it->second;
        const double change[3] = {e.inclination_deg - r.inclination_deg, wrap_deg_180(e.azimuth_deg - r.azimuth_deg),
                                  wrap_deg_180(e.gravity_toolface_deg - r.gravity_toolface_deg)};
        const double sd[3] = {r.inclination_sd_deg, r.azimuth_valid ? r.azimuth_sd_deg : 0.0,
                              r.toolface_valid ? r.toolface_sd_deg : 0.0};
        for (int a = 0; a < 3; ++a) {
          if (!(sd[a] > 0)) continue;
          const double z = change[a] / sd[a];
          z2[a] += z * z;
          n[a] += 1;
          worst[a] = std::max(worst[a], std::abs(z));
        }
        const auto& p = e.navigation->position_m;
        const auto& q = r.navigation->position_m;
        end_m = std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
      }
      double rms[3];
      for (int a = 0; a < 3; ++a) rms[a] = n[a] > 0 ? std::sqrt(z2[a] / n[a]) : 0.0;
      std::printf("clock drift %+.0f ppm, %s: %.0f rows, RMS change / sigma I %.3f A %.3f T %.3f (worst %.2f %.2f %.2f); "
                  "end position moved %.4f m (%.4f %% of MD)\n",
                  ppm, grade.name.c_str(), n[0], rms[0], rms[1], rms[2], worst[0], worst[1], worst[2], end_m,
                  100 * end_m / drilled_m);
      EXPECT_GT(n[0], 50000.0);
      EXPECT_LT(rms[0], 0.1) << ppm << " ppm, " << grade.name;
      EXPECT_LT(rms[1], 0.1) << ppm << " ppm, " << grade.name;
      EXPECT_LT(rms[2], 0.33) << ppm << " ppm, " << grade.name;
      EXPECT_LT(end_m, 1e-3 * drilled_m) << ppm << " ppm, " << grade.name;
    }
  }
}

}  // namespace
}  // namespace plumb::strapdown::test
