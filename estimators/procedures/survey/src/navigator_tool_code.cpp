#include "plumb/survey/navigator_tool_code.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "iscwsa_gyro_tool_codes.hpp"
#include "plumb/core/imu_grade.hpp"
#include "plumb/core/number.hpp"

namespace plumb::survey::iscwsa {
namespace {

constexpr std::size_t kSurveyNameChars = 63;  // idl/survey.idl's string<63>

class NavigatorReader {
 public:
  explicit NavigatorReader(const NavigatorParameters& p) : p_(p) {}

  const std::string& text(const std::string& key) const {
    const auto it = p_.find(key);
    if (it == p_.end())
      throw std::invalid_argument("the navigator's parameters lack '" + key +
                                  "' (every parameter of the strapdown plugin is needed, as plumb param dump gives them)");
    return it->second;
  }
  bool given(const std::string& key) const { return !text(key).empty(); }
  double number(const std::string& key) const {
    const auto v = parse_number(text(key));
    if (!v) throw std::invalid_argument("navigator parameter '" + key + "': '" + text(key) + "' is not a number");
    return *v;
  }
  // A figure the navigator takes from imu_grade when it is not given.
  double figure(const std::string& key, double preset) const { return given(key) ? number(key) : preset; }
  bool flag(const std::string& key) const {
    const std::string& v = text(key);
    if (v == "true" || v == "yes" || v == "on" || v == "1") return true;
    if (v == "false" || v == "no" || v == "off" || v == "0") return false;
    throw std::invalid_argument("navigator parameter '" + key + "': '" + v + "' is not true/false");
  }

 private:
  const NavigatorParameters& p_;
};

std::string short_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

}  // namespace

NavigatorModel navigator_tool_code(const NavigatorParameters& parameters, double reference_b_uT, double reference_dip_deg) {
  const NavigatorReader r(parameters);
  const std::string& grade_name = r.text("imu_grade");
  const ImuGradeFigures* grade = find_imu_grade(grade_name);
  if (grade == nullptr)
    throw std::invalid_argument("navigator parameter 'imu_grade': '" + grade_name + "' is not one of navigation, tactical, mems");
  const detail::StrapdownFigures figures{r.figure("gyro_bias_dph", grade->gyro_bias_dph),
                                         r.figure("gyro_arw_deg_rt_h", grade->gyro_arw_deg_rt_h),
                                         r.figure("accel_bias_mg", grade->accel_bias_mg),
                                         r.figure("accel_scale_factor_ppm", grade->accel_scale_ppm),
                                         r.figure("accel_misalignment_mrad", grade->accel_misalignment_mrad)};
  // The grade's name alone when every figure is its preset; the gyro bias said when one is not.
  const bool presets = !r.given("gyro_bias_dph") && !r.given("gyro_arw_deg_rt_h") && !r.given("accel_bias_mg") &&
                       !r.given("accel_scale_factor_ppm") && !r.given("accel_misalignment_mrad");
  const std::string grade_label = presets ? grade_name : grade_name + " " + short_number(figures.gyro_bias_dph) + " deg/h";

  NavigatorModel m{detail::strapdown_run("", figures), r.number("latitude_deg"), ""};
  const auto add = [&](const char* code, double magnitude, const char* unit, Propagation p) {
    m.tool.terms.push_back({code, code, magnitude, unit, p});
  };
  std::string initialisation_label;
  if (r.flag("gyrocompass")) {
    // The triad's gyrocompass at alignment: its gyros' bias in full (the earth rate and the bias
    // cannot be told apart standing still) and their noise averaged over the alignment.
    const double noise_dph = figures.gyro_arw_deg_rt_h / std::sqrt(r.number("align_s") / 3600.0);
    add("GXYZ-XYB1", figures.gyro_bias_dph, "deg/hr", Propagation::Systematic);
    add("GXYZ-XYB2", figures.gyro_bias_dph, "deg/hr", Propagation::Systematic);
    add("GXYZ-ZB", figures.gyro_bias_dph, "deg/hr", Propagation::Systematic);
    add("GXYZ-XYRN", noise_dph, "deg/hr", Propagation::Random);
    add("GXYZ-ZRN", noise_dph, "deg/hr", Propagation::Random);
    m.tool.gyro.initialisation = GyroInitialisation::Gyrocompass;
    m.tool.gyro.noise_reduction_factor = 1;  // the noise above is already the alignment's average
    m.initialisation = "gyrocompass";
    initialisation_label = "gyrocompass";
  } else if (r.given("initial_azimuth_deg")) {
    const double sd = r.number("initial_azimuth_sd_deg");
    add("EXT-REF", sd, "deg", Propagation::Systematic);
    m.initialisation = "given azimuth";
    initialisation_label = "given az " + short_number(sd) + " deg";
  } else if (r.flag("use_magnetometer")) {
    const double b = r.given("field_uT") ? r.number("field_uT") : reference_b_uT;
    const double dip = (r.given("dip_deg") ? r.number("dip_deg") : reference_dip_deg) * std::numbers::pi / 180.0;
    const double axial_deg = r.number("mag_axial_bias_uT") / (b * std::cos(dip)) * 180.0 / std::numbers::pi;
    const double sd = std::hypot(r.number("mag_heading_sd_deg"), axial_deg);
    add("EXT-REF", sd, "deg", Propagation::Systematic);
    m.initialisation = "magnetic azimuth";
    initialisation_label = "magnetic az " + short_number(sd) + " deg";
  } else {
    add("EXT-REF", 0, "deg", Propagation::Systematic);
    m.initialisation = "relative azimuth";
    initialisation_label = "relative az";
  }
  m.tool.name = "GYRO:navigator (" + grade_label + "; " + initialisation_label + ")";
  if (m.tool.name.size() > kSurveyNameChars) m.tool.name = "GYRO:navigator (" + grade_name + "; " + initialisation_label + ")";
  return m;
}

}  // namespace plumb::survey::iscwsa
