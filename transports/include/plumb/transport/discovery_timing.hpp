// The participant lease and announcement period both vendor plugins use, in one place: a
// participant that says nothing for the lease stays matched, so a link outage shorter than the
// lease loses nothing beyond the writers' history depth, and a killed component stays matched
// (its readers and writers listed, reliable writers repairing to it) until its lease ends.
// docs/operations.md gives the measurements behind the default.
#pragma once

namespace plumb::transport {

struct DiscoveryTiming {
  double lease_s = 30;    // Cyclone's own default is 10 s, Fast DDS's 20 s
  double announce_s = 3;  // how often a participant says it is alive (Fast DDS's default)
};

// The defaults, or the lease from $PLUMB_DDS_LEASE_S (seconds, 2..3600) with the announcement
// period shortened to a third of a short lease. Throws Error (one line) on a bad value.
DiscoveryTiming discovery_timing();

}  // namespace plumb::transport
