// export_gazebo (include/hydrocoef/exports.hpp): `hydrocoef export-gazebo`, a
// body's stored damping-law fits and an added mass as the parameters of
// Gazebo's underwater plugins (src/export/gazebo_export), and what the
// command prints about them.
#include "src/api/internal.hpp"
#include "src/api/surface_report.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

#include "src/core/escape.hpp"
#include "src/core/matrix6.hpp"
#include "src/core/numbers.hpp"
#include "src/core/sign_convention.hpp"
#include "src/core/text.hpp"
#include "src/dynamics/rigid_body.hpp"
#include "src/export/gazebo_export.hpp"
#include "src/pmm/added_mass_assembly.hpp"
#include "src/pmm/imposed_motion.hpp"

namespace hydrocoef {
inline namespace api {
namespace {

using surface_text::significant;

std::vector<double> parse_numbers(const std::string& text, std::size_t count, const std::string& option,
                                  const std::string& what) {
  std::vector<double> out;
  for (const std::string_view item : split(text, ',')) {
    double value = 0.0;
    const auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), value);
    if (item.empty() || ec != std::errc() || end != item.data() + item.size() || !std::isfinite(value))
      throw InputError(option + " '" + text + "': found '" + std::string(item) + "', expected " + what);
    out.push_back(value);
  }
  if (out.size() != count)
    throw InputError(option + " '" + text + "': " + std::to_string(out.size()) + " numbers; expected " + what);
  return out;
}

/// "NAME=TEXT", as the CLI's parse_text_assignment reads it.
std::pair<std::string, std::string> assignment(const std::string& text, const std::string& option) {
  const auto equals = text.find('=');
  if (equals == std::string::npos || equals == 0) throw InputError(option + " '" + text + "': expected NAME=VALUE");
  return {text.substr(0, equals), text.substr(equals + 1)};
}

/// --same DOF=DOF and --zero DOF of the added mass from stored runs.
AddedMassOptions assembly_options(const GazeboExportOptions& options) {
  std::map<std::string, std::string> same;
  for (const auto& text : options.same) {
    const auto [dof, from] = assignment(text, "--same");
    same[dof] = from;
  }
  return added_mass_options(same, options.zero, options.added_mass_period);
}

GazeboWriteOptions write_options(const GazeboExportOptions& options) {
  GazeboWriteOptions out;
  out.flavor = parse_gazebo_flavor(options.flavor);
  if (options.link) out.link_name = *options.link;
  if (options.link_axes) out.link_axes = parse_gazebo_link_axes(*options.link_axes);
  return out;
}

/// The added-mass matrix from its one source, and a sentence saying where it
/// came from. `store` is read for added_mass_from_database.
std::pair<Matrix6, std::string> added_mass(const GazeboExportOptions& options, RunDatabase& store) {
  if (options.added_mass_from_database) {
    const std::string& body = *options.added_mass_from_database;
    const AddedMassAssembly assembly =
        assemble_added_mass(body, store.pmm_records(body, false), assembly_options(options));
    if (!assembly.missing.empty()) {
      std::string list;
      for (const auto& m : assembly.missing) list += (list.empty() ? "" : "; ") + m;
      throw InputError("--added-mass-from-database " + printable_text(body, 80) + ": the stored runs lack " + list +
                       "; expected runs of those DOFs, or --same/--zero for them");
    }
    return {assembly.added_mass,
            "assembled from " + std::to_string(assembly.records) + " forced-oscillation runs of body '" + body + "'"};
  }
  if (options.added_mass) {
    const auto d = parse_numbers(*options.added_mass, 6, "--added-mass",
                                 "six numbers Xu' Yv' Zw' (kg) Kp' Mq' Nr' (kg m^2), comma-separated");
    return {added_mass_diagonal({d[0], d[1], d[2], d[3], d[4], d[5]}),
            "diagonal " + *options.added_mass + " (kg x3, kg m^2 x3)"};
  }
  if (options.added_mass_matrix)
    return {read_added_mass_matrix(*options.added_mass_matrix),
            "6x6 matrix from '" + *options.added_mass_matrix + "' (kg, kg m, kg m^2)"};
  std::optional<Vector3> rotation;
  std::string rotation_text;
  if (options.added_mass_rotation) {
    const auto r =
        parse_numbers(*options.added_mass_rotation, 3, "--added-mass-rotation", "three numbers a,b,c in kg m^2");
    rotation = Vector3(r[0], r[1], r[2]);
    rotation_text = ", rotation " + *options.added_mass_rotation + " kg m^2 as given";
  }
  const Matrix6 ma = sphere_added_mass(*options.rho, *options.sphere_radius, rotation);
  return {ma, "sphere of radius " + shortest_number(*options.sphere_radius) + " m in fluid of density " +
                  shortest_number(*options.rho) + " kg/m^3: 2/3 pi rho R^3 = " + significant(ma(0, 0)) +
                  " kg in each translation" + rotation_text};
}

std::vector<double> flat(const Matrix6& m) {
  const auto entries = row_major(m);
  return {entries.begin(), entries.end()};
}

std::string report_json(const GazeboExportResult& r) {
  nlohmann::json out = {{"body", r.body},
                        {"flavor", r.flavor},
                        {"file", r.file},
                        {"sign_convention", "on-body"},
                        {"frame", r.frame},
                        {"linear_b", r.linear_b},
                        {"quadratic_b", r.quadratic_b},
                        {"added_mass_b", r.added_mass_b},
                        {"added_mass_source", r.added_mass_source},
                        {"notes", r.notes}};
  if (r.flavor == "gz") out["link_name"] = r.link_name;
  out["linearized_at"] = std::isnan(r.linearized_at) ? nlohmann::json() : nlohmann::json(r.linearized_at);
  out["fits"] = nlohmann::json::array();
  for (const GazeboFitExport& s : r.fits) {
    nlohmann::json fit = {{"dof", s.dof},
                          {"variable", s.variable},
                          {"name", s.name},
                          {"id", s.id},
                          {"terms", s.terms},
                          {"stored_sign", s.stored_sign},
                          {"linear", s.linear},
                          {"quadratic", s.quadratic},
                          {"units", {{"linear", s.linear_unit}, {"quadratic", s.quadratic_unit}}},
                          {"runs", s.runs}};
    fit["dropped_constant"] = std::isnan(s.dropped_constant) ? nlohmann::json() : nlohmann::json(s.dropped_constant);
    out["fits"].push_back(fit);
  }
  out["missing"] = r.missing;
  for (const auto& e : r.elements) {
    out["elements"][e.name] = e.values.size() == 1 ? nlohmann::json(e.values.front()) : nlohmann::json(e.values);
    out["units"][e.name] = e.unit;
  }
  return escape::json_text(out, 2) + '\n';
}

std::string report_text(const GazeboCoefficients& coefficients, const std::vector<GazeboElement>& elements,
                        const GazeboWriteOptions& options, const std::string& output) {
  const bool gz = options.flavor == GazeboFlavor::Gz;
  std::ostringstream out;
  out << "exported body " << escape::one_line(coefficients.body) << " as "
      << (gz ? "gz-sim Hydrodynamics parameters (link '" + escape::one_line(options.link_name) + "', link axes " +
                   (options.link_axes == GazeboLinkAxes::Flu ? "FLU" : "FRD") + ")"
             : std::string("a uuv_simulator fossen model (FRD)"))
      << ", on-body SNAME signs (damping negative)\n";
  static const std::string kForceLetters = "xyzkmn";
  for (std::size_t dof = 0; dof < 6; ++dof) {
    out << "  " << gazebo_dof_name(dof) << ":";
    if (gz) {
      bool first = true;
      for (const GazeboElement& e : elements) {
        if (kForceLetters.find(e.name.front()) != dof) continue;
        out << (first ? " " : ", ") << escape::one_line(e.name) << " = " << significant(e.values.front()) << " "
            << escape::one_line(e.unit);
        first = false;
      }
    } else {
      out << " linear " << significant(coefficients.linear_b(dof, dof)) << " " << damping_unit(dof, dof, false)
          << ", quadratic " << significant(coefficients.quadratic_b(dof, dof)) << " " << damping_unit(dof, dof, true)
          << ", added mass " << significant(coefficients.added_mass_b(dof, dof)) << " " << (dof < 3 ? "kg" : "kg m^2");
    }
    out << '\n';
    for (const GazeboFitSource& s : coefficients.sources) {
      if (s.dof != dof) continue;
      out << "     " << gazebo_dof_name(s.dof) << " in " << gazebo_velocity_name(s.variable) << " from fit '"
          << escape::one_line(s.fit_name) << "' (" << to_string(s.stored_sign)
          << (s.stored_sign == SignConvention::OpposingMotion ? ", negated to on-body" : "") << ", " << s.run_ids.size()
          << " runs)\n";
    }
  }
  out << "  added mass: " << escape::one_line(coefficients.added_mass_source) << "; symmetric positive semi-definite\n";
  for (const std::string& note : coefficients.notes) out << "  note: " << escape::one_line(note) << '\n';
  out << "  wrote " << escape::one_line(output) << '\n';
  return out.str();
}

}  // namespace

