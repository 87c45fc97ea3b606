// The JSON the page reads: one object per message, written by hand (a few flat objects do not need
// a JSON library). Field names are short because every browser gets them up to 30 times a second;
// the page (web/index.html) is their only reader.
#pragma once

#include <string>

#include "plumb/topics/all.hpp"

namespace plumb::display_component {

// Appends `text` as a JSON string (quotes, escapes).
void append_json_string(std::string& out, const std::string& text);
// Appends a number, or null for NaN and infinities (JSON has neither).
void append_json_number(std::string& out, double value, int decimals);

// Milliseconds since the epoch: the time stamps the page measures latency against.
double wall_clock_ms();

// `rx_ms`: when the display took the message (wall_clock_ms()): the page's latency reference.
std::string attitude_json(const topics::Attitude& a, const std::string& key, double rx_ms);
std::string status_json(const topics::ComponentStatus& s, const std::string& key, double rx_ms);
std::string station_json(const topics::SurveyStation& s, const std::string& key);

}  // namespace plumb::display_component
