// How the CLI shows a stored surface: its axes and quality as text, and its
// description as JSON (surface build, rebuild, list, show).
#include "cli/surface_output.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <optional>

#include "cli/common.hpp"
#include "src/core/escape.hpp"
#include "src/export/export.hpp"
#include "src/pipeline/surface_build.hpp"
#include "src/surface/gp_design.hpp"
#include "src/surface/grid_table.hpp"

namespace hydrocoef::cli {
namespace {

std::string json_number_text(const nlohmann::json& value, int digits) {
  return value.is_number() ? significant(value.get<double>(), digits) : "n/a";
}

/// The grid nodes of a resampled surface that are far from every run, as
/// coordinates (empty for other surfaces).
std::vector<std::vector<double>> far_nodes(const SurfaceRecord& record, const CoefficientSurface& surface) {
  if (!surface.grid()) return {};
  return metadata_from_record(record, surface).far_from_data;
}

/// The run with the largest leave-one-out error of an output, and the error;
/// nullopt without per-run errors (surfaces built before they were stored).
std::optional<std::pair<std::int64_t, double>> worst_run(const nlohmann::json& quality, const std::string& output) {
  if (!quality.contains("loo_runs") || !quality.contains("outputs") || !quality["outputs"].contains(output) ||
      !quality["outputs"][output].contains("loo_errors"))
    return std::nullopt;
  const auto& runs = quality["loo_runs"];
  const auto& errors = quality["outputs"][output]["loo_errors"];
  std::optional<std::pair<std::int64_t, double>> worst;
  for (std::size_t i = 0; i < errors.size() && i < runs.size(); ++i)
    if (errors[i].is_number() && runs[i].is_number_integer() &&
        (!worst || std::abs(errors[i].get<double>()) > std::abs(worst->second)))
      worst = std::make_pair(runs[i].get<std::int64_t>(), errors[i].get<double>());
  return worst;
}

}  // namespace

void print_quality(const SurfaceRecord& record, const CoefficientSurface& surface) {
  const auto quality = nlohmann::json::parse(record.quality.empty() ? "{}" : record.quality);
  const std::string loo = quality.value("loo_method", "");
  std::cout << "  leave-one-out (" << loo_method_description(loo) << ", " << quality.value("loo_defined", 0) << " of "
            << quality.value("runs", 0) << " runs):\n";
  for (std::size_t k = 0; k < surface.output_count(); ++k) {
    const auto& name = surface.output_names()[k];
    const auto entry = quality.contains("outputs") && quality["outputs"].contains(name) ? quality["outputs"][name]
                                                                                        : nlohmann::json::object();
    std::cout << "    " << std::left << std::setw(4) << escape::one_line(name) << "max " << std::setw(12)
              << json_number_text(entry.value("loo_max", nlohmann::json()), 4) << "RMS " << std::setw(12)
              << json_number_text(entry.value("loo_rms", nlohmann::json()), 4)
              << escape::one_line(surface.output_units()[k]);
    if (const auto worst = worst_run(quality, name))
      std::cout << "  (worst: run " << worst->first << ", " << significant(worst->second, 4) << ")";
    std::cout << '\n';
  }
  if (quality.contains("physical") && quality["physical"].is_array())
    for (const auto& problem : quality["physical"])
      if (problem.is_string())
        std::cout << "  WARNING (energy-producing): " << escape::one_line(problem.get<std::string>())
                  << "; a simulation with it may run away\n";
  if (quality.contains("grid_points")) {
    const auto far = quality["far_from_data"].size();
    std::cout << "  resampled grid: " << quality["grid_points"].get<std::size_t>() << " points, " << far
              << " farther than " << significant(quality["far_threshold"].get<double>(), 3)
              << " (scaled) from every run" << (far ? ": extrapolated there, not data" : "") << '\n';
    const auto nodes = far_nodes(record, surface);
    for (std::size_t i = 0; i < nodes.size() && i < 20; ++i) {
      std::cout << "    (";
      for (std::size_t a = 0; a < nodes[i].size(); ++a)
        std::cout << (a ? ", " : "") << escape::one_line(surface.axis_names()[a]) << " = "
                  << significant(nodes[i][a], 6);
      std::cout << ")\n";
    }
    if (nodes.size() > 20) std::cout << "    ... and " << nodes.size() - 20 << " more (--json lists them all)\n";
  }
}

void print_axes(const CoefficientSurface& surface) {
  for (std::size_t a = 0; a < surface.axis_count(); ++a) {
    std::cout << "    " << std::left << std::setw(12) << escape::one_line(surface.axis_names()[a]) << "["
              << significant(surface.lower(a), 6) << ", " << significant(surface.upper(a), 6) << "] "
              << (surface.axis_units()[a].empty() ? "(SI)" : escape::one_line(surface.axis_units()[a]));
    if (const GridTable* grid = surface.grid())
      std::cout << ", " << grid->axes()[a].breakpoints.size() << " breakpoints"
                << (grid->evenly_spaced(a) ? " (even)" : "");
    std::cout << ", out of range: " << surface.out_of_range_name(a) << '\n';
  }
}

namespace {

/// A GP output's leave-one-out standardized residuals look like N(0, 1):
/// RMS within [0.5, 2] and none beyond 4.
bool gp_calibration_ok(const GpState& state) {
  return !std::isfinite(state.loo_rms_z) ||
         (state.loo_rms_z >= 0.5 && state.loo_rms_z <= 2.0 && state.loo_max_z <= 4.0);
}

/// A GP surface's hyperparameters per output, its calibration and the three
/// points of its range where its standard deviation is largest.
nlohmann::json gp_json(const CoefficientSurface& surface) {
  const GpSurfaces* gp = surface.gp();
  nlohmann::json out = {{"kernel", std::string(gp_kernel_name(gp->kernel()))}, {"mean_degree", gp->mean_degree()}};
  std::vector<double> lower, upper;
  for (std::size_t a = 0; a < surface.axis_count(); ++a)
    lower.push_back(surface.lower(a)), upper.push_back(surface.upper(a));
  for (std::size_t k = 0; k < surface.output_count(); ++k) {
    const GpSurface& output = gp->output(k);
    const GpState& state = output.state();
    nlohmann::json entry = {
        {"signal_sd", output.signal_sd()},
        {"discrepancy_sd", output.nugget_sd()},
        {"sd_factor", state.sd_factor},
        {"loo_rms_z", std::isfinite(state.loo_rms_z) ? nlohmann::json(state.loo_rms_z) : nlohmann::json()},
        {"loo_max_z", std::isfinite(state.loo_max_z) ? nlohmann::json(state.loo_max_z) : nlohmann::json()},
        {"calibrated", gp_calibration_ok(state)},
        {"length_scales", nlohmann::json::object()}};
    const auto lengths = output.length_scales();
    for (std::size_t a = 0; a < surface.axis_count(); ++a) entry["length_scales"][surface.axis_names()[a]] = lengths[a];
    entry["largest_sd"] = nlohmann::json::array();
    // About 2e7 operations per output: 1024 candidates up to 200 runs, fewer (at least 64) for more.
    const std::size_t n = output.samples();
    const std::size_t candidates = std::clamp<std::size_t>(20'000'000 / (n * n + 1), 64, 1024);
    for (const auto& where : largest_standard_deviations(output, lower, upper, 3, candidates)) {
      nlohmann::json point;
      for (std::size_t a = 0; a < surface.axis_count(); ++a) point[surface.axis_names()[a]] = where.point[a];
      entry["largest_sd"].push_back({{"point", point}, {"sd", where.standard_deviation}});
    }
    out["outputs"][surface.output_names()[k]] = entry;
  }
  return out;
}

/// The points of `largest` ({"point": {axis: value}, "sd": value}), one a line.
void print_largest_sd(const CoefficientSurface& surface, const nlohmann::json& largest) {
  for (const auto& where : largest) {
    std::cout << "      sd " << std::setw(12) << significant(where["sd"].get<double>(), 4) << "at";
    for (std::size_t a = 0; a < surface.axis_count(); ++a)
      std::cout << " " << escape::one_line(surface.axis_names()[a]) << "="
                << significant(where["point"][surface.axis_names()[a]].get<double>(), 5);
    std::cout << '\n';
  }
}

void print_gp(const CoefficientSurface& surface) {
  if (!surface.gp()) return;
  const nlohmann::json gp = gp_json(surface);
  std::cout << "  Gaussian process: " << escape::one_line(gp["kernel"].get<std::string>()) << " kernel, mean of degree "
            << gp["mean_degree"].get<int>() << "; standard deviation largest at:\n";
  for (std::size_t k = 0; k < surface.output_count(); ++k) {
    const auto& name = surface.output_names()[k];
    const auto& entry = gp["outputs"][name];
    std::cout << "    " << std::left << std::setw(4) << escape::one_line(name) << "signal sd "
              << significant(entry["signal_sd"].get<double>(), 4) << " " << escape::one_line(surface.output_units()[k])
              << ", length scales";
    for (std::size_t a = 0; a < surface.axis_count(); ++a)
      std::cout << " " << escape::one_line(surface.axis_names()[a]) << " "
                << significant(entry["length_scales"][surface.axis_names()[a]].get<double>(), 3);
    std::cout << ", discrepancy sd " << significant(entry["discrepancy_sd"].get<double>(), 3) << '\n';
    const GpState& state = surface.gp()->output(k).state();
    if (std::isfinite(state.loo_rms_z))
      std::cout << "      leave-one-out standardized residuals: RMS " << significant(state.loo_rms_z, 3) << ", largest "
                << significant(state.loo_max_z, 3)
                << (gp_calibration_ok(state) ? " (expected RMS about 1)"
                                             : " -- WARNING: outside RMS 0.5..2 or beyond 4: the stated sd does not "
                                               "describe the runs held out")
                << "; stated sd x " << significant(state.sd_factor, 3)
                << " (Student-t for the runs' count, and the RMS when above 1)\n";
    else
      std::cout << "      calibration not known (stored before it was kept): surface rebuild NAME computes it\n";
    print_largest_sd(surface, entry["largest_sd"]);
  }
}

/// A grid or RBF surface's stated uncertainty (CoefficientSurface::
/// with_run_uncertainty): the formula, its leave-one-out part per output and
/// the three candidate points of the range where the standard deviation is
/// largest. Candidates: every grid node (at most 100000) and a regular
/// lattice of about 4096 points over the range, so that an RBF's maxima
/// between samples are seen; the three are at least 1% of the range apart.
nlohmann::json run_uncertainty_json(const CoefficientSurface& surface) {
  const std::size_t d = surface.axis_count(), n_out = surface.output_count();
  nlohmann::json out = {{"formula", "sd^2 = (runs' uncertainty interpolated as the surface)^2 + loo_rms^2"}};
  std::vector<std::vector<double>> candidates;
  if (const GridTable* grid = surface.grid(); grid && grid->node_count() <= 100000)
    for (std::size_t node = 0; node < grid->node_count(); ++node) {
      std::vector<double> point(d);
      std::size_t rest = node;
      for (std::size_t a = 0; a < d; ++a) {
        const auto& x = grid->axes()[a].breakpoints;
        point[a] = x[rest % x.size()];
        rest /= x.size();
      }
      candidates.push_back(std::move(point));
    }
  const auto per_axis = std::max<std::size_t>(
      2, static_cast<std::size_t>(std::floor(std::pow(4096.0, 1.0 / static_cast<double>(d)) + 1e-9)));
  std::size_t lattice = 1;
  for (std::size_t a = 0; a < d; ++a) lattice *= per_axis;
  for (std::size_t i = 0; i < lattice; ++i) {
    std::vector<double> point(d);
    std::size_t rest = i;
    for (std::size_t a = 0; a < d; ++a) {
      const double t = static_cast<double>(rest % per_axis) / static_cast<double>(per_axis - 1);
      point[a] = surface.lower(a) + t * (surface.upper(a) - surface.lower(a));
      rest /= per_axis;
    }
    candidates.push_back(std::move(point));
  }
  std::vector<double> sd(candidates.size() * n_out), values(n_out);
  for (std::size_t i = 0; i < candidates.size(); ++i)
    surface.evaluate_with_standard_deviation(candidates[i], values, std::span<double>(sd).subspan(i * n_out, n_out));
  for (std::size_t k = 0; k < n_out; ++k) {
    std::vector<std::size_t> order(candidates.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return sd[a * n_out + k] > sd[b * n_out + k]; });
    // The three largest, each at least 1% of the range (on some axis) from
    // those already listed: a node and the lattice point on it are one point.
    const auto near = [&](std::size_t a, std::size_t b) {
      for (std::size_t axis = 0; axis < d; ++axis)
        if (std::abs(candidates[a][axis] - candidates[b][axis]) > 0.01 * (surface.upper(axis) - surface.lower(axis)))
          return false;
      return true;
    };
    std::vector<std::size_t> chosen;
    for (std::size_t i = 0; i < order.size() && chosen.size() < 3; ++i)
      if (std::none_of(chosen.begin(), chosen.end(), [&](std::size_t c) { return near(c, order[i]); }))
        chosen.push_back(order[i]);
    nlohmann::json entry = {{"loo_sd", surface.loo_standard_deviation()[k]}, {"largest_sd", nlohmann::json::array()}};
    for (const std::size_t c : chosen) {
      nlohmann::json point;
      for (std::size_t a = 0; a < d; ++a) point[surface.axis_names()[a]] = candidates[c][a];
      entry["largest_sd"].push_back({{"point", point}, {"sd", sd[c * n_out + k]}});
    }
    out["outputs"][surface.output_names()[k]] = entry;
  }
  return out;
}

void print_run_uncertainty(const CoefficientSurface& surface) {
  if (surface.gp()) return;
  if (!surface.has_standard_deviation()) {
    std::cout << "  uncertainty: none stated (stored without its runs' uncertainty or with no leave-one-out "
                 "error; hydrocoef surface rebuild adds it when the runs allow)\n";
    return;
  }
  const nlohmann::json uncertainty = run_uncertainty_json(surface);
  std::cout << "  uncertainty: sd^2 = (runs' uncertainty, interpolated as the surface)^2 + (leave-one-out RMS)^2;"
               " largest at:\n";
  for (std::size_t k = 0; k < surface.output_count(); ++k) {
    const auto& name = surface.output_names()[k];
    const auto& entry = uncertainty["outputs"][name];
    std::cout << "    " << std::left << std::setw(4) << escape::one_line(name) << "leave-one-out part "
              << significant(entry["loo_sd"].get<double>(), 4) << " " << escape::one_line(surface.output_units()[k])
              << '\n';
    print_largest_sd(surface, entry["largest_sd"]);
  }
}

}  // namespace

