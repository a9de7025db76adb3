// What the surface operations (src/api/surface_*.cpp) share: the reports of
// stored surfaces as `hydrocoef surface build | rebuild | list | show` print
// them (text and JSON), the search for a surface's largest standard
// deviation, and how the result types' rendered documents are set.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "src/api/internal.hpp"
#include "src/core/numbers.hpp"
#include "src/pipeline/surface_build.hpp"

#include "hydrocoef/exports.hpp"
#include "hydrocoef/surface.hpp"

namespace hydrocoef {
inline namespace api {

namespace surface_text {

using hydrocoef::significant;  // src/core/numbers.hpp: numbers as the CLI prints them

/// Per output, the `count` points of the surface's range where its standard
/// deviation is largest (Surface::largest_standard_deviations); empty when it
/// states none.
std::vector<std::vector<SigmaPeak>> largest_sd(const CoefficientSurface& surface, std::size_t count);

/// A stored surface's report: public fields, show's text and JSON (with
/// breakpoint values), and the JSON without them (list, build) in `brief_json`.
SurfaceReport report(const SurfaceRecord& record, const CoefficientSurface& surface, nlohmann::json* brief_json);

/// surface build's report of a build (the database's path in its last line).
SurfaceBuildReport build_report(const SurfaceBuildResult& result, const std::string& database);

/// surface list's report of the stored surfaces.
SurfaceList list_report(const std::vector<SurfaceRecord>& records, const std::string& database);

}  // namespace surface_text

struct SurfaceReport::Access {
  static void set(SurfaceReport& report, std::string text, std::string json) {
    report.text_ = std::move(text);
    report.json_ = std::move(json);
  }
};

struct SurfaceList::Access {
  static void set(SurfaceList& list, std::string text, std::string json) {
    list.text_ = std::move(text);
    list.json_ = std::move(json);
  }
};

struct SurfaceBuildReport::Access {
  static void set(SurfaceBuildReport& report, std::string text, std::string json) {
    report.text_ = std::move(text);
    report.json_ = std::move(json);
  }
};

struct SurfaceQueryResult::Access {
  static void set(SurfaceQueryResult& result, std::string text, std::string json, std::string note) {
    result.text_ = std::move(text);
    result.json_ = std::move(json);
    result.note_ = std::move(note);
  }
};

struct GazeboExportResult::Access {
  static void set(GazeboExportResult& result, std::string text, std::string json) {
    result.text_ = std::move(text);
    result.json_ = std::move(json);
  }
};

/// The Surface behind a stored surface (Database::surface's).
Surface make_surface(StoredSurface stored);

}  // namespace api
}  // namespace hydrocoef
