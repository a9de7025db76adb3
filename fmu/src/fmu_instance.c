/* The FMI 2.0 Co-Simulation functions of hydrocoef's FMUs
 * (fmu/include/hydrocoef/fmi2_interface.h; docs/fmu.md).
 *
 * Every function checks its instance and arguments before use: an instance
 * pointer that fmi2Instantiate did not return, or that was freed, gets
 * fmi2Error (no logger to tell: the pointer is not an instance) and is never
 * dereferenced (the live instances are kept in a list); NULL arrays with a
 * non-zero count, an unknown value reference or one of the wrong causality
 * get fmi2Error and a logger message. The calling sequence of the standard
 * (section 4.2.4) is enforced: a function called in a state where the
 * standard does not allow it returns fmi2Error and logs which function in
 * which state. An instance that returned fmi2Error is in the error state:
 * fmi2Reset, fmi2FreeInstance and the getters are all it accepts then. */
#include <math.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmu_internal.h"

#define FMU_ANY_BUT_START                                                                               \
  (FMU_INSTANTIATED | FMU_INITIALIZATION | FMU_STEP_COMPLETE | FMU_STEP_IN_PROGRESS | FMU_STEP_FAILED | \
   FMU_STEP_CANCELED | FMU_TERMINATED | FMU_ERROR)
#define FMU_GETTABLE \
  (FMU_INITIALIZATION | FMU_STEP_COMPLETE | FMU_STEP_FAILED | FMU_STEP_CANCELED | FMU_TERMINATED | FMU_ERROR)

/* ---- the live instances ------------------------------------------------- */

typedef struct fmu_live {
  fmu_instance* instance;
  struct fmu_live* next;
} fmu_live;

static pthread_mutex_t live_lock = PTHREAD_MUTEX_INITIALIZER;
static fmu_live* live_list = NULL;

static int live_add(fmu_instance* fmu) {
  fmu_live* entry = malloc(sizeof *entry);
  if (entry == NULL) return -1;
  entry->instance = fmu;
  pthread_mutex_lock(&live_lock);
  entry->next = live_list;
  live_list = entry;
  pthread_mutex_unlock(&live_lock);
  return 0;
}

static int live_has(const void* c) {
  int found = 0;
  pthread_mutex_lock(&live_lock);
  for (const fmu_live* entry = live_list; entry != NULL && !found; entry = entry->next) found = entry->instance == c;
  pthread_mutex_unlock(&live_lock);
  return found;
}

static int live_remove(const void* c) {
  int found = 0;
  pthread_mutex_lock(&live_lock);
  for (fmu_live** at = &live_list; *at != NULL; at = &(*at)->next) {
    if ((*at)->instance == c) {
      fmu_live* entry = *at;
      *at = entry->next;
      free(entry);
      found = 1;
      break;
    }
  }
  pthread_mutex_unlock(&live_lock);
  return found;
}

/* ---- memory and logging ------------------------------------------------- */

/* The FMU allocates with calloc and free (modelDescription.xml:
 * canNotUseMemoryManagementFunctions="true"), as the runtime library does. */
void* fmu_calloc(const fmu_instance* fmu, size_t count, size_t size) {
  (void)fmu;
  return calloc(count == 0 ? 1 : count, size);
}

void fmu_free(const fmu_instance* fmu, void* pointer) {
  (void)fmu;
  free(pointer);
}

int fmu_allocate_reals(fmu_instance* fmu, size_t n) {
  fmu->reals = fmu_calloc(fmu, n, sizeof(double));
  fmu->start = fmu_calloc(fmu, n, sizeof(double));
  fmu->role = fmu_calloc(fmu, n, 1);
  if (fmu->reals == NULL || fmu->start == NULL || fmu->role == NULL) return -1;
  memset(fmu->reals, 0, n * sizeof(double));
  memset(fmu->start, 0, n * sizeof(double));
  memset(fmu->role, 0, n);
  fmu->n_reals = n;
  return 0;
}

