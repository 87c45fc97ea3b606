/* plumb-c-attitude-listener: prints the attitude estimates a plumb estimator publishes, using
 * only Cyclone DDS and plumb's idl/attitude.idl. Another team can start from this file.
 *
 *   plumb-c-attitude-listener [--domain N] [--count N] [--timeout S] [--interface IF] [TOPIC]
 *
 * What it takes to talk to plumb (see docs/architecture.md, interoperability rules):
 *  - topic "plumb/attitude/<estimator>", type plumb::msg::Attitude (the idlc output names it so);
 *  - reliable QoS and the XCDR1 data representation (plumb's Fast DDS side reads and writes XCDR1);
 *  - the same domain id and network: plumb keeps to loopback unless given an interface. */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <dds/dds.h>

#include "attitude.h"

static volatile sig_atomic_t stop_requested = 0;

static void on_signal(int signal_number) {
  (void)signal_number;
  stop_requested = 1;
}

static void usage(FILE* out) {
  fprintf(out,
          "Usage: plumb-c-attitude-listener [OPTIONS] [TOPIC]\n"
          "Prints each plumb attitude message on TOPIC (default plumb/attitude/compensated), one per line.\n"
          "  --domain N       DDS domain id, 0..232 (default $PLUMB_DOMAIN_ID, else 0)\n"
          "  --transport T    cyclonedds only: this program uses Cyclone DDS directly (it hears Fast DDS\n"
          "                   publishers all the same); accepted so that plumb's command lines work here\n"
          "  --count N        exit after N messages (default: run until Ctrl-C)\n"
          "  --timeout S      give up (exit 1) after S seconds without reaching --count\n"
          "  --interface IF   network interface name or address (default $PLUMB_INTERFACE, else loopback only)\n"
          "  -h, --help       this text\n");
}

static int parse_long(const char* text, long min, long max, long* value) {
  char* end = NULL;
  errno = 0;
  const long v = strtol(text, &end, 10);
  if (errno != 0 || end == text || *end != '\0' || v < min || v > max) return 0;
  *value = v;
  return 1;
}

/* The same setup as plumb's own loopback default: unicast discovery on 127.0.0.1 (loopback has
 * no multicast), no shared memory. With an interface, that interface with multicast discovery. */
static char* make_config(const char* interface) {
  static const char* loopback =
      "<CycloneDDS><Domain Id=\"any\">"
      "<General><Interfaces><NetworkInterface address=\"127.0.0.1\"/></Interfaces>"
      "<AllowMulticast>false</AllowMulticast></General>"
      "<Discovery><ParticipantIndex>auto</ParticipantIndex><MaxAutoParticipantIndex>40</MaxAutoParticipantIndex>"
      "<Peers><Peer address=\"127.0.0.1\"/></Peers></Discovery>"
      "<SharedMemory><Enable>false</Enable></SharedMemory>"
      "</Domain></CycloneDDS>";
  static const char* with_interface =
      "<CycloneDDS><Domain Id=\"any\">"
      "<General><Interfaces><NetworkInterface %s=\"%s\"/></Interfaces></General>"
      "<SharedMemory><Enable>false</Enable></SharedMemory>"
      "</Domain></CycloneDDS>";
  if (interface == NULL) return dds_string_dup(loopback);
  for (const char* c = interface; *c; ++c) {
    if (strchr("<>&\"'", *c) != NULL) return NULL;
  }
  const int is_address = strspn(interface, "0123456789.") == strlen(interface);
  const size_t size = strlen(with_interface) + strlen(interface) + 16;
  char* config = dds_alloc(size);
  snprintf(config, size, with_interface, is_address ? "address" : "name", interface);
  return config;
}

static void print_attitude(const plumb_msg_Attitude* a) {
  /* plumb's integration test compares this line with what it sent: keep the format in step
   * with tests/integration/transport/test_messages.cpp. */
  printf("tool=%s estimator=%s end_ns=%lld inclination=%.17g azimuth=%.17g toolface=%.17g rpm=%.17g flags=%u reason=%s\n",
         a->tool_id, a->estimator, (long long)a->window_end_ns, a->inclination_deg, a->azimuth_deg,
         a->gravity_toolface_deg, a->rpm, (unsigned)a->flags, a->reason);
  fflush(stdout);
}

