#include "foxglove_server.hpp"

#include <civetweb.h>

#include <stdexcept>
#include <thread>
#include <vector>

#include "civetweb_start.hpp"

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
  subprotocols_ = std::make_unique<mg_websocket_subprotocols>();
  subprotocols_->nb_subprotocols = 1;
  subprotocols_->subprotocols = subprotocol_names_;
  // A thread per client, and two for plain HTTP requests.
  const CivetwebServer server =
      start_civetweb({options_.bind, options_.port, options_.max_clients + 2, "--foxglove-port", "Foxglove"}, this);
  context_ = server.context;
  port_ = server.port;
  mg_set_request_handler(context_, "/", foxglove_http_trampoline, this);
  mg_set_websocket_handler_with_subprotocols(context_, "/", subprotocols_.get(), foxglove_connect_trampoline,
                                             foxglove_ready_trampoline, foxglove_data_trampoline,
                                             foxglove_close_trampoline, this);
}

FoxgloveServer::~FoxgloveServer() {
  // mg_stop closes every connection: each close handler stops its sender thread.
  if (context_) stop_civetweb(context_, options_.bind, port_);
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