static void log_text(fmi2CallbackLogger logger, fmi2ComponentEnvironment environment, const char* instance,
                     fmi2Status status, const char* category, const char* text) {
  /* The logger's message is a printf format: every '%' of the text doubled. */
  char escaped[2048];
  size_t out = 0;
  for (const char* p = text; *p != '\0' && out + 3 < sizeof escaped; ++p) {
    if (*p == '%') escaped[out++] = '%';
    escaped[out++] = *p;
  }
  escaped[out] = '\0';
  logger(environment, instance != NULL ? instance : "", status, category, escaped);
}

void fmu_log(const fmu_instance* fmu, fmi2Status status, const char* category, const char* format, ...) {
  if (fmu == NULL || fmu->logger == NULL) return;
  if (status == fmi2OK && !fmu->logging_on) return;
  char text[1024];
  va_list arguments;
  va_start(arguments, format);
  vsnprintf(text, sizeof text, format, arguments);
  va_end(arguments);
  log_text(fmu->logger, fmu->environment, fmu->name, status, category, text);
}

static const char* state_name(unsigned state) {
  switch (state) {
    case FMU_INSTANTIATED: return "instantiated";
    case FMU_INITIALIZATION: return "initializationMode";
    case FMU_STEP_COMPLETE: return "stepComplete";
    case FMU_STEP_IN_PROGRESS: return "stepInProgress";
    case FMU_STEP_FAILED: return "stepFailed";
    case FMU_STEP_CANCELED: return "stepCanceled";
    case FMU_TERMINATED: return "terminated";
    case FMU_ERROR: return "error";
    case FMU_FATAL: return "fatal";
    default: return "unknown";
  }
}

static void state_list(unsigned states, char* out, size_t outlen) {
  size_t used = 0;
  out[0] = '\0';
  for (unsigned bit = 1; bit <= FMU_FATAL; bit <<= 1) {
    if ((states & bit) == 0) continue;
    const int n = snprintf(out + used, outlen - used, "%s%s", used ? ", " : "", state_name(bit));
    if (n < 0 || (size_t)n >= outlen - used) break;
    used += (size_t)n;
  }
}

/* An error: logged, the instance in the error state. */
static fmi2Status fail(fmu_instance* fmu, const char* format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
static fmi2Status fail(fmu_instance* fmu, const char* format, ...) {
  char text[1024];
  va_list arguments;
  va_start(arguments, format);
  vsnprintf(text, sizeof text, format, arguments);
  va_end(arguments);
  fmu_log(fmu, fmi2Error, "logStatusError", "%s", text);
  if (fmu->state != FMU_FATAL) fmu->state = FMU_ERROR;
  return fmi2Error;
}

/* The instance behind c, if c is one and `function` is allowed in its
 * state; NULL otherwise (logged when there is an instance). */
static fmu_instance* enter(fmi2Component c, const char* function, unsigned allowed) {
  if (c == NULL || !live_has(c)) return NULL;
  fmu_instance* fmu = c;
  if ((fmu->state & allowed) == 0) {
    char states[256];
    state_list(allowed, states, sizeof states);
    fail(fmu, "%s is not allowed in state %s; the standard allows it in: %s", function, state_name(fmu->state), states);
    return NULL;
  }
  fmu_log(fmu, fmi2OK, "logCalls", "%s", function);
  return fmu;
}

/* ---- inquiries ---------------------------------------------------------- */

const char* fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char* fmi2GetVersion(void) { return fmi2Version; }

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[]) {
  fmu_instance* fmu = enter(c, "fmi2SetDebugLogging", FMU_ANY_BUT_START);
  if (fmu == NULL) return fmi2Error;
  if (nCategories > 0 && categories == NULL)
    return fail(fmu, "fmi2SetDebugLogging: categories is NULL with nCategories = %zu", nCategories);
  for (size_t i = 0; i < nCategories; ++i) {
    const char* category = categories[i];
    if (category == NULL || (strcmp(category, "logStatusError") != 0 && strcmp(category, "logStatusWarning") != 0 &&
                             strcmp(category, "logCalls") != 0))
      return fail(fmu,
                  "fmi2SetDebugLogging: unknown category '%.100s'; expected logStatusError, logStatusWarning or "
                  "logCalls",
                  category == NULL ? "(NULL)" : category);
  }
  fmu->logging_on = loggingOn != fmi2False;
  return fmi2OK;
}

