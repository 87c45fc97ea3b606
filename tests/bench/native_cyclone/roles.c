#include "roles.h"

#include <pthread.h>
#include <stdbool.h>
#include <stdio.h>
#include <time.h>

#include "stats.h"

#define PING_TOPIC "plumb/bench/ping"
#define PONG_TOPIC "plumb/bench/pong"
#define DATA_TOPIC "plumb/bench/data"
#define WARMUP_ROUND_TRIPS 200
#define MATCH_TIMEOUT_S 15.0
#define LOANS_PER_TAKE 64

/* plumb's Qos::attitude() (reliable, volatile, keep-last 64) for latency and Qos::reliable_stream()
 * (keep-last 4096) for throughput, as transports/cyclonedds/qos.cpp sets them: a reliable writer
 * blocks at most 1 s, XCDR1. */
static dds_qos_t* endpoint_qos(int32_t depth) {
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  dds_qset_durability(qos, DDS_DURABILITY_VOLATILE);
  dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, depth);
  const dds_data_representation_id_t xcdr1[] = {DDS_DATA_REPRESENTATION_XCDR1};
  dds_qset_data_representation(qos, 1, xcdr1);
  return qos;
}
#define LATENCY_DEPTH 64
#define THROUGHPUT_DEPTH 4096

static double now_s(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* CPU time of this whole process (all threads), as plumb-bench-transport's roles report it. */
static double process_cpu_s(void) {
  struct timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static void sleep_s(double seconds) {
  struct timespec t = {(time_t)seconds, (long)((seconds - (double)(time_t)seconds) * 1e9)};
  nanosleep(&t, NULL);
}

/* Waits on `cond` (with `mutex` held) for at most `seconds`. */
static void timed_wait(pthread_cond_t* cond, pthread_mutex_t* mutex, double seconds) {
  struct timespec t;
  clock_gettime(CLOCK_REALTIME, &t);
  const double end = (double)t.tv_nsec * 1e-9 + seconds;
  t.tv_sec += (time_t)end;
  t.tv_nsec = (long)((end - (double)(time_t)end) * 1e9);
  pthread_cond_timedwait(cond, mutex, &t);
}

static dds_entity_t make_topic(dds_entity_t participant, const message_kind* kind, const char* name) {
  const dds_entity_t topic = dds_create_topic(participant, kind->descriptor, name, NULL, NULL);
  if (topic < 0) fprintf(stderr, "cannot create topic %s: %s\n", name, dds_strretcode(topic));
  return topic;
}

static dds_entity_t make_writer(dds_entity_t participant, dds_entity_t topic, int32_t depth) {
  dds_qos_t* qos = endpoint_qos(depth);
  const dds_entity_t writer = dds_create_writer(participant, topic, qos, NULL);
  dds_delete_qos(qos);
  return writer;
}

static dds_entity_t make_reader(dds_entity_t participant, dds_entity_t topic, int32_t depth,
                                dds_on_data_available_fn on_data, void* arg) {
  dds_qos_t* qos = endpoint_qos(depth);
  dds_listener_t* listener = dds_create_listener(arg);
  dds_lset_data_available(listener, on_data);
  const dds_entity_t reader = dds_create_reader(participant, topic, qos, listener);
  dds_delete_listener(listener);
  dds_delete_qos(qos);
  return reader;
}

static bool writer_matched(dds_entity_t writer) {
  dds_publication_matched_status_t status;
  return dds_get_publication_matched_status(writer, &status) == DDS_RETCODE_OK && status.current_count > 0;
}

static bool reader_matched(dds_entity_t reader) {
  dds_subscription_matched_status_t status;
  return dds_get_subscription_matched_status(reader, &status) == DDS_RETCODE_OK && status.current_count > 0;
}

/* --- ping ------------------------------------------------------------------------------------ */

typedef struct ping_state {
  pthread_mutex_t mutex;  /* guards everything below, touched by the listener and the watchdog */
  pthread_cond_t done_cond;
  const message_kind* kind;
  dds_entity_t writer;
  void* message;
  uint64_t seq;
  double sent_at, measure_until, seconds;
  double cpu_start, cpu_end; /* over the measured round trips */
  bool finished, closed;
  latencies one_way_us;
} ping_state;

/* The next ping leaves from this listener, as in ddsperf's listener mode and plumb's ping. */
static void on_pong(dds_entity_t reader, void* arg) {
  ping_state* s = arg;
  void* loaned[LOANS_PER_TAKE] = {NULL};
  dds_sample_info_t infos[LOANS_PER_TAKE];
  dds_return_t n;
  /* A short batch means the reader is empty: no second, empty take. */
  while ((n = dds_take(reader, loaned, infos, LOANS_PER_TAKE, LOANS_PER_TAKE)) > 0) {
    for (dds_return_t i = 0; i < n; ++i) {
      if (!infos[i].valid_data) continue;
      const double now = now_s();
      pthread_mutex_lock(&s->mutex);
      if (!s->closed && !s->finished && s->kind->get_seq(loaned[i]) == s->seq) {
        if (s->seq >= WARMUP_ROUND_TRIPS) {
          latencies_add(&s->one_way_us, (now - s->sent_at) * 1e6 / 2);
        } else if (s->seq + 1 == WARMUP_ROUND_TRIPS) {
          s->measure_until = now + s->seconds;
          s->cpu_start = process_cpu_s();
        }
        if (now >= s->measure_until) {
          s->cpu_end = process_cpu_s();
          s->finished = true;
          pthread_cond_broadcast(&s->done_cond);
        } else {
          s->kind->set_seq(s->message, ++s->seq);
          s->sent_at = now_s();
          dds_write(s->writer, s->message);
        }
      }
      pthread_mutex_unlock(&s->mutex);
    }
    dds_return_loan(reader, loaned, n);
    if (n < LOANS_PER_TAKE) break;
  }
}

int run_ping(dds_entity_t participant, const message_kind* kind, double seconds) {
  ping_state s = {.kind = kind, .seconds = seconds, .measure_until = 1e300};
  pthread_mutex_init(&s.mutex, NULL);
  pthread_cond_init(&s.done_cond, NULL);
  s.message = kind->make();
  const dds_entity_t ping_topic = make_topic(participant, kind, PING_TOPIC);
  const dds_entity_t pong_topic = make_topic(participant, kind, PONG_TOPIC);
  if (ping_topic < 0 || pong_topic < 0) return 1;
  s.writer = make_writer(participant, ping_topic, LATENCY_DEPTH);
  const dds_entity_t reader = make_reader(participant, pong_topic, LATENCY_DEPTH, on_pong, &s);
  if (s.writer < 0 || reader < 0) return 1;

  const double match_deadline = now_s() + MATCH_TIMEOUT_S;
  while (!(writer_matched(s.writer) && reader_matched(reader))) {
    if (now_s() > match_deadline) {
      fprintf(stderr, "ping: the pong process was not discovered within %.0f s\n", MATCH_TIMEOUT_S);
      return 1;
    }
    sleep_s(0.01);
  }
  pthread_mutex_lock(&s.mutex);
  kind->set_seq(s.message, s.seq);
  s.sent_at = now_s();
  dds_write(s.writer, s.message);
  /* Watchdog: a ping sent before the pong's reader had matched our writer may only be repaired by
   * a later heartbeat; resend the current one when nothing moved for a while. */
  const double give_up = now_s() + seconds + 20;
  uint64_t last_seq = 0;
  while (!s.finished) {
    timed_wait(&s.done_cond, &s.mutex, 0.5);
    if (s.finished) break;
    if (now_s() > give_up) {
      fprintf(stderr, "ping: stalled after %llu round trips\n", (unsigned long long)s.seq);
      break;
    }
    if (s.seq == last_seq) {
      s.sent_at = now_s();
      dds_write(s.writer, s.message);
    }
    last_seq = s.seq;
  }
  s.closed = true;
  void* stop = kind->make();
  kind->set_seq(stop, STOP_SEQ);
  dds_write(s.writer, stop);
  pthread_mutex_unlock(&s.mutex);
  sleep_s(0.1); /* let the stop message go out before the writer is deleted */
  dds_delete(reader);
  const int rc = s.one_way_us.count == 0 ? 1 : 0;
  if (rc == 0) {
    const size_t count = s.one_way_us.count;
    const double median = latencies_percentile(&s.one_way_us, 0.5);
    const double p99 = latencies_percentile(&s.one_way_us, 0.99);
    printf("RESULT count=%zu median_us=%.3f p99_us=%.3f cpu_us=%.3f\n", count, median, p99,
           (s.cpu_end - s.cpu_start) * 1e6 / (double)count);
    fflush(stdout); /* before the teardown of the vendor entities */
  }
  kind->release(stop);
  kind->release(s.message);
  latencies_free(&s.one_way_us);
  return rc;
}

/* --- pong ------------------------------------------------------------------------------------ */

typedef struct pong_state {
  pthread_mutex_t mutex;
  pthread_cond_t done_cond;
  const message_kind* kind;
  dds_entity_t writer;
  uint64_t echoed;
  double cpu_start, cpu_end; /* from the first echo to the stop message */
  bool stopped;
} pong_state;

/* Echoes every ping straight from the loaned sample. */
static void on_ping(dds_entity_t reader, void* arg) {
  pong_state* s = arg;
  void* loaned[LOANS_PER_TAKE] = {NULL};
  dds_sample_info_t infos[LOANS_PER_TAKE];
  dds_return_t n;
  /* A short batch means the reader is empty: no second, empty take. */
  while ((n = dds_take(reader, loaned, infos, LOANS_PER_TAKE, LOANS_PER_TAKE)) > 0) {
    for (dds_return_t i = 0; i < n; ++i) {
      if (!infos[i].valid_data) continue;
      if (s->kind->get_seq(loaned[i]) == STOP_SEQ) {
        pthread_mutex_lock(&s->mutex);
        s->cpu_end = process_cpu_s();
        s->stopped = true;
        pthread_cond_broadcast(&s->done_cond);
        pthread_mutex_unlock(&s->mutex);
        continue;
      }
      if (__atomic_load_n(&s->echoed, __ATOMIC_RELAXED) == 0) s->cpu_start = process_cpu_s();
      dds_write(s->writer, loaned[i]);
      __atomic_add_fetch(&s->echoed, 1, __ATOMIC_RELAXED);
    }
    dds_return_loan(reader, loaned, n);
    if (n < LOANS_PER_TAKE) break;
  }
}

int run_pong(dds_entity_t participant, const message_kind* kind, double seconds) {
  pong_state s = {.kind = kind};
  pthread_mutex_init(&s.mutex, NULL);
  pthread_cond_init(&s.done_cond, NULL);
  const dds_entity_t ping_topic = make_topic(participant, kind, PING_TOPIC);
  const dds_entity_t pong_topic = make_topic(participant, kind, PONG_TOPIC);
  if (ping_topic < 0 || pong_topic < 0) return 1;
  s.writer = make_writer(participant, pong_topic, LATENCY_DEPTH);
  if (s.writer < 0) return 1;
  const dds_entity_t reader = make_reader(participant, ping_topic, LATENCY_DEPTH, on_ping, &s);
  if (reader < 0) return 1;
  const double give_up = now_s() + seconds + 30;
  pthread_mutex_lock(&s.mutex);
  while (!s.stopped && now_s() < give_up) timed_wait(&s.done_cond, &s.mutex, 0.5);
  const bool stopped = s.stopped;
  pthread_mutex_unlock(&s.mutex);
  dds_delete(reader);
  const uint64_t echoed = __atomic_load_n(&s.echoed, __ATOMIC_RELAXED);
  const double cpu_us = echoed > 0 && s.cpu_end > s.cpu_start ? (s.cpu_end - s.cpu_start) * 1e6 / (double)echoed : 0;
  printf("RESULT echoed=%llu stopped=%d cpu_us=%.3f\n", (unsigned long long)echoed, stopped ? 1 : 0, cpu_us);
  fflush(stdout); /* before the teardown of the vendor entities */
  return 0;
}

/* --- source ---------------------------------------------------------------------------------- */

int run_source(dds_entity_t participant, const message_kind* kind, double seconds) {
  const dds_entity_t topic = make_topic(participant, kind, DATA_TOPIC);
  if (topic < 0) return 1;
  const dds_entity_t writer = make_writer(participant, topic, THROUGHPUT_DEPTH);
  if (writer < 0) return 1;
  const double match_deadline = now_s() + MATCH_TIMEOUT_S;
  while (!writer_matched(writer)) {
    if (now_s() > match_deadline) {
      fprintf(stderr, "source: the sink process was not discovered within %.0f s\n", MATCH_TIMEOUT_S);
      return 1;
    }
    sleep_s(0.01);
  }
  sleep_s(0.2); /* the reader side matches a little after the writer side */
  void* message = kind->make();
  const double cpu_start = process_cpu_s();
  const double start = now_s();
  const double end = start + seconds + 0.5;
  uint64_t seq = 0;
  while (now_s() < end) {
    for (int i = 0; i < 64; ++i) {
      kind->set_seq(message, seq++);
      dds_write(writer, message);
    }
  }
  const double elapsed = now_s() - start;
  const double cpu_us = (process_cpu_s() - cpu_start) * 1e6 / (double)seq;
  kind->set_seq(message, STOP_SEQ);
  for (int i = 0; i < 5; ++i) {
    dds_write(writer, message);
    sleep_s(0.05);
  }
  printf("RESULT sent=%llu seconds=%.6f cpu_us=%.3f\n", (unsigned long long)seq, elapsed, cpu_us);
  fflush(stdout); /* before the teardown of the vendor entities */
  kind->release(message);
  return 0;
}

/* --- sink ------------------------------------------------------------------------------------ */

typedef struct sink_state {
  pthread_mutex_t mutex;
  pthread_cond_t done_cond;
  const message_kind* kind;
  double window, first;
  double cpu_start, cpu_end; /* over the window */
  uint64_t received, lowest, highest;
  bool done;
} sink_state;

/* Counts what arrives during the window from the first message, taking loaned batches. */
static void on_data(dds_entity_t reader, void* arg) {
  sink_state* s = arg;
  void* loaned[LOANS_PER_TAKE] = {NULL};
  dds_sample_info_t infos[LOANS_PER_TAKE];
  dds_return_t n;
  /* A short batch means the reader is empty: no second, empty take. */
  while ((n = dds_take(reader, loaned, infos, LOANS_PER_TAKE, LOANS_PER_TAKE)) > 0) {
    const double now = now_s();
    pthread_mutex_lock(&s->mutex);
    for (dds_return_t i = 0; i < n; ++i) {
      if (!infos[i].valid_data) continue;
      const uint64_t seq = s->kind->get_seq(loaned[i]);
      if (seq == STOP_SEQ || (s->received > 0 && now - s->first > s->window)) {
        if (s->cpu_end == 0) s->cpu_end = process_cpu_s();
        s->done = true;
        pthread_cond_broadcast(&s->done_cond);
        continue;
      }
      if (s->received == 0) {
        s->first = now;
        s->cpu_start = process_cpu_s();
      }
      ++s->received;
      if (seq < s->lowest) s->lowest = seq;
      if (seq > s->highest) s->highest = seq;
    }
    pthread_mutex_unlock(&s->mutex);
    dds_return_loan(reader, loaned, n);
    if (n < LOANS_PER_TAKE) break;
  }
}

int run_sink(dds_entity_t participant, const message_kind* kind, double seconds) {
  sink_state s = {.kind = kind, .window = seconds, .lowest = STOP_SEQ};
  pthread_mutex_init(&s.mutex, NULL);
  pthread_cond_init(&s.done_cond, NULL);
  const dds_entity_t topic = make_topic(participant, kind, DATA_TOPIC);
  if (topic < 0) return 1;
  const dds_entity_t reader = make_reader(participant, topic, THROUGHPUT_DEPTH, on_data, &s);
  if (reader < 0) return 1;
  const double give_up = now_s() + seconds + 30;
  pthread_mutex_lock(&s.mutex);
  while (!s.done && now_s() < give_up) timed_wait(&s.done_cond, &s.mutex, 0.5);
  const bool complete = s.done;
  pthread_mutex_unlock(&s.mutex);
  dds_delete(reader);
  if (!complete || s.received < 2) {
    fprintf(stderr, "sink: received %llu messages, measurement %s\n", (unsigned long long)s.received,
            complete ? "complete" : "incomplete");
    return 1;
  }
  double measured = now_s() - s.first;
  if (measured > seconds) measured = seconds;
  printf("RESULT received=%llu sent=%llu seconds=%.6f cpu_us=%.3f\n", (unsigned long long)s.received,
         (unsigned long long)(s.highest - s.lowest + 1), measured, (s.cpu_end - s.cpu_start) * 1e6 / (double)s.received);
  fflush(stdout); /* before the teardown of the vendor entities */
  return 0;
}
