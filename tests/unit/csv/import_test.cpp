// Other loggers' sensor files read as they are (csv_import.hpp): columns, units, axes, quoting,
// files without magnetometers, and the checks that say when declared units look wrong.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "plumb/csv/files.hpp"
#include "plumb/csv/import.hpp"

namespace plumb::csv {
namespace {

namespace fs = std::filesystem;
constexpr double kG = 9.80665;
constexpr double kDeg = std::numbers::pi / 180;

// A tool turning at 60 rpm, inclined 30 deg, with a little wobble on every axis: one truth for
// both files.
std::vector<Sample> truth(int n = 300) {
  std::vector<Sample> out;
  for (int k = 0; k < n; ++k) {
    Sample s;
    s.seq = static_cast<std::uint64_t>(k);
    s.t = 0.01 * k;
    const double tf = 2 * std::numbers::pi * s.t;
    const double inc = 30 * kDeg;
    s.f = {9.81 * std::sin(inc) * std::cos(tf), -9.81 * std::sin(inc) * std::sin(tf), -9.81 * std::cos(inc)};
    s.f += Eigen::Vector3d(0.01 * std::sin(7.0 * k), 0.02 * std::cos(3.0 * k), 0.015 * std::sin(5.0 * k));
    s.b = {33.9 * std::cos(tf + 0.3), -33.9 * std::sin(tf + 0.3), 34.5 + 0.1 * std::sin(2.0 * k)};
    s.w = {0.001 * std::sin(1.0 * k), -0.002 * std::cos(2.0 * k), 2 * std::numbers::pi + 0.01 * std::sin(1.0 * k)};
    s.temp_c = 25 + 0.001 * k;
    s.flags = flags::kHasGyro | flags::kHasTemperature;
    out.push_back(s);
  }
  return out;
}

std::string g17(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

class TempDir : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("plumb_csv_import_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    const auto path = (dir_ / name).string();
    std::ofstream(path) << text;
    return path;
  }
  fs::path dir_;
};

// plumb's own format, full precision.
std::string plumb_file(const std::vector<Sample>& samples) {
  std::string text = "t,fx,fy,fz,bx,by,bz,wx,wy,wz,temp_c\n";
  for (const auto& s : samples) {
    text += g17(s.t);
    for (const auto* v : {&s.f, &s.b, &s.w})
      for (int i = 0; i < 3; ++i) text += "," + g17((*v)[i]);
    text += "," + g17(s.temp_c) + "\n";
  }
  return text;
}

// Another logger's export: quoted headers (one with a comma), its own column order, ms, g, deg/s,
// gauss, sensor axes x,-y,-z from the tool's, an unmapped column, some quoted numbers.
std::string other_logger_file(const std::vector<Sample>& samples) {
  std::string text =
      "# Exported by SomeLogger 4.2\n"
      "\"Time (ms)\",\"Battery, main (V)\",\"Accel X (g)\",\"Accel Y (g)\",\"Accel Z (g)\","
      "\"Gyroscope X (deg/s)\",\"Gyroscope Y (deg/s)\",\"Gyroscope Z (deg/s)\","
      "\"Mag X (G)\",\"Mag Y (G)\",\"Mag Z (G)\",\"Temp (C)\"\r\n";
  const Eigen::Vector3d flip(1, -1, -1);  // sensor = flip .* tool for x,-y,-z
  for (const auto& s : samples) {
    text += "\"" + g17(s.t * 1000) + "\",3.71";
    for (int i = 0; i < 3; ++i) text += "," + g17(flip[i] * s.f[i] / kG);
    for (int i = 0; i < 3; ++i) text += "," + g17(flip[i] * s.w[i] / kDeg);
    for (int i = 0; i < 3; ++i) text += ", " + g17(flip[i] * s.b[i] / 100);
    text += ",\"" + g17(s.temp_c) + "\"\r\n";
  }
  return text;
}

Import other_logger_import(const std::string& axes = "x,-y,-z") {
  return make_import({"t=Time (ms)", "fx=Accel X (g)", "fy=Accel Y (g)", "fz=Accel Z (g)", "wx=\"Gyroscope X (deg/s)\"",
                      "wy=Gyroscope Y (deg/s)", "wz=Gyroscope Z (deg/s)", "bx=Mag X (G)", "by=Mag Y (G)", "bz=Mag Z (G)",
                      "temp_c=Temp (C)"},
                     {"accel=g,gyro=deg/s", "mag=gauss,time=ms"}, axes);
}

void expect_same(const std::vector<Sample>& a, const std::vector<Sample>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    SCOPED_TRACE("sample " + std::to_string(k));
    EXPECT_EQ(a[k].seq, b[k].seq);
    EXPECT_EQ(a[k].flags, b[k].flags);
    EXPECT_NEAR(a[k].t, b[k].t, 1e-14);
    EXPECT_LT((a[k].f - b[k].f).norm(), 1e-13);
    EXPECT_LT((a[k].b - b[k].b).norm(), 1e-13);
    EXPECT_LT((a[k].w - b[k].w).norm(), 1e-13);
    EXPECT_DOUBLE_EQ(a[k].temp_c, b[k].temp_c);
  }
}

TEST_F(TempDir, OtherLoggersFileImportsToTheSamplesOfThePlumbFile) {
  const auto samples = truth();
  const auto ours = read_sensor_file(write("plumb.csv", plumb_file(samples)));
  const auto theirs = read_sensor_file(write("other.csv", other_logger_file(samples)), other_logger_import());
  expect_same(ours, theirs);
  expect_same(ours, samples);
}

TEST_F(TempDir, RotationMatrixFormEqualsThePermutationForm) {
  Import perm, matrix;
  set_axes(perm, "x,-y,-z");
  set_axes(matrix, "1 0 0  0 -1 0  0 0 -1");
  EXPECT_EQ(perm.axes, matrix.axes);
  EXPECT_EQ(perm.axes_text, "x,-y,-z");
  const auto path = write("other.csv", other_logger_file(truth(50)));
  expect_same(read_sensor_file(path, other_logger_import("x,-y,-z")),
              read_sensor_file(path, other_logger_import("1,0,0,0,-1,0,0,0,-1")));

  // A general rotation: tool = R sensor, R a turn of 30 deg about z (row i = tool axis i).
  Import turned;
  set_axes(turned, "0.8660254037844386 0.5 0 -0.5 0.8660254037844386 0 0 0 1");
  const Eigen::Vector3d tool = to_tool(turned, Eigen::Vector3d(1, 0, 0));
  EXPECT_NEAR(tool.x(), std::sqrt(3.0) / 2, 1e-15);
  EXPECT_NEAR(tool.y(), -0.5, 1e-15);
  Import swapped;
  set_axes(swapped, "y,-x,z");  // tool x = sensor y, tool y = -sensor x
  EXPECT_EQ(to_tool(swapped, Eigen::Vector3d(1, 2, 3)), Eigen::Vector3d(2, -1, 3));
}

TEST(CsvImport, NanOnOneSensorAxisStaysOnItsToolAxis) {
  Import import;
  set_axes(import, "z,x,y");
  const Eigen::Vector3d tool = to_tool(import, Eigen::Vector3d(NAN, 2, 3));
  EXPECT_EQ(tool.x(), 3);
  EXPECT_TRUE(std::isnan(tool.y()));
  EXPECT_EQ(tool.z(), 2);
}

// The message of the std::invalid_argument `f` throws; one line.
template <typename F>
std::string refusal(F f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(CsvImport, EachBadOptionIsRefusedWithOneLineNamingTheOptionAndTheAcceptedValues) {
  Import i;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {refusal([&] { add_units(i, "accel=furlong/s2"); }),
       "--units: unknown accel unit 'furlong/s2' (accepted: m/s2, m/s^2, m/s\xC2\xB2, g, mg)"},
      {refusal([&] { add_units(i, "gyro=rpm"); }), "--units: unknown gyro unit 'rpm' (accepted: rad/s, deg/s"},
      {refusal([&] { add_units(i, "mag=tesla"); }), "(accepted: uT, \xC2\xB5T, \xCE\xBCT, nT, mT, gauss)"},
      {refusal([&] { add_units(i, "pressure=bar"); }),
       "--units: unknown group 'pressure' (accepted: accel, gyro, mag, time, depth)"},
      {refusal([&] { add_units(i, "g"); }), "--units: expected GROUP=UNIT"},
      {refusal([&] { add_column(i, "wq=Gyro Q"); }), "--column: 'wq' is not a plumb column (accepted: t, seq, fx,"},
      {refusal([&] { add_column(i, "Gyroscope X"); }), "--column: expected NAME=HEADER"},
      {refusal([&] { add_column(i, "wx="); }), "--column wx=: the header text is empty"},
      {refusal([&] { set_axes(i, "x,y"); }), "--axes: expected a signed permutation such as x,-y,-z"},
      {refusal([&] { set_axes(i, "x,x,z"); }), "--axes 'x,x,z': sensor axis x is used twice"},
      {refusal([&] { set_axes(i, "x,y,w"); }), "--axes: expected a signed permutation"},
      {refusal([&] { set_axes(i, "x,y,-z"); }), "--axes 'x,y,-z': a reflection (determinant -1)"},
      {refusal([&] { set_axes(i, "1 0 0 0 1 0 0 0 -1"); }), "a reflection (determinant -1)"},
      {refusal([&] { set_axes(i, "1 0 0 0 1 0 0 0 1.001"); }), "not a rotation (rows not orthonormal within 1e-6"},
      {refusal([&] { set_axes(i, "1 0 0 0 1 0 0 0 one"); }), "--axes: 'one' is not a number"},
      {refusal([&] { set_axes(i, "1 0 0 0 1 0 0 0"); }), "--axes: expected a signed permutation"},
  };
  for (const auto& [message, expected] : cases) {
    EXPECT_NE(message.find(expected), std::string::npos) << message << "\n lacks: " << expected;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  Import twice;
  add_column(twice, "fx=A");
  EXPECT_NE(refusal([&] { add_column(twice, "fx=B"); }).find("fx is mapped twice"), std::string::npos);
  EXPECT_NE(refusal([&] { add_column(twice, "fy=A"); }).find("'A' is mapped to both fx and fy"), std::string::npos);
  // Within 1e-6 of a rotation is accepted (matrices typed with 7 digits).
  EXPECT_EQ(refusal([&] { set_axes(i, "0.7071068 0.7071068 0 -0.7071068 0.7071068 0 0 0 1"); }), "(no error)");
}

TEST(CsvImport, MappedColumnTheHeaderLacksIsOneLineWithTheNearestNames) {
  std::istringstream in("\"Time (ms)\",\"Accel X (g)\",\"Accel Y (g)\",\"Accel Z (g)\",\"Gyro X (dps)\",\"Gyro Y (dps)\","
                        "\"Gyro Z (dps)\"\n0,0,0,1,0,0,0\n");
  const Import import = make_import({"t=Time (ms)", "fx=Accel X (g)", "fy=Accel Y (g)", "fz=Accel Z (g)",
                                     "wx=Gyroscope X (deg/s)", "wy=Gyro Y (dps)", "wz=Gyro Z (dps)"},
                                    {}, "");
  try {
    SensorReader r(in, "other.csv", import);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find("other.csv:1: column 'wx': mapped to 'Gyroscope X (deg/s)', which the header lacks (closest: "
                        "'Gyro X (dps)'"),
              0u)
        << what;
    EXPECT_EQ(what.find('\n'), std::string::npos);
  }
}

TEST(CsvImport, UnmappedRequiredColumnSuggestsAMapping) {
  std::istringstream in("time,ax,ay,az\n0,0,0,1\n");
  try {
    SensorReader r(in, "o.csv", make_import({"fx=ax", "fy=ay", "fz=az"}, {}, ""));
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "o.csv:1: header lacks required column(s) t (map them with --column NAME=\"HEADER TEXT\")");
  }
}

