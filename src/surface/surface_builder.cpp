#include "src/surface/surface_builder.hpp"

#include "src/surface/grid_nodes.hpp"
#include "src/surface/surface_checks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>

#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/names.hpp"
#include "src/core/parallel.hpp"
#include "src/core/sign_convention.hpp"
#include "src/surface/stored_surface.hpp"

namespace hydrocoef {
namespace {

std::string run_label(const StoredRun& run) { return "run " + std::to_string(run.id) + " (" + describe(run.key) + ")"; }

double axis_value(const StoredRun& run, const std::string& axis) {
  if (const auto v = velocity_index(axis)) return run.key.nu_b[*v];
  const auto it = run.key.disturbances.find(axis);
  if (it == run.key.disturbances.end())
    throw InputError(run_label(run) + " has no disturbance '" + axis +
                     "'; expected every run of the surface to have it (select runs with --where)");
  return it->second;
}

void check_names(const SurfaceSpec& spec) {
  if (spec.axes.empty() || spec.axes.size() > kMaxGridAxes)
    throw InputError("a surface has " + std::to_string(spec.axes.size()) + " axes; expected 1 to 6");
  if (spec.outputs.empty()) throw InputError("a surface needs at least one output (X, Y, Z, K, M or N)");
  std::set<std::string> seen;
  for (const auto& axis : spec.axes) {
    if (axis.empty()) throw InputError("an axis name is empty; expected u, v, w, p, q, r or a disturbance name");
    check_name(NameKind::Parameter, axis, {}, "--axes");
    if (!seen.insert(axis).second) throw InputError("axis '" + axis + "' is given twice");
  }
  seen.clear();
  for (const auto& output : spec.outputs) {
    if (!force_index(output))
      throw InputError("output '" + output + "' is not a force component; expected X, Y, Z, K, M or N");
    if (!seen.insert(output).second) throw InputError("output '" + output + "' is given twice");
  }
  if (!spec.out_of_range.empty() && spec.out_of_range.size() != 1 && spec.out_of_range.size() != spec.axes.size())
    throw InputError("out-of-range policies: " + std::to_string(spec.out_of_range.size()) + " given for " +
                     std::to_string(spec.axes.size()) + " axes; expected one for all or one per axis");
}

std::string policy_of(const SurfaceSpec& spec, std::size_t axis) {
  if (spec.out_of_range.empty()) return "error";
  return spec.out_of_range.size() == 1 ? spec.out_of_range[0] : spec.out_of_range[axis];
}

bool same(double a, double b) { return std::abs(a - b) <= 1e-9 * (1.0 + std::max(std::abs(a), std::abs(b))); }

/// Distinct values, increasing, merging those within the key tolerance.
std::vector<double> levels_of(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  std::vector<double> out;
  for (double x : values)
    if (out.empty() || !same(out.back(), x)) out.push_back(x);
  return out;
}

std::size_t level_index(const std::vector<double>& levels, double x) {
  const auto it = std::lower_bound(levels.begin(), levels.end(), x - 1e-9 * (1.0 + std::abs(x)));
  return static_cast<std::size_t>(it - levels.begin());
}

struct Samples {
  std::vector<const StoredRun*> runs;
  std::vector<double> points;  // run-major, axes
  std::vector<double> values;  // run-major, outputs
  std::vector<double> noise;   // as values: the standard error of each (0: none stated)
  std::size_t skipped = 0;
};

Samples collect(const std::vector<StoredRun>& runs, const SurfaceSpec& spec) {
  Samples samples;
  const std::size_t n_axes = spec.axes.size();
  for (const auto& run : runs) {
    bool complete = true;
    for (const auto& output : spec.outputs) complete = complete && run.tau_b[*force_index(output)].has_value();
    if (!complete) {
      ++samples.skipped;
      continue;
    }
    samples.runs.push_back(&run);
    for (const auto& axis : spec.axes) samples.points.push_back(axis_value(run, axis));
    for (const auto& output : spec.outputs) {
      const StoredForce& force = *run.tau_b[*force_index(output)];
      samples.values.push_back(to_on_body(force.value.total, force.sign));
      samples.noise.push_back(force.standard_uncertainty());
    }
  }
  if (samples.runs.empty())
    throw InputError("no run has every output asked for; " + std::to_string(runs.size()) +
                     " runs were considered (check --body, --where and --outputs)");
  // Two runs at the same axis coordinates: something outside the axes varies.
  std::vector<std::size_t> order(samples.runs.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  const auto point = [&](std::size_t i) { return std::span<const double>(samples.points).subspan(i * n_axes, n_axes); };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::lexicographical_compare(point(a).begin(), point(a).end(), point(b).begin(), point(b).end());
  });
  for (std::size_t j = 1; j < order.size(); ++j) {
    const auto a = point(order[j - 1]), b = point(order[j]);
    bool equal = true;
    for (std::size_t k = 0; k < n_axes; ++k) equal = equal && same(a[k], b[k]);
    if (equal)
      throw InputError(run_label(*samples.runs[order[j - 1]]) + " and " + run_label(*samples.runs[order[j]]) +
                       " have the same coordinates on the surface's axes; expected one run per point (fix the "
                       "other velocity components and disturbances with --where, or add them as axes)");
  }
  return samples;
}

double mean_or_nan(const std::vector<double>& values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0.0;
  for (double v : values) sum += v;
  return sum / static_cast<double>(values.size());
}

void summarize(SurfaceQuality& quality, const std::vector<double>& errors, std::size_t n_outputs,
               const std::vector<std::int64_t>& run_ids) {
  const std::size_t n = errors.size() / n_outputs;
  quality.loo_runs = run_ids;
  quality.loo_errors = errors;
  quality.loo_max.assign(n_outputs, 0.0);
  quality.loo_rms.assign(n_outputs, 0.0);
  quality.loo_defined = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (std::isnan(errors[i * n_outputs])) continue;
    ++quality.loo_defined;
    for (std::size_t k = 0; k < n_outputs; ++k) {
      const double e = errors[i * n_outputs + k];
      quality.loo_max[k] = std::max(quality.loo_max[k], std::abs(e));
      quality.loo_rms[k] += e * e;
    }
  }
  for (std::size_t k = 0; k < n_outputs; ++k)
    quality.loo_rms[k] = quality.loo_defined ? std::sqrt(quality.loo_rms[k] / static_cast<double>(quality.loo_defined))
                                             : std::numeric_limits<double>::quiet_NaN();
  if (!quality.loo_defined)
    for (std::size_t k = 0; k < n_outputs; ++k) quality.loo_max[k] = std::numeric_limits<double>::quiet_NaN();
}