struct options {
  long domain, count, timeout_s;
  const char* topic_name;
  const char* interface;
};

/* The environment first (the same as every plumb executable's), then the command line over it.
 * Returns -1 to go on, else the exit status (0 after --help, 2 for a usage error). */
static int parse_options(int argc, char** argv, struct options* o) {
  const char* env_domain = getenv("PLUMB_DOMAIN_ID");
  if (env_domain != NULL && *env_domain != '\0' && !parse_long(env_domain, 0, 232, &o->domain)) {
    fprintf(stderr, "plumb-c-attitude-listener: PLUMB_DOMAIN_ID='%s' is not a domain id (0..232)\n", env_domain);
    return 2;
  }
  const char* env_interface = getenv("PLUMB_INTERFACE");
  if (env_interface != NULL && *env_interface != '\0') o->interface = env_interface;
  for (int i = 1; i < argc; ++i) {
    const char* arg = argv[i];
    const int has_value = i + 1 < argc;
    if (strcmp(arg, "-h") == 0 || strcmp(arg, "--help") == 0) {
      usage(stdout);
      return 0;
    } else if (strcmp(arg, "--domain") == 0 && has_value) {
      if (!parse_long(argv[++i], 0, 232, &o->domain)) {
        fprintf(stderr, "plumb-c-attitude-listener: --domain must be an integer in 0..232, not '%s'\n", argv[i]);
        return 2;
      }
    } else if (strcmp(arg, "--count") == 0 && has_value) {
      if (!parse_long(argv[++i], 1, 1000000000L, &o->count)) {
        fprintf(stderr, "plumb-c-attitude-listener: --count must be a positive integer, not '%s'\n", argv[i]);
        return 2;
      }
    } else if (strcmp(arg, "--timeout") == 0 && has_value) {
      if (!parse_long(argv[++i], 1, 1000000L, &o->timeout_s)) {
        fprintf(stderr, "plumb-c-attitude-listener: --timeout must be a positive number of seconds, not '%s'\n", argv[i]);
        return 2;
      }
    } else if (strcmp(arg, "--interface") == 0 && has_value) {
      o->interface = argv[++i];
    } else if (strcmp(arg, "--transport") == 0 && has_value) {
      if (strcmp(argv[++i], "cyclonedds") != 0) {
        fprintf(stderr, "plumb-c-attitude-listener: --transport %s: this example speaks Cyclone DDS only "
                        "(give cyclonedds; it receives from Fast DDS publishers too)\n", argv[i]);
        return 2;
      }
    } else if (arg[0] == '-') {
      fprintf(stderr, "plumb-c-attitude-listener: unknown or incomplete option '%s' (see --help)\n", arg);
      return 2;
    } else {
      o->topic_name = arg;
    }
  }
  return -1;
}

/* A reliable XCDR1 reader on the topic, with a waitset that wakes on its data. Returns 0 and the
 * entities, or the exit status after saying what failed (the domain deleted). */
static int open_reader(const struct options* o, dds_entity_t dom, dds_entity_t* reader, dds_entity_t* waitset) {
  const dds_entity_t participant = dds_create_participant((dds_domainid_t)o->domain, NULL, NULL);
  const dds_entity_t topic =
      participant < 0 ? participant : dds_create_topic(participant, &plumb_msg_Attitude_desc, o->topic_name, NULL, NULL);
  if (topic < 0) {
    fprintf(stderr, "plumb-c-attitude-listener: cannot subscribe to '%s': %s\n", o->topic_name, dds_strretcode(topic));
    dds_delete(dom);
    return 1;
  }
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 64);
  const dds_data_representation_id_t xcdr1[] = {DDS_DATA_REPRESENTATION_XCDR1};
  dds_qset_data_representation(qos, 1, xcdr1);
  *reader = dds_create_reader(participant, topic, qos, NULL);
  dds_delete_qos(qos);
  *waitset = dds_create_waitset(participant);
  const dds_entity_t condition = dds_create_readcondition(*reader, DDS_ANY_STATE);
  if (*reader < 0 || *waitset < 0 || condition < 0 || dds_waitset_attach(*waitset, condition, 0) < 0) {
    fprintf(stderr, "plumb-c-attitude-listener: cannot create a reader on '%s'\n", o->topic_name);
    dds_delete(dom);
    return 1;
  }
  return 0;
}