nlohmann::json surface_json(const SurfaceRecord& record, const CoefficientSurface& surface, bool with_values) {
  nlohmann::json out = {{"name", record.name},
                        {"body", record.body},
                        {"kind", record.kind},
                        {"method", record.method},
                        {"created_at", record.created_at},
                        {"stale", record.stale},
                        {"runs", record.run_ids}};
  out["axes"] = nlohmann::json::array();
  for (std::size_t a = 0; a < surface.axis_count(); ++a) {
    nlohmann::json axis = {{"name", surface.axis_names()[a]},
                           {"unit", surface.axis_units()[a]},
                           {"lower", surface.lower(a)},
                           {"upper", surface.upper(a)},
                           {"out_of_range", surface.out_of_range_name(a)}};
    if (const GridTable* grid = surface.grid()) {
      axis["breakpoints"] = grid->axes()[a].breakpoints.size();
      if (with_values) axis["breakpoint_values"] = grid->axes()[a].breakpoints;
    }
    out["axes"].push_back(axis);
  }
  out["outputs"] = nlohmann::json::array();
  for (std::size_t k = 0; k < surface.output_count(); ++k)
    out["outputs"].push_back({{"name", surface.output_names()[k]}, {"unit", surface.output_units()[k]}});
  out["quality"] = nlohmann::json::parse(record.quality.empty() ? "{}" : record.quality);
  out["loo_worst"] = nlohmann::json::object();
  for (const auto& name : surface.output_names())
    if (const auto worst = worst_run(out["quality"], name))
      out["loo_worst"][name] = {{"run", worst->first}, {"error", worst->second}};
  out["far_from_data_points"] = nlohmann::json::array();
  for (const auto& node : far_nodes(record, surface)) {
    nlohmann::json point = nlohmann::json::object();
    for (std::size_t a = 0; a < node.size(); ++a) point[surface.axis_names()[a]] = node[a];
    out["far_from_data_points"].push_back(point);
  }
  if (!surface.symmetry().empty())
    out["symmetry"] = surface.symmetry().describe(surface.axis_names(), surface.output_names());
  if (surface.gp()) out["gp"] = gp_json(surface);
  if (!surface.gp() && surface.has_standard_deviation()) out["uncertainty"] = run_uncertainty_json(surface);
  const auto definition = nlohmann::json::parse(record.definition);
  if (definition.contains("build_spec")) out["build_spec"] = definition["build_spec"];
  return out;
}

