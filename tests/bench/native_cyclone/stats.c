#include "stats.h"

#include <stdlib.h>

void latencies_add(latencies* list, double value) {
  if (list->count == list->capacity) {
    list->capacity = list->capacity == 0 ? 65536 : list->capacity * 2;
    list->values = realloc(list->values, list->capacity * sizeof *list->values);
    if (list->values == NULL) abort();
  }
  list->values[list->count++] = value;
}

static int compare_doubles(const void* a, const void* b) {
  const double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}

double latencies_percentile(latencies* list, double fraction) {
  if (list->count == 0) return 0;
  qsort(list->values, list->count, sizeof *list->values, compare_doubles);
  return list->values[(size_t)(fraction * (double)(list->count - 1) + 0.5)];
}

void latencies_free(latencies* list) {
  free(list->values);
  list->values = NULL;
  list->count = list->capacity = 0;
}
