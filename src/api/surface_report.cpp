// Stored surfaces as `hydrocoef surface build | rebuild | list | show` print
// them: axes, quality, the GP's hyperparameters and calibration, the stated
// uncertainty and where it is largest, as text and as JSON.
#include "src/api/surface_report.hpp"
#include "src/api/internal.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>

#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/export/export.hpp"
#include "src/surface/gp_design.hpp"
#include "src/surface/grid_table.hpp"

namespace hydrocoef {
inline namespace api {
namespace surface_text {

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

/// A GP output's leave-one-out standardized residuals look like N(0, 1):
/// RMS within [0.5, 2] and none beyond 4.
bool gp_calibration_ok(const GpState& state) {
  return !std::isfinite(state.loo_rms_z) ||
         (state.loo_rms_z >= 0.5 && state.loo_rms_z <= 2.0 && state.loo_max_z <= 4.0);
}

/// The largest-sd points of one output as JSON ({"point": {axis: value}, "sd": value} each).
nlohmann::json peaks_json(const CoefficientSurface& surface, const std::vector<SigmaPeak>& peaks) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& where : peaks) {
    nlohmann::json point;
    for (std::size_t a = 0; a < surface.axis_count(); ++a) point[surface.axis_names()[a]] = where.point[a];
    out.push_back({{"point", point}, {"sd", where.standard_deviation}});
  }
  return out;
}

/// A GP surface's hyperparameters per output, its calibration and the points
/// of its range where its standard deviation is largest.
nlohmann::json gp_json(const CoefficientSurface& surface, const std::vector<std::vector<SigmaPeak>>& peaks) {
  const GpSurfaces* gp = surface.gp();
  nlohmann::json out = {{"kernel", std::string(gp_kernel_name(gp->kernel()))}, {"mean_degree", gp->mean_degree()}};
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
    entry["largest_sd"] = peaks_json(surface, peaks[k]);
    out["outputs"][surface.output_names()[k]] = entry;
  }
  return out;
}

/// A grid or RBF surface's stated uncertainty: the formula, its
/// leave-one-out part per output and where the standard deviation is largest.
nlohmann::json run_uncertainty_json(const CoefficientSurface& surface,
                                    const std::vector<std::vector<SigmaPeak>>& peaks) {
  nlohmann::json out = {{"formula", "sd^2 = (runs' uncertainty interpolated as the surface)^2 + loo_rms^2"}};
  for (std::size_t k = 0; k < surface.output_count(); ++k)
    out["outputs"][surface.output_names()[k]] = {{"loo_sd", surface.loo_standard_deviation()[k]},
                                                 {"largest_sd", peaks_json(surface, peaks[k])}};
  return out;
}

/// What the text and JSON of one stored surface are made from: the record,
/// the surface and its largest standard deviations (searched once).
struct Facts {
  const SurfaceRecord& record;
  const CoefficientSurface& surface;
  std::vector<std::vector<SigmaPeak>> peaks;
  nlohmann::json quality;
};

Facts facts(const SurfaceRecord& record, const CoefficientSurface& surface) {
  return {record, surface, largest_sd(surface, 3),
          nlohmann::json::parse(record.quality.empty() ? "{}" : record.quality)};
}

