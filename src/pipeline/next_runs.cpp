#include "src/pipeline/next_runs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <variant>

#include "src/core/atomic_file.hpp"
#include "src/core/body_symmetry.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/core/text.hpp"
#include "src/pipeline/surface_build.hpp"
#include "src/pipeline/sweep_keys.hpp"

namespace hydrocoef {
namespace {

using LatticeKey = std::vector<std::int64_t>;

/// The largest of 1, 2 or 5 times a power of ten that is at most x (> 0).
double step_125_at_most(double x) {
  double power = std::pow(10.0, std::floor(std::log10(x)));
  // log10 may land one decade off near a power of ten.
  if (power > x) power /= 10.0;
  if (power * 10.0 <= x) power *= 10.0;
  for (const double m : {5.0, 2.0}) {
    if (m * power <= x) return m * power;
  }
  return power;
}

/// Multiples of one axis's resolution as the decimals they are: a step that
/// is m / 10^p for integers m and p (0.005 = 5 / 10^3) gives k m / 10^p, the
/// double nearest the decimal, which prints as that decimal; any other step
/// gives k * step.
struct AxisLattice {
  double step = 0.0;
  double mantissa = 0.0;  // m, or 0 when the step is no such decimal
  double scale = 1.0;     // 10^p

  explicit AxisLattice(double resolution) : step(resolution) {
    for (int p = 0; p <= 20; ++p) {
      const double s = std::pow(10.0, p);
      const double m = std::round(resolution * s);
      if (m >= 1.0 && m < 1e6 && std::abs(resolution * s - m) <= 1e-9 * m) {
        mantissa = m;
        scale = s;
        return;
      }
    }
  }
  double value(std::int64_t k) const {
    if (mantissa == 0.0) return static_cast<double>(k) * step;
    const double v = static_cast<double>(k) * mantissa / scale;
    return v == 0.0 ? 0.0 : v;  // never -0
  }
  /// The nearest multiple's index (the value is within 1e15 steps: checked by the caller).
  std::int64_t nearest(double x) const { return static_cast<std::int64_t>(std::llround(x / step)); }
};

/// The sign of each surface axis under each reflection of the mirror (and
/// their compositions), reflections that change no axis left out, and the
/// order in which the fundamental domain compares the axes: the planes' own
/// velocity components first.
struct KeySymmetry {
  std::vector<std::vector<double>> reflections;
  std::vector<std::size_t> order;
  std::string domain;

  KeySymmetry(const MirrorSpec& mirror, const std::vector<std::string>& axes) {
    const std::size_t d = axes.size();
    std::set<std::vector<double>> seen;
    for (const auto& chain : mirror.images()) {
      std::vector<double> signs(d, 1.0);
      for (const BodyMirror& reflection : chain)
        for (std::size_t a = 0; a < d; ++a) {
          if (const auto v = velocity_index(axes[a]))
            signs[a] *= reflection.signs()[*v];
          else if (reflection.odd_disturbances.count(axes[a]))
            signs[a] = -signs[a];
        }
      if (std::all_of(signs.begin(), signs.end(), [](double s) { return s > 0.0; })) continue;
      if (seen.insert(signs).second) reflections.push_back(signs);
    }
    for (const auto& plane : mirror.planes)
      for (std::size_t a = 0; a < d; ++a)
        if (axes[a] == plane) order.push_back(a);
    for (std::size_t a = 0; a < d; ++a)
      if (std::find(order.begin(), order.end(), a) == order.end()) order.push_back(a);
    // In words: per reflection, the first axis (in that order) it reverses is >= 0.
    std::set<std::size_t> named;
    for (const auto& signs : reflections)
      for (const std::size_t a : order)
        if (signs[a] < 0.0) {
          if (named.insert(a).second) domain += (domain.empty() ? "" : ", ") + axes[a] + " >= 0";
          break;
        }
  }

