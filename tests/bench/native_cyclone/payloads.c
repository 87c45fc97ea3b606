#include "payloads.h"

#include <stdlib.h>
#include <string.h>

#include "plumb_idl/attitude.h"
#include "plumb_idl/sensor.h"

static void* make_sensor(void) {
  plumb_msg_SensorBatch* batch = calloc(1, sizeof *batch);
  plumb_msg_SensorSample* samples = calloc(32, sizeof *samples);
  if (batch == NULL || samples == NULL) abort();
  strcpy(batch->tool_id, "bench-tool");
  strcpy(batch->calibration_id, "bench-calibration-0001");
  for (uint32_t i = 0; i < 32; ++i) {
    plumb_msg_SensorSample* s = &samples[i];
    s->seq = i;
    s->stamp_ns = (int64_t)i * 1000000;
    s->fx = 0.1; s->fy = -0.2; s->fz = 9.8;
    s->bx = 20.0; s->by = 5.0; s->bz = 45.0;
    s->wx = 0.001; s->wy = 0.002; s->wz = 6.28;
    s->temp_c = 85.0;
    s->flags = plumb_msg_SAMPLE_HAS_GYRO | plumb_msg_SAMPLE_HAS_TEMPERATURE;
  }
  batch->samples._buffer = samples;
  batch->samples._length = 32;
  batch->samples._maximum = 32;
  batch->samples._release = false;
  return batch;
}

static void release_sensor(void* sample) {
  plumb_msg_SensorBatch* batch = sample;
  free(batch->samples._buffer);
  free(batch);
}

/* The sequence number rides in the first sample's seq (batch) or in window_start_ns (attitude). */
static void set_sensor_seq(void* sample, uint64_t seq) { ((plumb_msg_SensorBatch*)sample)->samples._buffer[0].seq = seq; }
static uint64_t get_sensor_seq(const void* sample) {
  const plumb_msg_SensorBatch* batch = sample;
  return batch->samples._length == 0 ? 0 : batch->samples._buffer[0].seq;
}

static void* make_attitude(void) {
  plumb_msg_Attitude* attitude = calloc(1, sizeof *attitude);
  if (attitude == NULL) abort();
  strcpy(attitude->tool_id, "bench-tool");
  strcpy(attitude->estimator, "bench-estimator");
  attitude->inclination_deg = 30;
  attitude->azimuth_deg = 120;
  attitude->samples_used = 400;
  attitude->flags = plumb_msg_ATTITUDE_VALID;
  return attitude;
}

static void release_attitude(void* sample) { free(sample); }
static void set_attitude_seq(void* sample, uint64_t seq) { ((plumb_msg_Attitude*)sample)->window_start_ns = (int64_t)seq; }
static uint64_t get_attitude_seq(const void* sample) { return (uint64_t)((const plumb_msg_Attitude*)sample)->window_start_ns; }

static const message_kind sensor_kind = {&plumb_msg_SensorBatch_desc, make_sensor, release_sensor, set_sensor_seq,
                                         get_sensor_seq};
static const message_kind attitude_kind = {&plumb_msg_Attitude_desc, make_attitude, release_attitude, set_attitude_seq,
                                           get_attitude_seq};

const message_kind* find_message_kind(const char* name) {
  if (strcmp(name, "sensor") == 0) return &sensor_kind;
  if (strcmp(name, "attitude") == 0) return &attitude_kind;
  return NULL;
}
