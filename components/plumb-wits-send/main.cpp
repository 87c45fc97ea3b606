// plumb-wits-send: a rig's WITS level-0 depth feed, for tests and demos. Sends record 01 frames
// (date, time, bit depth, hole depth) of a string drilling ahead with pipe connections, over a
// TCP connection or a pseudo-terminal, and on request the faults of a real line: noise between
// frames, a frame cut off, the connection dropped. Prints one line per frame, so a test knows what
// the reader must deliver.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <iostream>
#include <set>
#include <thread>

#include "output.hpp"
#include "plumb/components/cli.hpp"
#include "plumb/wits/depth_decoder.hpp"
#include "plumb/wits/frame_writer.hpp"
#include "plumb/wits/link.hpp"

namespace plumb::wits_send {
namespace {

struct Options {
  std::string listen, connect, serial;
  double start_m = 1000;
  double speed_m_per_h = 30;
  double interval_s = 1;
  long long count = 0;
  std::string units = "m";
  int stop_every = 0;    // frames of drilling between connections (0: none)
  int stop_frames = 10;  // frames of each connection
  double pickup_m = 1;   // the bit lifted off bottom during a connection
  int garbage_every = 0;
  std::set<long long> cut, drop;
};

// Bit and hole depth (metres) of frame k: drilling at the speed, lifted and still at connections.
std::pair<double, double> depths(const Options& o, long long k) {
  const double step = o.speed_m_per_h * o.interval_s / 3600;
  if (o.stop_every <= 0) return {o.start_m + step * k, o.start_m + step * k};
  const long long cycle = o.stop_every + o.stop_frames;
  const long long drilled = (k / cycle) * o.stop_every + std::min<long long>(k % cycle, o.stop_every);
  const double hole = o.start_m + step * drilled;
  return {k % cycle >= o.stop_every ? hole - o.pickup_m : hole, hole};
}

std::unique_ptr<Output> make_output(const Options& o) {
  if (!o.connect.empty()) {
    std::string host;
    int port = 0;
    wits::split_host_port(o.connect, "--connect", host, port);
    return make_tcp_client_output(host, port);
  }
  if (!o.serial.empty()) return make_pty_output(o.serial);
  std::string host;
  int port = 0;
  wits::split_host_port("0.0.0.0:" + o.listen, "--listen", host, port);
  return make_tcp_server_output(port);
}

int run(const Options& o) {
  const double unit_m = o.units == "ft" ? wits::kFootInMetres : 1.0;
  auto out = make_output(o);
  std::cout << kProgram << ": WITS level 0 on " << out->describe() << ", a frame every " << o.interval_s << " s"
            << std::endl;
  auto next = std::chrono::steady_clock::now();
  long long k = 0, noise_lines = 0, noise_bytes = 0, cut_frames = 0, drops = 0;
  for (; !components::g_stop && (o.count == 0 || k < o.count); ++k) {
    const auto [bit, hole] = depths(o, k);
    std::string text = wits::record01_frame(bit, hole, unit_m, std::time(nullptr));
    if (o.garbage_every > 0 && k % o.garbage_every == o.garbage_every - 1) {
      const std::string noise = "#~noise \x07\xff on the line";
      text = noise + "\r\n" + text;
      ++noise_lines;
      noise_bytes += static_cast<long long>(noise.size());
    }
    const bool cut = o.cut.count(k) != 0;
    cut_frames += cut ? 1 : 0;
    if (cut) text = text.substr(0, text.find("\r\n0110") + 8);  // ends inside the hole depth's line
    const bool written = out->write(text);
    char line[128];
    std::snprintf(line, sizeof line, "frame %lld bit_depth %.2f %s %s", k, bit / unit_m, o.units.c_str(),
                  cut ? "cut" : written ? "sent" : "lost");
    std::cout << kProgram << ": " << line << std::endl;
    if (o.drop.count(k) != 0) {
      out->drop();
      ++drops;
      std::cout << kProgram << ": connection dropped after frame " << k << std::endl;
    }
    next += std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(o.interval_s));
    while (!components::g_stop && std::chrono::steady_clock::now() < next)
      std::this_thread::sleep_for(std::min<std::chrono::steady_clock::duration>(next - std::chrono::steady_clock::now(),
                                                                                std::chrono::milliseconds(50)));
  }
  out->drop();
  std::cout << kProgram << ": " << k << " frames (" << cut_frames << " cut), " << noise_lines << " noise lines ("
            << noise_bytes << " bytes), " << drops << " connections dropped" << std::endl;
  return 0;
}

}  // namespace
}  // namespace plumb::wits_send

int main(int argc, char** argv) {
  using namespace plumb;
  wits_send::Options o;
  std::vector<long long> cut, drop;
  CLI::App app{"plumb-wits-send: play a rig's WITS level-0 depth feed (tests and demos)"};
  auto* listen = app.add_option("--listen", o.listen, "TCP server on PORT: the reader connects (plumb-wits --connect)");
  auto* connect = app.add_option("--connect", o.connect, "TCP client to HOST:PORT (plumb-wits --listen)");
  auto* serial = app.add_option("--serial", o.serial, "a pseudo-terminal linked at this path (plumb-wits --device)");
  listen->excludes(connect)->excludes(serial);
  connect->excludes(serial);
  app.add_option("--start-depth", o.start_m, "bit depth of the first frame, m")->capture_default_str();
  app.add_option("--speed", o.speed_m_per_h, "rate of penetration while drilling, m/h")->capture_default_str();
  app.add_option("--interval", o.interval_s, "seconds between frames")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--count", o.count, "frames to send (0: until stopped)")->capture_default_str();
  app.add_option("--units", o.units, "depths in m or ft")->check(CLI::IsMember({"m", "ft"}))->capture_default_str();
  app.add_option("--stop-every", o.stop_every, "a pipe connection after every this many frames of drilling (0: none)");
  app.add_option("--stop-frames", o.stop_frames, "frames of each connection (bit lifted off bottom, still)")
      ->capture_default_str();
  app.add_option("--garbage-every", o.garbage_every, "a line of noise before every this many frames (0: none)");
  app.add_option("--cut-frame", cut, "send frame K cut off inside its hole depth line (repeatable; 0-based)");
  app.add_option("--drop-after", drop, "drop the connection after frame K and open a new one (repeatable)");
  app.name("plumb-wits-send");
  if (const int status = components::parse_command_line(app, argc, argv); status >= 0) return status;
  o.cut.insert(cut.begin(), cut.end());
  o.drop.insert(drop.begin(), drop.end());
  try {
    if (o.listen.empty() && o.connect.empty() && o.serial.empty())
      throw std::invalid_argument("say where to send: --listen PORT, --connect HOST:PORT or --serial PATH");
    components::install_stop_handler();
    return wits_send::run(o);
  } catch (const std::exception& e) {
    return components::exit_on_error("plumb-wits-send", e);
  }
}