  /// The representative of a key's images: the largest in `order`.
  LatticeKey canonical(const LatticeKey& key) const {
    LatticeKey best = key;
    LatticeKey image(key.size());
    for (const auto& signs : reflections) {
      for (std::size_t a = 0; a < key.size(); ++a) image[a] = signs[a] < 0.0 ? -key[a] : key[a];
      for (const std::size_t a : order) {
        if (image[a] == best[a]) continue;
        if (image[a] > best[a]) best = image;
        break;
      }
    }
    return best;
  }
};

std::vector<double> parse_axis_entries(const CoefficientSurface& surface, const std::vector<std::string>& entries,
                                       const std::string& option, std::vector<bool>& given) {
  std::vector<double> out(surface.axis_count(), 0.0);
  given.assign(surface.axis_count(), false);
  for (const std::string& entry : entries) {
    const auto equals = entry.find('=');
    const auto malformed = [&] {
      return InputError(option + " '" + escape::one_line(entry) + "': expected AXIS=STEP with STEP > 0, e.g. u=0.01");
    };
    if (equals == std::string::npos) throw malformed();
    const std::size_t a = surface.axis_index(std::string(trim(std::string_view(entry).substr(0, equals))));
    const auto step = parse_finite_number(trim(std::string_view(entry).substr(equals + 1)));
    if (!step || !(*step > 0.0)) throw malformed();
    if (given[a]) throw InputError(option + " gives axis '" + surface.axis_names()[a] + "' twice");
    given[a] = true;
    out[a] = *step;
  }
  return out;
}

}  // namespace

NextRuns suggest_next_runs(const CoefficientSurface& surface, const NextRunsRequest& request) {
  const GpSurfaces* gp = surface.gp();
  if (!gp)
    throw InputError("suggest: the surface (method '" + surface.method_name() +
                     "') states no uncertainty to reduce; expected a GP surface (surface build --method gp)");
  if (request.count == 0 || request.count > 1000)
    throw InputError("--count " + std::to_string(request.count) + ": expected 1 to 1000");
  NextRuns next;
  const std::size_t k = request.output ? surface.output_index(*request.output) : 0;
  const std::size_t d = surface.axis_count();
  next.output = surface.output_names()[k];
  next.unit = surface.output_units()[k];
  next.axes = surface.axis_names();
  for (std::size_t a = 0; a < d; ++a) {
    next.lower.push_back(surface.lower(a));
    next.upper.push_back(surface.upper(a));
  }
  std::vector<bool> bounded(d, false);
  std::vector<std::string> bound_text(d);
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
    bound_text[a] = "--bounds '" + escape::one_line(entry) + "'";
    next.lower[a] = *from;
    next.upper[a] = *to;
  }

  // Resolutions, and bounds that can hold distinct keys at them.
  next.resolution = parse_axis_entries(surface, request.round, "--round", next.resolution_given);
  std::vector<AxisLattice> lattice;
  std::vector<std::int64_t> first(d), last(d);
  for (std::size_t a = 0; a < d; ++a) {
    const std::string bounds = bound_text[a].empty()
                                   ? "the surface's range of " + next.axes[a] + " (" + shortest_number(next.lower[a]) +
                                         " to " + shortest_number(next.upper[a]) + ")"
                                   : bound_text[a];
    const double width = next.upper[a] - next.lower[a];
    const double magnitude = std::max(std::abs(next.lower[a]), std::abs(next.upper[a]));
    if (!std::isfinite(width))
      throw InputError(bounds + ": its width is not a finite number; expected finite bounds of a key's range");
    if (!next.resolution_given[a]) {
      if (!(width >= 1e-9 * magnitude) || !std::isnormal(width / 100.0))
        throw InputError(bounds + " is " + shortest_number(width) +
                         " wide; expected a range wider than the round-off of its values");
      next.resolution[a] = step_125_at_most(width / 100.0);
    }
    const double step = next.resolution[a];
    if (!(step < width))
      throw InputError(bounds + " is " + shortest_number(width) + " wide, not wider than the resolution " +
                       shortest_number(step) + " of " + next.axes[a] + "; expected wider bounds or a finer --round");
    if (!(magnitude / step <= 1e12))
      throw InputError("the resolution " + shortest_number(step) + " of " + next.axes[a] + " is too fine for " +
                       bounds + "; expected at most 1e12 steps to the bounds' largest value");
    lattice.emplace_back(step);
    first[a] = static_cast<std::int64_t>(std::ceil(next.lower[a] / step - 1e-9));
    last[a] = static_cast<std::int64_t>(std::floor(next.upper[a] / step + 1e-9));
    // A multiple within round-off of a bound counts as inside it.
    while (lattice[a].value(first[a]) < next.lower[a] && first[a] <= last[a]) ++first[a];
    while (lattice[a].value(last[a]) > next.upper[a] && last[a] >= first[a]) --last[a];
    if (first[a] > last[a])
      throw InputError(bounds + " holds no multiple of the resolution " + shortest_number(step) + " of " +
                       next.axes[a] + "; expected wider bounds or a finer --round");
  }

