// How a GP surface (GpSurfaces) is written into a SurfaceRecord and read
// back: its solved state, so that loading is linear in the stored size (no
// new factorisation, no hyperparameter search).
//
// Definition JSON member "gp" (beside the axes and outputs of every surface):
//   {"kernel": "matern52", "degree": 1, "samples": N,
//    "lower": [...], "upper": [...],                  (the runs' range per axis)
//    "outputs": [{"sigma": s, "value_centre": c, "value_scale": v,
//                 "log_likelihood": l, "axis_centre": [...], "axis_scale": [...],
//                 "length_scales": [...], "beta": [...], "nugget": tau, "sd_factor": f,
//                 "loo_rms_z": r, "loo_max_z": z}, ...]}   (one per output; the last four
//                 absent in surfaces stored before them: tau 0, f 1, r and z unknown)
// Data (float64), per output in turn: the scaled points (N x D, axis-major),
// alpha (N), the Cholesky factor L packed by rows (N (N + 1) / 2), (L^-1 H)^T
// (M x N) and the mean's Cholesky factor packed by rows (M (M + 1) / 2), with
// M the mean's terms (gp_surface.hpp). Every count is checked against the
// limits before it is used, every number for finiteness, every diagonal for
// positivity (GpSurface::from_state).
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <span>
#include <string>
#include <vector>

#include "src/surface/gp_surfaces.hpp"

namespace hydrocoef {

/// The "gp" member of the definition, and the data.
nlohmann::json gp_definition(const GpSurfaces& gp);
std::vector<double> gp_data(const GpSurfaces& gp);

/// The surface from its "gp" member and data, over the axes named (with their
/// out-of-range policies). `where` names the surface for messages; InputError
/// for anything missing, mis-sized or inconsistent.
GpSurfaces gp_from_stored(const nlohmann::json& gp_json, std::span<const double> data,
                          std::vector<std::string> axis_names, std::vector<RbfOutOfRange> policies, std::size_t outputs,
                          const std::string& where);

}  // namespace hydrocoef
