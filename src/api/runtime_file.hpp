// The runtime file of stored surfaces (docs/runtime.md), for the exports
// that write one: `export --format runtime` (export_table.cpp) and the FMUs'
// resources/model.hcr (fmu.cpp).
#pragma once

#include <string>
#include <vector>

#include "hydrocoef/database.hpp"
#include "src/export/runtime_export.hpp"
#include "src/surface/stored_surface.hpp"

namespace hydrocoef {
inline namespace api {

/// The bytes of the runtime file holding the stored surfaces `names` (in
/// order; all of one body, InputError otherwise), with the model texts
/// `extra` after the standard ones; `stored` receives the surfaces loaded.
/// With a `vehicle`, the file holds it too (runtime file version 2), the
/// file's body is `vehicle_body` and every surface must be that body's (a
/// vehicle may read none).
std::string runtime_file_of(const Database& db, const std::vector<std::string>& names, const RuntimeTexts& extra,
                            std::vector<StoredSurface>& stored, const RuntimeVehicle* vehicle = nullptr,
                            const std::string& vehicle_body = {});

}  // namespace api
}  // namespace hydrocoef