/* ---- creation and destruction ------------------------------------------- */

static void release(fmu_instance* fmu) {
  if (fmu->kind != NULL && fmu->kind->release != NULL) fmu->kind->release(fmu);
  hc_runtime_close(fmu->model);
  fmu_free(fmu, fmu->reals);
  fmu_free(fmu, fmu->start);
  fmu_free(fmu, fmu->role);
  fmu_free(fmu, fmu->name);
  fmu_free(fmu, fmu);
}

/* Opens the resource file and binds the model kind; 0 or -1 (logged). */
static int load(fmu_instance* fmu, fmi2String guid, fmi2String resources) {
  char path[FMU_MAX_PATH], err[1024];
  if (fmu_resource_path(resources, FMU_RESOURCE_FILE, path, sizeof path, err, sizeof err) != 0) {
    fmu_log(fmu, fmi2Error, "logStatusError", "fmi2Instantiate: %s", err);
    return -1;
  }
  const int status = hc_runtime_open(path, &fmu->model, err, sizeof err);
  if (status != HC_RUNTIME_OK) {
    fmu_log(fmu, fmi2Error, "logStatusError", "fmi2Instantiate: cannot load the FMU's model %s (%s): %s", path,
            hc_runtime_status_name(status), err);
    return -1;
  }
  char expected[64];
  fmu_guid_of((unsigned long long)hc_runtime_content_hash(fmu->model), expected, sizeof expected);
  if (strcmp(guid, expected) != 0) {
    fmu_log(fmu, fmi2Error, "logStatusError",
            "fmi2Instantiate: fmuGUID '%.100s' does not match the resource file %s, whose GUID is %s (the "
            "modelDescription.xml and the resources are of different exports)",
            guid, path, expected);
    return -1;
  }
  const char* kind = hc_runtime_metadata(fmu->model, "fmu_model");
  for (size_t i = 0; kind != NULL && fmu_kinds[i] != NULL; ++i)
    if (strcmp(fmu_kinds[i]->name, kind) == 0) fmu->kind = fmu_kinds[i];
  if (fmu->kind == NULL) {
    fmu_log(fmu, fmi2Error, "logStatusError",
            "fmi2Instantiate: the resource file %s states model kind '%.100s'; expected one this FMU binary runs "
            "(surface or vehicle)",
            path, kind == NULL ? "(none)" : kind);
    return -1;
  }
  if (fmu->kind->bind(fmu, err, sizeof err) != 0) {
    fmu_log(fmu, fmi2Error, "logStatusError", "fmi2Instantiate: %s", err);
    return -1;
  }
  memcpy(fmu->reals, fmu->start, fmu->n_reals * sizeof(double));
  return 0;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation, const fmi2CallbackFunctions* functions,
                              fmi2Boolean visible, fmi2Boolean loggingOn) {
  (void)visible;
  if (functions == NULL || functions->logger == NULL) return NULL; /* nobody to tell */
  fmu_instance scratch;
  memset(&scratch, 0, sizeof scratch);
  scratch.logger = functions->logger;
  scratch.environment = functions->componentEnvironment;
  scratch.name = (char*)(instanceName != NULL ? instanceName : "");
  if (instanceName == NULL || instanceName[0] == '\0') {
    fmu_log(&scratch, fmi2Error, "logStatusError", "fmi2Instantiate: instanceName is %s; expected a name",
            instanceName == NULL ? "NULL" : "empty");
    return NULL;
  }
  if (fmuType != fmi2CoSimulation) {
    fmu_log(&scratch, fmi2Error, "logStatusError",
            "fmi2Instantiate: fmuType %d is not fmi2CoSimulation; this FMU implements Co-Simulation only",
            (int)fmuType);
    return NULL;
  }
  if (fmuGUID == NULL) {
    fmu_log(&scratch, fmi2Error, "logStatusError",
            "fmi2Instantiate: fmuGUID is NULL; expected the GUID of "
            "modelDescription.xml");
    return NULL;
  }
  fmu_instance* fmu = fmu_calloc(&scratch, 1, sizeof *fmu);
  if (fmu == NULL) {
    fmu_log(&scratch, fmi2Error, "logStatusError", "fmi2Instantiate: out of memory");
    return NULL;
  }
  memcpy(fmu, &scratch, sizeof *fmu);
  fmu->name = NULL;
  const size_t name_length = strlen(instanceName);
  fmu->name = fmu_calloc(fmu, name_length + 1, 1);
  if (fmu->name == NULL) {
    fmu_log(&scratch, fmi2Error, "logStatusError", "fmi2Instantiate: out of memory");
    release(fmu);
    return NULL;
  }
  memcpy(fmu->name, instanceName, name_length + 1);
  fmu->logging_on = loggingOn != fmi2False;
  if (load(fmu, fmuGUID, fmuResourceLocation) != 0 || live_add(fmu) != 0) {
    release(fmu);
    return NULL;
  }
  fmu->state = FMU_INSTANTIATED;
  return fmu;
}

