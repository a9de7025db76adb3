/* The runtime library's model in memory (what runtime_file.c builds from a
 * checked file and runtime_evaluate.c evaluates). Not installed. */
#ifndef HYDROCOEF_RUNTIME_INTERNAL_H
#define HYDROCOEF_RUNTIME_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "grid_kernel.h"
#include "hydrocoef/runtime.h"

/* A text: its bytes (NUL-terminated, no NUL inside). */
typedef struct hc_text_pair {
  const char* key;
  const char* value;
} hc_text_pair;

typedef struct hc_runtime_axis_info {
  const char* name;
  const char* unit;
} hc_runtime_axis_info;

typedef struct hc_runtime_surface {
  const char* name;
  int method; /* HC_KERNEL_NEAREST .. HC_KERNEL_NATURAL_SPLINE */
  int has_sigma;
  size_t axis_count;
  size_t output_count;
  size_t node_count;
  size_t node_block;     /* numbers per node in data: 2^n * n_out (cubic) or n_out */
  size_t terms_per_axis; /* K: 1, 2 or 4 */
  hc_kernel_axis axes[HC_KERNEL_MAX_AXES];
  hc_kernel_axis sigma_axes[HC_KERNEL_MAX_AXES]; /* the same, every policy clamp */
  hc_runtime_axis_info axis_info[HC_KERNEL_MAX_AXES];
  const double* breakpoints; /* every axis's, one after another (axes[a].offset) */
  const char** output_names;
  const char** output_units;
  const double* data;       /* node_count * node_block evaluated numbers */
  const double* loo;        /* output_count leave-one-out standard deviations (has_sigma) */
  const double* sigma_data; /* the runs' sigma table, as data (has_sigma) */
  size_t* term_offsets;     /* K^n offsets of the local sum's terms */
  hc_text_pair* metadata;
  size_t metadata_count;
} hc_runtime_surface;

struct hc_runtime_model {
  unsigned char* bytes; /* the file, owned; doubles and texts point into it */
  size_t size;
  uint64_t hash;
  hc_text_pair* metadata;
  size_t metadata_count;
  hc_runtime_surface* surfaces;
  size_t surface_count;
};

#endif
