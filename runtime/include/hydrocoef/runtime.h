/* libhydrocoef_runtime: hydrocoef's coefficient surfaces inside a simulator
 * or a controller, without hydrocoef. C11 (callable from C99 and C++), libm
 * only: no C++ runtime, no SQLite, VTK or Eigen.
 *
 * A runtime file (written by `hydrocoef export NAME --format runtime`, by
 * hydrocoef::export_surface or by Python's hydrocoef.export_surface; the
 * format is docs/runtime.md) holds one body's gridded surfaces exactly as
 * hydrocoef evaluates them: breakpoints, method, extrapolation policies, the
 * node values and, for the cubic methods, the precomputed nodal and mixed
 * derivatives, and the standard deviation's tables where a surface states
 * one. hc_runtime_evaluate gives the numbers `hydrocoef query` gives, bit
 * for bit (the two libraries share their evaluation kernel).
 *
 * Units, frames and signs: SI throughout. Axis values in their axis's unit
 * (m/s for u, v, w; rad/s for p, q, r; rad for angles; a disturbance's SI
 * unit), outputs in their unit (N for X, Y, Z; N m for K, M, N; 1 for a
 * non-dimensional coefficient). Body axes x forward, y starboard, z down
 * (FRD); outputs are forces and moments of the fluid on the body (SNAME
 * "on-body" signs: damping is negative). Each axis's and output's name and
 * unit and the model's frame and sign convention are in the file
 * (hc_runtime_axis_unit, hc_runtime_metadata(model, "frame") ...).
 *
 * Errors: every function that can fail returns an hc_runtime_status; the
 * open functions also write a one-line message into err (at most errlen
 * bytes, NUL-terminated, truncated if need be; err may be NULL) naming what
 * was wrong and where (the byte offset and the section). A file is read
 * without trusting it: every size, count, offset, code, breakpoint, number
 * and the content hash are checked before use.
 *
 * Thread safety: a model is immutable once opened. Any number of threads may
 * query and evaluate one model at once; hc_runtime_close must not run
 * concurrently with other calls on the same model. Evaluation allocates
 * nothing and takes no lock.
 *
 * A file written with `--vehicle VEHICLE.json` also holds a vehicle: the
 * whole 6-DOF model of hydrocoef's dynamics (mass matrices, hydrostatics,
 * every DOF's damping: laws, derivative models or the file's surfaces), whose
 * derivative hc_runtime_vehicle_derivative computes with hydrocoef's own
 * arithmetic (the two libraries share it), so that a simulator's or a
 * controller's integration of it is `hydrocoef simulate`'s bit for bit.
 *
 * ABI: the exported symbols carry the version nodes HYDROCOEF_RUNTIME_1 (the
 * surfaces) and HYDROCOEF_RUNTIME_2 (the vehicle)
 * (runtime/hydrocoef_runtime.map); HC_RUNTIME_ABI_VERSION changes when a
 * declaration here changes; hc_runtime_abi_version() reports the library's. */
#ifndef HYDROCOEF_RUNTIME_H
#define HYDROCOEF_RUNTIME_H

#include <stddef.h>
#include <stdint.h>

#if defined(_WIN32)
#define HC_RUNTIME_API
#else
#define HC_RUNTIME_API __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* The ABI this header declares; compare with hc_runtime_abi_version(). */
#define HC_RUNTIME_ABI_VERSION 2
/* The newest runtime file format version this library reads: 1 (surfaces)
 * and 2 (surfaces and a vehicle). */
#define HC_RUNTIME_FILE_VERSION 2
/* Limits: axes per surface, outputs per surface, surfaces per file. */
#define HC_RUNTIME_MAX_AXES 6
#define HC_RUNTIME_MAX_OUTPUTS 4096
#define HC_RUNTIME_MAX_SURFACES 4096

typedef enum hc_runtime_status {
  HC_RUNTIME_OK = 0,
  HC_RUNTIME_E_ARGUMENT = 1,   /* a NULL pointer or an index out of range */
  HC_RUNTIME_E_IO = 2,         /* the file cannot be opened or read */
  HC_RUNTIME_E_FORMAT = 3,     /* not a runtime file, or malformed (the message says where) */
  HC_RUNTIME_E_VERSION = 4,    /* a format version this library does not read */
  HC_RUNTIME_E_HASH = 5,       /* the content hash does not match the content */
  HC_RUNTIME_E_MEMORY = 6,     /* out of memory while opening */
  HC_RUNTIME_E_OUTSIDE = 7,    /* a coordinate outside an axis whose policy is "error" */
  HC_RUNTIME_E_NOT_FINITE = 8, /* a coordinate is NaN or infinite */
  HC_RUNTIME_E_NO_SIGMA = 9,   /* sigma asked of a surface that states none */
  HC_RUNTIME_E_NOT_FOUND = 10, /* no surface of that name */
  HC_RUNTIME_E_NO_VEHICLE = 11 /* a vehicle function on a file that holds no vehicle */
} hc_runtime_status;

/* An opened runtime file (opaque). */
typedef struct hc_runtime_model hc_runtime_model;

