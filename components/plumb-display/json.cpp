#include "json.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

namespace plumb::display_component {

double wall_clock_ms() {
  const auto since_epoch = std::chrono::system_clock::now().time_since_epoch();
  return static_cast<double>(std::chrono::duration_cast<std::chrono::microseconds>(since_epoch).count()) * 1e-3;
}

void append_json_string(std::string& out, const std::string& text) {
  out += '"';
  for (const char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
          out += buf;
        } else {
          out += c;
        }
    }
  }
  out += '"';
}

void append_json_number(std::string& out, double value, int decimals) {
  if (!std::isfinite(value)) {
    out += "null";
    return;
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  out += buf;
}

namespace {

// Builds {"k":v,...} one field at a time.
class Object {
 public:
  Object& text(const char* name, const std::string& value) {
    key(name);
    append_json_string(out_, value);
    return *this;
  }
  Object& number(const char* name, double value, int decimals) {
    key(name);
    append_json_number(out_, value, decimals);
    return *this;
  }
  Object& raw(const char* name, const std::string& json) {
    key(name);
    out_ += json;
    return *this;
  }
  std::string done() { return std::move(out_) + '}'; }

 private:
  void key(const char* name) {
    out_ += out_.size() > 1 ? ",\"" : "\"";
    out_ += name;
    out_ += "\":";
  }
  std::string out_ = "{";
};

}  // namespace

std::string attitude_json(const topics::Attitude& a, const std::string& key, double rx_ms) {
  return Object()
      .text("k", key)
      .text("tool", a.tool_id)
      .text("est", a.estimator)
      .number("t", static_cast<double>(a.window_end_ns) * 1e-9, 6)
      .number("rx", rx_ms, 1)
      .number("inc", a.inclination_deg, 3)
      .number("azi", a.azimuth_deg, 3)
      .number("gtf", a.gravity_toolface_deg, 2)
      .number("mtf", a.magnetic_toolface_deg, 2)
      .number("rpm", a.rpm, 2)
      .number("sinc", a.inclination_sd_deg, 3)
      .number("sazi", a.azimuth_sd_deg, 3)
      .number("stf", a.toolface_sd_deg, 3)
      .number("dip", a.dip_deg, 3)
      .number("g", a.total_g, 4)
      .number("b", a.total_b, 3)
      .number("n", a.samples_used, 0)
      .number("flags", a.flags, 0)
      .text("why", a.reason)
      .done();
}

std::string status_json(const topics::ComponentStatus& s, const std::string& key, double rx_ms) {
  std::string counters = "[";
  for (const auto& c : s.counters) {
    if (counters.size() > 1) counters += ',';
    counters += '[';
    append_json_string(counters, c.name);
    counters += ',' + std::to_string(c.value) + ']';
  }
  counters += ']';
  return Object()
      .text("k", key)
      .text("comp", s.component)
      .text("host", s.host)
      .text("state", s.state)
      .number("rx", rx_ms, 1)
      .raw("counters", counters)
      .text("err", s.last_error)
      .done();
}

std::string station_json(const topics::SurveyStation& s, const std::string& key) {
  return Object()
      .text("k", key)
      .text("tool", s.tool_id)
      .text("src", s.source)
      .number("i", s.index, 0)
      .number("md", s.md_m, 2)
      .number("inc", s.inclination_deg, 3)
      .number("sinc", s.inclination_sd_deg, 3)
      .number("azi", s.azimuth_deg, 3)
      .number("sazi", s.azimuth_sd_deg, 3)
      .text("ref", s.azimuth_reference)
      .number("n", s.north_m, 2)
      .number("e", s.east_m, 2)
      .number("tvd", s.tvd_m, 2)
      .number("dls", s.dls_deg_per_30m, 2)
      .number("vs", s.vertical_section_m, 2)
      .number("maj", s.ellipse_major_sd_m, 3)
      .number("mnr", s.ellipse_minor_sd_m, 3)
      .number("maz", s.ellipse_major_azimuth_deg, 1)
      .number("sdt", s.tvd_sd_m, 3)
      .number("tf", s.gravity_toolface_deg, 1)
      .number("flags", s.flags, 0)
      .text("qc", s.qc_reason)
      .done();
}

}  // namespace plumb::display_component
