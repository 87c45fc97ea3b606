#include "reader.hpp"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <optional>
#include <thread>
#include <vector>

#include "plumb/components/convert.hpp"
#include "plumb/components/status_reporter.hpp"
#include "plumb/transport/topic_names.hpp"
#include "plumb/wits/frame_parser.hpp"

namespace plumb::wits_component {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

std::unique_ptr<wits::Link> make_link(const ReaderOptions& o) {
  if (!o.connect.empty()) {
    std::string host;
    int port = 0;
    wits::split_host_port(o.connect, "--connect", host, port);
    return wits::make_tcp_client(host, port, o.backoff);
  }
  if (!o.device.empty()) return wits::make_serial_link(o.device, o.baud, o.backoff);
  std::string address;
  int port = 0;
  wits::split_listen_address(o.listen, "--listen", address, port);
  return wits::make_tcp_server(address, port);
}

// Everything plumb-wits counts, as plumb/status carries it.
components::CounterList counters(const wits::Link& link, const wits::FrameParser& parser,
                                 const wits::DepthDecoder& decoder, std::uint64_t published) {
  const auto& l = link.counters();
  const auto& p = parser.counters();
  const auto& d = decoder.counters();
  return {{"depths_published", published}, {"frames", p.frames},
          {"garbage_bytes", p.garbage_bytes}, {"garbage_runs", p.garbage_runs},
          {"bad_lines", p.bad_lines},         {"cut_frames", p.cut_frames},
          {"empty_frames", p.empty_frames},   {"frames_without_depth", d.frames_without_depth},
          {"bad_values", d.bad_values},       {"depths_out_of_range", d.out_of_range},
          {"depth_jumps", d.jumps},           {"connects", l.connects},
          {"reconnects", l.reconnects},       {"disconnects", l.disconnects},
          {"bytes_read", l.bytes_read}};
}

topics::MeasuredDepth to_message(const wits::DepthReading& r, const ReaderOptions& o) {
  topics::MeasuredDepth m;
  m.tool_id = components::bounded(o.tool_id, topics::MeasuredDepth::kToolIdMax);
  m.stamp_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
                   std::chrono::system_clock::now().time_since_epoch()).count();
  m.depth_m = r.depth_m;
  m.depth_sd_m = o.depth_sd_m;
  m.flags = topics::DEPTH_VALID | (r.moving ? topics::DEPTH_MOVING : 0u) | (r.in_slips ? topics::DEPTH_IN_SLIPS : 0u);
  return m;
}

// A feed's first depth published before discovery matched its reader goes to nobody: wait, bounded,
// for a reader first (the link's bytes wait in the socket or the tty meanwhile), and say what happened.
// Its status goes out meanwhile: a monitor sees a plumb-wits that waits, not nothing.
bool wait_for_readers(transport::Writer<topics::MeasuredDepth>& writer, double seconds,
                      components::StatusReporter& status) {
  if (seconds <= 0) return true;
  std::cout << kProgram << ": waiting up to " << seconds << " s for a reader of plumb/depth" << std::endl;
  const auto start = Clock::now();
  while (writer.matched_readers() == 0 && seconds_since(start) < seconds && !components::g_stop) {
    if (status.due()) status.publish("running", {{"depths_published", 0}, {"readers", 0}});
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (components::g_stop) return false;
  if (writer.matched_readers() == 0)
    std::cout << kProgram << ": no reader of plumb/depth after " << seconds << " s; publishing anyway" << std::endl;
  else
    std::cout << kProgram << ": " << writer.matched_readers() << " reader(s) of plumb/depth matched after "
              << std::round(seconds_since(start) * 100) / 100 << " s" << std::endl;
  return true;
}

// The link's events in the log, once each (a server waiting, a client retrying, say it once).
class LinkLog {
 public:
  explicit LinkLog(const wits::Link& link) : link_(link) {}
  void on(wits::Link::Event e) {
    if (e == wits::Link::Event::Opened) {
      std::cout << kProgram << ": " << link_.last_event() << std::endl;
      failing_ = false;
    } else if (e == wits::Link::Event::Closed) {
      std::cout << kProgram << ": " << link_.last_event() << "; waiting for the feed again" << std::endl;
    } else if (e == wits::Link::Event::OpenFailed && !failing_) {
      std::cout << kProgram << ": " << link_.last_event() << "; retrying with back-off" << std::endl;
      failing_ = true;
    }
  }

 private:
  const wits::Link& link_;
  bool failing_ = false;
};

}  // namespace

int run_reader(const ReaderOptions& o) {
  auto link = make_link(o);
  wits::FrameParser parser;
  wits::DepthDecoder decoder(o.depth);
  auto conn = components::connect(o.transport, kProgram);
  auto writer = transport::make_writer<topics::MeasuredDepth>(*conn.participant, transport::topic_names::kDepth,
                                                              transport::default_qos_for_topic(transport::topic_names::kDepth));
  // One reader per tool: the tool in the component's name tells them apart in plumb status.
  components::StatusReporter status(*conn.participant, std::string(kProgram) + "/" + o.tool_id);
  if (!wait_for_readers(writer, o.wait_subscribers_s, status)) return 0;
  std::cout << kProgram << ": reading WITS level 0 from " << link->describe() << " for tool '" << o.tool_id
            << "' (bit depth item " << o.depth.bit_item << ", sensor " << o.depth.sensor_offset_m
            << " m behind the bit); publishing plumb/depth on " << conn.transport->name() << std::endl;
  LinkLog log(*link);
  std::vector<std::uint8_t> buffer(4096);
  std::vector<wits::Frame> frames;
  std::uint64_t published = 0;
  auto last_frame = Clock::now();
  bool said_silent = false;
  const auto start = Clock::now();
  while (!components::g_stop && (o.count == 0 || published < static_cast<std::uint64_t>(o.count))) {
    const auto r = link->read(buffer.data(), buffer.size(), std::chrono::milliseconds(100));
    log.on(r.event);
    if (r.event == wits::Link::Event::Closed) parser.end_of_stream();
    if (r.event == wits::Link::Event::Opened) last_frame = Clock::now(), said_silent = false;
    frames.clear();
    parser.feed(buffer.data(), r.bytes, frames);
    for (const auto& frame : frames) {
      last_frame = Clock::now();
      said_silent = false;
      if (const auto reading = decoder.decode(frame, seconds_since(start))) {
        writer.write(to_message(*reading, o));
        ++published;
      }
    }
    if (!said_silent && link->is_open() && seconds_since(last_frame) > o.silence_notice_s) {
      std::cout << kProgram << ": connected, but no WITS frame for " << o.silence_notice_s << " s (" << link->describe()
                << ")" << std::endl;
      said_silent = true;
    }
    if (status.due()) status.publish(link->is_open() ? "running" : "degraded", counters(*link, parser, decoder, published),
                                     link->is_open() ? "" : link->last_event());
  }
  const auto& p = parser.counters();
  std::cout << kProgram << ": " << p.frames << " frames, " << published << " depths published, " << p.garbage_bytes
            << " garbage bytes in " << p.garbage_runs << " runs, " << p.bad_lines << " bad lines, " << p.cut_frames
            << " cut frames, " << decoder.counters().frames_without_depth << " frames without depth, "
            << decoder.counters().out_of_range << " depths out of range, " << decoder.counters().jumps
            << " depth jumps refused, "
            << link->counters().connects << " connections" << std::endl;
  status.publish("stopping", counters(*link, parser, decoder, published));
  components::sleep_while_running(o.linger_s);
  return 0;
}

}  // namespace plumb::wits_component
