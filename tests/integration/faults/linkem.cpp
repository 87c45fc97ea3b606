// plumb-test-linkem: a link emulator for the fault tests, where the kernel has no netem. It relays
// raw Ethernet frames between two interfaces (AF_PACKET sockets: multicast discovery, unicast data,
// ARP, everything passes as on a wire), dropping a given percentage, delaying by a given time, or
// dropping everything while the link is "down", and counts what it dropped.
//
//   SIGUSR1: link down (drop every frame)     SIGUSR2: link up
//   SIGHUP:  re-read --control FILE (lines loss=PERCENT, delay=MS, down=0|1)
//   SIGINT, SIGTERM: write the counters and stop
//
// The counters (key=value lines) are rewritten into --stats FILE twice a second and at exit. A
// "big" dropped datagram is a UDP datagram of at least --big bytes of frame, or any IPv4 fragment
// counted once per datagram: on the tool-to-surface direction of a sensor run those are the
// sensor batches (status, heartbeats, discovery and truth are smaller), so the tests compare them
// with the samples plumb counts as lost.
#include <arpa/inet.h>
#include <linux/if_packet.h>
#include <net/ethernet.h>
#include <net/if.h>
#include <netinet/ip.h>
#include <netinet/udp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <deque>
#include <fstream>
#include <iostream>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "plumb/components/cli.hpp"

namespace {

constexpr const char* kProgram = "plumb-test-linkem";
using Clock = std::chrono::steady_clock;

volatile std::sig_atomic_t g_down_request = 0;  // 1: down, 2: up
volatile std::sig_atomic_t g_reload = 0;
volatile std::sig_atomic_t g_quit = 0;

void on_signal(int s) {
  if (s == SIGUSR1) g_down_request = 1;
  else if (s == SIGUSR2) g_down_request = 2;
  else if (s == SIGHUP) g_reload = 1;
  else g_quit = 1;
}

struct Settings {
  double loss_percent = 0;
  double delay_ms = 0;
  bool down = false;
};

struct Direction {
  std::string name;  // "a_to_b"
  int in = -1, out = -1, out_index = 0;
  std::uint64_t frames = 0, forwarded = 0, dropped_loss = 0, dropped_down = 0, dropped_big = 0, send_errors = 0;
  std::deque<std::pair<Clock::time_point, std::vector<unsigned char>>> queue;
  std::set<std::pair<std::uint32_t, std::uint16_t>> fragments_counted;  // (source, IP id) of dropped datagrams
};

int open_socket(const std::string& name, int& index) {
  index = static_cast<int>(if_nametoindex(name.c_str()));
  if (index == 0) throw std::runtime_error("no interface '" + name + "'");
  const int fd = socket(AF_PACKET, SOCK_RAW, htons(ETH_P_ALL));
  if (fd < 0) throw std::runtime_error("AF_PACKET socket: " + std::string(std::strerror(errno)) + " (needs root)");
  sockaddr_ll address{};
  address.sll_family = AF_PACKET;
  address.sll_protocol = htons(ETH_P_ALL);
  address.sll_ifindex = index;
  if (bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0)
    throw std::runtime_error("bind to " + name + ": " + std::strerror(errno));
  // Frames addressed to the other side's MAC must reach us too.
  packet_mreq mreq{};
  mreq.mr_ifindex = index;
  mreq.mr_type = PACKET_MR_PROMISC;
  if (setsockopt(fd, SOL_PACKET, PACKET_ADD_MEMBERSHIP, &mreq, sizeof mreq) != 0)
    throw std::runtime_error("promiscuous mode on " + name + ": " + std::strerror(errno));
  const int buffer = 8 << 20;
  setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &buffer, sizeof buffer);
  setsockopt(fd, SOL_SOCKET, SO_SNDBUF, &buffer, sizeof buffer);
  return fd;
}

// A veth whose sender offloads the UDP checksum hands us frames with a partial checksum, which the
// far side would then reject: IPv4 allows "no checksum" (0), so the relay clears it.
void clear_udp_checksum(std::vector<unsigned char>& f) {
  if (f.size() < sizeof(ether_header) + sizeof(iphdr)) return;
  const auto* eth = reinterpret_cast<const ether_header*>(f.data());
  if (ntohs(eth->ether_type) != ETHERTYPE_IP) return;
  const auto* ip = reinterpret_cast<const iphdr*>(f.data() + sizeof(ether_header));
  const std::size_t ihl = ip->ihl * 4u;
  if (ip->protocol != IPPROTO_UDP || (ntohs(ip->frag_off) & IP_OFFMASK) != 0) return;
  if (f.size() < sizeof(ether_header) + ihl + sizeof(udphdr)) return;
  auto* udp = reinterpret_cast<udphdr*>(f.data() + sizeof(ether_header) + ihl);
  udp->check = 0;
}

