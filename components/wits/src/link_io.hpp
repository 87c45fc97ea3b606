// What the TCP links share: reading a connected socket, and keep-alive so that a peer that
// vanished without closing (a cable pulled) is noticed.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>

#include "plumb/wits/link.hpp"

namespace plumb::wits {

// Waits up to `timeout` for bytes on `fd` and reads them; Closed when the peer closed or the
// socket failed (`last` then says why; the caller closes the socket).
Link::ReadResult read_socket(int fd, std::uint8_t* buffer, std::size_t capacity, std::chrono::milliseconds timeout,
                             LinkCounters& counters, std::string& last);
// TCP keep-alive after 10 s idle, probes every 5 s, dead after 3 unanswered.
void keep_alive(int fd);

}  // namespace plumb::wits
