#include "hub.hpp"

#include <algorithm>

#include "json.hpp"

namespace plumb::display_component {
namespace {

void append_list(std::string& out, const char* name, std::size_t count, const auto& each) {
  out += ",\"";
  out += name;
  out += "\":[";
  for (std::size_t i = 0; i < count; ++i) {
    if (i) out += ',';
    out += each(i);
  }
  out += ']';
}

}  // namespace

std::optional<std::string> Outbox::next() {
  std::unique_lock lock(mutex_);
  const auto heartbeat_at = std::max(last_sent_ + options_.heartbeat, std::chrono::steady_clock::now());
  // Something due and the throttle open, or nothing for a heartbeat period.
  while (!closed_) {
    const auto now = std::chrono::steady_clock::now();
    const auto open_at = last_sent_ + options_.min_gap;
    if (pending() && now >= open_at) break;
    if (now >= heartbeat_at) break;
    cv_.wait_until(lock, pending() ? std::min(open_at, heartbeat_at) : heartbeat_at);
  }
  if (closed_) return std::nullopt;
  last_sent_ = std::chrono::steady_clock::now();
  ++frames_;
  if (hello_) {
    std::string frame = *hello_;
    hello_.reset();
    return frame;
  }
  std::string frame = "{\"type\":\"update\",\"sent\":";
  append_json_number(frame, wall_clock_ms(), 1);
  frame += ",\"drops\":" + std::to_string(dropped_);
  std::vector<Text> attitudes;
  for (auto& [key, queue] : attitudes_) attitudes.insert(attitudes.end(), queue.begin(), queue.end());
  append_list(frame, "att", attitudes.size(), [&](std::size_t i) -> const std::string& { return *attitudes[i]; });
  for (const char* kind : {"status", "clearance", "depth"}) {
    std::vector<Text> texts;
    for (auto& [key, text] : states_[kind]) texts.push_back(text);
    append_list(frame, kind, texts.size(), [&](std::size_t i) -> const std::string& { return *texts[i]; });
  }
  append_list(frame, "survey", stations_.size(), [&](std::size_t i) -> const std::string& { return *stations_[i]; });
  const std::vector<std::string> gone(gone_.begin(), gone_.end());
  append_list(frame, "gone", gone.size(), [&](std::size_t i) { return json_text(Json(gone[i])); });
  frame += '}';
  gone_.clear();
  attitudes_.clear();
  states_.clear();
  stations_.clear();
  return frame;
}

void Outbox::close() {
  {
    std::lock_guard lock(mutex_);
    closed_ = true;
  }
  cv_.notify_all();
}

std::uint64_t Outbox::dropped() const {
  std::lock_guard lock(mutex_);
  return dropped_;
}

Hub::Hub(HubOptions options) : options_(std::move(options)) {}

void Hub::attitude(const std::string& key, const std::string& json, const HistoryPoint& point) {
  auto text = std::make_shared<const std::string>(json);
  std::lock_guard lock(mutex_);
  ++stats_.attitudes;
  latest_attitude_[key] = text;
  auto& history = history_[key];
  if (history.empty() || point.rx_ms - history.back().rx_ms >= options_.history_step_s * 1e3) history.push_back(point);
  while (!history.empty() && point.rx_ms - history.front().rx_ms > options_.history_s * 1e3) history.pop_front();
  for (const auto& box : outboxes_) {
    {
      std::lock_guard box_lock(box->mutex_);
      auto& queue = box->attitudes_[key];
      queue.push_back(text);
      while (queue.size() > options_.backlog) {
        queue.pop_front();
        ++box->dropped_;
      }
    }
    box->cv_.notify_one();
  }
}

void Hub::forget_attitude(const std::string& key) {
  std::lock_guard lock(mutex_);
  latest_attitude_.erase(key);
  history_.erase(key);
  for (const auto& box : outboxes_) {
    {
      std::lock_guard box_lock(box->mutex_);
      box->attitudes_.erase(key);
      box->gone_.insert(key);
    }
    box->cv_.notify_one();
  }
}

void Hub::latest(const std::string& kind, const std::string& key, const std::string& json) {
  auto text = std::make_shared<const std::string>(json);
  states_[kind][key] = text;
  for (const auto& box : outboxes_) {
    {
      std::lock_guard box_lock(box->mutex_);
      box->states_[kind][key] = text;
    }
    box->cv_.notify_one();
  }
}

void Hub::status(const std::string& key, const std::string& json) {
  std::lock_guard lock(mutex_);
  ++stats_.statuses;
  latest("status", key, json);
}

void Hub::clearance(const std::string& key, const std::string& json) {
  std::lock_guard lock(mutex_);
  ++stats_.clearances;
  latest("clearance", key, json);
}

void Hub::depth(const std::string& key, const std::string& json) {
  std::lock_guard lock(mutex_);
  ++stats_.depths;
  latest("depth", key, json);
}

void Hub::station(const std::string& key, const std::string& json) {
  auto text = std::make_shared<const std::string>(json);
  std::lock_guard lock(mutex_);
  ++stats_.stations;
  if (stations_.emplace(key, text).second) {
    station_order_.push_back(key);
  } else {
    stations_[key] = text;
  }
  while (station_order_.size() > options_.max_stations) {
    stations_.erase(station_order_.front());
    station_order_.pop_front();
  }
  for (const auto& box : outboxes_) {
    {
      std::lock_guard box_lock(box->mutex_);
      box->stations_.push_back(text);
      while (box->stations_.size() > options_.max_stations) {
        box->stations_.pop_front();
        ++box->dropped_;
      }
    }
    box->cv_.notify_one();
  }
}

std::string Hub::hello_json() const {
  Json history = Json::object();
  for (const auto& [key, points] : history_) {
    Json list = Json::array();
    for (const auto& p : points) {
      Json point = Json::array({json_number(p.rx_ms, 0)});
      for (const double v : {p.inclination, p.azimuth, p.toolface, p.rpm}) point.push_back(json_number(v, 3));
      point.push_back(p.flags);
      list.push_back(std::move(point));
    }
    history[key] = std::move(list);
  }
  Json hello;
  hello["type"] = "hello";
  hello["sent"] = json_number(wall_clock_ms(), 1);
  hello["history_s"] = json_number(options_.history_s, 0);
  hello["history"] = std::move(history);
  return json_text(hello);
}

std::shared_ptr<Outbox> Hub::join() {
  auto box = std::shared_ptr<Outbox>(new Outbox(options_));
  std::lock_guard lock(mutex_);
  box->hello_ = std::make_shared<const std::string>(hello_json());
  for (const auto& [key, text] : latest_attitude_) box->attitudes_[key].push_back(text);
  box->states_ = states_;
  for (const auto& key : station_order_) box->stations_.push_back(stations_.at(key));
  outboxes_.push_back(box);
  ++stats_.browsers_total;
  return box;
}

void Hub::leave(const std::shared_ptr<Outbox>& outbox) {
  outbox->close();
  std::lock_guard lock(mutex_);
  const auto it = std::find(outboxes_.begin(), outboxes_.end(), outbox);
  if (it == outboxes_.end()) return;
  dropped_by_gone_ += outbox->dropped();
  outboxes_.erase(it);
}

HubStats Hub::stats() const {
  std::lock_guard lock(mutex_);
  HubStats s = stats_;
  s.browsers = outboxes_.size();
  s.dropped = dropped_by_gone_;
  for (const auto& box : outboxes_) s.dropped += box->dropped();
  return s;
}

}  // namespace plumb::display_component
