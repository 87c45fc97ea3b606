#include "station_message.hpp"

#include <cmath>

#include "plumb/components/convert.hpp"

namespace plumb::survey_component {

using components::bounded;

topics::SurveyStation to_topic(const survey::SurveyRow& r, double section_azimuth_deg) {
  topics::SurveyStation m;
  const auto& s = r.station;
  m.tool_id = bounded(s.tool_id, topics::SurveyStation::kToolIdMax);
  m.source = bounded(s.source, topics::SurveyStation::kSourceMax);
  m.index = r.index;
  m.stamp_ns = components::seconds_to_ns(s.t_s);
  m.md_m = s.md_m;
  m.md_sd_m = s.md_sd_m;
  m.inclination_deg = s.inclination_deg;
  m.inclination_sd_deg = s.inclination_sd_deg;
  m.azimuth_deg = r.azimuth_deg;
  m.azimuth_sd_deg = s.azimuth_sd_deg;
  m.magnetic_azimuth_deg = s.magnetic_azimuth_deg;
  m.azimuth_reference = survey::to_string(r.reference);
  m.north_m = r.point.north_m;
  m.east_m = r.point.east_m;
  m.tvd_m = r.point.tvd_m;
  m.dogleg_deg = r.point.dogleg_deg;
  m.dls_deg_per_30m = r.point.dls_deg_per_30m;
  m.vertical_section_m = r.point.vertical_section_m;
  m.closure_distance_m = r.point.closure_distance_m;
  m.closure_azimuth_deg = r.point.closure_azimuth_deg;
  m.north_sd_m = r.uncertainty.north_sd_m;
  m.east_sd_m = r.uncertainty.east_sd_m;
  m.tvd_sd_m = r.uncertainty.tvd_sd_m;
  m.ellipse_major_sd_m = r.uncertainty.major_sd_m;
  m.ellipse_minor_sd_m = r.uncertainty.minor_sd_m;
  m.ellipse_major_azimuth_deg = r.uncertainty.major_azimuth_deg;
  // NaN (not measured) travels as 0, the topics' "unknown".
  const auto known = [](double v) { return std::isfinite(v) ? v : 0.0; };
  m.total_g = known(s.total_g_mps2);
  m.total_b = known(s.total_b_uT);
  m.dip_deg = known(s.dip_deg);
  m.g_residual = r.qc.gravity_residual_mps2;
  m.b_residual = r.qc.total_b_residual_uT;
  m.dip_residual_deg = r.qc.dip_residual_deg;
  m.flags = (r.qc.pass ? topics::SURVEY_QC_PASSED : 0u) | (s.azimuth_valid ? topics::SURVEY_AZIMUTH_VALID : 0u);
  m.qc_reason = bounded(r.qc.reason, topics::SurveyStation::kQcReasonMax);
  m.gravity_toolface_deg = s.toolface_deg;
  m.toolface_sd_deg = s.toolface_sd_deg;
  m.inclination_total_sd_deg = r.inclination_total_sd_deg;
  m.azimuth_total_sd_deg = r.azimuth_total_sd_deg;
  m.error_model = bounded(r.error_model, topics::SurveyStation::kErrorModelMax);
  m.section_azimuth_deg = section_azimuth_deg;
  return m;
}

topics::Clearance to_topic(const ClearanceWatch::Pair& p, const survey::SurveyRow& r, const survey::ClearanceLevels& l) {
  topics::Clearance m;
  const auto& c = p.clearance;
  m.tool_id = bounded(r.station.tool_id, topics::Clearance::kToolIdMax);
  m.offset_well = bounded(p.offset, topics::Clearance::kOffsetWellMax);
  m.station_index = r.index;
  m.stamp_ns = components::seconds_to_ns(r.station.t_s);
  m.reference_md_m = c.reference.md_m;
  m.reference_north_m = c.reference.position.x();
  m.reference_east_m = c.reference.position.y();
  m.reference_tvd_m = c.reference.position.z();
  m.offset_md_m = c.offset.md_m;
  m.offset_north_m = c.offset.position.x();
  m.offset_east_m = c.offset.position.y();
  m.offset_tvd_m = c.offset.position.z();
  m.centre_to_centre_m = c.centre_to_centre_m;
  m.horizontal_bearing_deg = c.horizontal_bearing_deg;
  m.high_side_bearing_deg = c.high_side_bearing_deg;
  m.reference_sigma_m = c.reference_sigma_m;
  m.offset_sigma_m = c.offset_sigma_m;
  m.masd_m = c.masd_m;
  m.ellipse_separation_m = c.ellipse_separation_m;
  m.separation_factor = c.separation_factor;
  m.level = p.level == survey::ClearanceLevel::Alarm     ? topics::CLEARANCE_ALARM
            : p.level == survey::ClearanceLevel::Warning ? topics::CLEARANCE_WARNING
                                                         : topics::CLEARANCE_CLEAR;
  m.warning_sf = l.warning_sf;
  m.alarm_sf = l.alarm_sf;
  return m;
}

survey::DepthReport from_topic(const topics::MeasuredDepth& d) {
  survey::DepthReport r;
  r.t_s = components::ns_to_seconds(d.stamp_ns);
  r.depth_m = d.depth_m;
  r.sd_m = d.depth_sd_m;
  r.moving = (d.flags & topics::DEPTH_MOVING) != 0;
  return r;
}

}  // namespace plumb::survey_component