/// Grid-line leave-one-out errors, node-major (see the header).
std::vector<double> grid_line_loo(const std::vector<GridAxis>& axes, const std::vector<double>& values,
                                  std::size_t n_outputs, Interpolation method) {
  const std::size_t n_axes = axes.size();
  std::size_t nodes = 1;
  for (const auto& axis : axes) nodes *= axis.breakpoints.size();
  std::vector<double> errors(nodes * n_outputs, std::numeric_limits<double>::quiet_NaN());
  std::vector<std::vector<double>> predictions(n_outputs);
  std::vector<double> out(n_outputs);
  for (std::size_t node = 0; node < nodes; ++node) {
    for (auto& p : predictions) p.clear();
    std::size_t stride = 1, rest = node;
    for (std::size_t a = 0; a < n_axes; ++a) {
      const auto& x = axes[a].breakpoints;
      const std::size_t n = x.size();
      const std::size_t index = rest % n;
      rest /= n;
      if (n >= 3) {
        const std::size_t first = node - index * stride;
        GridAxis line{axes[a].name, {}, Extrapolation::Method};
        std::vector<double> line_values;
        for (std::size_t i = 0; i < n; ++i) {
          if (i == index) continue;
          line.breakpoints.push_back(x[i]);
          for (std::size_t k = 0; k < n_outputs; ++k)
            line_values.push_back(values[(first + i * stride) * n_outputs + k]);
        }
        const bool cubic = method != Interpolation::Nearest && method != Interpolation::Linear;
        const Interpolation line_method = cubic && line.breakpoints.size() < 3 ? Interpolation::Linear : method;
        std::vector<std::string> names;
        for (std::size_t k = 0; k < n_outputs; ++k) names.push_back("o" + std::to_string(k));
        const GridTable table({line}, names, line_values, line_method);
        const double at = x[index];
        table.evaluate(std::span<const double>(&at, 1), out);
        for (std::size_t k = 0; k < n_outputs; ++k) predictions[k].push_back(out[k]);
      }
      stride *= n;
    }
    if (predictions[0].empty()) continue;
    for (std::size_t k = 0; k < n_outputs; ++k)
      errors[node * n_outputs + k] = values[node * n_outputs + k] - mean_or_nan(predictions[k]);
  }
  return errors;
}