/* HC_RUNTIME_ABI_VERSION of the library at run time. */
HC_RUNTIME_API int hc_runtime_abi_version(void);
/* The library's version text, e.g. "1.0.0". */
HC_RUNTIME_API const char* hc_runtime_version(void);
/* A status's name, e.g. "HC_RUNTIME_E_HASH"; "unknown status" otherwise. */
HC_RUNTIME_API const char* hc_runtime_status_name(int status);

/* Opens a runtime file: *model receives the model (NULL on failure). */
HC_RUNTIME_API int hc_runtime_open(const char* path, hc_runtime_model** model, char* err, size_t errlen);
/* As hc_runtime_open, from `size` bytes in memory (copied: the caller may
 * free them afterwards). */
HC_RUNTIME_API int hc_runtime_open_memory(const void* bytes, size_t size, hc_runtime_model** model, char* err,
                                          size_t errlen);
/* Frees a model (NULL is allowed). */
HC_RUNTIME_API void hc_runtime_close(hc_runtime_model* model);

/* The content hash stored in (and checked against) the file: XXH64, seed 0,
 * of every byte after the 64-byte header. */
HC_RUNTIME_API uint64_t hc_runtime_content_hash(const hc_runtime_model* model);
/* A model-level text by key ("database", "body", "created_at",
 * "hydrocoef_version", "frame", "units", "sign_convention", "surfaces");
 * NULL when the file has none. */
HC_RUNTIME_API const char* hc_runtime_metadata(const hc_runtime_model* model, const char* key);

HC_RUNTIME_API size_t hc_runtime_surface_count(const hc_runtime_model* model);
/* *index receives the position of the surface named `name`:
 * HC_RUNTIME_E_NOT_FOUND when there is none. */
HC_RUNTIME_API int hc_runtime_surface_index(const hc_runtime_model* model, const char* name, size_t* index);
/* Texts below are owned by the model; NULL for an index out of range. */
HC_RUNTIME_API const char* hc_runtime_surface_name(const hc_runtime_model* model, size_t surface);
/* "nearest", "linear", "pchip", "makima" or "natural-spline". */
HC_RUNTIME_API const char* hc_runtime_surface_method(const hc_runtime_model* model, size_t surface);
/* A surface's provenance text by key ("content_sha256", "runs",
 * "created_at", "stale", "source"); NULL when absent. */
HC_RUNTIME_API const char* hc_runtime_surface_metadata(const hc_runtime_model* model, size_t surface, const char* key);
/* 1 when the surface states a standard deviation (hc_runtime_evaluate's sigma), else 0. */
HC_RUNTIME_API int hc_runtime_surface_has_sigma(const hc_runtime_model* model, size_t surface);
/* Axis and output counts (0 for a surface index out of range). */
HC_RUNTIME_API size_t hc_runtime_axis_count(const hc_runtime_model* model, size_t surface);
HC_RUNTIME_API size_t hc_runtime_output_count(const hc_runtime_model* model, size_t surface);
HC_RUNTIME_API const char* hc_runtime_axis_name(const hc_runtime_model* model, size_t surface, size_t axis);
HC_RUNTIME_API const char* hc_runtime_axis_unit(const hc_runtime_model* model, size_t surface, size_t axis);
/* "error", "clamp", "linear" or "method" (see docs/runtime.md). */
HC_RUNTIME_API const char* hc_runtime_axis_extrapolation(const hc_runtime_model* model, size_t surface, size_t axis);
/* The axis's breakpoints: *count receives their number; the array is the model's. */
HC_RUNTIME_API const double* hc_runtime_axis_breakpoints(const hc_runtime_model* model, size_t surface, size_t axis,
                                                         size_t* count);
HC_RUNTIME_API const char* hc_runtime_output_name(const hc_runtime_model* model, size_t surface, size_t output);
HC_RUNTIME_API const char* hc_runtime_output_unit(const hc_runtime_model* model, size_t surface, size_t output);

/* Evaluates a surface at x (hc_runtime_axis_count coordinates, axis order):
 *   values[k]                 output k (hc_runtime_output_count entries);
 *   gradients[k * n_axes + a] d output_k / d axis_a, in output unit per axis
 *                             unit (NULL: not computed);
 *   sigma[k]                  the standard deviation of output k, as
 *                             `hydrocoef query` states it (NULL: not
 *                             computed; HC_RUNTIME_E_NO_SIGMA, nothing
 *                             written, for a surface that states none).
 * HC_RUNTIME_E_NOT_FINITE / HC_RUNTIME_E_OUTSIDE (nothing written) for a
 * coordinate that is not finite or outside an axis whose policy is "error";
 * hc_runtime_check_point names which. Allocation-free, thread-safe. */
HC_RUNTIME_API int hc_runtime_evaluate(const hc_runtime_model* model, size_t surface, const double* x, double* values,
                                       double* gradients, double* sigma);
/* What hc_runtime_evaluate would say of x: HC_RUNTIME_OK, or its error code
 * and a message in err naming the axis, the value and the valid range. */
HC_RUNTIME_API int hc_runtime_check_point(const hc_runtime_model* model, size_t surface, const double* x, char* err,
                                          size_t errlen);

