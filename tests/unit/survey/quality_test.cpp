// QC against the reference field, the azimuth references, and multi-station analysis.
#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include "plumb/core/attitude.hpp"
#include "plumb/survey/azimuth_reference.hpp"
#include "plumb/survey/multi_station.hpp"
#include "plumb/survey/quality.hpp"

namespace plumb::survey {
namespace {

ReferenceField site() {
  ReferenceField r;
  r.gravity_mps2 = 9.80665;
  r.total_b_uT = 50;
  r.dip_deg = 60;
  return r;
}

TEST(Quality, WithinDefaultTolerancesPasses) {
  const auto q = check_station(9.80665 + 0.02, 50.25, 60.2, site(), {});
  EXPECT_TRUE(q.pass) << q.reason;
  EXPECT_NEAR(q.total_b_residual_uT, 0.25, 1e-12);
  EXPECT_NEAR(q.dip_residual_deg, 0.2, 1e-12);
  EXPECT_TRUE(q.reason.empty());
}

TEST(Quality, EachFailedCheckIsNamed) {
  const auto q = check_station(9.80665 + 0.04, 50.4, 59.6, site(), {});
  EXPECT_FALSE(q.pass);
  EXPECT_NE(q.reason.find("|G| off by 0.0400"), std::string::npos) << q.reason;
  EXPECT_NE(q.reason.find("|B| off by 0.400"), std::string::npos) << q.reason;
  EXPECT_NE(q.reason.find("dip off by -0.400"), std::string::npos) << q.reason;
  // Per-tool overrides: a wider |B| tolerance passes the same field.
  QcTolerances wide;
  wide.total_b_uT = 0.5;
  wide.gravity_mps2 = 0.05;
  wide.dip_deg = 0.5;
  EXPECT_TRUE(check_station(9.80665 + 0.04, 50.4, 59.6, site(), wide).pass);
}

TEST(Quality, MissingReferenceOrMeasurementFailsNeverPasses) {
  ReferenceField r = site();
  r.total_b_uT.reset();
  auto q = check_station(9.80665, 50, 60, r, {});
  EXPECT_FALSE(q.pass);
  EXPECT_NE(q.reason.find("no reference |B|"), std::string::npos);
  QcChecks skip;
  skip.total_b = false;
  EXPECT_TRUE(check_station(9.80665, 50, 60, r, {}, skip).pass);
  q = check_station(9.80665, std::nan(""), std::nan(""), site(), {});
  EXPECT_FALSE(q.pass);
  EXPECT_NE(q.reason.find("no |B| measured"), std::string::npos) << q.reason;
}

TEST(Quality, ReferenceFile) {
  std::istringstream good("# site model\ngravity_mps2 9.81\ntotal_b_uT 48.4\ndip_deg 45.5\ndeclination_deg -3.2\n");
  const auto r = read_reference_file(good, "site.txt");
  EXPECT_EQ(*r.gravity_mps2, 9.81);
  EXPECT_EQ(*r.declination_deg, -3.2);
  std::istringstream bad_key("gravity 9.81\n");
  EXPECT_THROW(read_reference_file(bad_key, "site.txt"), std::runtime_error);
  std::istringstream bad_value("dip_deg 95\n");
  EXPECT_THROW(read_reference_file(bad_value, "site.txt"), std::runtime_error);
  std::istringstream junk("total_b_uT 48 extra\n");
  EXPECT_THROW(read_reference_file(junk, "site.txt"), std::runtime_error);
}

TEST(AzimuthReference, TrueAndGrid) {
  NorthCorrections c;
  c.declination_deg = -7.5;
  c.declination_known = true;
  c.convergence_deg = 1.25;
  c.convergence_known = true;
  EXPECT_NEAR(convert_magnetic_azimuth(3, AzimuthReference::True, c), 355.5, 1e-12);
  EXPECT_NEAR(convert_magnetic_azimuth(3, AzimuthReference::Grid, c), 354.25, 1e-12);
  EXPECT_NEAR(convert_magnetic_azimuth(-3, AzimuthReference::Magnetic, c), 357, 1e-12);
  // Back to true north from each reference: the grid azimuth 354.25 plus 1.25 is the true 355.5.
  EXPECT_EQ(true_azimuth_offset_deg(AzimuthReference::True, c), 0);
  EXPECT_EQ(true_azimuth_offset_deg(AzimuthReference::Grid, c), 1.25);
  EXPECT_EQ(true_azimuth_offset_deg(AzimuthReference::Magnetic, c), -7.5);
  NorthCorrections none;
  EXPECT_EQ(true_azimuth_offset_deg(AzimuthReference::Magnetic, none), 0);  // magnetic north taken for true
  EXPECT_THROW(convert_magnetic_azimuth(3, AzimuthReference::True, none), std::invalid_argument);
  none.declination_known = true;
  EXPECT_THROW(convert_magnetic_azimuth(3, AzimuthReference::Grid, none), std::invalid_argument);
  EXPECT_EQ(parse_azimuth_reference("grid"), AzimuthReference::Grid);
  EXPECT_FALSE(parse_azimuth_reference("Grid"));
}

}  // namespace
}  // namespace plumb::survey

