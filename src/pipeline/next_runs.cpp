#include "src/pipeline/next_runs.hpp"

#include <algorithm>
#include <cstdio>

#include "src/core/atomic_file.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/core/text.hpp"

namespace hydrocoef {

NextRuns suggest_next_runs(const CoefficientSurface& surface, const NextRunsRequest& request) {
  const GpSurfaces* gp = surface.gp();
  if (!gp)
    throw InputError("suggest: the surface (method '" + surface.method_name() +
                     "') states no uncertainty to reduce; expected a GP surface (surface build --method gp)");
  if (request.count == 0 || request.count > 1000)
    throw InputError("--count " + std::to_string(request.count) + ": expected 1 to 1000");
  NextRuns next;
  const std::size_t k = request.output ? surface.output_index(*request.output) : 0;
  next.output = surface.output_names()[k];
  next.unit = surface.output_units()[k];
  next.axes = surface.axis_names();
  for (std::size_t a = 0; a < surface.axis_count(); ++a) {
    next.lower.push_back(surface.lower(a));
    next.upper.push_back(surface.upper(a));
  }
  std::vector<bool> bounded(surface.axis_count(), false);
  for (const std::string& entry : request.bounds) {
    const auto equals = entry.find('=');
    const auto colon = entry.find(':', equals == std::string::npos ? 0 : equals);
    const auto malformed = [&] {
      return InputError("--bounds '" + escape::one_line(entry) + "': expected AXIS=FROM:TO, e.g. u=0:0.4");
    };
    if (equals == std::string::npos || colon == std::string::npos) throw malformed();
    const std::size_t a = surface.axis_index(std::string(trim(std::string_view(entry).substr(0, equals))));
    const auto from = parse_finite_number(trim(std::string_view(entry).substr(equals + 1, colon - equals - 1)));
    const auto to = parse_finite_number(trim(std::string_view(entry).substr(colon + 1)));
    if (!from || !to) throw malformed();
    if (!(*to > *from)) throw InputError("--bounds '" + escape::one_line(entry) + "': expected FROM < TO");
    if (bounded[a]) throw InputError("--bounds gives axis '" + next.axes[a] + "' twice");
    bounded[a] = true;
    next.lower[a] = *from;
    next.upper[a] = *to;
  }
  next.runs = suggest_runs(gp->output(k), next.lower, next.upper, request.count,
                           std::max(request.candidates, request.count), &next.largest_sd_after);
  return next;
}

void write_next_runs_manifest(const NextRuns& next, const std::string& body, const std::filesystem::path& file) {
  std::string text = "path,body";
  for (const auto& axis : next.axes) text += "," + escape::csv_field(axis);
  text += '\n';
  for (std::size_t i = 0; i < next.runs.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "next-%02zu", i + 1);
    text += std::string(name) + "," + escape::csv_field(body);
    for (const double x : next.runs[i].point) {
      text += ',';
      append_shortest_number(text, x);
    }
    text += '\n';
  }
  AtomicFile out(file);
  out.write(text);
  out.commit();
}

}  // namespace hydrocoef
