/* A growing list of one-way latencies and its percentiles. */
#ifndef PLUMB_BENCH_NATIVE_CYCLONE_STATS_H
#define PLUMB_BENCH_NATIVE_CYCLONE_STATS_H

#include <stddef.h>

typedef struct latencies {
  double* values;
  size_t count, capacity;
} latencies;

void latencies_add(latencies* list, double value);
/* The value at `fraction` (0.5: median) of the sorted list, index rounded as plumb's bench does. */
double latencies_percentile(latencies* list, double fraction);
void latencies_free(latencies* list);

#endif
