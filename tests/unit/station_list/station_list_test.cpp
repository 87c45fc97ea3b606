// The station list file: round trip, and errors that name file, line and column.
#include <sstream>

#include <gtest/gtest.h>

#include "plumb/calibration/report.hpp"
#include "plumb/calibration/station_list.hpp"

namespace plumb {
namespace {

TEST(StationList, RoundTrip) {
  std::vector<calibration::Station> in(2);
  in[0].name = "25C/+x@90";
  in[0].start_s = 0.1;
  in[0].end_s = 40.000000000000007;
  in[0].orientation = calibration::parse_orientation("+x@90");
  in[0].run = "25C";
  in[0].reference_temps_c = {25.01, 24.99};
  in[1].name = "s2";
  in[1].start_s = 45;
  in[1].end_s = 85;
  std::stringstream s;
  calibration::write_station_list(s, in);
  const auto out = calibration::parse_station_list(s, "mem");
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].name, in[0].name);
  EXPECT_EQ(out[0].end_s, in[0].end_s);
  EXPECT_EQ(out[0].orientation.label(), "+x@90");
  EXPECT_EQ(out[0].run, "25C");
  EXPECT_EQ(out[0].reference_temps_c, in[0].reference_temps_c);
  EXPECT_FALSE(out[1].orientation.known());
  EXPECT_TRUE(out[1].reference_temps_c.empty());
}

std::string error_of(const std::string& text) {
  std::istringstream in(text);
  try {
    calibration::parse_station_list(in, "st.csv");
  } catch (const calibration::CalibrationError& e) {
    return e.what();
  }
  return "";
}

TEST(StationList, ErrorsNameFileLineAndColumn) {
  EXPECT_NE(error_of("name,start_s,orientation\n").find("st.csv:1: header lacks column 'end_s'"), std::string::npos);
  EXPECT_NE(error_of("name,start_s,end_s,orientation\na,0,x,+x\n").find("st.csv:2: column 'end_s': bad number 'x'"),
            std::string::npos);
  EXPECT_NE(error_of("name,start_s,end_s,orientation\na,0,5,+w\n").find("st.csv:2: column 'orientation'"),
            std::string::npos);
  EXPECT_NE(error_of("name,start_s,end_s,orientation\na,0,5,+x\na,6,9,-x\n").find("already given on line 2"),
            std::string::npos);
  EXPECT_NE(error_of("name,start_s,end_s,orientation\na,5,5,+x\n").find("end_s is not after start_s"), std::string::npos);
  EXPECT_NE(error_of("# only a comment\n").find("no header"), std::string::npos);
}

TEST(Report, FailedOutcomeSaysNoCoefficients) {
  calibration::Outcome o;
  o.error = "station 'p+y': never settled";
  const std::string r = calibration::format_report(o, "6pos");
  EXPECT_NE(r.find("FAILED: station 'p+y': never settled"), std::string::npos);
  EXPECT_NE(r.find("no coefficients"), std::string::npos);
}

}  // namespace
}  // namespace plumb