/// The leave-one-out part of a grid or RBF surface's stated uncertainty
/// (CoefficientSurface::with_run_uncertainty): the RMS error per output, or
/// nullopt when no run has a leave-one-out error (the surface then states
/// no uncertainty rather than one without that part).
std::optional<std::vector<double>> stated_loo(const SurfaceQuality& quality) {
  if (quality.loo_defined == 0) return std::nullopt;
  for (const double x : quality.loo_rms)
    if (!std::isfinite(x)) return std::nullopt;
  return quality.loo_rms;
}

/// The RBF of the runs' uncertainties: the surface's samples and options
/// with the uncertainties as values, clamped outside the runs' range.
RbfSurface sigma_rbf(const Samples& samples, const RbfOptions& surface_options, std::size_t n_axes,
                     std::size_t n_outputs) {
  RbfOptions options = surface_options;
  options.out_of_range.assign(n_axes, RbfOutOfRange::Clamp);
  return RbfSurface(n_axes, samples.points, n_outputs, samples.noise, options);
}

BuiltSurface build_grid(const Samples& samples, const SurfaceSpec& spec) {
  const std::size_t n_axes = spec.axes.size(), n_outputs = spec.outputs.size(), n_runs = samples.runs.size();
  const Interpolation method = parse_interpolation(spec.method);
  std::vector<GridAxis> axes;
  std::size_t nodes = 1;
  for (std::size_t a = 0; a < n_axes; ++a) {
    std::vector<double> coordinates;
    for (std::size_t i = 0; i < n_runs; ++i) coordinates.push_back(samples.points[i * n_axes + a]);
    axes.push_back({spec.axes[a], levels_of(coordinates), parse_extrapolation(policy_of(spec, a))});
    nodes *= axes.back().breakpoints.size();
  }
  std::vector<double> values(nodes * n_outputs, std::numeric_limits<double>::quiet_NaN());
  std::vector<bool> filled(nodes, false);
  std::vector<std::int64_t> node_run(nodes, 0);  // the run at each node, for the per-run LOO errors
  std::vector<std::size_t> run_node(n_runs, 0);  // the node of each run, for its uncertainty
  for (std::size_t i = 0; i < n_runs; ++i) {
    std::size_t node = 0, stride = 1;
    for (std::size_t a = 0; a < n_axes; ++a) {
      node += level_index(axes[a].breakpoints, samples.points[i * n_axes + a]) * stride;
      stride *= axes[a].breakpoints.size();
    }
    filled[node] = true;
    node_run[node] = samples.runs[i]->id;
    run_node[i] = node;
    for (std::size_t k = 0; k < n_outputs; ++k) values[node * n_outputs + k] = samples.values[i * n_outputs + k];
  }
  if (n_runs != nodes) {
    std::string missing;
    std::size_t listed = 0;
    for (std::size_t node = 0; node < nodes && listed < 5; ++node) {
      if (filled[node]) continue;
      std::string text;
      std::size_t rest = node;
      for (std::size_t a = 0; a < n_axes; ++a) {
        const std::size_t n = axes[a].breakpoints.size();
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%s=%.9g", axes[a].name.c_str(), axes[a].breakpoints[rest % n]);
        text += (text.empty() ? "" : " ") + std::string(buffer);
        rest /= n;
      }
      missing += (missing.empty() ? "" : "; ") + text;
      ++listed;
    }
    throw InputError("the " + std::to_string(n_runs) + " runs do not fill a grid: the axes' values make " +
                     std::to_string(nodes) + " grid points and " + std::to_string(nodes - n_runs) + " have no run (" +
                     missing + (nodes - n_runs > listed ? "; ..." : "") + "); expected a full grid for method '" +
                     spec.method + "', or use --method rbf for scattered runs");
  }
  BuiltSurface built{
      CoefficientSurface(GridTable(axes, spec.outputs, values, method)), {}, {}, samples.skipped, {}, {}};
  built.quality.method = "grid-lines";
  built.quality.runs = n_runs;
  summarize(built.quality, grid_line_loo(axes, values, n_outputs, method), n_outputs, node_run);
  if (const auto loo = stated_loo(built.quality)) {
    std::vector<double> sigma(nodes * n_outputs, 0.0);
    for (std::size_t i = 0; i < n_runs; ++i)
      for (std::size_t k = 0; k < n_outputs; ++k) sigma[run_node[i] * n_outputs + k] = samples.noise[i * n_outputs + k];
    built.surface = built.surface.with_run_uncertainty(std::move(sigma), *loo);
  }
  return built;
}