/* Prints what arrives until Ctrl-C, --count or --timeout; returns the exit status. */
static int print_until_done(const struct options* o, dds_entity_t reader, dds_entity_t waitset) {
  const long count = o->count;
  const dds_time_t deadline = o->timeout_s > 0 ? dds_time() + DDS_SECS(o->timeout_s) : DDS_NEVER;
  long received = 0;
  /* While nothing arrives, say so after 3, 6, 12... s: a silent wait looks like a hang. */
  dds_time_t last_message = dds_time();
  dds_duration_t next_note = DDS_SECS(3);
  while (!stop_requested && (count == 0 || received < count)) {
    if (dds_time() >= deadline) {
      fprintf(stderr, "plumb-c-attitude-listener: %ld of %ld messages after %ld s, giving up\n", received, count, o->timeout_s);
      return 1;
    }
    /* Short waits so that Ctrl-C and the deadline are noticed promptly. */
    dds_waitset_wait(waitset, NULL, 0, DDS_MSECS(200));
    while (!stop_requested && (count == 0 || received < count)) {
      /* A NULL first pointer asks Cyclone to lend its own buffers; they go back with return_loan. */
      void* samples[16] = {NULL};
      dds_sample_info_t infos[16];
      const dds_return_t n = dds_take(reader, samples, infos, 16, 16);
      if (n <= 0) break;
      last_message = dds_time();
      next_note = DDS_SECS(3);
      for (dds_return_t i = 0; i < n && (count == 0 || received < count); ++i) {
        if (!infos[i].valid_data) continue;
        print_attitude((const plumb_msg_Attitude*)samples[i]);
        ++received;
      }
      dds_return_loan(reader, samples, n);
    }
    if (dds_time() - last_message >= next_note) {
      dds_subscription_matched_status_t matched;
      dds_get_subscription_matched_status(reader, &matched);
      fprintf(stderr, "plumb-c-attitude-listener: nothing on %s for %lld s (%u writer(s) matched; same domain?)\n",
              o->topic_name, (long long)((dds_time() - last_message) / DDS_NSECS_IN_SEC), matched.current_count);
      next_note *= 2;
    }
  }
  return 0;
}

int main(int argc, char** argv) {
  struct options o = {0, 0, 0, "plumb/attitude/compensated", NULL};
  const int parsed = parse_options(argc, argv, &o);
  if (parsed >= 0) return parsed;

  char* config = make_config(o.interface);
  if (config == NULL) {
    fprintf(stderr, "plumb-c-attitude-listener: invalid interface '%s'\n", o.interface);
    return 2;
  }
  /* The configuration is given here, so CYCLONEDDS_URI is not needed (nor used). */
  const dds_entity_t dom = dds_create_domain((dds_domainid_t)o.domain, config);
  dds_free(config);
  if (dom < 0) {
    fprintf(stderr, "plumb-c-attitude-listener: cannot start Cyclone DDS: %s\n", dds_strretcode(dom));
    return 1;
  }
  dds_entity_t reader = 0, waitset = 0;
  if (open_reader(&o, dom, &reader, &waitset) != 0) return 1;
  signal(SIGINT, on_signal);
  signal(SIGTERM, on_signal);
  const int status = print_until_done(&o, reader, waitset);
  dds_delete(dom); /* deletes the participant and everything in it */
  return status;
}
