// plumb-display's Foxglove WebSocket server (subprotocol foxglove.websocket.v1), on a civetweb
// context and port of its own, beside the page's: Foxglove (or any client of the protocol) opens
// ws://HOST:PORT/. Each client has its own sender thread, which writes what its queue in the hub
// holds; a slow client blocks only that thread.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>

#include "foxglove_hub.hpp"

struct mg_context;
struct mg_connection;
struct mg_websocket_subprotocols;

namespace plumb::display_component {

struct FoxgloveServerOptions {
  std::string bind = "127.0.0.1";
  int port = 8765;      // 0: any free port (port() tells which)
  int max_clients = 8;  // each holds a civetweb worker thread; more are refused
};

class FoxgloveServer {
 public:
  // Starts serving; throws std::runtime_error with a one-line message (port taken, bad address).
  FoxgloveServer(const FoxgloveServerOptions& options, FoxgloveHub& hub);
  ~FoxgloveServer();
  FoxgloveServer(const FoxgloveServer&) = delete;
  FoxgloveServer& operator=(const FoxgloveServer&) = delete;

  int port() const { return port_; }
  std::uint64_t frames_sent() const { return frames_sent_; }
  std::uint64_t refused() const { return refused_; }

  // civetweb's callbacks (public for the C trampolines only).
  bool client_may_connect();
  void client_ready(mg_connection* conn);
  int client_data(mg_connection* conn, int bits, const char* data, std::size_t size);
  void client_closed(const mg_connection* conn);

 private:
  struct Client;

  FoxgloveServerOptions options_;
  FoxgloveHub& hub_;
  // civetweb keeps a pointer to the list of subprotocols for the context's life.
  const char* subprotocol_names_[1] = {foxglove::kSubprotocol};
  std::unique_ptr<mg_websocket_subprotocols> subprotocols_;
  mg_context* context_ = nullptr;
  int port_ = 0;
  std::atomic<std::uint64_t> frames_sent_{0}, write_failures_{0}, refused_{0};
};

}  // namespace plumb::display_component