void fmi2FreeInstance(fmi2Component c) {
  fmu_instance* fmu = enter(c, "fmi2FreeInstance", FMU_ANY_BUT_START & ~FMU_STEP_IN_PROGRESS);
  if (fmu == NULL || !live_remove(fmu)) return;
  release(fmu);
}

/* ---- set-up, initialisation, termination -------------------------------- */

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance, fmi2Real startTime,
                               fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
  (void)toleranceDefined;
  (void)tolerance;
  fmu_instance* fmu = enter(c, "fmi2SetupExperiment", FMU_INSTANTIATED);
  if (fmu == NULL) return fmi2Error;
  if (!isfinite(startTime)) return fail(fmu, "fmi2SetupExperiment: startTime %g is not finite", startTime);
  if (stopTimeDefined && !(stopTime >= startTime))
    return fail(fmu, "fmi2SetupExperiment: stopTime %.17g is before startTime %.17g", stopTime, startTime);
  fmu->start_time = startTime;
  fmu->time = startTime;
  return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
  fmu_instance* fmu = enter(c, "fmi2EnterInitializationMode", FMU_INSTANTIATED);
  if (fmu == NULL) return fmi2Error;
  fmu->state = FMU_INITIALIZATION;
  fmu->outputs_current = 0;
  return fmi2OK;
}

/* The outputs of the present inputs, computed if the inputs changed. */
static fmi2Status update_outputs(fmu_instance* fmu, const char* function) {
  if (fmu->outputs_current) return fmi2OK;
  char err[1024];
  if (fmu->kind->step(fmu, fmu->time, 0.0, err, sizeof err) != 0) return fail(fmu, "%s: %s", function, err);
  fmu->outputs_current = 1;
  return fmi2OK;
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
  fmu_instance* fmu = enter(c, "fmi2ExitInitializationMode", FMU_INITIALIZATION);
  if (fmu == NULL) return fmi2Error;
  if (update_outputs(fmu, "fmi2ExitInitializationMode") != fmi2OK) return fmi2Error;
  fmu->state = FMU_STEP_COMPLETE;
  return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component c) {
  fmu_instance* fmu = enter(c, "fmi2Terminate", FMU_STEP_COMPLETE | FMU_STEP_FAILED | FMU_STEP_CANCELED);
  if (fmu == NULL) return fmi2Error;
  fmu->state = FMU_TERMINATED;
  return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component c) {
  fmu_instance* fmu = enter(c, "fmi2Reset", FMU_ANY_BUT_START & ~FMU_STEP_IN_PROGRESS);
  if (fmu == NULL) return fmi2Error;
  memcpy(fmu->reals, fmu->start, fmu->n_reals * sizeof(double));
  fmu->outputs_current = 0;
  fmu->time = fmu->start_time = 0.0;
  fmu->state = FMU_INSTANTIATED;
  return fmi2OK;
}

