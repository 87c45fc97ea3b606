// The built-in gyro tool codes. Values: the OWSG tool code set A, revision 5.1 (8 Oct 2020),
// codes A020Gb "GYRO-NS" (gyrocompass at each station), A019Gb "GYRO-MWD" and A021Gc "GYRO-NS-CT"
// (gyrocompass to 15 deg, then continuous from that initialisation to 150 deg at 2743.2 m/h);
// and plumb's two strapdown grades run continuously from a known azimuth, with the figures of the
// grades the navigator's presets are (plumb/core/imu_grade.hpp, docs/navigator.md): gyro bias and
// angle random walk, accelerometer bias, scale factor and misalignment.
#include "iscwsa_gyro_tool_codes.hpp"

#include "plumb/core/imu_grade.hpp"

namespace plumb::survey::iscwsa::detail {
namespace {

constexpr Propagation R = Propagation::Random, S = Propagation::Systematic, G = Propagation::Global;
constexpr double kMilliG = 9.80665e-3;                        // m/s^2
constexpr double kMilliradianDeg = 0.18 / 3.14159265358979323846;  // 1 mrad in degrees

// Depth, misalignment and course length: as in the MWD codes of revision 5.
std::vector<Term> depth_and_alignment() {
  return {{"DRFR", "DREF", 0.35, "m", R},    {"DSFS", "DSF", 0.00056, "-", S},  {"DSTG", "DST", 2.5e-07, "1/m", G},
          {"XYM1", "XYM1", 0.1, "deg", S},   {"XYM2", "XYM2", 0.1, "deg", S},   {"XYM3E", "XYM3E", 0.3, "deg", R},
          {"XYM4E", "XYM4E", 0.3, "deg", R}, {"XCLA", "XCLA", 0.167, "-", R},  {"XCLH", "XCLH", 0.167, "-", R}};
}

std::vector<Term> accelerometers(double misalignment_deg, double scale_factor, double bias_mps2) {
  return {{"AXYZ-MIS", "AXYZ-MIS", misalignment_deg, "deg", S},
          {"AXYZ-SF", "AXYZ-SF", scale_factor, "-", S},
          {"AXYZ-ZB", "AXYZ-ZB", bias_mps2, "m/s2", S}};
}

ToolCode owsg(const std::string& name, std::vector<Term> gyro_terms, double sag_deg) {
  ToolCode t{name, 5, 0.000572615, depth_and_alignment()};
  const auto acc = accelerometers(0.0095, 0.000111, 0.0017);
  t.terms.insert(t.terms.end(), acc.begin(), acc.end());
  t.terms.push_back({"SAGE", "SAGE", sag_deg, "deg", S});
  t.terms.insert(t.terms.end(), gyro_terms.begin(), gyro_terms.end());
  t.gyro.static_end_inc_deg = 89;  // the codes' range: an x-y gyrocompass fails toward horizontal
  return t;
}

ToolCode gyro_ns() {
  return owsg("GYRO-NS (OWSG A020Gb revision 5.1)",
              {{"GXY-B1R", "GXY-B1", 0.15, "deg/hr", R}, {"GXY-B2R", "GXY-B2", 0.15, "deg/hr", R},
               {"GXY-G1", "GXY-G1", 0.2, "deg/hr", S},   {"GXY-G4", "GXY-G4", 0.6, "deg/hr", S},
               {"GXY-RN", "GXY-RN", 0.4, "deg/hr", R}},
              0.2);
}

ToolCode gyro_mwd() {
  return owsg("GYRO-MWD (OWSG A019Gb revision 5.1)",
              {{"GXY-B1R", "GXY-B1", 0.15, "deg/hr", R}, {"GXY-B2R", "GXY-B2", 0.15, "deg/hr", R},
               {"GXY-G1", "GXY-G1", 0.4, "deg/hr", S},   {"GXY-G4", "GXY-G4", 1.0, "deg/hr", S},
               {"GXY-RN", "GXY-RN", 0.6, "deg/hr", R}},
              0.2);
}

ToolCode gyro_ns_ct() {
  ToolCode t = owsg("GYRO-NS-CT (OWSG A021Gc revision 5.1)",
                    {{"GXY-B1S", "GXY-B1", 0.15, "deg/hr", S},
                     {"GXY-B2S", "GXY-B2", 0.15, "deg/hr", S},
                     {"GXY-G4", "GXY-G4", 0.6, "deg/hr", S},
                     {"GXY-RN", "GXY-RN", 0.4, "deg/hr", R},
                     {"GXY-GD", "GXY-GD", 0.5, "deg/hr", S},
                     {"GXY-GRW", "GXY-GRW", 0.25, "deg/sqrt(hr)", S}},
                    0.08);
  t.gyro.static_end_inc_deg = 15;
  t.gyro.continuous = true;
  t.gyro.continuous_start_inc_deg = 15;
  t.gyro.continuous_end_inc_deg = 150;
  t.gyro.initialisation = GyroInitialisation::Gyrocompass;
  t.gyro.initialisation_inc_deg = 15;
  t.gyro.running_speed_m_per_h = 2743.2;
  t.gyro.noise_reduction_factor = 0.4082;
  return t;
}

// One of plumb's strapdown grades run from a known azimuth (given, or read off the magnetometer at
// alignment: EXT-REF, 0.5 deg), with the grade's figures from the table the navigator's imu_grade
// presets are (plumb/core/imu_grade.hpp).
ToolCode strapdown_grade(const std::string& grade) {
  const ImuGradeFigures& g = *find_imu_grade(grade);
  // Named within the survey message's 63 characters (idl/survey.idl).
  ToolCode t = strapdown_run("GYRO:" + grade + " (plumb strapdown, continuous)",
                             {g.gyro_bias_dph, g.gyro_arw_deg_rt_h, g.accel_bias_mg, g.accel_scale_ppm, g.accel_misalignment_mrad});
  t.terms.push_back({"EXT-REF", "EXT-REF", 0.5, "deg", S});
  return t;
}

}  // namespace

std::vector<std::string> gyro_tool_code_names() { return {"GYRO-NS", "GYRO-NS-CT", "GYRO-MWD", "GYRO:tactical", "GYRO:mems"}; }

std::optional<ToolCode> builtin_gyro_tool_code(const std::string& name) {
  if (name == "GYRO-NS") return gyro_ns();
  if (name == "GYRO-NS-CT") return gyro_ns_ct();
  if (name == "GYRO-MWD") return gyro_mwd();
  if (name == "GYRO:tactical") return strapdown_grade("tactical");
  if (name == "GYRO:mems") return strapdown_grade("mems");
  return std::nullopt;
}

// A strapdown triad run continuously from the first station, drifting with its gyro bias and random
// walk over the stations' own times.
ToolCode strapdown_run(const std::string& name, const StrapdownFigures& f) {
  ToolCode t{name, 5, 0.000572615, depth_and_alignment()};
  const auto acc = accelerometers(f.accel_misalignment_mrad * kMilliradianDeg, f.accel_scale_ppm * 1e-6,
                                  f.accel_bias_mg * kMilliG);
  t.terms.insert(t.terms.end(), acc.begin(), acc.end());
  t.terms.push_back({"SAGE", "SAGE", 0.2, "deg", S});
  t.terms.push_back({"GXYZ-GD", "GXYZ-GD", f.gyro_bias_dph, "deg/hr", S});
  t.terms.push_back({"GXYZ-GRW", "GXYZ-GRW", f.gyro_arw_deg_rt_h, "deg/sqrt(hr)", S});
  t.gyro.static_end_inc_deg = -1;  // no gyrocompass station
  t.gyro.continuous = true;
  t.gyro.initialisation = GyroInitialisation::Reference;
  t.gyro.running_speed_m_per_h = 0;  // the stations' times: a drilling run stops and goes
  return t;
}

}  // namespace plumb::survey::iscwsa::detail