void GazeboExportOptions::validate() const {
  // In the order the command line has always checked them.
  const GazeboWriteOptions writing = write_options(*this);
  if (writing.flavor == GazeboFlavor::Uuv && (link || link_axes))
    throw InputError(std::string(link ? "--link" : "--link-axes") +
                     " applies to --flavor gz only; expected it with gz (uuv_simulator assumes an FLU link and "
                     "converts to FRD itself)");
  for (const std::string& choice : fits) (void)assignment(choice, "--fit");
  const int sources = int(added_mass.has_value()) + int(added_mass_matrix.has_value()) +
                      int(sphere_radius.has_value()) + int(added_mass_from_database.has_value());
  if (sources != 1)
    throw InputError(std::string(sources == 0 ? "no added mass given" : "more than one added mass given") +
                     "; expected exactly one of --added-mass d1,...,d6, --added-mass-matrix FILE, --sphere-radius "
                     "R --rho RHO --added-mass-rotation a,b,c or --added-mass-from-database BODY");
  if ((!same.empty() || !zero.empty() || added_mass_period) && !added_mass_from_database)
    throw InputError(
        "--same, --zero and --added-mass-period apply to --added-mass-from-database only; expected it with them");
  if (added_mass_from_database) return;
  if (rho && !sphere_radius) throw InputError("--rho applies to --sphere-radius only; expected both");
  if (added_mass_rotation && !sphere_radius)
    throw InputError(
        "--added-mass-rotation applies to --sphere-radius only; expected both (or give the whole "
        "diagonal with --added-mass)");
  if (added_mass)
    (void)parse_numbers(*added_mass, 6, "--added-mass",
                        "six numbers Xu' Yv' Zw' (kg) Kp' Mq' Nr' (kg m^2), comma-separated");
  if (sphere_radius && !rho) throw InputError("--sphere-radius needs --rho RHO (fluid density, kg/m^3)");
  if (added_mass_rotation)
    (void)parse_numbers(*added_mass_rotation, 3, "--added-mass-rotation", "three numbers a,b,c in kg m^2");
}