// Multi-station analysis against the closed-form attitude: stations measured with a known axial
// magnetometer bias (G and B from the frames of docs/conventions.md, b added to Bz, then |B|, dip and
// azimuth as any estimator computes them) give that bias back, and the unbiased azimuths.
namespace plumb::survey {
namespace {

TEST(MultiStation, RecoversAKnownAxialMagnetometerBias) {
  ReferenceField ref;
  ref.gravity_mps2 = 9.80665;
  ref.total_b_uT = 50;
  ref.dip_deg = 60;
  const double bias = 0.4;  // uT: a magnetised drill string
  std::vector<Station> stations;
  std::vector<double> true_azimuth;
  for (int k = 0; k < 12; ++k) {
    const double inc = (20 + 6 * k) * kDeg, az = (15 + 29 * k) * kDeg, tf = (40 + 77 * k) * kDeg;
    const Eigen::Vector3d G = gravity_tool(inc, tf, 9.80665);
    Eigen::Vector3d B = field_tool(inc, az, tf, 50, 60 * kDeg);
    B.z() += bias;
    const ClosedForm m = closed_form_attitude(G, B);
    Station s;
    s.md_m = 100 + 10 * k;
    s.inclination_deg = m.inclination_deg;
    s.magnetic_azimuth_deg = m.azimuth_deg;
    s.total_g_mps2 = m.total_g;
    s.total_b_uT = m.total_b;
    s.dip_deg = m.dip_deg;
    stations.push_back(s);
    true_azimuth.push_back(az / kDeg);
  }
  const auto e = estimate_axial_bias(stations, ref);
  ASSERT_TRUE(e.valid) << e.reason;
  EXPECT_EQ(e.stations, 12u);
  EXPECT_NEAR(e.bias_uT, bias, 0.01);  // first-order model: the rest is (b/|B|)^2
  EXPECT_LT(e.rms_b_after_uT, 0.1 * e.rms_b_before_uT);
  for (std::size_t k = 0; k < stations.size(); ++k) {
    const double before = std::abs(wrap_deg_180(stations[k].magnetic_azimuth_deg - true_azimuth[k]));
    const double after = std::abs(wrap_deg_180(
        azimuth_without_axial_bias(stations[k].inclination_deg, stations[k].magnetic_azimuth_deg, e.bias_uT, ref) -
        true_azimuth[k]));
    EXPECT_LT(after, std::max(0.01, 0.1 * before)) << "station " << k << ": " << before << " -> " << after;
  }
  // No bias, no estimate beyond the noise: an unbiased run gives ~0.
  for (auto& s : stations) s.total_b_uT = 50, s.dip_deg = 60;
  EXPECT_NEAR(estimate_axial_bias(stations, ref).bias_uT, 0, 1e-12);
  EXPECT_FALSE(estimate_axial_bias(stations, ReferenceField{}).valid);
}

}  // namespace
}  // namespace plumb::survey
