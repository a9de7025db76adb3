/* Evaluation and queries of an opened model: the same kernel, in the same
 * order, as GridTable::evaluate / evaluate_with_gradient and
 * CoefficientSurface::evaluate_with_standard_deviation (grid_kernel.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "runtime_internal.h"

#ifndef HYDROCOEF_RUNTIME_VERSION
#define HYDROCOEF_RUNTIME_VERSION "unknown"
#endif

int hc_runtime_abi_version(void) { return HC_RUNTIME_ABI_VERSION; }

const char* hc_runtime_version(void) { return HYDROCOEF_RUNTIME_VERSION; }

const char* hc_runtime_status_name(int status) {
  switch (status) {
    case HC_RUNTIME_OK: return "HC_RUNTIME_OK";
    case HC_RUNTIME_E_ARGUMENT: return "HC_RUNTIME_E_ARGUMENT";
    case HC_RUNTIME_E_IO: return "HC_RUNTIME_E_IO";
    case HC_RUNTIME_E_FORMAT: return "HC_RUNTIME_E_FORMAT";
    case HC_RUNTIME_E_VERSION: return "HC_RUNTIME_E_VERSION";
    case HC_RUNTIME_E_HASH: return "HC_RUNTIME_E_HASH";
    case HC_RUNTIME_E_MEMORY: return "HC_RUNTIME_E_MEMORY";
    case HC_RUNTIME_E_OUTSIDE: return "HC_RUNTIME_E_OUTSIDE";
    case HC_RUNTIME_E_NOT_FINITE: return "HC_RUNTIME_E_NOT_FINITE";
    case HC_RUNTIME_E_NO_SIGMA: return "HC_RUNTIME_E_NO_SIGMA";
    case HC_RUNTIME_E_NOT_FOUND: return "HC_RUNTIME_E_NOT_FOUND";
    case HC_RUNTIME_E_NO_VEHICLE: return "HC_RUNTIME_E_NO_VEHICLE";
    default: return "unknown status";
  }
}

static const hc_runtime_surface* surface_at(const hc_runtime_model* model, size_t surface) {
  return model != NULL && surface < model->surface_count ? &model->surfaces[surface] : NULL;
}

uint64_t hc_runtime_content_hash(const hc_runtime_model* model) { return model != NULL ? model->hash : 0; }

const char* hc_runtime_metadata(const hc_runtime_model* model, const char* key) {
  return model != NULL ? hc_find_text(model->metadata, model->metadata_count, key) : NULL;
}

size_t hc_runtime_surface_count(const hc_runtime_model* model) { return model != NULL ? model->surface_count : 0; }

int hc_runtime_surface_index(const hc_runtime_model* model, const char* name, size_t* index) {
  if (model == NULL || name == NULL || index == NULL) return HC_RUNTIME_E_ARGUMENT;
  for (size_t i = 0; i < model->surface_count; ++i) {
    if (strcmp(model->surfaces[i].name, name) == 0) {
      *index = i;
      return HC_RUNTIME_OK;
    }
  }
  return HC_RUNTIME_E_NOT_FOUND;
}

const char* hc_runtime_surface_name(const hc_runtime_model* model, size_t surface) {
  const hc_runtime_surface* s = surface_at(model, surface);
  return s != NULL ? s->name : NULL;
}

const char* hc_runtime_surface_method(const hc_runtime_model* model, size_t surface) {
  static const char* const kNames[] = {"nearest", "linear", "pchip", "makima", "natural-spline"};
  const hc_runtime_surface* s = surface_at(model, surface);
  return s != NULL ? kNames[s->method] : NULL;
}

const char* hc_runtime_surface_metadata(const hc_runtime_model* model, size_t surface, const char* key) {
  const hc_runtime_surface* s = surface_at(model, surface);
  return s != NULL ? hc_find_text(s->metadata, s->metadata_count, key) : NULL;
}

int hc_runtime_surface_has_sigma(const hc_runtime_model* model, size_t surface) {
  const hc_runtime_surface* s = surface_at(model, surface);
  return s != NULL && s->has_sigma;
}

size_t hc_runtime_axis_count(const hc_runtime_model* model, size_t surface) {
  const hc_runtime_surface* s = surface_at(model, surface);
  return s != NULL ? s->axis_count : 0;
}

size_t hc_runtime_output_count(const hc_runtime_model* model, size_t surface) {
  const hc_runtime_surface* s = surface_at(model, surface);
  return s != NULL ? s->output_count : 0;
}

const char* hc_runtime_axis_name(const hc_runtime_model* model, size_t surface, size_t axis) {
  const hc_runtime_surface* s = surface_at(model, surface);
  return s != NULL && axis < s->axis_count ? s->axis_info[axis].name : NULL;
}

const char* hc_runtime_axis_unit(const hc_runtime_model* model, size_t surface, size_t axis) {
  const hc_runtime_surface* s = surface_at(model, surface);
  return s != NULL && axis < s->axis_count ? s->axis_info[axis].unit : NULL;
}

const char* hc_runtime_axis_extrapolation(const hc_runtime_model* model, size_t surface, size_t axis) {
  static const char* const kNames[] = {"error", "clamp", "linear", "method"};
  const hc_runtime_surface* s = surface_at(model, surface);
  return s != NULL && axis < s->axis_count ? kNames[s->axes[axis].extrapolation] : NULL;
}

const double* hc_runtime_axis_breakpoints(const hc_runtime_model* model, size_t surface, size_t axis, size_t* count) {
  const hc_runtime_surface* s = surface_at(model, surface);
  if (s == NULL || axis >= s->axis_count) {
    if (count != NULL) *count = 0;
    return NULL;
  }
  if (count != NULL) *count = s->axes[axis].count;
  return s->breakpoints + s->axes[axis].offset;
}

const char* hc_runtime_output_name(const hc_runtime_model* model, size_t surface, size_t output) {
  const hc_runtime_surface* s = surface_at(model, surface);
  return s != NULL && output < s->output_count ? s->output_names[output] : NULL;
}

const char* hc_runtime_output_unit(const hc_runtime_model* model, size_t surface, size_t output) {
  const hc_runtime_surface* s = surface_at(model, surface);
  return s != NULL && output < s->output_count ? s->output_units[output] : NULL;
}

/* The local sum with the axis count and terms per axis as constants, so the
 * compiler specializes the kernel for each (as GridTable's templates do). */