/* ---- The vehicle (ABI 2; files written with --vehicle) ----
 *
 * The state x is 13 numbers: the position of the body origin CO in NED
 * (x_n, y_n, z_n [m]); the body-to-NED attitude quaternion, scalar first
 * (eta, eps1, eps2, eps3; any non-zero norm, the rotation of x/|x| is used);
 * the body velocity over ground (u, v, w [m/s], p, q, r [rad/s], body axes x
 * forward, y starboard, z down). The inputs, held over a step: tau_b (6) the
 * control force and moment on the body about CO [N, N m] (commanded, plus
 * thrusters: hc_runtime_vehicle_thrust_force); current_n (3) the water
 * velocity in NED [m/s] (NULL: none); disturbances the values of the
 * disturbance parameters the damping reads [SI], in
 * hc_runtime_vehicle_disturbance_name order (NULL when there are none).
 *
 * The equation (Fossen 2011, eq. 6.1 with current) is hydrocoef's
 * (docs/dynamics.md): M_RB nu' + C_RB(nu) nu + M_A nu_r' + C_A(nu_r) nu_r +
 * D(nu_r) nu_r + g(eta) = tau, nu_r = nu - nu_c; p_n' = R nu1; q' = 1/2 T(q)
 * nu2 + gain/2 (1 - |q|^2) q.
 *
 * Errors: HC_RUNTIME_E_NO_VEHICLE for a file without a vehicle,
 * HC_RUNTIME_E_ARGUMENT for a NULL pointer (x, tau_b, x_dot; disturbances
 * when the vehicle reads some), and a surface's refusal of a relative
 * velocity or disturbance outside an axis whose policy is "error"
 * (HC_RUNTIME_E_OUTSIDE) or not finite (HC_RUNTIME_E_NOT_FINITE), with
 * hydrocoef's own message in err (e.g. "axis 'r' = 0.5 is outside [-0.3,
 * 0.3]; expected a value in range (or an extrapolation policy)"); nothing
 * is written then. err may be NULL. Allocation-free and thread-safe on one
 * model. */

/* 1 when the file holds a vehicle, else 0. */
HC_RUNTIME_API int hc_runtime_has_vehicle(const hc_runtime_model* model);
/* The vehicle's text by key ("name", "file", and "state", "inputs",
 * "equation": the frames, units and signs above); NULL when absent. */
HC_RUNTIME_API const char* hc_runtime_vehicle_metadata(const hc_runtime_model* model, const char* key);
/* The disturbance parameters the damping reads, in the order the inputs give them. */
HC_RUNTIME_API size_t hc_runtime_vehicle_disturbance_count(const hc_runtime_model* model);
HC_RUNTIME_API const char* hc_runtime_vehicle_disturbance_name(const hc_runtime_model* model, size_t index);
/* Thrusters: count, name, limits [N]. */
HC_RUNTIME_API size_t hc_runtime_vehicle_thruster_count(const hc_runtime_model* model);
HC_RUNTIME_API const char* hc_runtime_vehicle_thruster_name(const hc_runtime_model* model, size_t thruster);
HC_RUNTIME_API int hc_runtime_vehicle_thruster_limits(const hc_runtime_model* model, size_t thruster, double* min_N,
                                                      double* max_N);
/* tau_b (6) = the generalized force of the thrusts thrust_N (one per
 * thruster [N], used as given: clamp them to the limits first, as
 * `hydrocoef simulate` does). */
HC_RUNTIME_API int hc_runtime_vehicle_thrust_force(const hc_runtime_model* model, const double* thrust_N,
                                                   double* tau_b);
/* x_dot (13) = x' at state x (13). */
HC_RUNTIME_API int hc_runtime_vehicle_derivative(const hc_runtime_model* model, const double* x, const double* tau_b,
                                                 const double* current_n, const double* disturbances, double* x_dot,
                                                 char* err, size_t errlen);
/* The terms of the equation at x, each a generalized force on the body [N,
 * N m], M nu' = control + damping + hydrostatic + coriolis: breakdown (30) =
 * control (6), damping -D(nu_r) nu_r (6), hydrostatic -g(eta) (6), coriolis
 * -C_RB(nu) nu - C_A(nu_r) nu_r + M_A nu_c' (6), then nu_r (6). */
HC_RUNTIME_API int hc_runtime_vehicle_forces(const hc_runtime_model* model, const double* x, const double* tau_b,
                                             const double* current_n, const double* disturbances, double* breakdown,
                                             char* err, size_t errlen);
/* One classical Runge-Kutta 4 step of size dt [s] from x (13), replaced by
 * the state at t + dt with its attitude normalised: `hydrocoef simulate`'s
 * RK4 step (src/dynamics/integrators.hpp), bit for bit. On an error x is
 * left as it was. */
HC_RUNTIME_API int hc_runtime_vehicle_step_rk4(const hc_runtime_model* model, double* x, const double* tau_b,
                                               const double* current_n, const double* disturbances, double dt,
                                               char* err, size_t errlen);

#ifdef __cplusplus
}
#endif

#endif
