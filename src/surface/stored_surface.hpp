// Coefficient surfaces to and from the run database: the store keeps a
// surface as plain data (SurfaceRecord: a JSON definition and a blob of
// doubles); this file is the only place that knows how a GridTable or an
// RbfSurface is written into one and read back (a GP surface's part:
// src/surface/stored_gp_surface.hpp).
//
// Definition JSON (SurfaceRecord::definition):
//   {"axes": [{"name": "u", "unit": "m/s", "breakpoints": [...],     (grid only)
//              "extrapolation": "error"}, ...],                      (grid: extrapolation_name;
//                                                                      rbf: "error"|"clamp"|"extrapolate")
//    "outputs": [{"name": "X", "unit": "N"}, ...],
//    "sign": "on-body",
//    "rbf": {"kernel": "cubic", "degree": 1, "smoothing": 0,           (rbf only)
//            "length_scales": [...], "samples": N}}
// Data (SurfaceRecord::data): grid: the table's values in GridTable's layout;
// rbf: the N sample points (sample-major, axis_count each) followed by their
// values (sample-major, output_count each), and the solved weights.
//
// A grid or RBF surface that states an uncertainty
// (CoefficientSurface::with_run_uncertainty) has in its definition
//    "uncertainty": {"formula": "runs-interpolated+loo",
//                    "loo_sd": [...],                (per output)
//                    "run_sd": [...],                (the runs' standard uncertainty: grid,
//                                                     per node as the data; rbf, per sample)
//                    "kernel_weights": [...], "polynomial_weights": [...]}  (rbf: the solved
//                                                     RBF of run_sd, as the data's)
// A surface stored without it (by an older hydrocoef) states none.
#pragma once

#include <string>

#include "src/store/database.hpp"
#include "src/surface/coefficient_surface.hpp"

namespace hydrocoef {

/// "cubic", "thin-plate", "linear"; and back (InputError listing the names).
std::string_view rbf_kernel_name(RbfKernel kernel);
RbfKernel parse_rbf_kernel(std::string_view text);

/// The definition and data of a surface (kind, method, definition, data of the
/// record); the caller fills name, body, quality and run_ids. An RBF surface
/// needs its samples, which the RbfSurface does not keep: pass them as
/// RbfSurface's constructor took them (and, when it states an uncertainty,
/// its runs' standard uncertainties as the values: BuiltSurface::rbf_sigma).
SurfaceRecord record_from_surface(const CoefficientSurface& surface);
SurfaceRecord record_from_surface(const CoefficientSurface& surface, std::span<const double> rbf_points,
                                  std::span<const double> rbf_values, std::span<const double> rbf_sigma = {});

/// The surface a record describes. InputError naming the surface when the
/// definition is malformed or disagrees with the data.
CoefficientSurface surface_from_record(const SurfaceRecord& record);

/// A surface from the database with its record (provenance, quality, stale flag).
struct StoredSurface {
  SurfaceRecord record;
  CoefficientSurface surface;
};
/// Loads one surface by name; InputError listing the stored names when absent.
StoredSurface load_surface(RunDatabase& database, const std::string& name);

}  // namespace hydrocoef
