/* The vehicle FMU (docs/fmu.md): the runtime file's vehicle stepped with
 * libhydrocoef_runtime's RK4 (`hydrocoef simulate`'s step, bit for bit).
 * Value references, with d the vehicle's disturbance count:
 *   inputs      0 .. 5        X Y Z K M N: the control force and moment tau_b
 *                             on the body about CO, body FRD [N, N m]
 *               6 .. 8        the current in NED (north, east, down) [m/s]
 *               9 .. 9+d-1    the disturbances, by name [SI]
 *   outputs     O = 9+d: O+0..2 x_n y_n z_n (CO in NED) [m]; O+3..6 the
 *               attitude q_nb scalar first (body FRD to NED, normalised as
 *               simulate's samples state it); O+7..9 phi theta psi (zyx Euler
 *               of q_nb) [rad]; O+10..15 u v w [m/s] p q r [rad/s] (body
 *               velocity over ground); O+16..21 the damping -D(nu_r) nu_r on
 *               the body X..N [N, N m] (SNAME: damping opposes motion)
 *   parameters  P = O+22: P+0 the internal RK4 step [s]; P+1..3 the initial
 *               position; P+4..6 the initial Euler angles; P+7..12 the
 *               initial body velocity (set before initialisation ends).
 * fmi2DoStep(t, H) integrates from t to t + H in n = max(1, ceil(H/dt -
 * 1e-9)) equal RK4 steps of H/n (at most dt): simulate's rule for the span
 * between two of its events, so that a host stepping at simulate's output
 * times gets simulate's states bit for bit. The inputs are held over H. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fmu_internal.h"
#include "runtime/src/motion_kernel.h"

enum { V_TAU = 0, V_CURRENT = 6, V_DISTURBANCES = 9, V_OUTPUTS = 22, V_PARAMETERS = 13 };
/* Offsets inside the outputs and the parameters. */
enum { O_POSITION = 0, O_QUATERNION = 3, O_EULER = 7, O_VELOCITY = 10, O_DAMPING = 16 };
enum { P_STEP = 0, P_POSITION = 1, P_EULER = 4, P_VELOCITY = 7 };

typedef struct vehicle_data {
  size_t n_disturbances;
  size_t outputs;    /* O */
  size_t parameters; /* P */
  double x[13];      /* the state at fmu->time */
} vehicle_data;

static const char* const input_names[9] = {"X",           "Y", "Z", "K", "M", "N", "current_north", "current_east",
                                           "current_down"};
static const char* const parameter_names[13] = {"step", "x_n0", "y_n0", "z_n0", "phi0", "theta0", "psi0",
                                                "u0",   "v0",   "w0",   "p0",   "q0",   "r0"};

static int vehicle_bind(fmu_instance* fmu, char* err, size_t errlen) {
  if (!hc_runtime_has_vehicle(fmu->model)) {
    snprintf(err, errlen, "the runtime file holds no vehicle; expected one written with --vehicle");
    return -1;
  }
  vehicle_data* data = fmu_calloc(fmu, 1, sizeof *data);
  if (data == NULL) {
    snprintf(err, errlen, "out of memory");
    return -1;
  }
  fmu->kind_data = data;
  data->n_disturbances = hc_runtime_vehicle_disturbance_count(fmu->model);
  data->outputs = V_DISTURBANCES + data->n_disturbances;
  data->parameters = data->outputs + V_OUTPUTS;
  const size_t n = data->parameters + V_PARAMETERS;
  if (fmu_allocate_reals(fmu, n) != 0) {
    snprintf(err, errlen, "out of memory for %zu variables", n);
    return -1;
  }
  for (size_t k = 0; k < data->outputs; ++k) fmu->role[k] = FMU_VAR_INPUT;
  for (size_t k = data->outputs; k < data->parameters; ++k) fmu->role[k] = FMU_VAR_OUTPUT;
  for (size_t k = data->parameters; k < n; ++k) fmu->role[k] = FMU_VAR_PARAMETER;
  fmu->start[data->parameters + P_STEP] = 0.001;
  fmu->start[data->outputs + O_QUATERNION] = 1.0;
  return 0;
}

static void vehicle_release(fmu_instance* fmu) {
  fmu_free(fmu, fmu->kind_data);
  fmu->kind_data = NULL;
}

/* The name of Real k, for messages. */
static const char* name_of(const fmu_instance* fmu, const vehicle_data* data, size_t k) {
  if (k < V_DISTURBANCES) return input_names[k];
  if (k < data->outputs) return hc_runtime_vehicle_disturbance_name(fmu->model, k - V_DISTURBANCES);
  if (k >= data->parameters) return parameter_names[k - data->parameters];
  return "an output";
}

/* hydrocoef's quaternion_from_euler (src/dynamics/kinematics.cpp): zyx
 * Euler angles to q_nb, scalar first and non-negative, normalised (the
 * shared kernel's hc_motion_normalize, as the library's unit_attitude). */
