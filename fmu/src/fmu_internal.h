/* The machinery of hydrocoef's Co-Simulation FMUs (docs/fmu.md): one
 * instance type, the standard's state machine, the logger, the resource
 * file; and the model kinds that give an instance its variables and its
 * step. A model kind is chosen by the runtime file's model text "fmu_model"
 * (written by `hydrocoef export-fmu`): "surface" (fmu_surface.c) or
 * "vehicle" (fmu_vehicle.c), entries of fmu_kinds (fmu_kinds.c) with their
 * own bind and step functions, on the same instance, state machine and
 * logger. */
#ifndef HYDROCOEF_FMU_INTERNAL_H
#define HYDROCOEF_FMU_INTERNAL_H

#include <stddef.h>

#include "hydrocoef/fmi2_interface.h"
#include "hydrocoef/runtime.h"

/* The resource file inside the FMU, relative to fmuResourceLocation. */
#define FMU_RESOURCE_FILE "model.hcr"
/* The GUID of an FMU made of a runtime file: this prefix, then the file's
 * content hash (XXH64) as 16 lowercase hexadecimal digits. */
#define FMU_GUID_PREFIX "hcrt-xxh64-"
/* The longest resource path accepted (bytes, decoded). */
#define FMU_MAX_PATH 4096

/* The Co-Simulation states of the standard (section 4.2.4), as bits so
 * that a function states the set of states it is allowed in. */
enum {
  FMU_INSTANTIATED = 1u << 0,
  FMU_INITIALIZATION = 1u << 1,
  FMU_STEP_COMPLETE = 1u << 2,
  FMU_STEP_IN_PROGRESS = 1u << 3,
  FMU_STEP_FAILED = 1u << 4,
  FMU_STEP_CANCELED = 1u << 5,
  FMU_TERMINATED = 1u << 6,
  FMU_ERROR = 1u << 7,
  FMU_FATAL = 1u << 8
};

/* A Real variable's role (its causality in modelDescription.xml). */
enum { FMU_VAR_INPUT = 1, FMU_VAR_OUTPUT = 2, FMU_VAR_PARAMETER = 3 };

typedef struct fmu_instance fmu_instance;

/* A model kind: what its variables are and how a step computes them. */
typedef struct fmu_kind {
  const char* name; /* the runtime file's "fmu_model" text */
  /* Sets n_reals, the roles and start values (fmu_allocate_reals) from the
   * opened model; 0, or -1 with a message in err. */
  int (*bind)(fmu_instance* fmu, char* err, size_t errlen);
  /* The outputs at time `time + step` from the inputs (and the kind's state),
   * step >= 0 (0: the outputs at the current time, in initialisation);
   * 0, or -1 with a message in err (nothing written). */
  int (*step)(fmu_instance* fmu, double time, double step, char* err, size_t errlen);
  /* Frees what bind allocated beyond the reals (may be NULL). */
  void (*release)(fmu_instance* fmu);
} fmu_kind;

struct fmu_instance {
  unsigned state;
  char* name; /* instanceName, owned */
  fmi2CallbackLogger logger;
  fmi2ComponentEnvironment environment;
  int logging_on;
  hc_runtime_model* model;
  const fmu_kind* kind;
  /* The Real variables, by value reference 0 .. n_reals - 1. */
  size_t n_reals;
  double* reals;
  double* start;
  unsigned char* role;
  int outputs_current; /* the outputs are those of the present inputs */
  double time;         /* the current communication point */
  double start_time;
  /* The kind's own data. */
  size_t surface; /* surface: the surface's index in the model */
  size_t n_axes, n_outputs;
  int has_sigma;
  void* kind_data; /* a kind's further state (freed by release) */
};

/* The known kinds (fmu_kinds.c), NULL-terminated. */
extern const fmu_kind* const fmu_kinds[];
extern const fmu_kind fmu_surface_kind;
extern const fmu_kind fmu_vehicle_kind;

/* Allocates n reals, their start values and roles (zeroed); 0 or -1. */
int fmu_allocate_reals(fmu_instance* fmu, size_t n);
void* fmu_calloc(const fmu_instance* fmu, size_t count, size_t size);
void fmu_free(const fmu_instance* fmu, void* pointer);

/* Logs through the host's logger: printf-formatted text, '%' doubled before
 * the message reaches the logger (the logger's message is itself a format).
 * Errors and warnings are always logged; fmi2OK messages only when logging
 * is on. */
void fmu_log(const fmu_instance* fmu, fmi2Status status, const char* category, const char* format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* The file path of `file` in the resource directory given as a file URI
 * (file:///dir, file:/dir, file://localhost/dir; percent-encoded octets
 * decoded, %00 and malformed escapes refused): 0, or -1 with a message. */
int fmu_resource_path(const char* uri, const char* file, char* out, size_t outlen, char* err, size_t errlen);
/* The GUID of a runtime file's content hash, into out (at least 32 bytes). */
void fmu_guid_of(unsigned long long hash, char* out, size_t outlen);

#endif