namespace {

/// The symmetry imposed, in words, when there is one.
void print_symmetry(const CoefficientSurface& surface) {
  if (surface.symmetry().empty()) return;
  std::cout << "  symmetry imposed: " << surface.symmetry().describe(surface.axis_names(), surface.output_names())
            << " (an odd output is 0 on its plane, an even one flat across it)\n";
}

}  // namespace

void print_surface_list(const std::vector<SurfaceRecord>& records, const std::string& database, bool json) {
  if (json) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& record : records) out.push_back(surface_json(record, surface_from_record(record), false));
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  if (records.empty()) {
    std::cout << "no surfaces in " << escape::one_line(database) << '\n';
    return;
  }
  std::cout << std::left << std::setw(20) << "name" << std::setw(10) << "body" << std::setw(6) << "kind"
            << std::setw(16) << "method" << std::setw(18) << "axes" << std::setw(14) << "outputs" << std::setw(6)
            << "runs" << std::setw(22) << "state"
            << "built from\n";
  for (const auto& record : records) {
    const CoefficientSurface surface = surface_from_record(record);
    std::string axes, outputs;
    for (const auto& a : surface.axis_names()) axes += (axes.empty() ? "" : ",") + a;
    for (const auto& o : surface.output_names()) outputs += (outputs.empty() ? "" : ",") + o;
    std::cout << std::setw(20) << escape::one_line(record.name) << std::setw(10) << escape::one_line(record.body)
              << std::setw(6) << escape::one_line(record.kind) << std::setw(16)
              << escape::one_line(surface.method_name()) << std::setw(18) << escape::one_line(axes) << std::setw(14)
              << escape::one_line(outputs) << std::setw(6) << record.run_ids.size() << std::setw(22)
              << (record.stale ? "STALE (runs changed)" : "current") << escape::one_line(built_from(record)) << '\n';
  }
}

