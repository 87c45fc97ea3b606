// QC against the reference field and the azimuth references.
#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include "plumb/survey/azimuth_reference.hpp"
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
  NorthCorrections none;
  EXPECT_THROW(convert_magnetic_azimuth(3, AzimuthReference::True, none), std::invalid_argument);
  none.declination_known = true;
  EXPECT_THROW(convert_magnetic_azimuth(3, AzimuthReference::Grid, none), std::invalid_argument);
  EXPECT_EQ(parse_azimuth_reference("grid"), AzimuthReference::Grid);
  EXPECT_FALSE(parse_azimuth_reference("Grid"));
}

}  // namespace
}  // namespace plumb::survey
