// The JSON the page reads: one object per message, written with nlohmann::json (Debian's
// nlohmann-json3-dev), which escapes strings and writes NaN as null. Field names are short and
// numbers rounded to what the page shows because every browser gets them up to 30 times a second;
// the page (web/index.html) is their only reader.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "attitude_difference.hpp"
#include "plumb/topics/all.hpp"

namespace plumb::display_component {

// Objects keep their fields in the order written.
using Json = nlohmann::ordered_json;

// A number rounded to `decimals` places (an integer for 0), or null for NaN and infinities (JSON
// has neither).
Json json_number(double value, int decimals);
// The JSON text of a value; bytes that are not UTF-8 become U+FFFD rather than an invalid document.
std::string json_text(const Json& value);

// Appends `text` as a JSON string (quotes, escapes).
void append_json_string(std::string& out, const std::string& text);
// Appends a number as json_number writes it.
void append_json_number(std::string& out, double value, int decimals);

// Milliseconds since the epoch: the time stamps the page measures latency against.
double wall_clock_ms();

// `rx_ms`: when the display took the message (wall_clock_ms()): the page's latency reference.
// `difference`: the estimate against its tool's reference plugin (PluginDifferences), which the
// page draws as it is ("diff": {"ref", "inc", "azi", "tf"}, each angle {"d", "sd"} or null; null
// for the reference itself and a tool's only plugin): the page computes none of its own.
std::string attitude_json(const topics::Attitude& a, const std::string& key, double rx_ms,
                          const std::optional<AttitudeDifference>& difference = std::nullopt);
std::string status_json(const topics::ComponentStatus& s, const std::string& key, double rx_ms);
std::string station_json(const topics::SurveyStation& s, const std::string& key);
std::string clearance_json(const topics::Clearance& c, const std::string& key);
std::string depth_json(const topics::MeasuredDepth& d);

}  // namespace plumb::display_component
