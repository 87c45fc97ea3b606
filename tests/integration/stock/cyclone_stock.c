/* A stock Cyclone DDS program, as a team that is not plumb writes it: plain C, types from idlc on
 * idl/attitude.idl and idl/sensor.idl, network settings from the configuration file named by
 * CYCLONEDDS_URI (transports/config/cyclonedds-*.xml), no plumb code. What it sets to talk to
 * plumb (docs/transports.md): the topic names, the scoped type names idlc gives, reliable QoS and
 * the XCDR1 data representation, the domain id.
 *   cyclone-stock listen TOPIC COUNT     print the inclination of COUNT plumb attitudes
 *   cyclone-stock publish TOPIC BATCHES  publish BATCHES sensor batches of a level tool at
 *                                        inclination 2 deg, azimuth 30 deg, once a reader matched
 * The domain id is $PLUMB_DOMAIN_ID (else 0), as for plumb's programs. Exit 1 on a timeout (60 s). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "attitude.h"
#include "dds/dds.h"
#include "sensor.h"

static dds_qos_t* plumb_qos(int depth) {
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, depth);
  /* Cyclone DDS 0.10 may choose XCDR2; Fast DDS 2.9, and plumb, speak XCDR1. */
  dds_data_representation_id_t xcdr1[] = {DDS_DATA_REPRESENTATION_XCDR1};
  dds_qset_data_representation(qos, 1, xcdr1);
  return qos;
}

static int listen_attitudes(dds_entity_t participant, const char* topic_name, int count) {
  dds_entity_t topic = dds_create_topic(participant, &plumb_msg_Attitude_desc, topic_name, NULL, NULL);
  dds_qos_t* qos = plumb_qos(64);
  dds_entity_t reader = dds_create_reader(participant, topic, qos, NULL);
  dds_delete_qos(qos);
  if (reader < 0) return fprintf(stderr, "cyclone-stock: reader: %s\n", dds_strretcode(reader)), 1;
  printf("listening on %s\n", topic_name);
  fflush(stdout);
  int received = 0;
  for (int tick = 0; received < count && tick < 6000; ++tick) {
    plumb_msg_Attitude sample;
    void* samples[1] = {&sample};
    dds_sample_info_t info;
    memset(&sample, 0, sizeof sample);
    if (dds_take(reader, samples, &info, 1, 1) == 1 && info.valid_data) {
      printf("attitude %d from %s: inclination_deg=%g azimuth_deg=%g\n", ++received, sample.estimator,
             sample.inclination_deg, sample.azimuth_deg);
      fflush(stdout);
    } else {
      dds_sleepfor(DDS_MSECS(10));
    }
  }
  return received == count ? 0 : (fprintf(stderr, "cyclone-stock: %d of %d attitudes\n", received, count), 1);
}

static void fill_batch(plumb_msg_SensorBatch* batch, int n) {
  const double d = 3.14159265358979323846 / 180.0, g = 9.81, field = 48.4, dip = 45.5 * d, inc = 2.0 * d, azi = 30.0 * d;
  const double bn = field * cos(dip), bd = field * sin(dip);
  for (uint32_t i = 0; i < batch->samples._length; ++i) {
    plumb_msg_SensorSample* s = &batch->samples._buffer[i];
    const long long k = 32LL * n + i;
    memset(s, 0, sizeof *s);
    s->seq = (uint64_t)k;
    s->stamp_ns = k * 10000000LL; /* 100 Hz */
    s->fx = g * sin(inc); s->fy = 0; s->fz = -g * cos(inc); /* at rest f = -G */
    s->bx = cos(inc) * cos(azi) * bn - sin(inc) * bd;
    s->by = -sin(azi) * bn;
    s->bz = sin(inc) * cos(azi) * bn + cos(inc) * bd;
    s->temp_c = 25;
  }
}

static int publish_batches(dds_entity_t participant, const char* topic_name, int batches) {
  dds_entity_t topic = dds_create_topic(participant, &plumb_msg_SensorBatch_desc, topic_name, NULL, NULL);
  dds_qos_t* qos = plumb_qos(64);
  dds_entity_t writer = dds_create_writer(participant, topic, qos, NULL);
  dds_delete_qos(qos);
  if (writer < 0) return fprintf(stderr, "cyclone-stock: writer: %s\n", dds_strretcode(writer)), 1;
  dds_publication_matched_status_t matched = {0};
  for (int tick = 0; matched.current_count == 0; ++tick) {
    if (tick == 6000) return fprintf(stderr, "cyclone-stock: no reader of %s within 60 s\n", topic_name), 1;
    dds_get_publication_matched_status(writer, &matched);
    dds_sleepfor(DDS_MSECS(10));
  }
  plumb_msg_SensorSample buffer[32];
  plumb_msg_SensorBatch batch;
  memset(&batch, 0, sizeof batch);
  strcpy(batch.tool_id, "board");
  batch.samples._buffer = buffer;
  batch.samples._length = batch.samples._maximum = 32;
  for (int n = 0; n < batches; ++n) {
    fill_batch(&batch, n);
    dds_return_t rc = dds_write(writer, &batch);
    if (rc != DDS_RETCODE_OK) return fprintf(stderr, "cyclone-stock: write: %s\n", dds_strretcode(rc)), 1;
    dds_sleepfor(DDS_MSECS(100)); /* about 3 times real time, as a board would send them */
  }
  printf("published %d batches on %s\n", batches, topic_name);
  dds_sleepfor(DDS_SECS(1)); /* a reliable writer delivers only while it exists */
  return 0;
}

int main(int argc, char** argv) {
  if (argc != 4 || (strcmp(argv[1], "listen") != 0 && strcmp(argv[1], "publish") != 0)) {
    fprintf(stderr, "usage: cyclone-stock listen TOPIC COUNT | publish TOPIC BATCHES\n");
    return 2;
  }
  const char* domain = getenv("PLUMB_DOMAIN_ID");
  dds_entity_t participant = dds_create_participant(domain ? (dds_domainid_t)atoi(domain) : 0, NULL, NULL);
  if (participant < 0) return fprintf(stderr, "cyclone-stock: participant: %s\n", dds_strretcode(participant)), 1;
  int rc = strcmp(argv[1], "listen") == 0 ? listen_attitudes(participant, argv[2], atoi(argv[3]))
                                          : publish_batches(participant, argv[2], atoi(argv[3]));
  dds_delete(participant);
  return rc;
}