GazeboExportResult export_gazebo(const Database& db, const GazeboExportOptions& options) {
  options.validate();
  const GazeboWriteOptions writing = write_options(options);
  GazeboRequest request;
  request.body = options.body;
  for (const std::string& choice : options.fits) request.fits.push_back(assignment(choice, "--fit"));
  request.drop_constant = options.drop_constant;
  request.allow_missing = options.allow_missing;
  request.allow_unphysical = options.allow_unphysical;
  request.linearize_at = options.linearize_at;

  auto& impl = Database::Access::impl(db);
  const std::lock_guard lock(impl.mutex);
  RunDatabase& store = impl.open_store();
  std::tie(request.added_mass, request.added_mass_source) = added_mass(options, store);
  // --where picks the fits made from that selection of runs (a filtered fit
  // or one level of a per-level fit), e.g. the model at one current.
  const auto fits = fits_made_from(store, options.body, parse_selection(options.where, options.exclude_runs));
  const GazeboCoefficients coefficients = gazebo_coefficients(fits, request);
  const std::vector<GazeboElement> elements = gazebo_elements(coefficients, writing);
  write_gazebo(coefficients, writing, options.output);

  GazeboExportResult r;
  const bool gz = writing.flavor == GazeboFlavor::Gz;
  r.body = coefficients.body;
  r.flavor = std::string(gazebo_flavor_name(writing.flavor));
  r.file = options.output;
  r.frame = gz ? (writing.link_axes == GazeboLinkAxes::Flu ? "flu" : "frd") : "frd";
  if (gz) r.link_name = writing.link_name;
  r.linear_b = flat(coefficients.linear_b);
  r.quadratic_b = flat(coefficients.quadratic_b);
  r.added_mass_b = flat(coefficients.added_mass_b);
  r.added_mass_source = coefficients.added_mass_source;
  r.linearized_at = coefficients.linearized_at.value_or(std::numeric_limits<double>::quiet_NaN());
  for (const GazeboFitSource& s : coefficients.sources)
    r.fits.push_back({std::string(gazebo_dof_name(s.dof)), std::string(gazebo_velocity_name(s.variable)), s.fit_name,
                      s.fit_id, s.terms, std::string(to_string(s.stored_sign)), s.linear, s.quadratic,
                      damping_unit(s.dof, s.variable, false), damping_unit(s.dof, s.variable, true), s.run_ids,
                      s.dropped_constant.value_or(std::numeric_limits<double>::quiet_NaN())});
  for (std::size_t dof : coefficients.missing_dofs) r.missing.push_back(std::string(gazebo_dof_name(dof)));
  for (const GazeboElement& e : elements) r.elements.push_back({e.name, e.values, e.unit});
  r.notes = coefficients.notes;
  GazeboExportResult::Access::set(r, report_text(coefficients, elements, writing, options.output), report_json(r));
  return r;
}

std::string GazeboExportResult::text() const { return text_; }
std::string GazeboExportResult::json() const { return json_; }

}  // namespace api
}  // namespace hydrocoef
