/* plumb-bench-native-cyclone: the Cyclone DDS baseline of plumb-bench-transport. One role of a
 * latency (ping/pong) or throughput (source/sink) measurement of SensorBatch or Attitude, on
 * loopback, written the way a plain Cyclone C application would be: idlc's types from idl/, loaned
 * multi-sample takes in listeners, the same topics, QoS and loopback configuration as plumb's
 * Cyclone plugin. No plumb code. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "roles.h"

/* The loopback setup of plumb's Cyclone plugin (transports/cyclonedds/domain_config.cpp): unicast
 * discovery on 127.0.0.1, no multicast, no shared memory. Repeated here: no plumb code. */
static const char* const loopback_config =
    "<CycloneDDS><Domain Id=\"any\">"
    "<General><Interfaces><NetworkInterface address=\"127.0.0.1\"/></Interfaces>"
    "<AllowMulticast>false</AllowMulticast></General>"
    "<Discovery><ParticipantIndex>auto</ParticipantIndex>"
    "<MaxAutoParticipantIndex>40</MaxAutoParticipantIndex>"
    "<Peers><Peer address=\"127.0.0.1\"/></Peers></Discovery>"
    "<SharedMemory><Enable>false</Enable></SharedMemory>"
    "<Tracing><Verbosity>none</Verbosity></Tracing>"
    "</Domain></CycloneDDS>";

static void usage(FILE* out) {
  fputs("usage: plumb-bench-native-cyclone --role ping|pong|source|sink --type sensor|attitude\n"
        "                                  [--domain ID] [--seconds S]\n"
        "One role of plumb-bench-transport's native Cyclone DDS baseline (normally started by it).\n"
        "  --role      ping/pong: latency (round trip / 2); source/sink: throughput\n"
        "  --type      sensor (SensorBatch, 32 samples) or attitude\n"
        "  --domain    DDS domain id (default 0)\n"
        "  --seconds   measuring time (default 1)\n"
        "Prints one line \"RESULT key=value ...\" on success.\n",
        out);
}

int main(int argc, char** argv) {
  const char* role = NULL;
  const char* type = NULL;
  int domain = 0;
  double seconds = 1;
  for (int i = 1; i < argc; ++i) {
    if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
      usage(stdout);
      return 0;
    }
    if (i + 1 >= argc) {
      usage(stderr);
      return 1;
    }
    if (strcmp(argv[i], "--role") == 0) role = argv[++i];
    else if (strcmp(argv[i], "--type") == 0) type = argv[++i];
    else if (strcmp(argv[i], "--domain") == 0) domain = atoi(argv[++i]);
    else if (strcmp(argv[i], "--seconds") == 0) seconds = atof(argv[++i]);
    else {
      fprintf(stderr, "unknown option %s\n", argv[i]);
      usage(stderr);
      return 1;
    }
  }
  const message_kind* kind = type == NULL ? NULL : find_message_kind(type);
  if (role == NULL || kind == NULL || domain < 0 || domain > 232 || seconds <= 0) {
    usage(stderr);
    return 1;
  }
  const dds_entity_t domain_handle = dds_create_domain((dds_domainid_t)domain, loopback_config);
  if (domain_handle < 0) {
    fprintf(stderr, "cannot create domain %d: %s\n", domain, dds_strretcode(domain_handle));
    return 1;
  }
  const dds_entity_t participant = dds_create_participant((dds_domainid_t)domain, NULL, NULL);
  if (participant < 0) {
    fprintf(stderr, "cannot create a participant: %s\n", dds_strretcode(participant));
    return 1;
  }
  int rc = 1;
  if (strcmp(role, "ping") == 0) rc = run_ping(participant, kind, seconds);
  else if (strcmp(role, "pong") == 0) rc = run_pong(participant, kind, seconds);
  else if (strcmp(role, "source") == 0) rc = run_source(participant, kind, seconds);
  else if (strcmp(role, "sink") == 0) rc = run_sink(participant, kind, seconds);
  else fprintf(stderr, "unknown role %s\n", role);
  fflush(stdout);
  dds_delete(domain_handle);
  return rc;
}