// Counts a dropped frame as a dropped big datagram when it is one (see the file comment).
void count_big(Direction& d, const std::vector<unsigned char>& f, std::size_t big) {
  if (f.size() < sizeof(ether_header) + sizeof(iphdr)) return;
  const auto* eth = reinterpret_cast<const ether_header*>(f.data());
  if (ntohs(eth->ether_type) != ETHERTYPE_IP) return;
  const auto* ip = reinterpret_cast<const iphdr*>(f.data() + sizeof(ether_header));
  if (ip->protocol != IPPROTO_UDP) return;
  const auto frag = ntohs(ip->frag_off);
  if ((frag & IP_MF) != 0 || (frag & IP_OFFMASK) != 0) {
    if (d.fragments_counted.size() > 4096) d.fragments_counted.clear();
    if (d.fragments_counted.insert({ip->saddr, ntohs(ip->id)}).second) ++d.dropped_big;
  } else if (f.size() >= big) {
    ++d.dropped_big;
  }
}

void read_control(const std::string& path, Settings& s) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    const auto eq = line.find('=');
    if (eq == std::string::npos) continue;
    const std::string key = line.substr(0, eq), value = line.substr(eq + 1);
    try {
      if (key == "loss") s.loss_percent = std::stod(value);
      else if (key == "delay") s.delay_ms = std::stod(value);
      else if (key == "down") s.down = value == "1";
    } catch (const std::exception&) {
      std::cerr << kProgram << ": ignoring control line '" << line << "'" << std::endl;
    }
  }
}

