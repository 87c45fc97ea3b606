// Near vertical the azimuth and the gravity toolface are weakly defined: their sigma grows as
// 1/sin(I), as the survey error models say, while the tool axis (what position needs) and the
// toolface from north (magnetic, as drilling tools steer by there) stay well defined. The rows
// below toolface_switch_deg say which toolface to steer by, with its sigma.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "drilling_support.hpp"

namespace plumb::strapdown::test {
namespace {

// Rotary drilling at inclination inc: four 8 m segments at 0.05 m/s and 60 rpm with 60 s stops.
sim::DrillingScenario near_vertical(const char* grade, std::uint64_t seed, double inc) {
  auto s = sim::DrillingScenario::reference(sim::ImuGrade::named(grade), 100, seed);
  s.plan.inclination_deg = inc;
  s.plan.segments.clear();
  for (int k = 0; k < 4; ++k) {
    s.plan.segments.push_back(sim::DrillSegment::rotary(8, 0.05, 60, 0, 0));
    s.plan.segments.push_back(sim::DrillSegment::stop(60));
  }
  return s;
}

// The magnetic toolface of the truth: the field (magnetic north, dip) in the tool frame.
double true_magnetic_toolface_deg(const TruthSample& tr, double dip_deg) {
  const Eigen::Vector3d b_n(std::cos(dip_deg * kDeg), 0.0, std::sin(dip_deg * kDeg));
  const Eigen::Vector3d b = c_nb(tr.inclination_deg * kDeg, tr.azimuth_deg * kDeg, tr.toolface_deg * kDeg) * b_n;
  return std::atan2(-b.y(), b.x()) / kDeg;
}

struct NearVerticalScore {
  double azimuth_sd_sin_i = 0;  // mean of the azimuth's sigma times sin(I) over the rows at stops
  double max_mtf_err_deg = 0, mtf_rms_z = 0;
  std::size_t rows = 0, rows_with_note = 0;
};

NearVerticalScore score(const sim::DrillingScenario& scenario) {
  auto [samples, truth] = simulate(scenario);
  for (Sample& x : samples) x.flags &= ~flags::kHasDepth;
  Navigator nav(parse_parameters(parameters_for(scenario)));
  std::vector<Estimate> rows;
  for (const Sample& s : samples) nav.push(s, rows);
  nav.flush(rows);
  NearVerticalScore out;
  double z2 = 0, at_stops = 0;
  const std::string key = "steer by the magnetic toolface magnetic_toolface_deg (sigma ";
  for (const Estimate& e : rows) {
    if (!e.valid) continue;
    ++out.rows;
    const TruthSample& tr = truth[std::min<std::size_t>(std::llround(e.t_end * 100), truth.size() - 1)];
    if (e.navigation->still) {
      out.azimuth_sd_sin_i += e.azimuth_sd_deg * std::sin(e.inclination_deg * kDeg);
      ++at_stops;
    }
    const std::size_t at = e.reason.find(key);
    if (at == std::string::npos) continue;
    ++out.rows_with_note;
    const double sd = std::atof(e.reason.c_str() + at + key.size());
    const double err = wrap_deg_180(e.magnetic_toolface_deg - true_magnetic_toolface_deg(tr, scenario.dip_deg));
    out.max_mtf_err_deg = std::max(out.max_mtf_err_deg, std::abs(err));
    z2 += err * err / (sd * sd);
  }
  out.azimuth_sd_sin_i /= std::max(at_stops, 1.0);
  out.mtf_rms_z = std::sqrt(z2 / std::max<double>(out.rows_with_note, 1));
  return out;
}

TEST(StrapdownNearVertical, AzimuthSigmaFollowsTheGeometryAndTheToolfaceFromNorthStaysHonest) {
  for (const char* grade : {"tactical", "mems"}) {
    NearVerticalScore at[3];
    const double inclinations[3] = {1.0, 2.0, 4.0};
    for (int k = 0; k < 3; ++k) {
      at[k] = score(near_vertical(grade, 7, inclinations[k]));
      std::printf("%s I %.0f deg: azimuth sigma x sin(I) %.4f deg, magnetic toolface max error %.3f deg, "
                  "RMS(error/sigma) %.2f over %zu rows of %zu\n",
                  grade, inclinations[k], at[k].azimuth_sd_sin_i, at[k].max_mtf_err_deg, at[k].mtf_rms_z,
                  at[k].rows_with_note, at[k].rows);
      EXPECT_EQ(at[k].rows_with_note, at[k].rows) << grade << " " << inclinations[k];  // below 5 deg: every row
      EXPECT_LE(at[k].mtf_rms_z, 2.0) << grade << " " << inclinations[k];
      // While the string turns the toolface is only as good as the gyro's scale factor, which the stops
      // find from a gravity toolface that weakens as sin(I): 1.25 deg (tactical) and 5.6 deg (MEMS) at 1 deg.
      EXPECT_LE(at[k].max_mtf_err_deg, (std::string(grade) == "mems" ? 8.0 : 2.0) / inclinations[k]) << grade << " " << inclinations[k];
    }
    // The azimuth's sigma is the tilt's across the high side over sin(I): the same tilt at 1, 2 and 4 deg.
    for (int k = 1; k < 3; ++k) {
      EXPECT_NEAR(at[k].azimuth_sd_sin_i / at[0].azimuth_sd_sin_i, 1.0, 0.35) << grade << " " << inclinations[k];
    }
  }
}

}  // namespace
}  // namespace plumb::strapdown::test