/* ---- values ------------------------------------------------------------- */

/* Checks vr / value arrays of a get or set; fmi2OK or fmi2Error (logged). */
static fmi2Status check_arrays(fmu_instance* fmu, const char* function, const fmi2ValueReference vr[], size_t nvr,
                               const void* value) {
  if (nvr > 0 && vr == NULL) return fail(fmu, "%s: vr is NULL with nvr = %zu", function, nvr);
  if (nvr > 0 && value == NULL) return fail(fmu, "%s: value is NULL with nvr = %zu", function, nvr);
  return fmi2OK;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[]) {
  fmu_instance* fmu = enter(c, "fmi2GetReal", FMU_GETTABLE);
  if (fmu == NULL || check_arrays(fmu, "fmi2GetReal", vr, nvr, value) != fmi2OK) return fmi2Error;
  for (size_t i = 0; i < nvr; ++i)
    if (vr[i] >= fmu->n_reals)
      return fail(fmu, "fmi2GetReal: unknown value reference %u (element %zu); this FMU's Reals are 0 to %zu", vr[i], i,
                  fmu->n_reals - 1);
  if (fmu->state == FMU_INITIALIZATION && update_outputs(fmu, "fmi2GetReal") != fmi2OK) return fmi2Error;
  for (size_t i = 0; i < nvr; ++i) value[i] = fmu->reals[vr[i]];
  return fmi2OK;
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[]) {
  fmu_instance* fmu = enter(c, "fmi2SetReal", FMU_INSTANTIATED | FMU_INITIALIZATION | FMU_STEP_COMPLETE);
  if (fmu == NULL || check_arrays(fmu, "fmi2SetReal", vr, nvr, value) != fmi2OK) return fmi2Error;
  for (size_t i = 0; i < nvr; ++i) {
    if (vr[i] >= fmu->n_reals)
      return fail(fmu, "fmi2SetReal: unknown value reference %u (element %zu); this FMU's Reals are 0 to %zu", vr[i], i,
                  fmu->n_reals - 1);
    if (fmu->role[vr[i]] == FMU_VAR_OUTPUT)
      return fail(fmu, "fmi2SetReal: value reference %u is an output; only inputs and parameters can be set", vr[i]);
    if (fmu->role[vr[i]] == FMU_VAR_PARAMETER && fmu->state == FMU_STEP_COMPLETE)
      return fail(fmu, "fmi2SetReal: value reference %u is a fixed parameter; it is set before initialisation ends",
                  vr[i]);
  }
  for (size_t i = 0; i < nvr; ++i) fmu->reals[vr[i]] = value[i];
  if (nvr > 0) fmu->outputs_current = 0;
  return fmi2OK;
}

/* The types this FMU has no variables of: any value reference is unknown. */
static fmi2Status no_variables(fmi2Component c, const char* function, unsigned allowed, const fmi2ValueReference vr[],
                               size_t nvr, const void* value) {
  fmu_instance* fmu = enter(c, function, allowed);
  if (fmu == NULL || check_arrays(fmu, function, vr, nvr, value) != fmi2OK) return fmi2Error;
  if (nvr > 0) return fail(fmu, "%s: unknown value reference %u; this FMU has Real variables only", function, vr[0]);
  return fmi2OK;
}

