// How the CLI shows a stored surface (text and JSON).
#pragma once

#include <nlohmann/json.hpp>

#include "src/pipeline/surface_build.hpp"
#include "src/store/database.hpp"
#include "src/surface/coefficient_surface.hpp"
#include "src/surface/stored_surface.hpp"

namespace hydrocoef::cli {

/// "  leave-one-out ..." lines per output, and the resampled grid's points
/// far from data.
void print_quality(const SurfaceRecord& record, const CoefficientSurface& surface);
/// One line per axis: range, breakpoints, out-of-range policy.
void print_axes(const CoefficientSurface& surface);
/// The surface's description: record, axes, outputs, quality, worst runs,
/// far-from-data points, build specification; breakpoint values when asked.
nlohmann::json surface_json(const SurfaceRecord& record, const CoefficientSurface& surface, bool with_values);
/// surface list: a table of the stored surfaces (or JSON).
void print_surface_list(const std::vector<SurfaceRecord>& records, const std::string& database, bool json);
/// surface show: one surface in full (or JSON with breakpoints).
void print_surface(const StoredSurface& stored, bool json);
/// surface build and rebuild: what was built from which runs, and where it
/// was stored (text, or the JSON of surface_json with the run counts).
void print_surface_build(const SurfaceBuildResult& result, const std::string& database);
nlohmann::json surface_build_json(const SurfaceBuildResult& result);

}  // namespace hydrocoef::cli
