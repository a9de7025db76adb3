// JSON export of a gridded surface: everything needed to rebuild the same
// interpolant elsewhere (a GridTable built from "axes", "outputs", "values"
// and "method" evaluates exactly as the original).
//
//   {"format": "hydrocoef-grid-table", "format_version": 1,
//    "surface": NAME, "body": BODY,
//    "method": "pchip",                       (interpolation_name)
//    "axes": [{"name": "u", "unit": "m/s", "breakpoints": [...],
//              "valid_range": [lo, hi], "extrapolation": "clamp"}, ...],
//    "outputs": [{"name": "X", "unit": "N"}, ...],
//    "values": {"X": [...], ...},             (per output, one per node, axis 0 fastest)
//    "sigma": {"X": [...], ...},              (when the surface states a standard deviation:
//                                                per output, one per node, as "values")
//    "sigma_definition": "...",               (what sigma is, in words; with "sigma")
//    "layout": "...",                         (the index formula in words)
//    "sign_convention": "on-body", "frame": "...",
//    "fit_statistics": {...},                 (the stored leave-one-out figures, or null)
//    "provenance": {"surface", "body", "runs", "content_sha256", "created_at", "stale",
//                   "exported_by"}}
// Doubles are written in shortest round-trip form.
#pragma once

#include <string>

#include "src/export/export.hpp"

namespace hydrocoef {

std::string json_text(const GridTable& table, const ExportMetadata& metadata);

}  // namespace hydrocoef