#define FMU_SETTABLE (FMU_INSTANTIATED | FMU_INITIALIZATION | FMU_STEP_COMPLETE)
fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Integer value[]) {
  return no_variables(c, "fmi2GetInteger", FMU_GETTABLE, vr, nvr, value);
}
fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Boolean value[]) {
  return no_variables(c, "fmi2GetBoolean", FMU_GETTABLE, vr, nvr, value);
}
fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2String value[]) {
  return no_variables(c, "fmi2GetString", FMU_GETTABLE, vr, nvr, value);
}
fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Integer value[]) {
  return no_variables(c, "fmi2SetInteger", FMU_SETTABLE, vr, nvr, value);
}
fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Boolean value[]) {
  return no_variables(c, "fmi2SetBoolean", FMU_SETTABLE, vr, nvr, value);
}
fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2String value[]) {
  return no_variables(c, "fmi2SetString", FMU_SETTABLE, vr, nvr, value);
}

/* ---- capabilities this FMU does not have (modelDescription.xml says so) -- */

static fmi2Status not_provided(fmi2Component c, const char* function, unsigned allowed, const char* capability) {
  fmu_instance* fmu = enter(c, function, allowed);
  if (fmu == NULL) return fmi2Error;
  return fail(fmu, "%s: not provided (modelDescription.xml: %s=\"false\")", function, capability);
}

#define FMU_STATE_STATES (FMU_ANY_BUT_START & ~FMU_STEP_IN_PROGRESS)
fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate* FMUstate) {
  (void)FMUstate;
  return not_provided(c, "fmi2GetFMUstate", FMU_STATE_STATES, "canGetAndSetFMUstate");
}
fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate) {
  (void)FMUstate;
  return not_provided(c, "fmi2SetFMUstate", FMU_STATE_STATES, "canGetAndSetFMUstate");
}
fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate* FMUstate) {
  (void)FMUstate;
  return not_provided(c, "fmi2FreeFMUstate", FMU_STATE_STATES, "canGetAndSetFMUstate");
}
fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t* size) {
  (void)FMUstate;
  (void)size;
  return not_provided(c, "fmi2SerializedFMUstateSize", FMU_STATE_STATES, "canSerializeFMUstate");
}
fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate, fmi2Byte serializedState[], size_t size) {
  (void)FMUstate;
  (void)serializedState;
  (void)size;
  return not_provided(c, "fmi2SerializeFMUstate", FMU_STATE_STATES, "canSerializeFMUstate");
}
fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[], size_t size,
                                   fmi2FMUstate* FMUstate) {
  (void)serializedState;
  (void)size;
  (void)FMUstate;
  return not_provided(c, "fmi2DeSerializeFMUstate", FMU_STATE_STATES, "canSerializeFMUstate");
}
fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference vUnknown_ref[], size_t nUnknown,
                                        const fmi2ValueReference vKnown_ref[], size_t nKnown, const fmi2Real dvKnown[],
                                        fmi2Real dvUnknown[]) {
  (void)vUnknown_ref;
  (void)nUnknown;
  (void)vKnown_ref;
  (void)nKnown;
  (void)dvKnown;
  (void)dvUnknown;
  return not_provided(c, "fmi2GetDirectionalDerivative", FMU_GETTABLE, "providesDirectionalDerivative");
}
fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[]) {
  (void)vr;
  (void)nvr;
  (void)order;
  (void)value;
  return not_provided(c, "fmi2SetRealInputDerivatives", FMU_SETTABLE, "canInterpolateInputs");
}
fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                        const fmi2Integer order[], fmi2Real value[]) {
  (void)vr;
  (void)nvr;
  (void)order;
  (void)value;
  return not_provided(c, "fmi2GetRealOutputDerivatives",
                      FMU_STEP_COMPLETE | FMU_STEP_FAILED | FMU_STEP_CANCELED | FMU_TERMINATED | FMU_ERROR,
                      "maxOutputDerivativeOrder > 0");
}

