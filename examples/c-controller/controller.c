/* A controller loop on libhydrocoef_runtime, shaped as a simulator plugin
 * would be: load a runtime file holding a vehicle (`hydrocoef export BODY
 * --format runtime --vehicle VEHICLE.json -o MODEL.hcrt`), then at 1 kHz
 * read the state, compute the control force with a PD heading controller,
 * and advance the vehicle one RK4 step with hc_runtime_vehicle_step_rk4;
 * log the state at 10 Hz. C99, libc, libm and the runtime library only.
 *
 *   controller MODEL.hcrt [--seconds S] [--heading PSI_REF] [--kp KP]
 *              [--kd KD] [--torque N0]
 *
 * The yaw moment is tau_N = N0 + KP wrap(PSI_REF - psi) - KD r [N m] (psi
 * the yaw angle of the attitude [rad], r the yaw rate [rad/s]); the other
 * five components of tau_b are zero. Defaults: 10 s, PSI_REF 0, gains 0,
 * N0 0. With zero gains and a constant N0 the loop is `hydrocoef simulate`
 * with a constant yaw torque: each 0.1 s log interval is 100 steps of
 * (t_log - t_previous_log) / 100 s, with t_log = k / 10 (no drift of the
 * clock), the span split as simulate splits the span between its output
 * times, so the logged states are simulate's bit for bit.
 *
 * Output (stdout): a header line, then one line per 0.1 s: t, x_n y_n z_n
 * [m] (NED), q_eta q_eps1 q_eps2 q_eps3 (body FRD to NED, scalar first),
 * u v w [m/s] p q r [rad/s] (body FRD), psi [rad], tau_N [N m]; numbers
 * with 17 significant digits (they read back to the same doubles).
 * Errors (a file the runtime refuses, a file without a vehicle, a state a
 * surface refuses, a bad argument): one line on stderr with the runtime's
 * message, exit status 1 (2 for a bad argument). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hydrocoef/runtime.h"

#define STEPS_PER_LOG 100 /* 1 kHz control, 10 Hz log */
#define LOG_RATE_HZ 10.0

static const double kPi = 3.14159265358979323846;

/* The yaw angle of q_nb (zyx Euler, as hydrocoef states it). */
static double yaw_of(const double* q) {
  return atan2(2.0 * (q[1] * q[2] + q[3] * q[0]), 1.0 - 2.0 * (q[2] * q[2] + q[3] * q[3]));
}

/* An angle into [-pi, pi). */
static double wrap(double angle) {
  angle = fmod(angle + kPi, 2.0 * kPi);
  if (angle < 0.0) angle += 2.0 * kPi;
  return angle - kPi;
}

static void log_line(double t, const double* x, double tau_n) {
  int i;
  printf("%.17g", t);
  for (i = 0; i < 13; ++i) printf(" %.17g", x[i]);
  printf(" %.17g %.17g\n", yaw_of(x + 3), tau_n);
}

static int number(const char* option, const char* text, double* out) {
  char* end = NULL;
  *out = strtod(text, &end);
  if (end == text || *end != '\0' || !isfinite(*out)) {
    fprintf(stderr, "controller: %s '%s' is not a finite number\n", option, text);
    return -1;
  }
  return 0;
}

int main(int argc, char** argv) {
  double seconds = 10.0, heading = 0.0, kp = 0.0, kd = 0.0, torque = 0.0;
  double x[13] = {0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const double current_n[3] = {0.0, 0.0, 0.0};
  double tau_b[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  double* disturbances = NULL;
  hc_runtime_model* model = NULL;
  char err[1024];
  long logs, k;
  double t = 0.0;
  int i, status;

  if (argc < 2 || argc % 2 != 0) {
    fprintf(stderr,
            "usage: controller MODEL.hcrt [--seconds S] [--heading PSI_REF] [--kp KP] [--kd KD] "
            "[--torque N0]\n");
    return 2;
  }
  for (i = 2; i + 1 < argc; i += 2) {
    double* target = strcmp(argv[i], "--seconds") == 0   ? &seconds
                     : strcmp(argv[i], "--heading") == 0 ? &heading
                     : strcmp(argv[i], "--kp") == 0      ? &kp
                     : strcmp(argv[i], "--kd") == 0      ? &kd
                     : strcmp(argv[i], "--torque") == 0  ? &torque
                                                         : NULL;
    if (target == NULL) {
      fprintf(stderr, "controller: unknown option '%s'; expected --seconds, --heading, --kp, --kd or --torque\n",
              argv[i]);
      return 2;
    }
    if (number(argv[i], argv[i + 1], target) != 0) return 2;
  }
  if (!(seconds > 0.0 && seconds <= 1e6)) {
    fprintf(stderr, "controller: --seconds %g is outside (0, 1e6]\n", seconds);
    return 2;
  }

  status = hc_runtime_open(argv[1], &model, err, sizeof err);
  if (status != HC_RUNTIME_OK) {
    fprintf(stderr, "controller: %s (%s)\n", err, hc_runtime_status_name(status));
    return 1;
  }
  if (!hc_runtime_has_vehicle(model)) {
    fprintf(stderr,
            "controller: %s holds no vehicle; export one with hydrocoef export BODY --format runtime "
            "--vehicle VEHICLE.json\n",
            argv[1]);
    hc_runtime_close(model);
    return 1;
  }
  /* The disturbances the damping reads, held at 0. */
  if (hc_runtime_vehicle_disturbance_count(model) > 0) {
    disturbances = calloc(hc_runtime_vehicle_disturbance_count(model), sizeof(double));
    if (disturbances == NULL) {
      fprintf(stderr, "controller: out of memory\n");
      hc_runtime_close(model);
      return 1;
    }
  }

  printf("t x_n y_n z_n q_eta q_eps1 q_eps2 q_eps3 u v w p q r psi tau_N\n");
  log_line(t, x, torque);
  logs = (long)floor(seconds * LOG_RATE_HZ * (1.0 + 1e-12));
  for (k = 1; k <= logs; ++k) {
    const double t_log = (double)k / LOG_RATE_HZ;
    const double h = (t_log - t) / STEPS_PER_LOG;
    int s;
    for (s = 0; s < STEPS_PER_LOG; ++s) {
      /* Read the state, control, step. */
      const double psi = yaw_of(x + 3);
      tau_b[5] = torque + kp * wrap(heading - psi) - kd * x[12];
      status = hc_runtime_vehicle_step_rk4(model, x, tau_b, current_n, disturbances, h, err, sizeof err);
      if (status != HC_RUNTIME_OK) {
        fprintf(stderr, "controller: step at t = %.17g s refused (%s): %s\n", t + s * h, hc_runtime_status_name(status),
                err);
        free(disturbances);
        hc_runtime_close(model);
        return 1;
      }
    }
    t = t_log;
    log_line(t, x, tau_b[5]);
  }
  free(disturbances);
  hc_runtime_close(model);
  return 0;
}