void print_surface(const StoredSurface& stored, bool json) {
  if (json) {
    std::cout << escape::json_text(surface_json(stored.record, stored.surface, true), 2) << '\n';
    return;
  }
  const auto& record = stored.record;
  std::cout << "surface " << escape::one_line(record.name) << " of body " << escape::one_line(record.body)
            << "\n  kind: " << escape::one_line(record.kind)
            << ", method: " << escape::one_line(stored.surface.method_name())
            << "\n  built: " << escape::one_line(record.created_at) << " from " << record.run_ids.size()
            << " runs\n  state: "
            << (record.stale ? "STALE: forces of this body changed since it was built (hydrocoef surface rebuild " +
                                   escape::one_line(record.name) + ")"
                             : std::string("current"))
            << "\n  axes:\n";
  print_axes(stored.surface);
  print_symmetry(stored.surface);
  std::cout << "  outputs (forces on the body):\n";
  for (std::size_t k = 0; k < stored.surface.output_count(); ++k)
    std::cout << "    " << escape::one_line(stored.surface.output_names()[k]) << " ["
              << escape::one_line(stored.surface.output_units()[k]) << "]\n";
  print_quality(record, stored.surface);
  print_gp(stored.surface);
  print_run_uncertainty(stored.surface);
}

nlohmann::json surface_build_json(const SurfaceBuildResult& result) {
  nlohmann::json out = surface_json(result.stored.record, result.stored.surface, false);
  out["runs_skipped"] = result.runs_skipped;
  out["mirror"] = result.mirror;
  out["mirror_images"] = result.mirror_images;
  out["id"] = result.stored.record.id;
  return out;
}

