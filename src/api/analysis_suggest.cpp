// suggest_runs (include/hydrocoef/analysis.hpp): `hydrocoef suggest` without
// its printing. The design is src/pipeline/next_runs; its numbers become the
// public Suggestion, printed as the CLI prints it (text and JSON below).
#include "src/api/internal.hpp"

#include <iomanip>
#include <sstream>

#include "hydrocoef/analysis.hpp"
#include "src/api/analysis_format.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/pipeline/next_runs.hpp"

namespace hydrocoef {
inline namespace api {

void SuggestOptions::validate() const {
  if (count == 0 || count > 1000) throw InputError("--count " + std::to_string(count) + ": expected 1 to 1000");
}

Suggestion suggest_runs(const Database& database, const SuggestOptions& options) {
  options.validate();
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  RunDatabase& store = impl.open_store();
  const StoredSurface stored = load_surface(store, options.surface);
  NextRunsRequest request;
  if (!options.output.empty()) request.output = options.output;
  request.bounds = options.bounds;
  request.round = options.round;
  request.count = options.count;
  request.candidates = options.candidates;
  request.mirror = surface_mirror(stored.record);
  request.imported = imported_keys(store, stored.record.body, stored.surface);
  for (const auto& file : options.running)
    for (auto& key : running_keys(file, stored.record.body, stored.surface)) request.running.push_back(std::move(key));
  const NextRuns next = suggest_next_runs(stored.surface, request);
  if (!options.manifest.empty()) write_next_runs_manifest(next, stored.record.body, options.manifest);

  Suggestion out;
  out.surface = options.surface;
  out.output = next.output;
  out.unit = next.unit;
  out.axes = next.axes;
  out.lower = next.lower;
  out.upper = next.upper;
  out.resolution = next.resolution;
  out.resolution_given = next.resolution_given;
  out.mirror = next.mirror;
  out.domain = next.domain;
  out.candidates = next.candidates;
  out.imported_skipped = next.imported_skipped;
  out.running_skipped = next.running_skipped;
  for (const auto& run : next.runs) out.runs.push_back({run.point, run.standard_deviation});
  out.largest_sd_after = next.largest_sd_after;
  out.manifest = options.manifest;
  return out;
}

std::string Suggestion::json() const {
  nlohmann::json out = {
      {"surface", surface}, {"output", output}, {"unit", unit}, {"largest_sd_after", largest_sd_after}};
  for (std::size_t a = 0; a < axes.size(); ++a) {
    out["bounds"][axes[a]] = {lower.at(a), upper.at(a)};
    out["resolution"][axes[a]] = resolution.at(a);
  }
  out["mirror"] = mirror;
  out["domain"] = domain;
  out["candidates"] = candidates;
  out["skipped"] = {{"imported", imported_skipped}, {"running", running_skipped}};
  out["runs"] = nlohmann::json::array();
  for (const auto& run : runs) {
    nlohmann::json entry = {{"sd_before", run.sd_before}};
    for (std::size_t a = 0; a < axes.size(); ++a) entry["key"][axes[a]] = run.key.at(a);
    out["runs"].push_back(entry);
  }
  if (!manifest.empty()) out["manifest"] = manifest;
  return escape::json_text(out, 2);
}

std::string Suggestion::text() const {
  using analysis_format::significant;
  std::ostringstream out;
  out << "next runs for surface " << escape::one_line(surface) << ": where the standard deviation of "
      << escape::one_line(output) << " is largest, each run counted before the next is chosen\n  bounds:";
  for (std::size_t a = 0; a < axes.size(); ++a)
    out << " " << escape::one_line(axes[a]) << "=" << significant(lower.at(a), 6) << ":" << significant(upper.at(a), 6);
  out << "\n  keys rounded to:";
  for (std::size_t a = 0; a < axes.size(); ++a)
    out << " " << escape::one_line(axes[a]) << "=" << shortest_number(resolution.at(a))
        << (a < resolution_given.size() && resolution_given[a] ? "" : " (default: 1/100 of the bounds, 1-2-5)");
  out << '\n';
  if (!mirror.empty())
    out << "  mirror " << escape::one_line(mirror) << ": "
        << (domain.empty() ? "changes none of the surface's axes"
                           : "keys with " + escape::one_line(domain) + ", each standing for its mirror image too")
        << '\n';
  out << "  " << candidates << " new keys searched";
  if (imported_skipped + running_skipped > 0)
    out << " (left out: " << imported_skipped << " where the body has a run, " << running_skipped << " running)";
  out << "\n  #   ";
  for (const auto& axis : axes) out << std::left << std::setw(14) << escape::one_line(axis);
  out << "sd of " << escape::one_line(output) << " there before [" << escape::one_line(unit) << "]\n";
  for (std::size_t i = 0; i < runs.size(); ++i) {
    out << "  " << std::left << std::setw(4) << i + 1;
    for (const double x : runs[i].key) out << std::setw(14) << shortest_number(x);
    out << significant(runs[i].sd_before, 4) << '\n';
  }
  out << "  largest sd in the bounds: " << (runs.empty() ? std::string("-") : significant(runs.front().sd_before, 4))
      << " now, " << significant(largest_sd_after, 4) << " " << escape::one_line(unit) << " with these runs\n";
  if (!manifest.empty())
    out << "  manifest " << escape::one_line(manifest)
        << " (fill in each case's path; hydrocoef import --manifest reads it)\n";
  return out.str();
}

}  // namespace api
}  // namespace hydrocoef
