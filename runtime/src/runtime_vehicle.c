/* The vehicle of a runtime file: its derivative, forces and RK4 step, with
 * the C++ library's own arithmetic (motion_kernel.h, damping_kernel.h and
 * grid_kernel.h are both libraries' sources), so its numbers are
 * VehicleModel::derivative's and `hydrocoef simulate`'s bit for bit. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "motion_kernel.h"
#include "runtime_internal.h"

static const hc_runtime_vehicle* vehicle_of(const hc_runtime_model* model) {
  return model != NULL ? model->vehicle : NULL;
}

int hc_runtime_has_vehicle(const hc_runtime_model* model) { return vehicle_of(model) != NULL; }

const char* hc_runtime_vehicle_metadata(const hc_runtime_model* model, const char* key) {
  const hc_runtime_vehicle* v = vehicle_of(model);
  return v != NULL ? hc_find_text(v->metadata, v->metadata_count, key) : NULL;
}

size_t hc_runtime_vehicle_disturbance_count(const hc_runtime_model* model) {
  const hc_runtime_vehicle* v = vehicle_of(model);
  return v != NULL ? v->disturbance_count : 0;
}

const char* hc_runtime_vehicle_disturbance_name(const hc_runtime_model* model, size_t index) {
  const hc_runtime_vehicle* v = vehicle_of(model);
  return v != NULL && index < v->disturbance_count ? v->disturbance_names[index] : NULL;
}

size_t hc_runtime_vehicle_thruster_count(const hc_runtime_model* model) {
  const hc_runtime_vehicle* v = vehicle_of(model);
  return v != NULL ? v->thruster_count : 0;
}

const char* hc_runtime_vehicle_thruster_name(const hc_runtime_model* model, size_t thruster) {
  const hc_runtime_vehicle* v = vehicle_of(model);
  return v != NULL && thruster < v->thruster_count ? v->thruster_names[thruster] : NULL;
}

int hc_runtime_vehicle_thruster_limits(const hc_runtime_model* model, size_t thruster, double* min_N, double* max_N) {
  const hc_runtime_vehicle* v = vehicle_of(model);
  if (v == NULL) return model == NULL ? HC_RUNTIME_E_ARGUMENT : HC_RUNTIME_E_NO_VEHICLE;
  if (thruster >= v->thruster_count) return HC_RUNTIME_E_ARGUMENT;
  if (min_N != NULL) *min_N = v->thrusters[8 * thruster + 6];
  if (max_N != NULL) *max_N = v->thrusters[8 * thruster + 7];
  return HC_RUNTIME_OK;
}

int hc_runtime_vehicle_thrust_force(const hc_runtime_model* model, const double* thrust_N, double* tau_b) {
  const hc_runtime_vehicle* v = vehicle_of(model);
  if (v == NULL) return model == NULL ? HC_RUNTIME_E_ARGUMENT : HC_RUNTIME_E_NO_VEHICLE;
  if (tau_b == NULL || (thrust_N == NULL && v->thruster_count > 0)) return HC_RUNTIME_E_ARGUMENT;
  /* VehicleModel::thrust_force: tau += thrust_i * column_i from zero. */
  for (size_t j = 0; j < 6; ++j) tau_b[j] = 0.0;
  for (size_t i = 0; i < v->thruster_count; ++i)
    for (size_t j = 0; j < 6; ++j) tau_b[j] += thrust_N[i] * v->thrusters[8 * i + j];
  return HC_RUNTIME_OK;
}

/* std::to_chars(double)'s text (the library's shortest_number): the fewest
 * significant digits that read back to the value, in fixed or scientific
 * notation, whichever is shorter (fixed on a tie). */
static void shortest_number(double value, char* out, size_t size) {
  if (isnan(value)) {
    snprintf(out, size, "%s", signbit(value) ? "-nan" : "nan");
    return;
  }
  if (isinf(value)) {
    snprintf(out, size, "%s", value < 0 ? "-inf" : "inf");
    return;
  }
  char scientific[40];
  int precision = 0;
  for (; precision < 17; ++precision) {
    snprintf(scientific, sizeof scientific, "%.*e", precision, value);
    if (strtod(scientific, NULL) == value) break;
  }
  /* Digits and exponent of "-d.ddde+XX". */
  const char* p = scientific;
  const int negative = *p == '-';
  if (negative) ++p;
  char digits[24];
  size_t n = 0;
  for (; *p != 'e'; ++p)
    if (*p != '.') digits[n++] = *p;
  const int exponent = atoi(p + 1);
  while (n > 1 && digits[n - 1] == '0') --n;
  digits[n] = '\0';
  char sci[48], fixed[400];
  snprintf(sci, sizeof sci, "%s%c%s%s%se%c%02d", negative ? "-" : "", digits[0], n > 1 ? "." : "",
           n > 1 ? digits + 1 : "", "", exponent < 0 ? '-' : '+', exponent < 0 ? -exponent : exponent);
  size_t f = 0;
  if (negative) fixed[f++] = '-';
  if (exponent < 0) {
    fixed[f++] = '0';
    fixed[f++] = '.';
    for (int i = 0; i < -exponent - 1; ++i) fixed[f++] = '0';
    for (size_t i = 0; i < n; ++i) fixed[f++] = digits[i];
  } else {
    for (int i = 0; i <= exponent; ++i) fixed[f++] = (size_t)i < n ? digits[i] : '0';
    if (n > (size_t)exponent + 1) {
      fixed[f++] = '.';
      for (size_t i = (size_t)exponent + 1; i < n; ++i) fixed[f++] = digits[i];
    }
  }
  fixed[f] = '\0';
  /* The shorter is at most the scientific form's 24 characters. */
  const char* chosen = strlen(fixed) <= strlen(sci) ? fixed : sci;
  size_t length = strlen(chosen);
  if (length >= size) length = size - 1;
  memcpy(out, chosen, length);
  out[length] = '\0';
}

