// The addresses a person can open for the page, whatever --bind says: 0.0.0.0 is where the server
// listens (every interface), not an address a browser can reach.
#pragma once

#include <string>
#include <vector>

namespace plumb::display_component {

// For a server bound to every interface (0.0.0.0, ::, or empty): http://127.0.0.1:PORT/ first,
// then http://<host name>:PORT/ and http://<address>:PORT/ for each IPv4 interface that is up
// (loopback left out). For any other address: that address alone.
// `scheme` "ws" gives the Foxglove server's addresses (ws://HOST:PORT/) alike.
std::vector<std::string> page_addresses(const std::string& bind, int port, const std::string& scheme = "http");

// Why a server cannot listen on address:port, in the system's words (civetweb only says "Failed to
// setup server ports"): the address is tried once more here. `port_option` names the option to
// change ("--port"). Empty when the address can be bound after all.
std::string listen_failure(const std::string& address, int port, const std::string& port_option);

}  // namespace plumb::display_component
