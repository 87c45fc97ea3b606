#include "json.hpp"

#include <chrono>
#include <cmath>
#include <cstdint>

namespace plumb::display_component {
namespace {

Json page_angle_difference(const std::optional<AngleDifference>& d, int decimals) {
  if (!d) return nullptr;
  return Json{{"d", json_number(d->degrees, decimals)}, {"sd", json_number(d->sd_degrees, decimals)}};
}

}  // namespace

double wall_clock_ms() {
  const auto since_epoch = std::chrono::system_clock::now().time_since_epoch();
  return static_cast<double>(std::chrono::duration_cast<std::chrono::microseconds>(since_epoch).count()) * 1e-3;
}

Json json_number(double value, int decimals) {
  if (!std::isfinite(value)) return nullptr;
  if (decimals <= 0) return static_cast<std::int64_t>(std::llround(value));
  const double scale = std::pow(10.0, decimals);
  // The double nearest the rounded decimal: written back in its shortest form, it has at most
  // `decimals` places.
  return std::round(value * scale) / scale;
}

std::string json_text(const Json& value) { return value.dump(-1, ' ', false, Json::error_handler_t::replace); }

void append_json_string(std::string& out, const std::string& text) { out += json_text(Json(text)); }

void append_json_number(std::string& out, double value, int decimals) { out += json_text(json_number(value, decimals)); }

std::string attitude_json(const topics::Attitude& a, const std::string& key, double rx_ms,
                          const std::optional<AttitudeDifference>& difference) {
  Json j;
  j["k"] = key;
  j["tool"] = a.tool_id;
  j["est"] = a.estimator;
  j["t"] = json_number(static_cast<double>(a.window_end_ns) * 1e-9, 6);
  j["rx"] = json_number(rx_ms, 1);
  j["inc"] = json_number(a.inclination_deg, 3);
  j["azi"] = json_number(a.azimuth_deg, 3);
  j["gtf"] = json_number(a.gravity_toolface_deg, 2);
  j["mtf"] = json_number(a.magnetic_toolface_deg, 2);
  j["rpm"] = json_number(a.rpm, 2);
  j["sinc"] = json_number(a.inclination_sd_deg, 3);
  j["sazi"] = json_number(a.azimuth_sd_deg, 3);
  j["stf"] = json_number(a.toolface_sd_deg, 3);
  j["dip"] = json_number(a.dip_deg, 3);
  j["g"] = json_number(a.total_g, 4);
  j["b"] = json_number(a.total_b, 3);
  j["n"] = a.samples_used;
  j["flags"] = a.flags;
  j["why"] = a.reason;
  if (difference) {
    j["diff"] = {{"ref", difference->reference},
                 {"inc", page_angle_difference(difference->inclination, 4)},
                 {"azi", page_angle_difference(difference->azimuth, 3)},
                 {"tf", page_angle_difference(difference->toolface, 2)}};
  } else {
    j["diff"] = nullptr;
  }
  return json_text(j);
}

std::string status_json(const topics::ComponentStatus& s, const std::string& key, double rx_ms) {
  Json counters = Json::array();
  for (const auto& c : s.counters) counters.push_back(Json::array({c.name, c.value}));
  Json j;
  j["k"] = key;
  j["comp"] = s.component;
  j["host"] = s.host;
  j["state"] = s.state;
  j["rx"] = json_number(rx_ms, 1);
  j["counters"] = std::move(counters);
  j["err"] = s.last_error;
  return json_text(j);
}

std::string station_json(const topics::SurveyStation& s, const std::string& key) {
  Json j;
  j["k"] = key;
  j["tool"] = s.tool_id;
  j["src"] = s.source;
  j["i"] = s.index;
  j["md"] = json_number(s.md_m, 2);
  j["inc"] = json_number(s.inclination_deg, 3);
  j["sinc"] = json_number(s.inclination_sd_deg, 3);
  j["azi"] = json_number(s.azimuth_deg, 3);
  j["sazi"] = json_number(s.azimuth_sd_deg, 3);
  j["tinc"] = json_number(s.inclination_total_sd_deg, 3);  // the survey's: noise and every error-model term
  j["tazi"] = json_number(s.azimuth_total_sd_deg, 3);
  j["ref"] = s.azimuth_reference;
  j["n"] = json_number(s.north_m, 2);
  j["e"] = json_number(s.east_m, 2);
  j["tvd"] = json_number(s.tvd_m, 2);
  j["dls"] = json_number(s.dls_deg_per_30m, 2);
  j["vs"] = json_number(s.vertical_section_m, 2);
  j["saz"] = json_number(s.section_azimuth_deg, 3);
  j["maj"] = json_number(s.ellipse_major_sd_m, 3);
  j["mnr"] = json_number(s.ellipse_minor_sd_m, 3);
  j["maz"] = json_number(s.ellipse_major_azimuth_deg, 1);
  j["sdt"] = json_number(s.tvd_sd_m, 3);
  j["tf"] = json_number(s.gravity_toolface_deg, 1);
  j["flags"] = s.flags;
  j["qc"] = s.qc_reason;
  return json_text(j);
}

std::string depth_json(const topics::MeasuredDepth& d) {
  Json j;
  j["tool"] = d.tool_id;
  j["md"] = json_number(d.depth_m, 3);
  j["flags"] = d.flags;
  return json_text(j);
}

std::string clearance_json(const topics::Clearance& c, const std::string& key) {
  Json j;
  j["k"] = key;
  j["tool"] = c.tool_id;
  j["off"] = c.offset_well;
  j["i"] = c.station_index;
  j["md"] = json_number(c.reference_md_m, 2);
  j["omd"] = json_number(c.offset_md_m, 2);
  j["ctc"] = json_number(c.centre_to_centre_m, 2);
  j["es"] = json_number(c.ellipse_separation_m, 2);
  j["sf"] = json_number(c.separation_factor, 2);
  j["hs"] = json_number(c.high_side_bearing_deg, 1);
  j["lvl"] = c.level;
  j["warn"] = json_number(c.warning_sf, 2);
  j["alarm"] = json_number(c.alarm_sf, 2);
  return json_text(j);
}

}  // namespace plumb::display_component