TEST(SensorCsvNoMagnetometer, AllThreeAbsentIsAGyroToolSomeAbsentIsAnError) {
  std::istringstream in("t,fx,fy,fz,wx,wy,wz\n0,0,0,-9.8,0.1,0.2,0.3\n");
  SensorReader r(in, "m");
  EXPECT_FALSE(r.has_magnetometer());
  Sample s;
  ASSERT_TRUE(r.next(s));
  EXPECT_TRUE(s.flags & flags::kNoMagnetometer);
  EXPECT_TRUE(s.flags & flags::kHasGyro);
  EXPECT_EQ(s.b, Eigen::Vector3d::Zero());
  EXPECT_EQ(s.w, Eigen::Vector3d(0.1, 0.2, 0.3));

  std::istringstream partial("t,fx,fy,fz,bx,by\n");
  try {
    SensorReader bad(partial, "m");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "m:1: header lacks bz: bx, by, bz come all three or none");
  }
  std::istringstream with("t,fx,fy,fz,bx,by,bz\n0,0,0,0,1,2,3\n");
  SensorReader ok(with, "m");
  ASSERT_TRUE(ok.next(s));
  EXPECT_FALSE(s.flags & flags::kNoMagnetometer);
}

TEST(SplitLine, DoubleQuotedFieldsAsRfc4180) {
  EXPECT_EQ(split_line("\"a \"\"b\"\"\", c ,\"d,e\",\"\", \"f\" \r"),
            (std::vector<std::string>{"a \"b\"", "c", "d,e", "", "f"}));
  EXPECT_EQ(split_line("x,\"unterminated, still one field"), (std::vector<std::string>{"x", "unterminated, still one field"}));
  EXPECT_EQ(split_line("1,2,"), (std::vector<std::string>{"1", "2", ""}));
  EXPECT_EQ(split_line("in\"side,2"), (std::vector<std::string>{"in\"side", "2"}));
}

