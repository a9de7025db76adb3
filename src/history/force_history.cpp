#include "src/history/force_history.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "src/core/error.hpp"
#include "src/core/numbers.hpp"

namespace hydrocoef {

std::string_view abscissa_name(HistoryAbscissa abscissa) {
  return abscissa == HistoryAbscissa::Time ? "time" : "iteration";
}

std::string_view abscissa_unit(HistoryAbscissa abscissa) { return abscissa == HistoryAbscissa::Time ? "s" : ""; }

std::string_view component_name(HistoryComponent component, ComponentNaming naming) {
  static constexpr std::array<std::string_view, kHistoryComponents> source{"Fx", "Fy", "Fz", "Mx", "My", "Mz"};
  static constexpr std::array<std::string_view, kHistoryComponents> body{"X", "Y", "Z", "K", "M", "N"};
  const auto index = static_cast<std::size_t>(component);
  return naming == ComponentNaming::BodyAxes ? body[index] : source[index];
}

std::string_view part_name(ForcePart part) {
  static constexpr std::array<std::string_view, kForceParts> names{"total", "pressure", "viscous", "porous"};
  return names[static_cast<std::size_t>(part)];
}

namespace {

bool is_force(HistoryComponent component) { return static_cast<std::size_t>(component) < 3; }

bool within_magnitudes(double value) {
  const double magnitude = std::abs(value);
  return magnitude == 0.0 || (magnitude >= kMinHistoryMagnitude && magnitude <= kMaxHistoryMagnitude);
}

std::string magnitudes_expected(std::string_view unit) {
  return "expected 0 or a magnitude from " + shortest_number(kMinHistoryMagnitude) + " to " +
         shortest_number(kMaxHistoryMagnitude) + (unit.empty() ? "" : " ") + std::string(unit) +
         " (the history's statistics would not be finite)";
}

}  // namespace

std::string sample_location(const ForceHistory& history, std::size_t sample, HistoryComponent component) {
  const auto& origins = is_force(component) ? history.force_origin : history.moment_origin;
  if (sample < origins.size() && origins[sample].file < history.files.size())
    return history.files[origins[sample].file].path.string() + ":" + std::to_string(origins[sample].line);
  return "sample " + std::to_string(sample + 1);
}

void check_force_history(const ForceHistory& history) {
  const std::size_t n = history.size();
  const auto fail = [](const std::string& what) { throw std::invalid_argument("force history: " + what); };
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(history.abscissa_values[i])) fail("abscissa value " + std::to_string(i) + " is not finite");
    if (i > 0 && !(history.abscissa_values[i] > history.abscissa_values[i - 1]))
      fail("abscissa not strictly increasing at sample " + std::to_string(i));
  }
  // Bad input rather than a broken invariant: the magnitudes of times and
  // values, checked here so that no importer can let one through.
  const HistoryComponent any_origin =
      history.force_origin.empty() && !history.moment_origin.empty() ? HistoryComponent::Mx : HistoryComponent::Fx;
  for (std::size_t i = 0; i < n; ++i)
    if (!within_magnitudes(history.abscissa_values[i]))
      throw InputError(sample_location(history, i, any_origin) + ": " + std::string(abscissa_name(history.abscissa)) +
                       " " + shortest_number(history.abscissa_values[i]) + "; " +
                       magnitudes_expected(abscissa_unit(history.abscissa)));
  bool any_force = false;
  bool any_moment = false;
  for (const ForcePart part : kAllForceParts)
    for (const HistoryComponent component : kAllHistoryComponents) {
      const auto& values = history.values(part, component);
      if (values.empty()) continue;
      if (values.size() != n)
        fail(std::string(part_name(part)) + " " + std::string(component_name(component)) + " has " +
             std::to_string(values.size()) + " values for " + std::to_string(n) + " samples");
      for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(values[i]))
          fail(std::string(part_name(part)) + " " + std::string(component_name(component)) +
               " holds a value that is not finite");
        if (!within_magnitudes(values[i]))
          throw InputError(sample_location(history, i, component) + ": " + std::string(part_name(part)) + " " +
                           std::string(component_name(component, history.frame.naming)) + " " +
                           shortest_number(values[i]) + "; " + magnitudes_expected(is_force(component) ? "N" : "N m"));
      }
      (is_force(component) ? any_force : any_moment) = true;
    }
  const auto check_origins = [&](const std::vector<SampleOrigin>& origins, bool present, const char* what) {
    if (origins.empty()) return;
    if (!present) fail(std::string(what) + " origins without " + what + " values");
    if (origins.size() != n) fail(std::string(what) + " origins for " + std::to_string(origins.size()) + " samples");
    for (const SampleOrigin& origin : origins)
      if (origin.file >= history.files.size())
        fail(std::string(what) + " origin names file " + std::to_string(origin.file));
  };
  check_origins(history.force_origin, any_force, "force");
  check_origins(history.moment_origin, any_moment, "moment");
}

ForceHistory rotated_to_global_axes(const ForceHistory& history) {
  if (!history.frame.axes_in_global) return history;
  const auto& axes = *history.frame.axes_in_global;  // rows: local axes in global coordinates
  ForceHistory out = history;
  const std::size_t n = history.size();
  for (const ForcePart part : kAllForceParts)
    for (std::size_t vector = 0; vector < 2; ++vector) {
      const std::size_t first = 3 * vector;
      std::array<std::vector<double>, 3> global;
      for (std::size_t g = 0; g < 3; ++g) {
        // Global component g takes a share of every local component k with
        // axes[k][g] != 0; it exists only when all of those do.
        std::size_t contributors = 0;
        std::size_t missing = 0;
        for (std::size_t k = 0; k < 3; ++k) {
          if (axes[k][g] == 0.0) continue;
          ++contributors;
          if (!history.has(part, static_cast<HistoryComponent>(first + k))) ++missing;
        }
        if (contributors == 0 || missing == contributors) continue;
        if (missing > 0)
          throw InputError(std::string("cannot turn the ") + std::string(part_name(part)) +
                           (vector == 0 ? " force" : " moment") +
                           " into global axes: a component it needs is missing from the source; expected all "
                           "components that the global " +
                           std::string(component_name(static_cast<HistoryComponent>(first + g))) + " depends on");
        global[g].assign(n, 0.0);
        for (std::size_t k = 0; k < 3; ++k) {
          const double weight = axes[k][g];
          if (weight == 0.0) continue;
          const auto& local = history.values(part, static_cast<HistoryComponent>(first + k));
          for (std::size_t i = 0; i < n; ++i) global[g][i] += weight * local[i];
        }
      }
      for (std::size_t g = 0; g < 3; ++g)
        out.values(part, static_cast<HistoryComponent>(first + g)) = std::move(global[g]);
    }
  out.frame.axes_in_global.reset();
  out.frame.description = "global axes (turned from: " + history.frame.description + ")";
  return out;
}

}  // namespace hydrocoef
