#include "civetweb_start.hpp"

#include <civetweb.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <thread>

#include "addresses.hpp"

namespace plumb::display_component {
namespace {

int civetweb_quiet_log(const mg_connection*, const char*) { return 1; }

// One connection to the listening port, closed at once (the listener, stopping, accepts nothing).
void knock(const std::string& bind, int port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return;
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  // 0.0.0.0 listens on loopback too.
  const std::string host = bind == "0.0.0.0" ? "127.0.0.1" : bind;
  if (::inet_pton(AF_INET, host.c_str(), &address.sin_addr) == 1)
    (void)::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address);
  ::close(fd);
}

}  // namespace

void stop_civetweb(mg_context* context, const std::string& bind, int port) {
  std::atomic<bool> stopped{false};
  std::thread waker([&] {
    while (!stopped) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      if (!stopped) knock(bind, port);
    }
  });
  mg_stop(context);
  stopped = true;
  waker.join();
}

CivetwebServer start_civetweb(const CivetwebStart& start, void* user_data) {
  mg_init_library(0);
  const std::string ports = start.bind + ":" + std::to_string(start.port);
  const std::string threads = std::to_string(start.threads);
  const char* config[] = {"listening_ports", ports.c_str(),
                          "num_threads", threads.c_str(),
                          // A peer that stops answering is found by pings when it sends nothing for 5 s.
                          "enable_websocket_ping_pong", "yes",
                          "websocket_timeout_ms", "5000",
                          "request_timeout_ms", "10000",
                          nullptr};
  mg_callbacks callbacks{};
  callbacks.log_message = civetweb_quiet_log;
  mg_init_data init{};
  init.callbacks = &callbacks;
  init.user_data = user_data;
  init.configuration_options = config;
  char text[256] = {};
  unsigned code = 0;
  mg_error_data error{};
  error.code = &code;
  error.text = text;
  error.text_buffer_size = sizeof text;
  CivetwebServer server;
  server.context = mg_start2(&init, &error);
  if (!server.context) {
    mg_exit_library();
    std::string why = listen_failure(start.bind, start.port, start.port_option);
    if (why.empty()) why = text[0] ? text : "civetweb could not start";
    throw std::runtime_error("cannot serve " + (start.what.empty() ? std::string() : start.what + " ") + "on " + ports +
                             ": " + why);
  }
  mg_server_port served[4]{};
  server.port = mg_get_server_ports(server.context, 4, served) > 0 ? served[0].port : start.port;
  return server;
}

}  // namespace plumb::display_component