/* ---- computation -------------------------------------------------------- */

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint, fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
  (void)noSetFMUStatePriorToCurrentPoint;
  fmu_instance* fmu = enter(c, "fmi2DoStep", FMU_STEP_COMPLETE);
  if (fmu == NULL) return fmi2Error;
  if (!isfinite(currentCommunicationPoint) || !isfinite(communicationStepSize) || !(communicationStepSize > 0.0))
    return fail(fmu, "fmi2DoStep: communication point %.17g, step %.17g; expected finite values and a step above 0",
                currentCommunicationPoint, communicationStepSize);
  const double slack = 1e-9 * fmax(1.0, fabs(fmu->time));
  if (fabs(currentCommunicationPoint - fmu->time) > slack)
    return fail(fmu,
                "fmi2DoStep: currentCommunicationPoint %.17g is not the instance's time %.17g (the end of the "
                "last step)",
                currentCommunicationPoint, fmu->time);
  char err[1024];
  if (fmu->kind->step(fmu, currentCommunicationPoint, communicationStepSize, err, sizeof err) != 0)
    return fail(fmu, "fmi2DoStep at t = %.17g: %s", currentCommunicationPoint, err);
  fmu->outputs_current = 1;
  fmu->time = currentCommunicationPoint + communicationStepSize;
  return fmi2OK;
}

fmi2Status fmi2CancelStep(fmi2Component c) {
  /* Steps are synchronous (never fmi2Pending): there is never a step to cancel. */
  fmu_instance* fmu = enter(c, "fmi2CancelStep", FMU_STEP_IN_PROGRESS);
  return fmu == NULL ? fmi2Error : fmi2OK;
}

#define FMU_STATUS_STATES \
  (FMU_STEP_COMPLETE | FMU_STEP_IN_PROGRESS | FMU_STEP_FAILED | FMU_STEP_CANCELED | FMU_TERMINATED)
static fmi2Status status_pointer(fmu_instance* fmu, const char* function, const void* value) {
  if (value == NULL) return fail(fmu, "%s: value is NULL", function);
  return fmi2OK;
}
static fmi2Status no_such_status(fmu_instance* fmu, const char* function, fmi2StatusKind s) {
  fmu_log(fmu, fmi2Warning, "logStatusWarning", "%s: status kind %d is not given by this FMU (steps are synchronous)",
          function, (int)s);
  return fmi2Discard;
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status* value) {
  fmu_instance* fmu = enter(c, "fmi2GetStatus", FMU_STATUS_STATES);
  if (fmu == NULL || status_pointer(fmu, "fmi2GetStatus", value) != fmi2OK) return fmi2Error;
  return no_such_status(fmu, "fmi2GetStatus", s);
}
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real* value) {
  fmu_instance* fmu = enter(c, "fmi2GetRealStatus", FMU_STATUS_STATES);
  if (fmu == NULL || status_pointer(fmu, "fmi2GetRealStatus", value) != fmi2OK) return fmi2Error;
  if (s != fmi2LastSuccessfulTime) return no_such_status(fmu, "fmi2GetRealStatus", s);
  *value = fmu->time;
  return fmi2OK;
}
fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer* value) {
  fmu_instance* fmu = enter(c, "fmi2GetIntegerStatus", FMU_STATUS_STATES);
  if (fmu == NULL || status_pointer(fmu, "fmi2GetIntegerStatus", value) != fmi2OK) return fmi2Error;
  return no_such_status(fmu, "fmi2GetIntegerStatus", s);
}
fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean* value) {
  fmu_instance* fmu = enter(c, "fmi2GetBooleanStatus", FMU_STATUS_STATES);
  if (fmu == NULL || status_pointer(fmu, "fmi2GetBooleanStatus", value) != fmi2OK) return fmi2Error;
  if (s != fmi2Terminated) return no_such_status(fmu, "fmi2GetBooleanStatus", s);
  *value = fmi2False; /* the FMU never asks to end the simulation */
  return fmi2OK;
}
fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String* value) {
  fmu_instance* fmu = enter(c, "fmi2GetStringStatus", FMU_STATUS_STATES);
  if (fmu == NULL || status_pointer(fmu, "fmi2GetStringStatus", value) != fmi2OK) return fmi2Error;
  return no_such_status(fmu, "fmi2GetStringStatus", s);
}