/// The out-of-range policies of a scattered-run surface (RBF or GP).
std::vector<RbfOutOfRange> scattered_policies(const SurfaceSpec& spec, const char* what) {
  std::vector<RbfOutOfRange> out;
  for (std::size_t a = 0; a < spec.axes.size(); ++a) {
    const std::string policy = policy_of(spec, a);
    if (policy == "error")
      out.push_back(RbfOutOfRange::Error);
    else if (policy == "clamp")
      out.push_back(RbfOutOfRange::Clamp);
    else if (policy == "extrapolate")
      out.push_back(RbfOutOfRange::Extrapolate);
    else
      throw InputError("out-of-range policy '" + policy + "' for axis '" + spec.axes[a] + "' of " + what +
                       " surface; expected error, clamp or extrapolate");
  }
  return out;
}

constexpr std::size_t kMaxGpLooRuns = 400;

/// GP leave-one-out errors, run-major (see the header): each run left out in
/// turn, the rest fitted with the hyperparameters of the whole surface.
std::vector<double> gp_loo(const GpSurfaces& gp, const Samples& samples) {
  const std::size_t n = samples.runs.size(), d = gp.axis_count(), k_count = gp.output_count();
  std::vector<double> errors(n * k_count, std::numeric_limits<double>::quiet_NaN());
  if (n > kMaxGpLooRuns) return errors;
  parallel_for(n * k_count, 0, [&](std::size_t job) {
    const std::size_t i = job / k_count, k = job % k_count;
    const GpSurface& full = gp.output(k);
    GpOptions options;
    options.kernel = full.state().kernel;
    options.mean_degree = full.state().mean_degree;
    options.fixed_hyperparameters = {full.signal_sd()};
    for (const double l : full.length_scales()) options.fixed_hyperparameters.push_back(l);
    options.fixed_hyperparameters.push_back(full.nugget_sd());
    std::vector<double> x, y, noise;
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      x.insert(x.end(), samples.points.begin() + static_cast<std::ptrdiff_t>(j * d),
               samples.points.begin() + static_cast<std::ptrdiff_t>((j + 1) * d));
      y.push_back(samples.values[j * k_count + k]);
      noise.push_back(samples.noise[j * k_count + k]);
    }
    try {
      const GpSurface without = GpSurface::fit(x, d, y, noise, options);
      GpSurface::Workspace workspace(without);
      errors[i * k_count + k] = samples.values[i * k_count + k] - without.evaluate(&samples.points[i * d], workspace);
    } catch (const InputError&) {
      // Too few runs left for the mean, or an axis left with one value: no LOO error.
    }
  });
  return errors;
}