void print_quality(std::ostream& out, const Facts& f) {
  nlohmann::json quality = f.quality;  // a copy: a member a received record lacks reads as null
  const auto& surface = f.surface;
  const std::string loo = quality.value("loo_method", "");
  out << "  leave-one-out (" << loo_method_description(loo) << ", " << quality.value("loo_defined", 0) << " of "
      << quality.value("runs", 0) << " runs):\n";
  for (std::size_t k = 0; k < surface.output_count(); ++k) {
    const auto& name = surface.output_names()[k];
    const auto entry = quality.contains("outputs") && quality["outputs"].contains(name) ? quality["outputs"][name]
                                                                                        : nlohmann::json::object();
    out << "    " << std::left << std::setw(4) << escape::one_line(name) << "max " << std::setw(12)
        << json_number_text(entry.value("loo_max", nlohmann::json()), 4) << "RMS " << std::setw(12)
        << json_number_text(entry.value("loo_rms", nlohmann::json()), 4) << escape::one_line(surface.output_units()[k]);
    if (const auto worst = worst_run(quality, name))
      out << "  (worst: run " << worst->first << ", " << significant(worst->second, 4) << ")";
    out << '\n';
  }
  if (quality.contains("physical") && quality["physical"].is_array())
    for (const auto& problem : quality["physical"])
      if (problem.is_string())
        out << "  WARNING (energy-producing): " << escape::one_line(problem.get<std::string>())
            << "; a simulation with it may run away\n";
  if (quality.contains("grid_points")) {
    const auto far = quality["far_from_data"].size();
    out << "  resampled grid: " << quality["grid_points"].get<std::size_t>() << " points, " << far << " farther than "
        << significant(quality["far_threshold"].get<double>(), 3) << " (scaled) from every run"
        << (far ? ": extrapolated there, not data" : "") << '\n';
    const auto nodes = far_nodes(f.record, surface);
    for (std::size_t i = 0; i < nodes.size() && i < 20; ++i) {
      out << "    (";
      for (std::size_t a = 0; a < nodes[i].size(); ++a)
        out << (a ? ", " : "") << escape::one_line(surface.axis_names()[a]) << " = " << significant(nodes[i][a], 6);
      out << ")\n";
    }
    if (nodes.size() > 20) out << "    ... and " << nodes.size() - 20 << " more (--json lists them all)\n";
  }
}

void print_axes(std::ostream& out, const CoefficientSurface& surface) {
  for (std::size_t a = 0; a < surface.axis_count(); ++a) {
    out << "    " << std::left << std::setw(12) << escape::one_line(surface.axis_names()[a]) << "["
        << significant(surface.lower(a), 6) << ", " << significant(surface.upper(a), 6) << "] "
        << (surface.axis_units()[a].empty() ? "(SI)" : escape::one_line(surface.axis_units()[a]));
    if (const GridTable* grid = surface.grid())
      out << ", " << grid->axes()[a].breakpoints.size() << " breakpoints" << (grid->evenly_spaced(a) ? " (even)" : "");
    out << ", out of range: " << surface.out_of_range_name(a) << '\n';
  }
}

/// The points of `peaks`, one a line.
void print_largest_sd(std::ostream& out, const CoefficientSurface& surface, const std::vector<SigmaPeak>& peaks) {
  for (const auto& where : peaks) {
    out << "      sd " << std::setw(12) << significant(where.standard_deviation, 4) << "at";
    for (std::size_t a = 0; a < surface.axis_count(); ++a)
      out << " " << escape::one_line(surface.axis_names()[a]) << "=" << significant(where.point[a], 5);
    out << '\n';
  }
}

void print_gp(std::ostream& out, const Facts& f) {
  const auto& surface = f.surface;
  if (!surface.gp()) return;
  const nlohmann::json gp = gp_json(surface, f.peaks);
  out << "  Gaussian process: " << escape::one_line(gp["kernel"].get<std::string>()) << " kernel, mean of degree "
      << gp["mean_degree"].get<int>() << "; standard deviation largest at:\n";
  for (std::size_t k = 0; k < surface.output_count(); ++k) {
    const auto& name = surface.output_names()[k];
    const auto& entry = gp["outputs"][name];
    out << "    " << std::left << std::setw(4) << escape::one_line(name) << "signal sd "
        << significant(entry["signal_sd"].get<double>(), 4) << " " << escape::one_line(surface.output_units()[k])
        << ", length scales";
    for (std::size_t a = 0; a < surface.axis_count(); ++a)
      out << " " << escape::one_line(surface.axis_names()[a]) << " "
          << significant(entry["length_scales"][surface.axis_names()[a]].get<double>(), 3);
    out << ", discrepancy sd " << significant(entry["discrepancy_sd"].get<double>(), 3) << '\n';
    const GpState& state = surface.gp()->output(k).state();
    if (std::isfinite(state.loo_rms_z))
      out << "      leave-one-out standardized residuals: RMS " << significant(state.loo_rms_z, 3) << ", largest "
          << significant(state.loo_max_z, 3)
          << (gp_calibration_ok(state) ? " (expected RMS about 1)"
                                       : " -- WARNING: outside RMS 0.5..2 or beyond 4: the stated sd does not "
                                         "describe the runs held out")
          << "; stated sd x " << significant(state.sd_factor, 3)
          << " (Student-t for the runs' count, and the RMS when above 1)\n";
    else
      out << "      calibration not known (stored before it was kept): surface rebuild NAME computes it\n";
    print_largest_sd(out, surface, f.peaks[k]);
  }
}