#define HC_SUM_CASE(N, K)                                                                                  \
  case (K)*8 + (N):                                                                                        \
    hc_kernel_sum((N), (K), weights, replaced, replacement, offsets, data, count, out, out_stride, inner); \
    break;

static void sum(size_t n, size_t K, const double* weights, size_t replaced, const double* replacement,
                const size_t* offsets, const double* data, size_t count, double* out, size_t out_stride) {
  double inner[1024]; /* K^(n-1) <= 4^5 */
  switch (K * 8 + n) {
    HC_SUM_CASE(1, 1)
    HC_SUM_CASE(2, 1)
    HC_SUM_CASE(3, 1) HC_SUM_CASE(4, 1) HC_SUM_CASE(5, 1) HC_SUM_CASE(6, 1) HC_SUM_CASE(1, 2) HC_SUM_CASE(2, 2)
        HC_SUM_CASE(3, 2) HC_SUM_CASE(4, 2) HC_SUM_CASE(5, 2) HC_SUM_CASE(6, 2) HC_SUM_CASE(1, 4) HC_SUM_CASE(2, 4)
            HC_SUM_CASE(3, 4) HC_SUM_CASE(4, 4) HC_SUM_CASE(5, 4) HC_SUM_CASE(6, 4) default : break;
  }
}

/* Locates x on the axes: weights (and derivative weights) per axis and the
 * base node; a kernel status on failure, axis receiving the failing axis. */
static int locate(const hc_runtime_surface* s, const hc_kernel_axis* axes, const double* x, int with_gradient,
                  double* w, double* dw, size_t* base_node, size_t* failed_axis) {
  size_t base = 0;
  for (size_t a = 0; a < s->axis_count; ++a) {
    size_t node = 0;
    const int status = hc_kernel_axis_cell(&axes[a], s->breakpoints + axes[a].offset, s->terms_per_axis, with_gradient,
                                           x[a], w + 4 * a, dw + 4 * a, &node);
    if (status != HC_KERNEL_OK) {
      *failed_axis = a;
      return status;
    }
    base += node * axes[a].node_stride;
  }
  *base_node = base;
  return HC_KERNEL_OK;
}

/* hc_runtime_evaluate's values alone, with the axis count and the terms per
 * axis constants in each case (the same kernel calls in the same order): the
 * vehicle's hot path. */
#define HC_VALUES_CASE(N, K)                                                                                          \
  case (K)*8 + (N): {                                                                                                 \
    size_t base = 0;                                                                                                  \
    for (size_t a = 0; a < (N); ++a) {                                                                                \
      size_t node = 0;                                                                                                \
      const int status =                                                                                              \
          hc_kernel_axis_cell(&s->axes[a], s->breakpoints + s->axes[a].offset, (K), 0, x[a], w + 4 * a, NULL, &node); \
      if (status != HC_KERNEL_OK) {                                                                                   \
        *failed_axis = a;                                                                                             \
        return status;                                                                                                \
      }                                                                                                               \
      base += node * s->axes[a].node_stride;                                                                          \
    }                                                                                                                 \
    hc_kernel_sum((N), (K), w, HC_KERNEL_MAX_AXES, NULL, s->term_offsets, s->data + base * s->node_block,             \
                  s->output_count, values, 1, inner);                                                                 \
    return HC_KERNEL_OK;                                                                                              \
  }