static void quaternion_from_euler(const double e[3], double q[4]) {
  const double cp = cos(0.5 * e[0]), sp = sin(0.5 * e[0]);
  const double ct = cos(0.5 * e[1]), st = sin(0.5 * e[1]);
  const double cy = cos(0.5 * e[2]), sy = sin(0.5 * e[2]);
  q[0] = cp * ct * cy + sp * st * sy;
  q[1] = sp * ct * cy - cp * st * sy;
  q[2] = cp * st * cy + sp * ct * sy;
  q[3] = cp * ct * sy - sp * st * cy;
  if (q[0] < 0.0)
    for (int i = 0; i < 4; ++i) q[i] = -q[i];
  hc_motion_normalize(q);
}

/* The outputs of state x at the held inputs; 0 or -1 (err). */
static int write_outputs(fmu_instance* fmu, const vehicle_data* data, const double* x, char* err, size_t errlen) {
  const double* in = fmu->reals;
  double breakdown[30];
  if (hc_runtime_vehicle_forces(fmu->model, x, in + V_TAU, in + V_CURRENT,
                                data->n_disturbances ? in + V_DISTURBANCES : NULL, breakdown, err,
                                errlen) != HC_RUNTIME_OK)
    return -1;
  double* out = fmu->reals + data->outputs;
  for (int i = 0; i < 3; ++i) out[O_POSITION + i] = x[i];
  /* The attitude normalised once more, as simulate's samples state it (unit_attitude). */
  double q[4] = {x[3], x[4], x[5], x[6]};
  hc_motion_normalize(q);
  for (int i = 0; i < 4; ++i) out[O_QUATERNION + i] = q[i];
  /* hydrocoef's euler_from_quaternion (src/dynamics/kinematics.cpp). */
  const double e = q[0], a = q[1], b = q[2], c = q[3];
  out[O_EULER + 0] = atan2(2.0 * (b * c + a * e), 1.0 - 2.0 * (a * a + b * b));
  out[O_EULER + 1] = -asin(fmin(fmax(2.0 * (a * c - b * e), -1.0), 1.0));
  out[O_EULER + 2] = atan2(2.0 * (a * b + c * e), 1.0 - 2.0 * (b * b + c * c));
  for (int i = 0; i < 6; ++i) out[O_VELOCITY + i] = x[7 + i];
  for (int i = 0; i < 6; ++i) out[O_DAMPING + i] = breakdown[6 + i];
  return 0;
}

/* 0 when every input (or, with `parameters`, every parameter) is finite. */
static int check_finite(const fmu_instance* fmu, const vehicle_data* data, size_t from, size_t to, char* err,
                        size_t errlen) {
  for (size_t k = from; k < to; ++k)
    if (!isfinite(fmu->reals[k])) {
      snprintf(err, errlen, "%s '%.200s' (value reference %zu) is %g; expected a finite value",
               k >= data->parameters ? "parameter" : "input", name_of(fmu, data, k), k, fmu->reals[k]);
      return -1;
    }
  return 0;
}

static int vehicle_step(fmu_instance* fmu, double time, double step, char* err, size_t errlen) {
  (void)time;
  vehicle_data* data = fmu->kind_data;
  if (check_finite(fmu, data, 0, data->outputs, err, errlen) != 0) return -1;
  const double* par = fmu->reals + data->parameters;
  if (step == 0.0) {
    /* Initialisation: the state from the parameters. */
    if (check_finite(fmu, data, data->parameters, fmu->n_reals, err, errlen) != 0) return -1;
    if (!(par[P_STEP] > 0.0)) {
      snprintf(err, errlen, "parameter 'step' is %.17g; expected an internal RK4 step above 0 s", par[P_STEP]);
      return -1;
    }
    double x[13];
    for (int i = 0; i < 3; ++i) x[i] = par[P_POSITION + i];
    quaternion_from_euler(par + P_EULER, x + 3);
    for (int i = 0; i < 6; ++i) x[7 + i] = par[P_VELOCITY + i];
    if (write_outputs(fmu, data, x, err, errlen) != 0) return -1;
    memcpy(data->x, x, sizeof x);
    return 0;
  }
  const double dt = par[P_STEP];
  const double ratio = ceil(step / dt - 1e-9);
  if (!(ratio < 1e9)) {
    snprintf(err, errlen, "a communication step of %.17g s is %.17g internal steps of %.17g s; expected at most 1e9",
             step, ratio, dt);
    return -1;
  }
  const size_t count = ratio < 1.0 ? 1u : (size_t)ratio;
  const double h = step / (double)count;
  const double* in = fmu->reals;
  const double* disturbances = data->n_disturbances ? in + V_DISTURBANCES : NULL;
  double x[13];
  memcpy(x, data->x, sizeof x);
  for (size_t k = 0; k < count; ++k)
    if (hc_runtime_vehicle_step_rk4(fmu->model, x, in + V_TAU, in + V_CURRENT, disturbances, h, err, errlen) !=
        HC_RUNTIME_OK)
      return -1;
  if (write_outputs(fmu, data, x, err, errlen) != 0) return -1;
  memcpy(data->x, x, sizeof x);
  return 0;
}

const fmu_kind fmu_vehicle_kind = {"vehicle", vehicle_bind, vehicle_step, vehicle_release};