void print_run_uncertainty(std::ostream& out, const Facts& f) {
  const auto& surface = f.surface;
  if (surface.gp()) return;
  if (!surface.has_standard_deviation()) {
    out << "  uncertainty: none stated (stored without its runs' uncertainty or with no leave-one-out "
           "error; hydrocoef surface rebuild adds it when the runs allow)\n";
    return;
  }
  out << "  uncertainty: sd^2 = (runs' uncertainty, interpolated as the surface)^2 + (leave-one-out RMS)^2;"
         " largest at:\n";
  for (std::size_t k = 0; k < surface.output_count(); ++k) {
    out << "    " << std::left << std::setw(4) << escape::one_line(surface.output_names()[k]) << "leave-one-out part "
        << significant(surface.loo_standard_deviation()[k], 4) << " " << escape::one_line(surface.output_units()[k])
        << '\n';
    print_largest_sd(out, surface, f.peaks[k]);
  }
}

/// The symmetry imposed, in words, when there is one.
void print_symmetry(std::ostream& out, const CoefficientSurface& surface) {
  if (surface.symmetry().empty()) return;
  out << "  symmetry imposed: " << surface.symmetry().describe(surface.axis_names(), surface.output_names())
      << " (an odd output is 0 on its plane, an even one flat across it)\n";
}

nlohmann::json surface_json(const Facts& f, bool with_values) {
  const auto& record = f.record;
  const auto& surface = f.surface;
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
  out["quality"] = f.quality;
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
  if (surface.gp()) out["gp"] = gp_json(surface, f.peaks);
  if (!surface.gp() && surface.has_standard_deviation()) out["uncertainty"] = run_uncertainty_json(surface, f.peaks);
  const auto definition = nlohmann::json::parse(record.definition);
  if (definition.contains("build_spec")) out["build_spec"] = definition["build_spec"];
  return out;
}

std::string show_text(const Facts& f) {
  const auto& record = f.record;
  const auto& surface = f.surface;
  std::ostringstream out;
  out << "surface " << escape::one_line(record.name) << " of body " << escape::one_line(record.body)
      << "\n  kind: " << escape::one_line(record.kind) << ", method: " << escape::one_line(surface.method_name())
      << "\n  built: " << escape::one_line(record.created_at) << " from " << record.run_ids.size() << " runs\n  state: "
      << (record.stale ? "STALE: forces of this body changed since it was built (hydrocoef surface rebuild " +
                             escape::one_line(record.name) + ")"
                       : std::string("current"))
      << "\n  axes:\n";
  print_axes(out, surface);
  print_symmetry(out, surface);
  out << "  outputs (forces on the body):\n";
  for (std::size_t k = 0; k < surface.output_count(); ++k)
    out << "    " << escape::one_line(surface.output_names()[k]) << " [" << escape::one_line(surface.output_units()[k])
        << "]\n";
  print_quality(out, f);
  print_gp(out, f);
  print_run_uncertainty(out, f);
  return out.str();
}