/* GridTable's refusal of a point (its throw_outside), in err. */
static int surface_refusal(const hc_runtime_surface* s, size_t axis, double value, int status, char* err,
                           size_t errlen) {
  if (err != NULL && errlen > 0) {
    char number[64], lo[64], hi[64];
    shortest_number(value, number, sizeof number);
    if (status == HC_KERNEL_NOT_FINITE) {
      snprintf(err, errlen, "axis '%s' = %s is not a number; expected a finite value", s->axis_info[axis].name, number);
    } else {
      shortest_number(s->axes[axis].lo, lo, sizeof lo);
      shortest_number(s->axes[axis].hi, hi, sizeof hi);
      snprintf(err, errlen,
               "axis '%s' = %s is outside [%s, %s]; expected a value in range (or an extrapolation policy)",
               s->axis_info[axis].name, number, lo, hi);
    }
  }
  return status == HC_KERNEL_OUTSIDE ? HC_RUNTIME_E_OUTSIDE : HC_RUNTIME_E_NOT_FINITE;
}

/* tau (6) += the damping force at nu_r (6): DampingModel::add's terms. */
static int add_damping(const hc_runtime_model* model, const double* nu_r, const double* disturbances, double* tau,
                       char* err, size_t errlen) {
  const hc_runtime_vehicle* v = model->vehicle;
  for (size_t dof = 0; dof < 6; ++dof) {
    const hc_runtime_dof* d = &v->dofs[dof];
    if (d->kind == HC_DOF_LAW)
      tau[dof] += hc_damping_law_value(d->codes, d->coefficients, d->count, &nu_r[d->variable]);
  }
  for (size_t dof = 0; dof < 6; ++dof) {
    const hc_runtime_dof* d = &v->dofs[dof];
    if (d->kind == HC_DOF_DERIVATIVES)
      tau[dof] += hc_damping_derivatives_value(d->coefficients, d->count, d->begin, d->factors, nu_r, disturbances);
  }
  double out[HC_VEHICLE_MAX_OUTPUTS];
  for (size_t i = 0; i < v->lookup_count; ++i) {
    const hc_runtime_lookup* l = &v->lookups[i];
    const hc_runtime_surface* s = &model->surfaces[l->surface];
    double point[HC_KERNEL_MAX_AXES];
    for (size_t a = 0; a < l->axis_count; ++a)
      point[a] = l->sources[a] < 6 ? nu_r[l->sources[a]] : disturbances[l->sources[a] - 6];
    size_t failed = 0;
    const int status = hc_runtime_surface_values(s, point, out, &failed);
    if (status != HC_KERNEL_OK) return surface_refusal(s, failed, point[failed], status, err, errlen);
    for (size_t k = 0; k < l->used; ++k) tau[l->dof[k]] += l->sign[k] * out[l->output[k]];
  }
  return HC_RUNTIME_OK;
}

/* The checks every vehicle call makes. */
static int check_call(const hc_runtime_model* model, const double* x, const double* tau_b, const double* disturbances,
                      const void* out, char* err, size_t errlen) {
  if (err != NULL && errlen > 0) err[0] = '\0';
  if (model == NULL || x == NULL || tau_b == NULL || out == NULL) {
    if (err != NULL && errlen > 0) snprintf(err, errlen, "hc_runtime_vehicle: a NULL model, state, tau_b or output");
    return HC_RUNTIME_E_ARGUMENT;
  }
  if (model->vehicle == NULL) {
    if (err != NULL && errlen > 0) snprintf(err, errlen, "hc_runtime_vehicle: the runtime file holds no vehicle");
    return HC_RUNTIME_E_NO_VEHICLE;
  }
  if (disturbances == NULL && model->vehicle->disturbance_count > 0) {
    if (err != NULL && errlen > 0)
      snprintf(err, errlen, "hc_runtime_vehicle: disturbances is NULL; the vehicle reads %zu",
               model->vehicle->disturbance_count);
    return HC_RUNTIME_E_ARGUMENT;
  }
  return HC_RUNTIME_OK;
}

