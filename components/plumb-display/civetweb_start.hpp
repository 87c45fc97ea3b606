// Starting one civetweb server, as the page's and Foxglove's both do: the listening address, the
// thread count, pings that find a silent WebSocket peer, no log of its own (plumb's lines say what
// happened), and a failure to listen said in the system's words.
#pragma once

#include <string>

struct mg_context;

namespace plumb::display_component {

struct CivetwebStart {
  std::string bind;
  int port = 0;
  int threads = 1;
  std::string port_option;  // the option a user changes when the port is taken ("--port")
  std::string what;         // what is served, for the error: "" (the page) or "Foxglove"
};

// The running server and the port it got (port 0: any free one). Throws std::runtime_error
// "cannot serve [WHAT ]on ADDRESS:PORT: why" when it cannot listen.
struct CivetwebServer {
  mg_context* context = nullptr;
  int port = 0;
};
CivetwebServer start_civetweb(const CivetwebStart& start, void* user_data);

// mg_stop, without its wait: civetweb's listener looks at its stop flag only between polls of its
// listening socket, 2 s each, and holds the port until then; a connection while it stops wakes it.
void stop_civetweb(mg_context* context, const std::string& bind, int port);

}  // namespace plumb::display_component
