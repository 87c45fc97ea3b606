// plumb-estimator: the estimator host. Subscribes to a sensor topic, runs one or more estimator
// plugins side by side on the same stream and publishes one attitude topic per plugin.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>

#include "host.hpp"
#include "plumb/components/cli.hpp"

int main(int argc, char** argv) {
  using namespace plumb;
  estimator_component::HostOptions o;
  CLI::App app{"plumb-estimator: run estimator plugins side by side on a sensor topic; publish plumb/attitude/<plugin>"};
  components::add_transport_options(app, o.transport);
  app.add_option("-p,--plugin,--estimator", o.plugins, "estimator plugin (repeat for several; see `plumb plugins`; --estimator, as for plumb estimate, is the same)")->required();
  app.add_option("--name", o.name,
                 "what `plumb component` and `plumb param` call this host (default: the computer's host name; give "
                 "each host on one computer its own)");
  app.add_option("--input", o.input_topic, "sensor topic to read")->capture_default_str();
  app.add_option("-w,--window", o.window_s, "window length in seconds for windowed plugins")->capture_default_str();
  components::add_param_option(app, o.params);
  app.add_option("--tool-id", o.tool_id,
                 "estimate only this tool and count the batches of others (default: every tool on the topic "
                 "separately, each estimate carrying its tool's id)");
  app.add_flag("--reliable", o.reliable, "reliable sensor reader (use with a reliable publisher: nothing lost)");
  app.add_option("--flush-after-idle", o.idle_flush_s,
                 "when no sample came for this many seconds, publish the partial windows (0: never)")
      ->capture_default_str();
  app.add_option("--count", o.max_estimates, "exit after publishing this many estimates per plugin (0: run until stopped)");
  app.add_option("--timeout", o.timeout_s, "exit with an error if that many estimates did not come within this many seconds");
  app.add_option("--linger", o.linger_s, "seconds to stay after --count is reached so reliable readers get the last estimates")
      ->capture_default_str();
  app.add_flag("-q,--quiet", o.quiet, "do not print each estimate");
  app.add_flag("--truth", o.compare_truth,
               "print each estimate's error against the simulator's truth (plumb-sim publishes it on plumb/sim/truth)");
  app.add_option("--truth-topic", o.truth_topic, "topic of the truth for --truth")->capture_default_str();
  app.add_option("--state-dir", o.state_dir,
                 "folder of the record of the last sequence number taken of each tool, which a restarted host reads "
                 "to count the samples lost while it was down (default: $PLUMB_STATE_DIR, else "
                 "$XDG_STATE_HOME/plumb, else ~/.local/state/plumb)");
  app.add_flag("--no-state", o.no_state, "keep no record and count nothing lost while down");
  app.name("plumb-estimator");
  if (const int status = components::parse_command_line(app, argc, argv); status >= 0) return status;
  try {
    return estimator_component::run_host(o);
  } catch (const std::exception& e) {
    return components::exit_on_error("plumb-estimator", e);
  }
}
