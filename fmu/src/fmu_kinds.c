/* The model kinds an FMU binary knows, chosen by the runtime file's
 * "fmu_model" text (docs/fmu.md). */
#include "fmu_internal.h"

const fmu_kind* const fmu_kinds[] = {&fmu_surface_kind, &fmu_vehicle_kind, NULL};