void write_stats(const std::string& path, const Settings& s, const Direction (&dirs)[2]) {
  if (path.empty()) return;
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp);
    out << "state=" << (s.down ? "down" : "up") << "\nloss=" << s.loss_percent << "\ndelay=" << s.delay_ms << "\n";
    for (const auto& d : dirs)
      out << d.name << "_frames=" << d.frames << "\n"
          << d.name << "_forwarded=" << d.forwarded << "\n"
          << d.name << "_dropped_loss=" << d.dropped_loss << "\n"
          << d.name << "_dropped_down=" << d.dropped_down << "\n"
          << d.name << "_dropped_big=" << d.dropped_big << "\n"
          << d.name << "_send_errors=" << d.send_errors << "\n";
  }
  std::rename(tmp.c_str(), path.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"relays Ethernet frames between two interfaces with loss, delay and outages (a netem stand-in)"};
  app.name(kProgram);
  std::string if_a, if_b, control, stats;
  Settings s;
  unsigned seed = 1;
  std::size_t big = 600;
  app.add_option("--a", if_a, "first interface")->required();
  app.add_option("--b", if_b, "second interface")->required();
  app.add_option("--loss", s.loss_percent, "percentage of frames dropped at random, each direction")
      ->check(CLI::Range(0.0, 100.0));
  app.add_option("--delay", s.delay_ms, "one-way delay, ms")->check(CLI::Range(0.0, 10000.0));
  app.add_flag("--down", s.down, "start with the link down");
  app.add_option("--seed", seed, "random seed of the losses")->capture_default_str();
  app.add_option("--control", control, "file re-read on SIGHUP: loss=PERCENT, delay=MS, down=0|1 lines");
  app.add_option("--stats", stats, "file of counters (key=value), rewritten twice a second and at exit");
  app.add_option("--big", big, "frames of at least this many bytes count as big datagrams")->capture_default_str();
  if (const int status = plumb::components::parse_command_line(app, argc, argv); status >= 0) return status;

  Direction dirs[2];
  try {
    int index_a = 0, index_b = 0;
    const int a = open_socket(if_a, index_a), b = open_socket(if_b, index_b);
    dirs[0].name = "a_to_b", dirs[0].in = a, dirs[0].out = b, dirs[0].out_index = index_b;
    dirs[1].name = "b_to_a", dirs[1].in = b, dirs[1].out = a, dirs[1].out_index = index_a;
  } catch (const std::exception& e) {
    plumb::components::print_error(kProgram, e.what());
    return 1;
  }
  struct sigaction action{};
  action.sa_handler = on_signal;  // no SA_RESTART: poll() returns at once
  for (int sig : {SIGUSR1, SIGUSR2, SIGHUP, SIGINT, SIGTERM}) sigaction(sig, &action, nullptr);

  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 100.0);
  std::vector<unsigned char> buffer(65536);
  auto next_stats = Clock::now();
  std::cerr << kProgram << ": " << if_a << " <-> " << if_b << ", loss " << s.loss_percent << " %, delay " << s.delay_ms
            << " ms" << (s.down ? ", down" : "") << std::endl;
  while (!g_quit) {
    if (g_down_request) {
      s.down = g_down_request == 1;
      g_down_request = 0;
      std::cerr << kProgram << ": link " << (s.down ? "down" : "up") << std::endl;
    }
    if (g_reload) {
      g_reload = 0;
      if (!control.empty()) read_control(control, s);
      std::cerr << kProgram << ": loss " << s.loss_percent << " %, delay " << s.delay_ms << " ms"
                << (s.down ? ", down" : "") << std::endl;
    }
    // Sleep until a frame arrives or the oldest delayed frame is due.
    const auto now = Clock::now();
    int timeout_ms = 100;
    for (const auto& d : dirs)
      if (!d.queue.empty()) {
        const auto wait = std::chrono::duration_cast<std::chrono::milliseconds>(d.queue.front().first - now).count();
        timeout_ms = std::max(0, std::min(timeout_ms, static_cast<int>(wait) + 1));
      }
    pollfd fds[2] = {{dirs[0].in, POLLIN, 0}, {dirs[1].in, POLLIN, 0}};
    const int ready = poll(fds, 2, timeout_ms);
    if (ready < 0 && errno != EINTR) {
      plumb::components::print_error(kProgram, std::string("poll: ") + std::strerror(errno));
      return 1;
    }
    for (int i = 0; i < 2 && ready > 0; ++i) {
      if ((fds[i].revents & POLLIN) == 0) continue;
      Direction& d = dirs[i];
      for (;;) {
        sockaddr_ll from{};
        socklen_t from_len = sizeof from;
        const ssize_t n = recvfrom(d.in, buffer.data(), buffer.size(), MSG_DONTWAIT, reinterpret_cast<sockaddr*>(&from), &from_len);
        if (n <= 0) break;
        if (from.sll_pkttype == PACKET_OUTGOING) continue;  // our own transmissions on this interface
        ++d.frames;
        std::vector<unsigned char> frame(buffer.begin(), buffer.begin() + n);
        if (s.down) {
          ++d.dropped_down;
          count_big(d, frame, big);
        } else if (s.loss_percent > 0 && uniform(random) < s.loss_percent) {
          ++d.dropped_loss;
          count_big(d, frame, big);
        } else {
          clear_udp_checksum(frame);
          d.queue.emplace_back(Clock::now() + std::chrono::microseconds(static_cast<long>(s.delay_ms * 1000)), std::move(frame));
        }
      }
    }
    const auto release = Clock::now();
    for (auto& d : dirs) {
      while (!d.queue.empty() && d.queue.front().first <= release) {
        auto& frame = d.queue.front().second;
        sockaddr_ll to{};
        to.sll_family = AF_PACKET;
        to.sll_ifindex = d.out_index;
        to.sll_halen = ETH_ALEN;
        std::memcpy(to.sll_addr, frame.data(), ETH_ALEN);
        if (sendto(d.out, frame.data(), frame.size(), 0, reinterpret_cast<sockaddr*>(&to), sizeof to) < 0) ++d.send_errors;
        else ++d.forwarded;
        d.queue.pop_front();
      }
    }
    if (Clock::now() >= next_stats) {
      write_stats(stats, s, dirs);
      next_stats = Clock::now() + std::chrono::milliseconds(500);
    }
  }
  write_stats(stats, s, dirs);
  std::cerr << kProgram << ": stopped;";
  for (const auto& d : dirs)
    std::cerr << " " << d.name << " " << d.frames << " frames, " << d.forwarded << " forwarded, " << d.dropped_loss
              << " lost, " << d.dropped_down << " dropped while down;";
  std::cerr << std::endl;
  return 0;
}