SurfaceReport report_of(const Facts& f) {
  const auto& record = f.record;
  const auto& surface = f.surface;
  SurfaceReport report;
  report.name = record.name;
  report.body = record.body;
  report.kind = record.kind;
  report.method = surface.method_name();
  report.created_at = record.created_at;
  report.stale = record.stale;
  report.runs = record.run_ids;
  report.built_from = built_from(record);
  for (std::size_t a = 0; a < surface.axis_count(); ++a) {
    SurfaceAxisReport axis{surface.axis_names()[a], surface.axis_units()[a],      surface.lower(a),
                           surface.upper(a),        surface.out_of_range_name(a), {}};
    if (const GridTable* grid = surface.grid()) axis.breakpoints = grid->axes()[a].breakpoints;
    report.axes.push_back(std::move(axis));
  }
  for (std::size_t k = 0; k < surface.output_count(); ++k) {
    const auto& name = surface.output_names()[k];
    SurfaceOutputReport output{name, surface.output_units()[k], kNaN, kNaN, 0, kNaN, {}};
    if (f.quality.contains("outputs") && f.quality["outputs"].contains(name)) {
      const auto& entry = f.quality["outputs"][name];
      if (entry.contains("loo_max") && entry["loo_max"].is_number()) output.loo_max = entry["loo_max"].get<double>();
      if (entry.contains("loo_rms") && entry["loo_rms"].is_number()) output.loo_rms = entry["loo_rms"].get<double>();
    }
    if (const auto worst = worst_run(f.quality, name)) std::tie(output.worst_run, output.worst_error) = *worst;
    output.largest_sd = f.peaks[k];
    report.outputs.push_back(std::move(output));
  }
  SurfaceReport::Access::set(report, show_text(f), escape::json_text(surface_json(f, true), 2) + '\n');
  return report;
}

}  // namespace

std::vector<std::vector<SigmaPeak>> largest_sd(const CoefficientSurface& surface, std::size_t count) {
  const std::size_t d = surface.axis_count(), n_out = surface.output_count();
  std::vector<std::vector<SigmaPeak>> out(n_out);
  if (!surface.has_standard_deviation() || count == 0) return out;
  std::vector<double> lower, upper;
  for (std::size_t a = 0; a < d; ++a) lower.push_back(surface.lower(a)), upper.push_back(surface.upper(a));
  if (const GpSurfaces* gp = surface.gp()) {
    // The GP's own search: about 2e7 operations per output, 1024 candidates up
    // to 200 runs, fewer (at least 64) for more.
    for (std::size_t k = 0; k < n_out; ++k) {
      const GpSurface& output = gp->output(k);
      const std::size_t n = output.samples();
      const std::size_t candidates = std::clamp<std::size_t>(20'000'000 / (n * n + 1), 64, 1024);
      for (const auto& where : largest_standard_deviations(output, lower, upper, count, candidates))
        out[k].push_back({where.point, where.standard_deviation});
    }
    return out;
  }
  // A grid or RBF surface's stated uncertainty (CoefficientSurface::
  // with_run_uncertainty). Candidates: every grid node (at most 100000) and a
  // regular lattice of about 4096 points over the range, so that an RBF's
  // maxima between samples are seen; those listed are at least 1% of the
  // range apart.
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
      point[a] = lower[a] + t * (upper[a] - lower[a]);
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
    // A node and the lattice point on it are one point.
    const auto near = [&](std::size_t a, std::size_t b) {
      for (std::size_t axis = 0; axis < d; ++axis)
        if (std::abs(candidates[a][axis] - candidates[b][axis]) > 0.01 * (upper[axis] - lower[axis])) return false;
      return true;
    };
    std::vector<std::size_t> chosen;
    for (std::size_t i = 0; i < order.size() && chosen.size() < count; ++i)
      if (std::none_of(chosen.begin(), chosen.end(), [&](std::size_t c) { return near(c, order[i]); }))
        chosen.push_back(order[i]);
    for (const std::size_t c : chosen) out[k].push_back({candidates[c], sd[c * n_out + k]});
  }
  return out;
}

SurfaceReport report(const SurfaceRecord& record, const CoefficientSurface& surface, nlohmann::json* brief_json) {
  const Facts f = facts(record, surface);
  if (brief_json) *brief_json = surface_json(f, false);
  return report_of(f);
}

