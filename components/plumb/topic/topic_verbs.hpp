// What the verbs of `plumb topic` share: their registrations, and the pieces of a receiving loop
// (batched takes, elapsed time, why it ended).
#pragma once

#include <chrono>
#include <string>

#include "plumb/components/cli.hpp"
#include "verbs.hpp"

namespace plumb::cli {

// The verbs of `plumb topic`, each in its own file.
void add_topic_list(CLI::App& topic, Verbs& verbs);
void add_topic_echo(CLI::App& topic, Verbs& verbs);
void add_topic_hz(CLI::App& topic, Verbs& verbs);
void add_topic_pub(CLI::App& topic, Verbs& verbs);

// Messages per batched take: one vendor call for everything that arrived, up to this many.
inline constexpr std::size_t kTakeBatch = 64;

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Why a receiving command ended, for its summary line (timeout_s 0: none).
std::string end_reason(double timeout_s, double elapsed_s);

}  // namespace plumb::cli
