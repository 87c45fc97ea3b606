// plumb-wits: the rig's depth on DDS. Reads the rig's WITS level-0 feed (a TCP connection it
// opens or accepts, or a serial port), takes the bit depth of record 01 (or the items it is told),
// and publishes the depth of a tool's sensor on plumb/depth, with what it could not use counted on
// plumb/status. Bad input is counted, never fatal; a lost feed is waited for again.
#include <algorithm>
#include <chrono>
#include <iostream>

#include "plumb/components/cli.hpp"
#include "reader.hpp"

namespace plumb::wits_component {
namespace {

void add_link_options(CLI::App& app, ReaderOptions& o, double& reconnect_max_s) {
  auto* listen = app.add_option("--listen", o.listen, "TCP server: take the feed on [ADDRESS:]PORT (the rig connects here)");
  auto* connect = app.add_option("--connect", o.connect, "TCP client: connect to the rig's WITS server at HOST:PORT");
  auto* device = app.add_option("--device", o.device, "serial port of the rig's WITS line (e.g. /dev/ttyS0)");
  listen->excludes(connect)->excludes(device);
  connect->excludes(device);
  app.add_option("--baud", o.baud, "serial baud rate (a standard rate)")->capture_default_str();
  app.add_option("--reconnect-max", reconnect_max_s, "longest wait between two attempts to reopen the feed, s")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
}

void add_depth_options(CLI::App& app, ReaderOptions& o, std::string& units, std::string& bit, std::string& hole,
                       std::string& moving, std::string& slips) {
  app.add_option("--tool-id", o.tool_id, "the tool whose depth this is (as its bridge's --tool-id)")->capture_default_str();
  app.add_option("--units", units, "the feed's depths: m or ft")->check(CLI::IsMember({"m", "ft"}))->capture_default_str();
  app.add_option("--sensor-offset", o.depth.sensor_offset_m,
                 "how far the sensor sits behind (above) the bit, in metres: published depth = bit depth - offset")
      ->capture_default_str();
  app.add_option("--depth-sd", o.depth_sd_m, "the depth's standard deviation, m (0: unknown)")->capture_default_str();
  app.add_option("--bit-item", bit, "WITS item of the bit depth, RRII")->capture_default_str();
  app.add_option("--hole-item", hole, "WITS item of the hole depth, RRII (off bottom, for in slips)")->capture_default_str();
  app.add_option("--moving-item", moving, "WITS item whose non-zero value says the string moves (default: from the depth)");
  app.add_option("--slips-item", slips, "WITS item whose non-zero value says the string is in slips (default: from the depth)");
  app.add_option("--moving-tolerance", o.depth.moving_tolerance_m, "from the depth: a change beyond this is motion, m")
      ->capture_default_str();
  app.add_option("--moving-window", o.depth.moving_window_s,
                 "from the depth: a change beyond the tolerance over this window is motion too (slow drilling), s")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--max-depth", o.depth.max_depth_m, "a bit depth beyond this is refused and counted, m")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--max-speed", o.depth.max_speed_mps,
                 "a bit depth that moved faster than this is refused and counted (3 frames that hold: taken), m/s")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--slips-after", o.depth.slips_still_s,
                 "from the depth: still this long with the bit off bottom is in slips, s (0: never)")
      ->capture_default_str();
}

}  // namespace
}  // namespace plumb::wits_component

int main(int argc, char** argv) {
  using namespace plumb;
  wits_component::ReaderOptions o;
  std::string units = "m", bit = "0108", hole = "0110", moving, slips;
  double reconnect_max_s = 5;
  CLI::App app{"plumb-wits: the rig's WITS level-0 depth feed (TCP or serial) on plumb/depth for a tool"};
  components::add_transport_options(app, o.transport);
  wits_component::add_link_options(app, o, reconnect_max_s);
  wits_component::add_depth_options(app, o, units, bit, hole, moving, slips);
  app.add_option("--wait-subscribers", o.wait_subscribers_s,
                 "wait up to this many seconds for a reader of plumb/depth before reading the feed (0: publish at once)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--count", o.count, "exit after publishing this many depths (0: run until stopped)")->capture_default_str();
  app.add_option("--silence-notice", o.silence_notice_s, "say so when connected but no frame came for this many seconds")
      ->capture_default_str();
  app.name(wits_component::kProgram);
  if (const int status = components::parse_command_line(app, argc, argv); status >= 0) return status;
  try {
    if (o.listen.empty() && o.connect.empty() && o.device.empty())
      throw std::invalid_argument("say where the feed comes from: --listen PORT, --connect HOST:PORT or --device PATH");
    o.depth.bit_item = wits::item_code_option(bit, "--bit-item");
    o.depth.hole_item = wits::item_code_option(hole, "--hole-item");
    if (!moving.empty()) o.depth.moving_item = wits::item_code_option(moving, "--moving-item");
    if (!slips.empty()) o.depth.slips_item = wits::item_code_option(slips, "--slips-item");
    if (units == "ft") o.depth.unit_m = wits::kFootInMetres;
    o.backoff.max = std::chrono::milliseconds(static_cast<long long>(reconnect_max_s * 1000));
    o.backoff.min = std::min(o.backoff.min, o.backoff.max);
    components::install_stop_handler();
    return wits_component::run_reader(o);
  } catch (const std::exception& e) {
    return components::exit_on_error(wits_component::kProgram, e);
  }
}
