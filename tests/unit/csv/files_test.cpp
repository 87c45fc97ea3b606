// The sensor, attitude and truth CSV formats of docs/conventions.md.
#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include "plumb/csv/files.hpp"

namespace plumb::csv {
namespace {

TEST(SensorCsv, ColumnOrderIsFreeUnknownColumnsIgnoredCommentsSkipped) {
  std::istringstream in(
      "# recorded on the bench\n"
      "bz,by,bx,extra,fz,fy,fx,t\n"
      "3,2,1,junk,-9.8,0.5,0.25,0.01\n"
      "\n"
      "# a comment between rows\n"
      "6,5,4,junk,-9.7,0.4,0.2,0.02\n");
  SensorReader r(in, "mem");
  EXPECT_FALSE(r.has_gyro());
  EXPECT_FALSE(r.has_temperature());
  Sample s;
  ASSERT_TRUE(r.next(s));
  EXPECT_EQ(s.seq, 0u);
  EXPECT_DOUBLE_EQ(s.t, 0.01);
  EXPECT_EQ(s.f, Eigen::Vector3d(0.25, 0.5, -9.8));
  EXPECT_EQ(s.b, Eigen::Vector3d(1, 2, 3));
  ASSERT_TRUE(r.next(s));
  EXPECT_EQ(s.seq, 1u);
  EXPECT_EQ(s.b, Eigen::Vector3d(4, 5, 6));
  EXPECT_FALSE(r.next(s));
}

TEST(SensorCsv, MissingColumnIsNamed) {
  std::istringstream in("t,fx,fy,fz,bx,bz\n0,0,0,0,0,0\n");
  try {
    SensorReader r(in, "file.csv");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.line, 1u);
    EXPECT_NE(std::string(e.what()).find("by"), std::string::npos) << e.what();
  }
}

TEST(SensorCsv, BadNumberNamesLineAndColumnAndReadingGoesOn) {
  std::istringstream in("t,fx,fy,fz,bx,by,bz,temp_c\n0,0,0,0,0,0,0,25\n0.01,0,abc,0,0,0,0,25\n0.02,1,1,1,1,1,1,26\n");
  SensorReader r(in, "file.csv");
  Sample s;
  ASSERT_TRUE(r.next(s));
  try {
    r.next(s);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.line, 3u);
    EXPECT_EQ(e.column, "fy");
    EXPECT_EQ(std::string(e.what()), "file.csv:3: column 'fy': bad number 'abc'");
  }
  ASSERT_TRUE(r.next(s));
  EXPECT_DOUBLE_EQ(s.temp_c, 26);
  EXPECT_TRUE(s.flags & flags::kHasTemperature);
}

TEST(SensorCsv, ShortRowAndPartialGyroAreErrors) {
  std::istringstream short_row("t,fx,fy,fz,bx,by,bz\n0,1,2\n");
  SensorReader r(short_row, "m");
  Sample s;
  EXPECT_THROW(r.next(s), Error);
  std::istringstream partial("t,fx,fy,fz,bx,by,bz,wx,wy\n");
  EXPECT_THROW(SensorReader(partial, "m"), Error);
  std::istringstream empty("");
  EXPECT_THROW(SensorReader(empty, "m"), Error);
}

TEST(SensorCsv, NonFiniteValuesAreKeptAndFlagged) {
  std::istringstream in("t,fx,fy,fz,bx,by,bz\n0,nan,0,0,inf,0,0\n");
  SensorReader r(in, "m");
  Sample s;
  ASSERT_TRUE(r.next(s));
  EXPECT_TRUE(s.flags & flags::kNotFinite);
  EXPECT_TRUE(std::isnan(s.f.x()));
}

// Rig depth arrives about once a second: the rows between reports leave depth_m empty.
TEST(SensorCsv, EmptyDepthCellIsARowWithoutDepth) {
  std::istringstream in("t,fx,fy,fz,depth_m\n0,0,0,-9.8,12.5\n0.01,0,0,-9.8,\n0.02,0,0,-9.8,12.51\n");
  SensorReader r(in, "m");
  Sample s;
  ASSERT_TRUE(r.next(s));
  EXPECT_TRUE(s.flags & flags::kHasDepth);
  EXPECT_DOUBLE_EQ(s.depth_m, 12.5);
  ASSERT_TRUE(r.next(s));
  EXPECT_FALSE(s.flags & flags::kHasDepth);
  EXPECT_FALSE(s.flags & flags::kNotFinite);
  ASSERT_TRUE(r.next(s));
  EXPECT_TRUE(s.flags & flags::kHasDepth);
  EXPECT_DOUBLE_EQ(s.depth_m, 12.51);
}

TEST(SensorCsv, WriteThenReadRoundTrips) {
  std::stringstream io;
  write_sensor_header(io, true, true);
  Sample a;
  a.seq = 41;
  a.t = 12.345678901;
  a.f = {0.125, -9.80665, 1e-5};
  a.b = {20.5, -3.25, 40.125};
  a.w = {1e-5, -2e-5, 6.283};
  a.temp_c = 151.5;
  write_sensor_row(io, a, true, true);
  SensorReader r(io, "m");
  ASSERT_TRUE(r.has_gyro());
  Sample b;
  ASSERT_TRUE(r.next(b));
  EXPECT_EQ(b.seq, 41u);
  EXPECT_NEAR(b.t, a.t, 1e-9);
  EXPECT_NEAR((b.f - a.f).norm(), 0, 1e-9);
  EXPECT_NEAR((b.b - a.b).norm(), 0, 1e-8);
  EXPECT_NEAR((b.w - a.w).norm(), 0, 1e-9);
  EXPECT_DOUBLE_EQ(b.temp_c, 151.5);
}

TEST(AttitudeCsv, HeaderStartsWithTheRequiredColumnsAndReasonsCannotBreakRows) {
  std::ostringstream out;
  write_attitude_header(out);
  EXPECT_EQ(out.str().rfind("t,inclination_deg,azimuth_deg,toolface_deg,rpm,valid,", 0), 0u);
  Estimate e;
  e.reason = "bad, very bad\nreally";
  write_attitude_row(out, e);
  const std::string text = out.str();
  const std::string row = text.substr(text.find('\n') + 1);
  EXPECT_EQ(split_line(row.substr(0, row.size() - 1)).size(), split_line(text.substr(0, text.find('\n'))).size());
}

TEST(AttitudeCsv, WhatWasNotMeasuredIsAnEmptyCell) {
  std::ostringstream out;
  write_attitude_header(out);
  Estimate e;
  e.t_end = 2;
  e.inclination_deg = e.azimuth_deg = e.gravity_toolface_deg = e.dip_deg = std::nan("");
  e.rpm = 60;
  write_attitude_row(out, e);
  const std::string text = out.str();
  const auto header = split_line(text.substr(0, text.find('\n')));
  const std::string row = text.substr(text.find('\n') + 1);
  const auto cells = split_line(row.substr(0, row.size() - 1));
  ASSERT_EQ(cells.size(), header.size());
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == "inclination_deg" || header[i] == "azimuth_deg" || header[i] == "toolface_deg" || header[i] == "dip_deg") {
      EXPECT_EQ(cells[i], "") << header[i];
    }
    if (header[i] == "rpm") {
      EXPECT_EQ(cells[i], "60");
    }
  }
  EXPECT_EQ(text.find("nan"), std::string::npos) << text;
}

}  // namespace
}  // namespace plumb::csv