typedef struct terms {
  double rotation[9], nu_r[6], hydrostatic[6], damping[6], coriolis[6], current_b[3];
} terms;

static int motion_terms(const hc_runtime_model* model, const double* x, const double* current_n,
                        const double* disturbances, terms* t, char* err, size_t errlen) {
  static const double kNoCurrent[3] = {0.0, 0.0, 0.0};
  const hc_runtime_vehicle* v = model->vehicle;
  const int current =
      hc_motion_begin(x, v->weight_N, v->buoyancy_N, v->r_g, v->r_b, current_n != NULL ? current_n : kNoCurrent,
                      t->rotation, t->nu_r, t->hydrostatic, t->damping, t->coriolis, t->current_b);
  const int status = add_damping(model, t->nu_r, disturbances, t->damping, err, errlen);
  if (status != HC_RUNTIME_OK) return status;
  hc_motion_finish(x, current, v->m, v->m_rb, v->m_a, t->nu_r, t->current_b, t->coriolis);
  return HC_RUNTIME_OK;
}

static int derivative(const hc_runtime_model* model, const double* x, const double* tau_b, const double* current_n,
                      const double* disturbances, double* x_dot, char* err, size_t errlen) {
  terms t;
  const int status = motion_terms(model, x, current_n, disturbances, &t, err, errlen);
  if (status != HC_RUNTIME_OK) return status;
  const hc_runtime_vehicle* v = model->vehicle;
  hc_motion_rates(x, tau_b, v->gain, v->m_inv, t.rotation, t.hydrostatic, t.damping, t.coriolis, x_dot);
  return HC_RUNTIME_OK;
}

int hc_runtime_vehicle_derivative(const hc_runtime_model* model, const double* x, const double* tau_b,
                                  const double* current_n, const double* disturbances, double* x_dot, char* err,
                                  size_t errlen) {
  const int status = check_call(model, x, tau_b, disturbances, x_dot, err, errlen);
  if (status != HC_RUNTIME_OK) return status;
  double rates[13];
  const int evaluated = derivative(model, x, tau_b, current_n, disturbances, rates, err, errlen);
  if (evaluated == HC_RUNTIME_OK) memcpy(x_dot, rates, sizeof rates);
  return evaluated;
}

int hc_runtime_vehicle_forces(const hc_runtime_model* model, const double* x, const double* tau_b,
                              const double* current_n, const double* disturbances, double* breakdown, char* err,
                              size_t errlen) {
  int status = check_call(model, x, tau_b, disturbances, breakdown, err, errlen);
  if (status != HC_RUNTIME_OK) return status;
  terms t;
  status = motion_terms(model, x, current_n, disturbances, &t, err, errlen);
  if (status != HC_RUNTIME_OK) return status;
  for (size_t i = 0; i < 6; ++i) {
    breakdown[i] = tau_b[i];
    breakdown[6 + i] = t.damping[i];
    breakdown[12 + i] = t.hydrostatic[i];
    breakdown[18 + i] = t.coriolis[i];
    breakdown[24 + i] = t.nu_r[i];
  }
  return HC_RUNTIME_OK;
}

int hc_runtime_vehicle_step_rk4(const hc_runtime_model* model, double* x, const double* tau_b, const double* current_n,
                                const double* disturbances, double dt, char* err, size_t errlen) {
  int status = check_call(model, x, tau_b, disturbances, x, err, errlen);
  if (status != HC_RUNTIME_OK) return status;
  /* rk4_step (src/dynamics/integrators.hpp), element by element as Eigen
   * evaluates its expressions, then the attitude normalised as simulate
   * does after each step. */
  double k1[13], k2[13], k3[13], k4[13], stage[13];
  const double half = 0.5 * dt, sixth = dt / 6.0;
  status = derivative(model, x, tau_b, current_n, disturbances, k1, err, errlen);
  if (status != HC_RUNTIME_OK) return status;
  for (int i = 0; i < 13; ++i) stage[i] = x[i] + half * k1[i];
  status = derivative(model, stage, tau_b, current_n, disturbances, k2, err, errlen);
  if (status != HC_RUNTIME_OK) return status;
  for (int i = 0; i < 13; ++i) stage[i] = x[i] + half * k2[i];
  status = derivative(model, stage, tau_b, current_n, disturbances, k3, err, errlen);
  if (status != HC_RUNTIME_OK) return status;
  for (int i = 0; i < 13; ++i) stage[i] = x[i] + dt * k3[i];
  status = derivative(model, stage, tau_b, current_n, disturbances, k4, err, errlen);
  if (status != HC_RUNTIME_OK) return status;
  for (int i = 0; i < 13; ++i) x[i] += sixth * (((k1[i] + 2.0 * k2[i]) + 2.0 * k3[i]) + k4[i]);
  hc_motion_normalize(x + 3);
  return HC_RUNTIME_OK;
}
