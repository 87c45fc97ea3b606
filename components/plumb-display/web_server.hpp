// The HTTP side of plumb-display, on civetweb: the page at / (embedded, or from --web-root), the
// live feed at /ws (one WebSocket per browser, fed from the hub by a sender thread of its own),
// and the server's counters at /stats.json.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>

#include "hub.hpp"

struct mg_context;
struct mg_connection;

namespace plumb::display_component {

struct WebOptions {
  std::string bind = "127.0.0.1";
  int port = 8080;           // 0: any free port (port() tells which)
  std::string web_root;      // "": the embedded page
  int max_browsers = 50;     // WebSockets at once (each holds a civetweb worker thread); more are refused
};

class WebServer {
 public:
  // Starts serving; throws std::runtime_error with a one-line message (port taken, bad address).
  WebServer(const WebOptions& options, Hub& hub);
  ~WebServer();
  WebServer(const WebServer&) = delete;
  WebServer& operator=(const WebServer&) = delete;

  int port() const { return port_; }
  std::uint64_t frames_sent() const { return frames_sent_; }
  std::uint64_t write_failures() const { return write_failures_; }
  // Counters of the server, as /stats.json shows them.
  std::string stats_json() const;

  // civetweb's callbacks (public for the C trampolines only).
  int serve(mg_connection* conn);
  bool browser_may_connect();
  void browser_ready(mg_connection* conn);
  void browser_closed(const mg_connection* conn);

 private:
  struct Browser;

  WebOptions options_;
  Hub& hub_;
  mg_context* context_ = nullptr;
  int port_ = 0;
  std::atomic<std::uint64_t> frames_sent_{0}, write_failures_{0}, refused_{0};
};

}  // namespace plumb::display_component
