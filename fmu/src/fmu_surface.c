/* The surface FMU (docs/fmu.md): one coefficient surface of the runtime
 * file. Value references: 0 .. n-1 the axes (inputs, the axis's unit), n ..
 * n+m-1 the outputs, and with a standard deviation n+m .. n+2m-1 each
 * output's sigma (outputs). A step evaluates the surface at the inputs held
 * over the step: the outputs are algebraic functions of the inputs, the
 * runtime library's (`hydrocoef query`'s) numbers bit for bit. An input's
 * start value is 0 clamped into the axis's breakpoint range. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fmu_internal.h"

static int surface_bind(fmu_instance* fmu, char* err, size_t errlen) {
  const char* name = hc_runtime_metadata(fmu->model, "fmu_surface");
  if (name == NULL) {
    snprintf(err, errlen, "the runtime file states no fmu_surface; expected the surface this FMU evaluates");
    return -1;
  }
  if (hc_runtime_surface_index(fmu->model, name, &fmu->surface) != HC_RUNTIME_OK) {
    snprintf(err, errlen, "the runtime file has no surface '%.200s' (its fmu_surface)", name);
    return -1;
  }
  fmu->n_axes = hc_runtime_axis_count(fmu->model, fmu->surface);
  fmu->n_outputs = hc_runtime_output_count(fmu->model, fmu->surface);
  fmu->has_sigma = hc_runtime_surface_has_sigma(fmu->model, fmu->surface);
  const size_t n = fmu->n_axes + fmu->n_outputs * (fmu->has_sigma ? 2u : 1u);
  if (fmu_allocate_reals(fmu, n) != 0) {
    snprintf(err, errlen, "out of memory for %zu variables", n);
    return -1;
  }
  for (size_t a = 0; a < fmu->n_axes; ++a) {
    size_t count = 0;
    const double* breakpoints = hc_runtime_axis_breakpoints(fmu->model, fmu->surface, a, &count);
    fmu->role[a] = FMU_VAR_INPUT;
    fmu->start[a] = fmin(fmax(0.0, breakpoints[0]), breakpoints[count - 1]);
  }
  for (size_t k = fmu->n_axes; k < n; ++k) fmu->role[k] = FMU_VAR_OUTPUT;
  return 0;
}

static int surface_step(fmu_instance* fmu, double time, double step, char* err, size_t errlen) {
  (void)time;
  (void)step;
  const double* x = fmu->reals;
  double* values = fmu->reals + fmu->n_axes;
  double* sigma = fmu->has_sigma ? values + fmu->n_outputs : NULL;
  const int status = hc_runtime_evaluate(fmu->model, fmu->surface, x, values, NULL, sigma);
  if (status == HC_RUNTIME_OK) return 0;
  char why[512] = "";
  hc_runtime_check_point(fmu->model, fmu->surface, x, why, sizeof why);
  snprintf(err, errlen, "surface '%.200s' cannot be evaluated at the inputs (%s): %s",
           hc_runtime_surface_name(fmu->model, fmu->surface), hc_runtime_status_name(status), why);
  return -1;
}

const fmu_kind fmu_surface_kind = {"surface", surface_bind, surface_step, NULL};
