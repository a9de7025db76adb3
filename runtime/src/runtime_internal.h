/* The runtime library's model in memory (what runtime_file.c builds from a
 * checked file and runtime_evaluate.c evaluates). Not installed. */
#ifndef HYDROCOEF_RUNTIME_INTERNAL_H
#define HYDROCOEF_RUNTIME_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "damping_kernel.h"
#include "grid_kernel.h"
#include "hydrocoef/runtime.h"

/* A text: its bytes (NUL-terminated, no NUL inside). */
typedef struct hc_text_pair {
  const char* key;
  const char* value;
} hc_text_pair;

/* The value of `key` among count pairs, or NULL (also for a NULL key). */
static inline const char* hc_find_text(const hc_text_pair* pairs, size_t count, const char* key) {
  if (key == NULL) return NULL;
  for (size_t i = 0; i < count; ++i) {
    if (strcmp(pairs[i].key, key) == 0) return pairs[i].value;
  }
  return NULL;
}

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

/* Limits of a vehicle section: the damping surfaces' outputs (the
 * library's DampingModel::kMaxOutputs), a derivative model's terms and a
 * term's factors, disturbances and thrusters. */
enum {
  HC_VEHICLE_MAX_OUTPUTS = 32,
  HC_VEHICLE_MAX_TERMS = 64,
  HC_VEHICLE_MAX_FACTORS = 64,
  HC_VEHICLE_MAX_DISTURBANCES = 4096,
  HC_VEHICLE_MAX_THRUSTERS = 4096
};

/* One DOF's damping (docs/runtime.md, the vehicle section). */
enum { HC_DOF_NONE = 0, HC_DOF_LAW = 1, HC_DOF_DERIVATIVES = 2, HC_DOF_SURFACE = 3 };
typedef struct hc_runtime_dof {
  int kind;
  size_t variable;            /* law: the nu_r component */
  size_t count;               /* law, derivatives: the terms */
  int codes[6];               /* law: HC_DAMPING_* */
  const double* coefficients; /* law, derivatives: count numbers in the file (on the body) */
  size_t* begin;              /* derivatives: count + 1 */
  hc_damping_factor* factors; /* derivatives: begin[count] */
  size_t surface, output, axis_count;
  double sign;
  size_t sources[HC_KERNEL_MAX_AXES];
} hc_runtime_dof;

/* The surface DOFs that read one surface with the same axis sources: one
 * evaluation serves them all (as the library's lookups). */
typedef struct hc_runtime_lookup {
  size_t surface;
  size_t axis_count;
  size_t sources[HC_KERNEL_MAX_AXES];
  size_t used;
  size_t dof[6];
  size_t output[6];
  double sign[6];
} hc_runtime_lookup;

typedef struct hc_runtime_vehicle {
  hc_text_pair* metadata;
  size_t metadata_count;
  /* Column by column (motion_kernel.h's order; the file's are row by row). */
  double m_rb[36], m_a[36], m[36], m_inv[36];
  double weight_N, buoyancy_N, r_g[3], r_b[3], gain;
  size_t disturbance_count;
  const char** disturbance_names;
  size_t thruster_count;
  const char** thruster_names;
  double* thrusters; /* 8 per thruster: allocation column (6), min, max (a copy) */
  hc_runtime_dof dofs[6];
  hc_runtime_lookup lookups[6];
  size_t lookup_count;
} hc_runtime_vehicle;

/* Surface s at x into values (no gradient): HC_KERNEL_OK, or the kernel's
 * status with *failed_axis the axis (runtime_evaluate.c). */
int hc_runtime_surface_values(const hc_runtime_surface* s, const double* x, double* values, size_t* failed_axis);

struct hc_runtime_model {
  unsigned char* bytes; /* the file, owned; doubles and texts point into it */
  size_t size;
  uint64_t hash;
  hc_text_pair* metadata;
  size_t metadata_count;
  hc_runtime_surface* surfaces;
  size_t surface_count;
  hc_runtime_vehicle* vehicle; /* NULL: the file holds none */
};

#endif