  const KeySymmetry symmetry(request.mirror, next.axes);
  next.mirror = request.mirror.text();
  next.domain = symmetry.domain;
  const auto key_of = [&](const std::vector<double>& point, const char* what) {
    if (point.size() != d)
      throw InputError(std::string("suggest: a key ") + what + " has " + std::to_string(point.size()) +
                       " values; expected one per axis of the surface (" + std::to_string(d) + ")");
    LatticeKey nearest(d);
    for (std::size_t a = 0; a < d; ++a) {
      const double steps = point[a] / lattice[a].step;
      if (!std::isfinite(steps) || std::abs(steps) > 1e15) return std::optional<LatticeKey>{};  // no key near
      nearest[a] = lattice[a].nearest(point[a]);
    }
    return std::optional<LatticeKey>(symmetry.canonical(nearest));
  };
  std::set<LatticeKey> imported, running;
  for (const auto& point : request.imported)
    if (const auto found = key_of(point, "imported")) imported.insert(*found);
  // Keys in flight count as pseudo-runs (once each, and not where a run is already imported).
  DesignContext context;
  context.reflections = symmetry.reflections;
  for (const auto& point : request.running) {
    const auto found = key_of(point, "running");
    if (found && (imported.count(*found) || !running.insert(*found).second)) continue;
    context.in_flight.insert(context.in_flight.end(), point.begin(), point.end());
  }

  // Candidate keys: distinct, canonical, new.
  double lattice_size = 1.0;
  for (std::size_t a = 0; a < d; ++a) lattice_size *= static_cast<double>(last[a] - first[a] + 1);
  const std::size_t wanted = std::max(request.candidates, request.count);
  std::set<LatticeKey> seen;
  std::vector<double> candidates;
  const auto consider = [&](const LatticeKey& raw) {
    const LatticeKey key = symmetry.canonical(raw);
    if (!seen.insert(key).second) return;
    if (imported.count(key)) {
      ++next.imported_skipped;
      return;
    }
    if (running.count(key)) {
      ++next.running_skipped;
      return;
    }
    for (std::size_t a = 0; a < d; ++a) candidates.push_back(lattice[a].value(key[a]));
  };
  LatticeKey key(d);
  if (lattice_size <= static_cast<double>(wanted)) {
    // Every key in the bounds, axis 0 fastest.
    key = first;
    for (bool more = true; more;) {
      consider(key);
      more = false;
      for (std::size_t a = 0; a < d; ++a) {
        if (key[a] < last[a]) {
          ++key[a];
          more = true;
          break;
        }
        key[a] = first[a];
      }
    }
  } else {
    const std::size_t corners = std::size_t{1} << d;
    for (std::size_t c = 0; c < corners; ++c) {
      for (std::size_t a = 0; a < d; ++a) key[a] = (c >> a) & 1 ? last[a] : first[a];
      consider(key);
    }
    // Halton points until `wanted` distinct new keys (rounding merges some), within a budget.
    for (std::size_t i = 0; candidates.size() < wanted * d && i < 16 * wanted; ++i) {
      const auto h = halton_point(i, d);
      for (std::size_t a = 0; a < d; ++a) {
        const double x = next.lower[a] + h[a] * (next.upper[a] - next.lower[a]);
        key[a] = std::clamp(lattice[a].nearest(x), first[a], last[a]);
      }
      consider(key);
    }
  }
  next.candidates = candidates.size() / d;
  if (next.candidates < request.count) {
    std::string steps;
    for (std::size_t a = 0; a < d; ++a)
      steps += (steps.empty() ? "" : ",") + next.axes[a] + "=" + shortest_number(next.resolution[a]);
    throw InputError("--count " + std::to_string(request.count) + ": the bounds hold " +
                     std::to_string(next.candidates) + " new keys at the resolution " + steps + " (" +
                     std::to_string(next.imported_skipped) + " imported, " + std::to_string(next.running_skipped) +
                     " running" + (next.mirror.empty() ? "" : ", mirror images counted once") +
                     "); expected a count of at most that, or a finer --round");
  }
  next.runs = suggest_among_candidates(gp->output(k), candidates, request.count, context, &next.largest_sd_after);
  return next;
}