BuiltSurface build_gp(const Samples& samples, const SurfaceSpec& spec) {
  const std::size_t n_axes = spec.axes.size(), n_outputs = spec.outputs.size();
  GpSurfaces gp(n_axes, samples.points, n_outputs, samples.values, samples.noise, spec.gp, spec.axes,
                scattered_policies(spec, "a GP"));
  SurfaceQuality quality;
  quality.method = samples.runs.size() <= kMaxGpLooRuns ? "gp-refit" : "gp-none";
  quality.runs = samples.runs.size();
  std::vector<std::int64_t> sample_runs;
  for (const StoredRun* run : samples.runs) sample_runs.push_back(run->id);
  summarize(quality, gp_loo(gp, samples), n_outputs, sample_runs);
  return BuiltSurface{CoefficientSurface(std::move(gp), spec.axes, spec.outputs), quality, {}, samples.skipped, {}, {}};
}

BuiltSurface build_rbf(const Samples& samples, const SurfaceSpec& spec) {
  const std::size_t n_axes = spec.axes.size(), n_outputs = spec.outputs.size();
  RbfOptions options = spec.rbf;
  options.axis_names = spec.axes;
  options.out_of_range = scattered_policies(spec, "an RBF");
  RbfSurface rbf(n_axes, samples.points, n_outputs, samples.values, options);
  SurfaceQuality quality;
  quality.method = "rbf-exact";
  quality.runs = samples.runs.size();
  std::vector<std::int64_t> sample_runs;
  for (const StoredRun* run : samples.runs) sample_runs.push_back(run->id);
  summarize(quality, rbf.cross_validation().errors, n_outputs, sample_runs);

  const auto loo = stated_loo(quality);
  if (!spec.resample) {
    BuiltSurface built{CoefficientSurface(std::move(rbf), spec.axes, spec.outputs),
                       quality,
                       {},
                       samples.skipped,
                       samples.points,
                       samples.values};
    if (loo) {
      built.surface = built.surface.with_run_uncertainty(sigma_rbf(samples, options, n_axes, n_outputs), *loo);
      built.rbf_sigma = samples.noise;
    }
    return built;
  }
  if (spec.resample->size() != n_axes)
    throw InputError("resampling grid has " + std::to_string(spec.resample->size()) + " axes; expected " +
                     std::to_string(n_axes) + " (one list of breakpoints per axis)");
  const RbfGrid grid = rbf.resample(*spec.resample, spec.far_threshold);
  quality.far_from_data = grid.far_from_data;
  quality.far_threshold = grid.far_threshold;
  quality.grid_points = grid.nearest_sample_distance.size();
  std::vector<GridAxis> axes;
  for (std::size_t a = 0; a < n_axes; ++a) {
    std::string policy = policy_of(spec, a);
    if (policy == "extrapolate") policy = "method";
    axes.push_back({spec.axes[a], grid.breakpoints[a], parse_extrapolation(policy)});
  }
  BuiltSurface built{
      CoefficientSurface(GridTable(axes, spec.outputs, grid.values, parse_interpolation(spec.resample_method))),
      quality,
      {},
      samples.skipped,
      {},
      {}};
  if (loo) {
    // The tabulated surface's nodes carry the RBF of the runs' uncertainty
    // there (the grid is a tabulation of the RBF, and so is its uncertainty).
    const RbfSurface sigma = sigma_rbf(samples, options, n_axes, n_outputs);
    const GridTable& table = *built.surface.grid();
    std::vector<double> node_sigma(table.values().size());
    std::vector<double> point(n_axes);
    for (std::size_t node = 0; node < table.node_count(); ++node) {
      grid_node_point(table.axes(), node, point);
      sigma.evaluate(point, std::span<double>(node_sigma).subspan(node * n_outputs, n_outputs));
      for (std::size_t k = 0; k < n_outputs; ++k)
        node_sigma[node * n_outputs + k] = std::max(0.0, node_sigma[node * n_outputs + k]);
    }
    built.surface = built.surface.with_run_uncertainty(std::move(node_sigma), *loo);
  }
  return built;
}

}  // namespace