TEST_F(TempDir, AccelerometersInGDeclaredMetresPerSecondSquaredAreSaidSo) {
  auto samples = truth();
  // Written in g, read as plumb's m/s^2.
  for (auto& s : samples) s.f /= kG;
  const auto read = read_sensor_file(write("g.csv", plumb_file(samples)));
  const auto findings = check_units(read);
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_EQ(findings[0], "accelerometers look like they are in g (|f| \xE2\x89\x88 1.0); give --units accel=g");

  EXPECT_TRUE(check_units(read_sensor_file(write("ok.csv", plumb_file(truth())))).empty());
  // The same g file read with the right units is quiet.
  Import g;
  add_units(g, "accel=g");
  EXPECT_TRUE(check_units(read_sensor_file(write("g2.csv", plumb_file(samples)), g), g).empty());
}

TEST_F(TempDir, DegreesPerSecondAndGaussDeclaredAsPlumbUnitsAreSaidSo) {
  auto samples = truth();
  for (auto& s : samples) s.w /= kDeg, s.b /= 100;
  const auto findings = check_units(read_sensor_file(write("dps.csv", plumb_file(samples))));
  ASSERT_EQ(findings.size(), 2u);
  EXPECT_EQ(findings[0], "magnetometers look like they are in gauss (|b| \xE2\x89\x88 0.48); give --units mag=gauss");
  EXPECT_EQ(findings[1].rfind("gyros look like they are in deg/s (|w| \xE2\x89\x88 360 sustained", 0), 0u) << findings[1];
  // The other logger's file, read correctly, is quiet; read without units it is not.
  const auto path = write("other.csv", other_logger_file(truth()));
  EXPECT_TRUE(check_units(read_sensor_file(path, other_logger_import()), other_logger_import()).empty());
  Import columns_only = other_logger_import();
  columns_only.accel = {"m/s2", 1}, columns_only.gyro = {"rad/s", 1}, columns_only.mag = {"uT", 1};
  EXPECT_EQ(check_units(read_sensor_file(path, columns_only), columns_only).size(), 3u);
}

TEST(CsvImport, TooLittleDataOrNoMagnetometerSaysNothingAboutIt) {
  EXPECT_TRUE(check_units({}).empty());
  std::vector<Sample> gyro_tool(20);
  for (std::size_t k = 0; k < gyro_tool.size(); ++k) {
    gyro_tool[k].t = 0.01 * static_cast<double>(k);
    gyro_tool[k].f = {0, 0, -kG};
    gyro_tool[k].flags = flags::kNoMagnetometer;
  }
  EXPECT_TRUE(check_units(gyro_tool).empty());
}

TEST(CsvImport, DescribeNamesEverything) {
  const auto import = make_import({"wx=Gyro X", "t=time"}, {"gyro=deg/s"}, "x,-y,-z");
  EXPECT_EQ(describe(import),
            "columns t='time', wx='Gyro X'; units accel=m/s2, gyro=deg/s, mag=uT, time=s, depth=m; axes x,-y,-z");
  EXPECT_TRUE(is_default(make_import({}, {}, "")));
  EXPECT_TRUE(is_default(make_import({}, {"accel=m/s^2"}, "x,y,z")));
  EXPECT_FALSE(is_default(import));
}

}  // namespace
}  // namespace plumb::csv
