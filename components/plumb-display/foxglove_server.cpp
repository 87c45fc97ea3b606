#include "foxglove_server.hpp"

#include <civetweb.h>

#include <stdexcept>
#include <thread>
#include <vector>

#include "addresses.hpp"

namespace plumb::display_component {

struct FoxgloveServer::Client {
  std::shared_ptr<FoxgloveClient> queue;
  std::thread sender;
};

namespace {

int foxglove_connect_trampoline(const mg_connection*, void* self) {
  return static_cast<FoxgloveServer*>(self)->client_may_connect() ? 0 : 1;
}
void foxglove_ready_trampoline(mg_connection* conn, void* self) { static_cast<FoxgloveServer*>(self)->client_ready(conn); }
int foxglove_data_trampoline(mg_connection* conn, int bits, char* data, size_t size, void* self) {
  return static_cast<FoxgloveServer*>(self)->client_data(conn, bits, data, size);
}
void foxglove_close_trampoline(const mg_connection* conn, void* self) { static_cast<FoxgloveServer*>(self)->client_closed(conn); }
// civetweb's own log lines would interleave with ours: plumb/status counts what matters.
int foxglove_quiet_log(const mg_connection*, const char*) { return 1; }
// A plain HTTP request on the Foxglove port: say what the port is for.
int foxglove_http_trampoline(mg_connection* conn, void*) {
  const std::string body = "plumb-display: Foxglove WebSocket server (subprotocol foxglove.websocket.v1); "
                           "in Foxglove: Open connection, Foxglove WebSocket, ws://HOST:PORT\n";
  mg_send_http_ok(conn, "text/plain; charset=utf-8", static_cast<long long>(body.size()));
  mg_write(conn, body.data(), body.size());
  return 200;
}

}  // namespace

FoxgloveServer::FoxgloveServer(const FoxgloveServerOptions& options, FoxgloveHub& hub) : options_(options), hub_(hub) {
  mg_init_library(0);
  subprotocols_ = std::make_unique<mg_websocket_subprotocols>();
  subprotocols_->nb_subprotocols = 1;
  subprotocols_->subprotocols = subprotocol_names_;
  const std::string ports = options_.bind + ":" + std::to_string(options_.port);
  const std::string threads = std::to_string(options_.max_clients + 2);  // + plain HTTP requests
  const char* config[] = {"listening_ports", ports.c_str(),
                          "num_threads", threads.c_str(),
                          "enable_websocket_ping_pong", "yes",
                          "websocket_timeout_ms", "5000",
                          "request_timeout_ms", "10000",
                          nullptr};
  mg_callbacks callbacks{};
  callbacks.log_message = foxglove_quiet_log;
  mg_init_data init{};
  init.callbacks = &callbacks;
  init.user_data = this;
  init.configuration_options = config;
  char text[256] = {};
  unsigned code = 0;
  mg_error_data error{};
  error.code = &code;
  error.text = text;
  error.text_buffer_size = sizeof text;
  context_ = mg_start2(&init, &error);
  if (!context_) {
    mg_exit_library();
    std::string why = listen_failure(options_.bind, options_.port, "--foxglove-port");
    if (why.empty()) why = text[0] ? text : "civetweb could not start";
    throw std::runtime_error("cannot serve Foxglove on " + ports + ": " + why);
  }
  mg_server_port served[4]{};
  if (mg_get_server_ports(context_, 4, served) > 0) port_ = served[0].port;
  mg_set_request_handler(context_, "/", foxglove_http_trampoline, this);
  mg_set_websocket_handler_with_subprotocols(context_, "/", subprotocols_.get(), foxglove_connect_trampoline,
                                             foxglove_ready_trampoline, foxglove_data_trampoline,
                                             foxglove_close_trampoline, this);
}

FoxgloveServer::~FoxgloveServer() {
  // mg_stop closes every connection: each close handler stops its sender thread.
  if (context_) mg_stop(context_);
  mg_exit_library();
}

bool FoxgloveServer::client_may_connect() {
  if (hub_.stats().clients < static_cast<std::size_t>(options_.max_clients)) return true;
  ++refused_;
  return false;
}

void FoxgloveServer::client_ready(mg_connection* conn) {
  auto* client = new Client;
  client->queue = hub_.join();
  mg_set_user_connection_data(conn, client);
  client->sender = std::thread([this, conn, queue = client->queue] {
    // Only this thread writes to the client: a slow one blocks nothing but itself, while its queue
    // drops its oldest messages and counts them.
    std::vector<FoxgloveFrame> frames;
    while (queue->next(frames)) {
      for (const auto& f : frames) {
        const int written = f.binary ? mg_websocket_write(conn, MG_WEBSOCKET_OPCODE_BINARY,
                                                          reinterpret_cast<const char*>(f.data.data()), f.data.size())
                                     : mg_websocket_write(conn, MG_WEBSOCKET_OPCODE_TEXT, f.text.data(), f.text.size());
        if (written <= 0) {
          ++write_failures_;
          return;  // the connection is going: its close handler ends this client
        }
        ++frames_sent_;
      }
    }
  });
}

int FoxgloveServer::client_data(mg_connection* conn, int bits, const char* data, std::size_t size) {
  auto* client = static_cast<Client*>(mg_get_user_connection_data(conn));
  const int opcode = bits & 0x0f;
  if (opcode == MG_WEBSOCKET_OPCODE_CONNECTION_CLOSE) return 0;
  if (!client) return 1;
  if (opcode == MG_WEBSOCKET_OPCODE_TEXT) {
    hub_.receive(client->queue, std::string(data, size));
  } else if (opcode == MG_WEBSOCKET_OPCODE_BINARY) {
    // Binary from a client is client publishing or a service call: neither is offered.
    hub_.receive(client->queue, R"({"op":"binary message"})");
  }
  return 1;
}

void FoxgloveServer::client_closed(const mg_connection* conn) {
  auto* client = static_cast<Client*>(mg_get_user_connection_data(conn));
  if (!client) return;
  hub_.leave(client->queue);  // wakes the sender, which then ends
  if (client->sender.joinable()) client->sender.join();
  delete client;
}

}  // namespace plumb::display_component