std::string loo_method_description(std::string_view method) {
  if (method == "rbf-exact") return "exact, RBF";
  if (method == "grid-lines") return "along grid lines";
  if (method == "gp-refit") return "GP refitted without each run, same hyperparameters";
  if (method == "gp-none") return "none: over " + std::to_string(kMaxGpLooRuns) + " runs";
  return "by a method this hydrocoef does not know";
}

std::string SurfaceQuality::to_json(const std::vector<std::string>& outputs) const {
  nlohmann::json json;
  json["loo_method"] = method;
  json["runs"] = runs;
  json["loo_defined"] = loo_defined;
  const auto number = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); };
  for (std::size_t k = 0; k < outputs.size() && k < loo_max.size(); ++k)
    json["outputs"][outputs[k]] = {{"loo_max", number(loo_max[k])}, {"loo_rms", number(loo_rms[k])}};
  // Per-run errors, in the order of loo_runs (null where undefined).
  if (!loo_runs.empty() && loo_errors.size() == loo_runs.size() * outputs.size()) {
    json["loo_runs"] = loo_runs;
    for (std::size_t k = 0; k < outputs.size(); ++k) {
      nlohmann::json errors = nlohmann::json::array();
      for (std::size_t i = 0; i < loo_runs.size(); ++i) errors.push_back(number(loo_errors[i * outputs.size() + k]));
      json["outputs"][outputs[k]]["loo_errors"] = errors;
    }
  }
  if (!physical.empty()) json["physical"] = physical;
  if (grid_points) {
    json["grid_points"] = grid_points;
    json["far_threshold"] = far_threshold;
    json["far_from_data"] = far_from_data;
  }
  return escape::json_text(json);
}

SurfaceRecord BuiltSurface::record(const std::string& name, const std::string& body) const {
  SurfaceRecord out =
      surface.rbf() ? record_from_surface(surface, rbf_points, rbf_values, rbf_sigma) : record_from_surface(surface);
  out.name = name;
  out.body = body;
  out.quality = quality.to_json(surface.output_names());
  out.run_ids = run_ids;
  return out;
}

BuiltSurface build_surface(const std::vector<StoredRun>& runs, const SurfaceSpec& spec) {
  check_names(spec);
  const Samples samples = collect(runs, spec);
  BuiltSurface built = spec.method == "rbf"  ? build_rbf(samples, spec)
                       : spec.method == "gp" ? build_gp(samples, spec)
                                             : build_grid(samples, spec);
  built.surface = built.surface.with_symmetry(spec.symmetry);
  for (const auto& problem : dissipativity_problems(built.surface)) built.quality.physical.push_back(problem.message);
  for (const StoredRun* run : samples.runs) built.run_ids.push_back(run->id);
  // A mirror image carries the id of the run it is the image of: each id once.
  std::sort(built.run_ids.begin(), built.run_ids.end());
  built.run_ids.erase(std::unique(built.run_ids.begin(), built.run_ids.end()), built.run_ids.end());
  return built;
}

}  // namespace hydrocoef