SurfaceBuildReport build_report(const SurfaceBuildResult& result, const std::string& database) {
  const auto& [record, surface] = result.stored;
  const Facts f = facts(record, surface);
  SurfaceBuildReport out;
  out.surface = report_of(f);
  out.id = record.id;
  out.runs_measured = result.runs_measured;
  out.mirror_images = result.mirror_images;
  out.images_skipped = result.images_skipped;
  out.runs_skipped = result.runs_skipped;
  out.mirror = result.mirror;

  nlohmann::json json = surface_json(f, false);
  json["runs_skipped"] = result.runs_skipped;
  json["mirror"] = result.mirror;
  json["mirror_images"] = result.mirror_images;
  json["id"] = record.id;

  std::ostringstream text;
  text << "surface " << escape::one_line(record.name) << " of body " << escape::one_line(record.body) << ": "
       << escape::one_line(record.kind) << ", " << escape::one_line(record.method) << ", " << record.run_ids.size()
       << " runs";
  if (result.runs_skipped) text << " (" << result.runs_skipped << " runs without every output skipped)";
  if (!result.mirror.empty())
    text << "\n  mirror " << escape::one_line(result.mirror) << ": " << result.runs_measured << " runs and "
         << result.mirror_images << " mirror images (never stored as runs)"
         << (result.images_skipped ? ", " + std::to_string(result.images_skipped) + " images left out at measured keys"
                                   : std::string());
  text << "\n  axes:\n";
  print_axes(text, surface);
  print_symmetry(text, surface);
  text << "  outputs: ";
  for (std::size_t k = 0; k < surface.output_count(); ++k)
    text << (k ? ", " : "") << escape::one_line(surface.output_names()[k]) << " ["
         << escape::one_line(surface.output_units()[k]) << "]";
  text << " (forces on the body)\n";
  print_quality(text, f);
  print_gp(text, f);
  print_run_uncertainty(text, f);
  text << "  stored as surface " << record.id << " in " << escape::one_line(database) << '\n';
  SurfaceBuildReport::Access::set(out, text.str(), escape::json_text(json, 2) + '\n');
  return out;
}

SurfaceList list_report(const std::vector<SurfaceRecord>& records, const std::string& database) {
  SurfaceList list;
  nlohmann::json json = nlohmann::json::array();
  std::ostringstream text;
  if (records.empty())
    text << "no surfaces in " << escape::one_line(database) << '\n';
  else
    text << std::left << std::setw(20) << "name" << std::setw(10) << "body" << std::setw(6) << "kind" << std::setw(16)
         << "method" << std::setw(18) << "axes" << std::setw(14) << "outputs" << std::setw(6) << "runs" << std::setw(22)
         << "state"
         << "built from\n";
  for (const auto& record : records) {
    const CoefficientSurface surface = surface_from_record(record);
    nlohmann::json brief;
    list.surfaces.push_back(report(record, surface, &brief));
    json.push_back(std::move(brief));
    std::string axes, outputs;
    for (const auto& a : surface.axis_names()) axes += (axes.empty() ? "" : ",") + a;
    for (const auto& o : surface.output_names()) outputs += (outputs.empty() ? "" : ",") + o;
    text << std::setw(20) << escape::one_line(record.name) << std::setw(10) << escape::one_line(record.body)
         << std::setw(6) << escape::one_line(record.kind) << std::setw(16) << escape::one_line(surface.method_name())
         << std::setw(18) << escape::one_line(axes) << std::setw(14) << escape::one_line(outputs) << std::setw(6)
         << record.run_ids.size() << std::setw(22) << (record.stale ? "STALE (runs changed)" : "current")
         << escape::one_line(built_from(record)) << '\n';
  }
  SurfaceList::Access::set(list, text.str(), escape::json_text(json, 2) + '\n');
  return list;
}

}  // namespace surface_text

std::string SurfaceReport::text() const { return text_; }
std::string SurfaceReport::json() const { return json_; }
std::string SurfaceList::text() const { return text_; }
std::string SurfaceList::json() const { return json_; }
std::string SurfaceBuildReport::text() const { return text_; }
std::string SurfaceBuildReport::json() const { return json_; }

}  // namespace api
}  // namespace hydrocoef
