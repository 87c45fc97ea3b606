#include "web_server.hpp"

#include <civetweb.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "civetweb_start.hpp"
#include "json.hpp"
#include "web_assets.hpp"

namespace plumb::display_component {

struct WebServer::Browser {
  std::shared_ptr<Outbox> outbox;
  std::thread sender;
};

namespace {

std::string mime_type(const std::string& path) {
  const auto dot = path.rfind('.');
  const std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  if (ext == "html") return "text/html; charset=utf-8";
  if (ext == "js") return "text/javascript; charset=utf-8";
  if (ext == "css") return "text/css; charset=utf-8";
  if (ext == "svg") return "image/svg+xml";
  if (ext == "json") return "application/json";
  return "application/octet-stream";
}

// A file name of the page (no folders, no dot files): all --web-root may serve.
bool plain_name(const std::string& name) {
  return !name.empty() && name[0] != '.' && name.find('/') == std::string::npos && name.find('\\') == std::string::npos;
}

int send_body(mg_connection* conn, const std::string& type, std::string_view body) {
  mg_send_http_ok(conn, type.c_str(), static_cast<long long>(body.size()));
  mg_write(conn, body.data(), body.size());
  return 200;
}

int serve_trampoline(mg_connection* conn, void* self) { return static_cast<WebServer*>(self)->serve(conn); }
int connect_trampoline(const mg_connection*, void* self) { return static_cast<WebServer*>(self)->browser_may_connect() ? 0 : 1; }
void ready_trampoline(mg_connection* conn, void* self) { static_cast<WebServer*>(self)->browser_ready(conn); }
// The page sends nothing the server needs (it may send keep-alive text); 1 keeps the connection open.
int data_trampoline(mg_connection*, int, char*, size_t, void*) { return 1; }
void close_trampoline(const mg_connection* conn, void* self) { static_cast<WebServer*>(self)->browser_closed(conn); }
// civetweb's own log lines (a browser that vanished mid-request, ...) would interleave with ours on
// stderr: the counters of /stats.json and plumb/status say what matters.

}  // namespace

WebServer::WebServer(const WebOptions& options, Hub& hub) : options_(options), hub_(hub) {
  // A thread per browser, and eight for the page's and the stats' requests.
  const CivetwebServer server = start_civetweb({options_.bind, options_.port, options_.max_browsers + 8, "--port", ""}, this);
  context_ = server.context;
  port_ = server.port;
  mg_set_request_handler(context_, "/", serve_trampoline, this);
  mg_set_websocket_handler(context_, "/ws", connect_trampoline, ready_trampoline, data_trampoline, close_trampoline, this);
}

WebServer::~WebServer() {
  // mg_stop closes every connection: each close handler stops its sender thread.
  if (context_) stop_civetweb(context_, options_.bind, port_);
  mg_exit_library();
}

int WebServer::serve(mg_connection* conn) {
  const mg_request_info* request = mg_get_request_info(conn);
  std::string path = request->local_uri ? request->local_uri : "/";
  if (path == "/") path = "/index.html";
  const std::string name = path.substr(1);
  if (name == "stats.json") return send_body(conn, mime_type(name), stats_json());
  if (!plain_name(name)) {
    mg_send_http_error(conn, 404, "%s", "not found");
    return 404;
  }
  if (!options_.web_root.empty()) {
    std::ifstream in(options_.web_root + "/" + name, std::ios::binary);
    if (in) {
      std::ostringstream body;
      body << in.rdbuf();
      return send_body(conn, mime_type(name), body.str());
    }
  } else if (const auto* asset = web_asset(name)) {
    return send_body(conn, mime_type(name), *asset);
  }
  mg_send_http_error(conn, 404, "%s", "not found");
  return 404;
}

bool WebServer::browser_may_connect() {
  // Beyond --max-browsers a WebSocket is refused (the page retries, up to every 5 s): the worker
  // threads left are kept for page and stats requests.
  if (hub_.stats().browsers < static_cast<std::size_t>(options_.max_browsers)) return true;
  ++refused_;
  return false;
}

void WebServer::browser_ready(mg_connection* conn) {
  auto* browser = new Browser;
  browser->outbox = hub_.join();
  mg_set_user_connection_data(conn, browser);
  browser->sender = std::thread([this, conn, outbox = browser->outbox] {
    // Only this thread writes frames to the browser, so a slow one blocks nothing but itself: its
    // outbox meanwhile keeps the latest estimates and counts what it drops.
    while (auto frame = outbox->next()) {
      if (mg_websocket_write(conn, MG_WEBSOCKET_OPCODE_TEXT, frame->data(), frame->size()) <= 0) {
        ++write_failures_;
        break;  // the connection is going: its close handler ends this browser
      }
      ++frames_sent_;
    }
  });
}

void WebServer::browser_closed(const mg_connection* conn) {
  auto* browser = static_cast<Browser*>(mg_get_user_connection_data(conn));
  if (!browser) return;
  hub_.leave(browser->outbox);  // wakes the sender, which then ends
  if (browser->sender.joinable()) browser->sender.join();
  delete browser;
}

std::string WebServer::stats_json() const {
  const HubStats s = hub_.stats();
  Json j;
  j["browsers"] = s.browsers;
  j["browsers_total"] = s.browsers_total;
  j["attitudes"] = s.attitudes;
  j["statuses"] = s.statuses;
  j["stations"] = s.stations;
  j["clearances"] = s.clearances;
  j["depths"] = s.depths;
  j["dropped"] = s.dropped;
  j["frames_sent"] = frames_sent_.load();
  j["write_failures"] = write_failures_.load();
  j["refused"] = refused_.load();
  return json_text(j);
}

}  // namespace plumb::display_component
