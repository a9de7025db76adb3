#include "src/plot/plots.hpp"
#include "src/core/numbers.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>

#include "src/core/damping_terms.hpp"
#include "src/core/error.hpp"
#include "src/core/sign_convention.hpp"
#include "src/core/text.hpp"
#include "src/dynamics/equilibrium.hpp"
#include "src/dynamics/experiment.hpp"
#include "src/fit/fit_names.hpp"
#include "src/surface/stored_surface.hpp"

namespace hydrocoef::plot {
namespace {

std::string sign_note(SignConvention sign) {
  return sign == SignConvention::OnBody ? "on body: damping negative" : "opposing: positive opposes motion";
}

std::vector<double> linspace(double from, double to, std::size_t count) {
  std::vector<double> out(count);
  for (std::size_t i = 0; i < count; ++i)
    out[i] = count == 1 ? from : from + (to - from) * static_cast<double>(i) / static_cast<double>(count - 1);
  if (count > 1) out.back() = to;
  return out;
}

/// "X = 0.0155 u + 11 u|u|" from a stored fit.
std::string law_text(const FitRecord& fit) {
  std::string out = fit.dof + " =";
  bool first = true;
  for (const auto& c : fit.coefficients) {
    const double v = c.value;
    out += first ? (v < 0 ? " -" : " ") : (v < 0 ? " - " : " + ");
    out += significant(std::abs(v), 6);
    if (c.term != "1") out += " " + c.term;
    first = false;
  }
  return out;
}

/// The value of a velocity component or disturbance in a run's key; nullopt
/// when the run has no such disturbance.
std::optional<double> key_value(const RunKey& key, const std::string& name) {
  if (const auto v = velocity_index(name)) return key.nu_b[*v];
  const auto it = key.disturbances.find(name);
  if (it == key.disturbances.end()) return std::nullopt;
  return it->second;
}

std::vector<StoredRun> runs_by_id(RunDatabase& database, const std::string& body,
                                  const std::vector<std::int64_t>& ids) {
  const std::set<std::int64_t> wanted(ids.begin(), ids.end());
  RunFilter filter;
  filter.body = body;
  std::vector<StoredRun> out;
  for (auto& run : database.runs(filter))
    if (wanted.count(run.id)) out.push_back(std::move(run));
  return out;
}

std::string axis_label(const std::string& name, const std::string& unit) {
  return unit.empty() ? name : name + " [" + unit + "]";
}

/// f over an 81 x 81 grid of [x0, x1] x [y0, y1] (x fastest), as a colour map.
template <typename F>
ColourMap sampled_map(double x0, double x1, double y0, double y1, std::string z_label, const F& f) {
  ColourMap map;
  map.z_label = std::move(z_label);
  map.x = linspace(x0, x1, 81);
  map.y = linspace(y0, y1, 81);
  for (double y : map.y)
    for (double x : map.x) map.z.push_back(f(std::array<double, 2>{x, y}));
  return map;
}

}  // namespace

double evaluate_fit(const FitRecord& fit, double x) {
  const DampingLawSpec spec = parse_damping_terms(fit.terms);
  std::vector<double> coefficients;  // in term order
  for (const auto term : spec.terms) {
    const std::string name = term_name(term, spec.variable);
    const auto it = std::find_if(fit.coefficients.begin(), fit.coefficients.end(),
                                 [&](const FitRecord::Coefficient& c) { return c.term == name; });
    if (it == fit.coefficients.end())
      throw InputError("fit '" + fit.name + "': no coefficient for term " + name + " of its law " + fit.terms);
    coefficients.push_back(it->value);
  }
  return damping_law_value(spec.terms, coefficients, x);
}

std::vector<FitRecord> fit_family(RunDatabase& database, const std::string& name) {
  if (database.runs().empty())
    throw InputError("database " + database.path().string() +
                     " has no runs: import CFD results first (hydrocoef import)");
  auto fits = database.fits();
  if (fits.empty())
    throw InputError("database " + database.path().string() + " has no fits: fit a law first (hydrocoef fit)");
  std::vector<FitRecord> family;
  for (auto& fit : fits)
    if (fit.name == name || fit_level(fit.name, name)) family.push_back(fit);
  if (family.empty()) {
    std::vector<std::string> names;
    for (const auto& fit : fits) names.push_back(fit.name);
    throw InputError("no fit '" + name + "' in " + database.path().string() + "; stored fits: " + join(names, ", "));
  }
  // The pooled fit first, then the levels in increasing order.
  std::stable_sort(family.begin(), family.end(), [&](const FitRecord& a, const FitRecord& b) {
    const auto la = fit_level(a.name, name), lb = fit_level(b.name, name);
    if (!la || !lb) return !la && lb;
    return la->second < lb->second;
  });
  return family;
}

Figure fit_figure(RunDatabase& database, const std::string& name) {
  const auto family = fit_family(database, name);
  const FitRecord& first = family.front();
  const auto dof = force_index(first.dof);
  const auto variable = velocity_index(first.variable);
  if (!dof || !variable)
    throw InputError("fit '" + first.name + "': unknown force " + first.dof + " or velocity " + first.variable);
  Figure figure;
  figure.title = "fit " + name + " (" + first.body + ")";
  Panel panel;
  panel.x_label = axis_label(first.variable, kVelocityUnits[*variable]);
  panel.y_label = first.dof + " [" + kForceUnits[*dof] + "] (" + sign_note(first.sign) + ")";
  panel.title = "CFD runs as points, fitted law as curves";
  std::size_t colour = 0;
  for (const auto& fit : family) {
    const auto level = fit_level(fit.name, name);
    const std::string tag = level ? level->first + "=" + significant(level->second) + ": " : "";
    Series points;
    points.title = tag + "CFD runs (" + std::to_string(fit.run_ids.size()) + ")";
    points.style = Series::Style::Points;
    points.colour = colour;
    for (const auto& run : runs_by_id(database, fit.body, fit.run_ids)) {
      const auto& force = run.tau_b[*dof];
      if (!force) continue;
      points.x.push_back(run.key.nu_b[*variable]);
      points.y.push_back(to_convention(force->value.total, force->sign, fit.sign));
    }
    double lo = 0.0, hi = 0.0;
    if (!points.x.empty()) {
      lo = *std::min_element(points.x.begin(), points.x.end());
      hi = *std::max_element(points.x.begin(), points.x.end());
    }
    if (!(hi > lo)) {
      lo -= 1.0;
      hi += 1.0;
    }
    Series curve;
    curve.title = tag + law_text(fit) + ", R² = " + (std::isfinite(fit.r2) ? significant(fit.r2, 8) : "n/a");
    curve.style = Series::Style::Line;
    curve.colour = colour;
    curve.x = linspace(lo, hi, 101);
    for (double x : curve.x) curve.y.push_back(evaluate_fit(fit, x));
    panel.series.push_back(std::move(points));
    panel.series.push_back(std::move(curve));
    ++colour;
  }
  figure.panels.push_back(std::move(panel));
  return figure;
}

Figure curves_figure(RunDatabase& database, const std::string& base, CurveKind kind, int degree) {
  auto family = fit_family(database, base);
  std::vector<LevelFit> levels;
  std::string by;
  for (const auto& fit : family) {
    const auto level = fit_level(fit.name, base);
    if (!level) continue;
    if (!by.empty() && level->first != by)
      throw InputError("fits under '" + base + "' are per level of both " + by + " and " + level->first +
                       "; expected one disturbance");
    by = level->first;
    LevelFit lf;
    lf.level = level->second;
    lf.fit.spec = parse_damping_terms(fit.terms);
    for (const auto term : lf.fit.spec.terms) {
      const std::string tn = term_name(term, lf.fit.spec.variable);
      const auto it = std::find_if(fit.coefficients.begin(), fit.coefficients.end(),
                                   [&](const FitRecord::Coefficient& c) { return c.term == tn; });
      if (it == fit.coefficients.end()) throw InputError("fit '" + fit.name + "': no coefficient for term " + tn);
      lf.fit.coefficients.push_back(it->value);
    }
    lf.fit.n = fit.n;
    lf.fit.rmse = fit.rmse;
    lf.fit.r2 = fit.r2;
    levels.push_back(std::move(lf));
  }
  if (levels.size() < 2)
    throw InputError("coefficient curves of '" + base + "': found " + std::to_string(levels.size()) +
                     " per-level fit(s) named '" + base +
                     "@NAME=VALUE'; expected at least 2 (hydrocoef fit ... --by NAME)");
  const auto curves = fit_coefficient_curves(levels, kind, degree);
  const FitRecord& first = family.back();
  const auto dof = force_index(first.dof);
  const auto variable = velocity_index(first.variable);
  Figure figure;
  figure.title = "coefficients of " + base + " against " + by + " (" +
                 (kind == CurveKind::Pchip ? std::string("PCHIP") : "polynomial of degree " + std::to_string(degree)) +
                 "; " + sign_note(first.sign) + ")";
  std::size_t colour = 0;
  for (const auto& curve : curves) {
    Panel panel;
    panel.title = "coefficient of " + curve.term +
                  (kind == CurveKind::Polynomial ? ", curve RMSE " + significant(curve.rmse, 3) : std::string());
    panel.x_label = by;
    std::string unit = dof ? kForceUnits[*dof] : "";
    if (curve.term != "1" && variable) {
      const int power = curve.term.find('|') != std::string::npos && curve.term.front() != '|' ? 2
                        : curve.term.find("^2") != std::string::npos                           ? 2
                        : curve.term.find("^3") != std::string::npos                           ? 3
                                                                                               : 1;
      unit += std::string("/(") + kVelocityUnits[*variable] + ")" + (power > 1 ? "^" + std::to_string(power) : "");
    }
    panel.y_label = "c(" + curve.term + ") [" + unit + "]";
    Series points;
    points.title = "per-level fit";
    points.style = Series::Style::Points;
    points.colour = colour;
    points.x = curve.levels;
    points.y = curve.values;
    Series line;
    line.title = kind == CurveKind::Pchip ? "PCHIP" : "polynomial, degree " + std::to_string(curve.degree);
    line.style = Series::Style::Line;
    line.colour = colour;
    line.x = linspace(curve.levels.front(), curve.levels.back(), 101);
    for (double l : line.x) line.y.push_back(curve.evaluate(l));
    panel.series.push_back(std::move(points));
    panel.series.push_back(std::move(line));
    figure.panels.push_back(std::move(panel));
    ++colour;
  }
  return figure;
}

Figure surface_figure(RunDatabase& database, const std::string& name, const std::optional<std::string>& output) {
  const StoredSurface stored = load_surface(database, name);
  const CoefficientSurface& surface = stored.surface;
  if (surface.axis_count() > 2)
    throw InputError("surface '" + name + "' has " + std::to_string(surface.axis_count()) + " axes (" +
                     join(surface.axis_names(), ", ") + "); plots draw 1 or 2 axes");
  const std::size_t k = output ? surface.output_index(*output) : 0;
  const std::string out_name = surface.output_names()[k];
  const std::string out_label = axis_label(out_name, surface.output_units()[k]) + " (on body: damping negative)";
  std::vector<double> values(surface.output_count());
  auto eval = [&](std::span<const double> point) {
    surface.evaluate(point, values);
    return values[k];
  };

  // The runs it was built from, at their coordinates, with the output's force
  // value brought to forces on the body.
  Series runs;
  runs.title = "CFD runs (" + std::to_string(stored.record.run_ids.size()) + ")";
  runs.style = Series::Style::Points;
  runs.colour = 6;
  std::vector<double> run_values;
  const auto force = force_index(out_name);
  for (const auto& run : runs_by_id(database, stored.record.body, stored.record.run_ids)) {
    std::vector<double> point;
    for (const auto& axis : surface.axis_names()) {
      const auto v = key_value(run.key, axis);
      if (v) point.push_back(*v);
    }
    if (point.size() != surface.axis_count()) continue;
    double value = std::nan("");
    if (force && run.tau_b[*force]) value = to_on_body(run.tau_b[*force]->value.total, run.tau_b[*force]->sign);
    runs.x.push_back(point[0]);
    runs.y.push_back(surface.axis_count() == 1 ? value : point[1]);
    run_values.push_back(value);
  }

  Figure figure;
  figure.title = "surface " + name + " (" + stored.record.body + ", " + surface.method_name() + ")" +
                 (stored.record.stale ? " STALE: forces changed since it was built" : "");
  Panel panel;
  const double x0 = surface.lower(0), x1 = surface.upper(0);
  const double xm = 0.12 * (x1 - x0 > 0 ? x1 - x0 : 1.0);
  panel.x_range = std::array<double, 2>{x0 - xm, x1 + xm};
  panel.x_label = axis_label(surface.axis_names()[0], surface.axis_units()[0]);
  if (surface.axis_count() == 1) {
    panel.title =
        out_name + " against " + surface.axis_names()[0] + "; outside the range: " + surface.out_of_range_name(0);
    panel.y_label = out_label;
    Series line;
    line.title = "surface";
    line.x = linspace(x0, x1, 201);
    for (double x : line.x) line.y.push_back(eval(std::span<const double>(&x, 1)));
    // The continuation beyond the range, where the policy gives one.
    bool titled = false;
    for (const auto& [from, to] : {std::pair{x0 - xm, x0}, std::pair{x1, x1 + xm}}) {
      Series beyond;
      beyond.style = Series::Style::DashedLine;
      try {
        for (double x : linspace(from, to, 21)) {
          const double y = eval(std::span<const double>(&x, 1));
          beyond.x.push_back(x);
          beyond.y.push_back(y);
        }
      } catch (const InputError&) {
        beyond.x.clear();
        beyond.y.clear();
      }
      if (!beyond.x.empty()) {
        if (!titled) beyond.title = "beyond the range (" + surface.out_of_range_name(0) + ")";
        titled = true;
        panel.series.push_back(std::move(beyond));
      }
    }
    panel.series.insert(panel.series.begin(), std::move(line));
  } else {
    const double y0 = surface.lower(1), y1 = surface.upper(1);
    const double ym = 0.12 * (y1 - y0 > 0 ? y1 - y0 : 1.0);
    panel.y_range = std::array<double, 2>{y0 - ym, y1 + ym};
    panel.y_label = axis_label(surface.axis_names()[1], surface.axis_units()[1]);
    panel.title = out_name + " over " + surface.axis_names()[0] + ", " + surface.axis_names()[1] +
                  "; outside: " + surface.out_of_range_name(0) + " / " + surface.out_of_range_name(1);
    panel.map = sampled_map(x0, x1, y0, y1, out_label, eval);
    panel.shaded.push_back({x0 - xm, x1 + xm, y0 - ym, y0});
    panel.shaded.push_back({x0 - xm, x1 + xm, y1, y1 + ym});
  }
  panel.shaded.push_back({x0 - xm, x0, std::nullopt, std::nullopt});
  panel.shaded.push_back({x1, x1 + xm, std::nullopt, std::nullopt});
  panel.shaded_title = "outside the surface's range";
  panel.series.push_back(std::move(runs));
  figure.panels.push_back(std::move(panel));
  return figure;
}

Figure surface_sigma_figure(RunDatabase& database, const std::string& name, const std::optional<std::string>& output) {
  const StoredSurface stored = load_surface(database, name);
  const CoefficientSurface& surface = stored.surface;
  if (surface.axis_count() > 2)
    throw InputError("surface '" + name + "' has " + std::to_string(surface.axis_count()) + " axes (" +
                     join(surface.axis_names(), ", ") + "); plots draw 1 or 2 axes");
  if (!surface.has_standard_deviation())
    throw InputError("surface '" + name +
                     "' states no standard deviation (a grid or RBF surface stored by an older hydrocoef: surface "
                     "rebuild NAME gives it one)");
  const std::size_t k = output ? surface.output_index(*output) : 0;
  const std::string out_name = surface.output_names()[k];
  const std::string sd_label = axis_label("sd of " + out_name, surface.output_units()[k]);
  std::vector<double> values(surface.output_count()), sd(surface.output_count());
  auto sd_at = [&](std::span<const double> point) {
    surface.evaluate_with_standard_deviation(point, values, sd);
    return sd[k];
  };
  const std::string what = surface.gp() ? "the Gaussian process's predictive sd"
                                        : "the runs' uncertainty interpolated, with the leave-one-out RMS";
  Figure figure;
  figure.title = "standard deviation of surface " + name + " (" + stored.record.body + ", " + surface.method_name() +
                 ")" + (stored.record.stale ? " STALE: forces changed since it was built" : "");
  Panel panel;
  const double x0 = surface.lower(0), x1 = surface.upper(0);
  panel.x_range = std::array<double, 2>{x0, x1};
  panel.x_label = axis_label(surface.axis_names()[0], surface.axis_units()[0]);
  Series runs;
  runs.title = "CFD runs (" + std::to_string(stored.record.run_ids.size()) + ")";
  runs.style = Series::Style::Points;
  runs.colour = 6;
  std::vector<std::vector<double>> run_points;
  for (const auto& run : runs_by_id(database, stored.record.body, stored.record.run_ids)) {
    std::vector<double> point;
    for (const auto& axis : surface.axis_names())
      if (const auto v = key_value(run.key, axis)) point.push_back(*v);
    if (point.size() == surface.axis_count()) run_points.push_back(std::move(point));
  }
  if (surface.axis_count() == 1) {
    panel.title = "sd of " + out_name + " against " + surface.axis_names()[0] + ": " + what;
    panel.y_label = sd_label;
    Series line;
    line.title = "standard deviation";
    line.x = linspace(x0, x1, 201);
    for (double x : line.x) line.y.push_back(sd_at(std::span<const double>(&x, 1)));
    panel.series.push_back(std::move(line));
    for (const auto& point : run_points) {
      runs.x.push_back(point[0]);
      runs.y.push_back(sd_at(point));
    }
  } else {
    const double y0 = surface.lower(1), y1 = surface.upper(1);
    panel.y_range = std::array<double, 2>{y0, y1};
    panel.y_label = axis_label(surface.axis_names()[1], surface.axis_units()[1]);
    panel.title =
        "sd of " + out_name + " over " + surface.axis_names()[0] + ", " + surface.axis_names()[1] + ": " + what;
    panel.map = sampled_map(x0, x1, y0, y1, sd_label, sd_at);
    for (const auto& point : run_points) {
      runs.x.push_back(point[0]);
      runs.y.push_back(point[1]);
    }
  }
  panel.series.push_back(std::move(runs));
  figure.panels.push_back(std::move(panel));
  return figure;
}

Figure simulation_figure(const std::filesystem::path& trajectory,
                         const std::optional<std::filesystem::path>& experiment, const std::string& component) {
  const auto index = velocity_index(component);
  if (!index) throw InputError("--component '" + component + "': expected one of u, v, w, p, q, r");
  const MeasuredTrajectory simulated = read_measured_trajectory(trajectory);
  if (simulated.nu_b[*index].empty())
    throw InputError(trajectory.string() + ": no column " + component +
                     " (expected a trajectory from hydrocoef simulate --out)");
  Figure figure;
  figure.title = "simulation: " + component + " against time";
  Panel panel;
  panel.x_label = "t [s]";
  panel.y_label = axis_label(component, kVelocityUnits[*index]) + " (body axes)";
  panel.title = trajectory.filename().string() + (experiment ? " and " + experiment->filename().string() : "");
  // A Monte Carlo run's band first (behind), between its outer percentiles,
  // and its median; then the nominal trajectory; the experiment on top.
  const auto& bands = simulated.bands_b[*index];
  if (bands.size() >= 2) {
    Series band;
    band.title = "simulated p" + significant(bands.front().first) + "-p" + significant(bands.back().first) +
                 " over the damping's uncertainty";
    band.style = Series::Style::Band;
    band.colour = 0;
    band.x = simulated.t_s;
    band.y = bands.front().second;
    band.y_high = bands.back().second;
    panel.series.push_back(std::move(band));
    for (const auto& [percentile, values] : bands)
      if (percentile == 50.0) {
        Series median;
        median.title = "simulated median (p50)";
        median.style = Series::Style::DashedLine;
        median.colour = 0;
        median.x = simulated.t_s;
        median.y = values;
        panel.series.push_back(std::move(median));
      }
  }
  Series sim;
  sim.title = "simulated (" + trajectory.filename().string() + ")";
  sim.x = simulated.t_s;
  sim.y = simulated.nu_b[*index];
  panel.series.push_back(std::move(sim));
  if (experiment) {
    const MeasuredTrajectory measured = read_measured_trajectory(*experiment);
    if (measured.nu_b[*index].empty())
      throw InputError(experiment->string() + ": no column " + component + " to compare with");
    Series points;
    points.title = "measured (" + experiment->filename().string() + ")";
    points.style = Series::Style::Points;
    points.colour = 1;
    points.x = measured.t_s;
    points.y = measured.nu_b[*index];
    panel.series.push_back(std::move(points));
  }
  figure.panels.push_back(std::move(panel));
  return figure;
}

std::vector<SteadyPoint> steady_curve(const VehicleModel& model, std::size_t dof, const std::vector<double>& taus) {
  if (dof > 5) throw InputError("steady curve: DOF index " + std::to_string(dof) + " is not one of X..N");
  std::vector<SteadyPoint> out;
  Vector6 guess = Vector6::Zero();
  for (double tau : taus) {
    EquilibriumInputs in;
    in.tau_b[static_cast<Eigen::Index>(dof)] = tau;
    in.disturbances.assign(model.disturbance_names().size(), 0.0);
    in.initial_guess_b = guess;
    const EquilibriumResult eq = solve_equilibrium(model, in);
    if (!eq.converged)
      throw InputError("no steady state under " + std::string(kForceNames[dof]) + " = " + significant(tau) + " " +
                       kForceUnits[dof] + " (the solver's residual stays at " +
                       significant(eq.residual_b.cwiseAbs().maxCoeff(), 3) + ")");
    guess = eq.nu_b;
    out.push_back({tau, eq.nu_b[static_cast<Eigen::Index>(dof)]});
  }
  return out;
}

Figure steady_figure(const VehicleModel& model, std::size_t dof, const std::vector<double>& taus,
                     const std::vector<SteadyPoint>& measured, const std::string& vehicle_name,
                     const SteadyBandOptions* band_options) {
  if (taus.empty()) throw InputError("steady curve: no forces to solve for");
  const auto points = steady_curve(model, dof, taus);
  Figure figure;
  figure.title = "steady " + std::string(kVelocityNames[dof]) + " against " + std::string(kForceNames[dof]) + " (" +
                 vehicle_name + ", equilibrium, attitude held)";
  Panel panel;
  panel.x_label = std::string(kForceNames[dof]) + " [" + kForceUnits[dof] + "] (applied, on body)";
  panel.y_label = axis_label(std::string(kVelocityNames[dof]), kVelocityUnits[dof]);
  if (band_options) {
    // The equilibrium's interval at each force over the damping's draws.
    const auto d = static_cast<Eigen::Index>(dof);
    Series band;
    const auto& percentiles = band_options->options.percentiles;
    band.title = "p" + significant(percentiles.front()) + "-p" + significant(percentiles.back()) + " of " +
                 std::to_string(band_options->options.samples) + " draws of the damping";
    band.style = Series::Style::Band;
    for (std::size_t i = 0; i < taus.size(); ++i) {
      EquilibriumInputs in;
      in.tau_b[d] = taus[i];
      in.disturbances.assign(model.disturbance_names().size(), 0.0);
      Vector6 guess = Vector6::Zero();
      guess[d] = points[i].velocity;
      in.initial_guess_b = guess;
      const EquilibriumSamples s = solve_equilibrium_samples(model, band_options->draws, in, band_options->options);
      if (s.failures.count > 0)
        throw InputError("steady band under " + std::string(kForceNames[dof]) + " = " + significant(taus[i]) + " " +
                         kForceUnits[dof] + ": " + std::to_string(s.failures.count) + " draws have no equilibrium; " +
                         s.failures.first.front());
      band.x.push_back(taus[i]);
      band.y.push_back(s.percentile_values.front()[d]);
      band.y_high.push_back(s.percentile_values.back()[d]);
    }
    panel.series.push_back(std::move(band));
  }
  Series line;
  line.title = "model (equilibrium)";
  for (const auto& p : points) {
    line.x.push_back(p.tau);
    line.y.push_back(p.velocity);
  }
  panel.series.push_back(line);
  if (points.size() <= 12) {
    line.title = "";
    line.style = Series::Style::Points;
    panel.series.push_back(line);
  }
  if (!measured.empty()) {
    Series m;
    m.title = "measured";
    m.style = Series::Style::Points;
    m.colour = 1;
    for (const auto& p : measured) {
      m.x.push_back(p.tau);
      m.y.push_back(p.velocity);
    }
    panel.series.push_back(std::move(m));
  }
  figure.panels.push_back(std::move(panel));
  return figure;
}

std::vector<SteadyPoint> read_steady_points(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path.string() + ": cannot open the measured steady points");
  std::vector<SteadyPoint> out;
  std::string line;
  std::size_t number = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line[start] == '#') continue;
    if (!header) {
      header = true;
      continue;
    }
    for (char& c : line)
      if (c == ';' || c == '\t') c = ',';
    const auto comma = line.find(',');
    SteadyPoint p;
    try {
      if (comma == std::string::npos) throw std::invalid_argument("one column");
      std::size_t used = 0;
      p.tau = std::stod(line.substr(0, comma), &used);
      p.velocity = std::stod(line.substr(comma + 1), &used);
    } catch (const std::exception&) {
      throw InputError(SourceLocation{path.string(), number, 0}, "found '" + line +
                                                                     "', expected two numbers: force [N or N m], "
                                                                     "velocity [m/s or rad/s]");
    }
    if (!std::isfinite(p.tau) || !std::isfinite(p.velocity))
      throw InputError(SourceLocation{path.string(), number, 0}, "a value is not finite");
    out.push_back(p);
  }
  if (out.empty()) throw InputError(path.string() + ": no rows after the header (expected force,velocity rows)");
  return out;
}

}  // namespace hydrocoef::plot