void print_surface_build(const SurfaceBuildResult& result, const std::string& database) {
  const auto& [record, surface] = result.stored;
  std::cout << "surface " << escape::one_line(record.name) << " of body " << escape::one_line(record.body) << ": "
            << escape::one_line(record.kind) << ", " << escape::one_line(record.method) << ", " << record.run_ids.size()
            << " runs";
  if (result.runs_skipped) std::cout << " (" << result.runs_skipped << " runs without every output skipped)";
  if (!result.mirror.empty())
    std::cout << "\n  mirror " << escape::one_line(result.mirror) << ": " << result.runs_measured << " runs and "
              << result.mirror_images << " mirror images (never stored as runs)"
              << (result.images_skipped
                      ? ", " + std::to_string(result.images_skipped) + " images left out at measured keys"
                      : std::string());
  std::cout << "\n  axes:\n";
  print_axes(surface);
  print_symmetry(surface);
  std::cout << "  outputs: ";
  for (std::size_t k = 0; k < surface.output_count(); ++k)
    std::cout << (k ? ", " : "") << escape::one_line(surface.output_names()[k]) << " ["
              << escape::one_line(surface.output_units()[k]) << "]";
  std::cout << " (forces on the body)\n";
  print_quality(record, surface);
  print_gp(surface);
  print_run_uncertainty(surface);
  std::cout << "  stored as surface " << record.id << " in " << escape::one_line(database) << '\n';
}

}  // namespace hydrocoef::cli