int hc_runtime_surface_values(const hc_runtime_surface* s, const double* x, double* values, size_t* failed_axis) {
  double w[4 * HC_KERNEL_MAX_AXES];
  double inner[1024]; /* K^(n-1) <= 4^5 */
  switch (s->terms_per_axis * 8 + s->axis_count) {
    HC_VALUES_CASE(1, 1)
    HC_VALUES_CASE(2, 1)
    HC_VALUES_CASE(3, 1)
    HC_VALUES_CASE(4, 1)
    HC_VALUES_CASE(5, 1)
    HC_VALUES_CASE(6, 1)
    HC_VALUES_CASE(1, 2)
    HC_VALUES_CASE(2, 2)
    HC_VALUES_CASE(3, 2)
    HC_VALUES_CASE(4, 2)
    HC_VALUES_CASE(5, 2)
    HC_VALUES_CASE(6, 2)
    HC_VALUES_CASE(1, 4)
    HC_VALUES_CASE(2, 4)
    HC_VALUES_CASE(3, 4)
    HC_VALUES_CASE(4, 4)
    HC_VALUES_CASE(5, 4)
    HC_VALUES_CASE(6, 4)
    default: break;
  }
  return HC_KERNEL_OK;
}

int hc_runtime_evaluate(const hc_runtime_model* model, size_t surface, const double* x, double* values,
                        double* gradients, double* sigma) {
  const hc_runtime_surface* s = surface_at(model, surface);
  if (s == NULL || x == NULL || values == NULL) return HC_RUNTIME_E_ARGUMENT;
  if (sigma != NULL && !s->has_sigma) return HC_RUNTIME_E_NO_SIGMA;
  const size_t n = s->axis_count, K = s->terms_per_axis, n_out = s->output_count;
  double w[4 * HC_KERNEL_MAX_AXES], dw[4 * HC_KERNEL_MAX_AXES];
  size_t base = 0, failed = 0;
  const int status = locate(s, s->axes, x, gradients != NULL, w, dw, &base, &failed);
  if (status != HC_KERNEL_OK) return status == HC_KERNEL_OUTSIDE ? HC_RUNTIME_E_OUTSIDE : HC_RUNTIME_E_NOT_FINITE;
  const double* data = s->data + base * s->node_block;
  sum(n, K, w, HC_KERNEL_MAX_AXES, NULL, s->term_offsets, data, n_out, values, 1);
  if (gradients != NULL) {
    for (size_t a = 0; a < n; ++a) sum(n, K, w, a, dw + 4 * a, s->term_offsets, data, n_out, gradients + a, n);
  }
  if (sigma != NULL) {
    /* The runs' part through the same interpolant, clamped outside the
     * range, at least 0, with the leave-one-out part in quadrature. */
    if (locate(s, s->sigma_axes, x, 0, w, dw, &base, &failed) != HC_KERNEL_OK) return HC_RUNTIME_E_NOT_FINITE;
    sum(n, K, w, HC_KERNEL_MAX_AXES, NULL, s->term_offsets, s->sigma_data + base * s->node_block, n_out, sigma, 1);
    for (size_t k = 0; k < n_out; ++k) {
      const double part = 0.0 < sigma[k] ? sigma[k] : 0.0;
      sigma[k] = hypot(part, s->loo[k]);
    }
  }
  return HC_RUNTIME_OK;
}

int hc_runtime_check_point(const hc_runtime_model* model, size_t surface, const double* x, char* err, size_t errlen) {
  const hc_runtime_surface* s = surface_at(model, surface);
  if (err != NULL && errlen > 0) err[0] = '\0';
  if (s == NULL || x == NULL) {
    if (err != NULL && errlen > 0)
      snprintf(err, errlen, "hc_runtime_check_point: %s", s == NULL ? "no such surface" : "x is NULL");
    return HC_RUNTIME_E_ARGUMENT;
  }
  double w[4 * HC_KERNEL_MAX_AXES], dw[4 * HC_KERNEL_MAX_AXES];
  size_t base = 0, a = 0;
  const int status = locate(s, s->axes, x, 0, w, dw, &base, &a);
  if (status == HC_KERNEL_OK) return HC_RUNTIME_OK;
  if (err != NULL && errlen > 0) {
    if (status == HC_KERNEL_NOT_FINITE)
      snprintf(err, errlen, "surface '%s': axis '%s' = %g is not a number; expected a finite value", s->name,
               s->axis_info[a].name, x[a]);
    else
      snprintf(err, errlen,
               "surface '%s': axis '%s' = %.17g is outside [%.17g, %.17g]; expected a value in range "
               "(its extrapolation policy is error)",
               s->name, s->axis_info[a].name, x[a], s->axes[a].lo, s->axes[a].hi);
  }
  return status == HC_KERNEL_OUTSIDE ? HC_RUNTIME_E_OUTSIDE : HC_RUNTIME_E_NOT_FINITE;
}