std::vector<std::vector<double>> imported_keys(RunDatabase& database, const std::string& body,
                                               const CoefficientSurface& surface) {
  RunFilter filter;
  filter.body = body;
  std::vector<std::vector<double>> out;
  for (const StoredRun& run : database.runs(filter)) {
    std::vector<double> key;
    for (const auto& axis : surface.axis_names()) {
      if (const auto v = velocity_index(axis)) {
        key.push_back(run.key.nu_b[*v]);
      } else if (const auto it = run.key.disturbances.find(axis); it != run.key.disturbances.end()) {
        key.push_back(it->second);
      } else {
        break;
      }
    }
    if (key.size() == surface.axis_count()) out.push_back(std::move(key));
  }
  return out;
}

std::vector<std::vector<double>> running_keys(const std::filesystem::path& file, const std::string& body,
                                              const CoefficientSurface& surface) {
  const Manifest manifest = Manifest::read(file);
  std::vector<std::vector<double>> out;
  for (const auto& path : manifest.paths()) {
    const SettingsLayer* row = manifest.find(path);
    if (!row) continue;
    if (const auto it = row->values.find("body"); it != row->values.end()) {
      const auto* name = std::get_if<std::string>(&it->second.value);
      if (name && *name != body) continue;
    }
    std::vector<double> key;
    for (const auto& axis : surface.axis_names()) {
      const std::string setting = velocity_index(axis) ? axis : "disturbance." + axis;
      const auto it = row->values.find(setting);
      const double* value = it == row->values.end() ? nullptr : std::get_if<double>(&it->second.value);
      if (!value)
        throw InputError((row->origin.where.empty() ? file.string() : row->origin.where) + ": the running case '" +
                         escape::one_line(path.filename().string()) + "' gives no value of " + axis +
                         "; expected a number for every axis of the surface (" + join(surface.axis_names(), ", ") +
                         ")");
      key.push_back(*value);
    }
    out.push_back(std::move(key));
  }
  return out;
}

MirrorSpec surface_mirror(const SurfaceRecord& record) {
  const auto definition = nlohmann::json::parse(record.definition, nullptr, false);
  if (definition.is_discarded() || !definition.is_object() || !definition.contains("build_spec")) return {};
  const SurfaceBuildSpec spec = stored_build_spec(record);
  return make_mirror_spec(spec.mirror_planes, spec.mirror_odd);
}

void write_next_runs_manifest(const NextRuns& next, const std::string& body, const std::filesystem::path& file) {
  std::string text = "path,body";
  for (const auto& axis : next.axes) text += "," + escape::csv_text(axis);
  text += '\n';
  for (std::size_t i = 0; i < next.runs.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "next-%02zu", i + 1);
    text += std::string(name) + "," + escape::csv_text(body);
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
