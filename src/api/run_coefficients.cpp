// The runs' non-dimensional coefficients, Reynolds and Froude numbers
// (`hydrocoef runs --coefficients`): include/hydrocoef/reference.hpp. The
// arithmetic is src/loads/force_coefficients; the reference data is the
// body's (src/store/body_reference.hpp).
#include "src/api/internal.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/core/sign_convention.hpp"
#include "src/loads/force_coefficients.hpp"
#include "src/store/body_reference.hpp"

#include <cmath>
#include <iomanip>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

namespace hydrocoef {
inline namespace api {
namespace {

constexpr std::array<const char*, 6> kCoefficientNames = {"C_X", "C_Y", "C_Z", "C_K", "C_M", "C_N"};

std::string quote_name(const std::string& name) { return "'" + printable_text(name, 80) + "'"; }

std::string area_list(const std::map<std::string, double>& areas) {
  std::string out;
  for (const auto& [name, value] : areas) out += (out.empty() ? "" : ", ") + quote_name(name);
  return out;
}

/// The reference a body's coefficients use, or InputError saying what to give.
CoefficientReference reference_of(const std::string& body, const std::optional<BodyReferenceRecord>& record,
                                  const std::string& area, const SourceLocation& where) {
  const std::string fix = "; give it with 'hydrocoef body set NAME ";
  if (!record || !record->length)
    throw InputError(where, "body " + quote_name(body) + " has no reference length" + fix +
                                "--length L' (and a reference area with --area NAME=A)");
  if (record->areas.empty())
    throw InputError(where, "body " + quote_name(body) + " has no reference area" + fix + "--area NAME=A'");
  std::string name = area.empty() ? record->default_area : area;
  if (name.empty())
    throw InputError(where, "body " + quote_name(body) + " has several reference areas (" + area_list(record->areas) +
                                ") and no default; choose one with --area NAME, or set a default with 'hydrocoef "
                                "body set NAME --default-area AREA'");
  const auto found = record->areas.find(name);
  if (found == record->areas.end())
    throw InputError(where, "--area " + quote_name(name) + ": body " + quote_name(body) +
                                " has no such area (areas: " + area_list(record->areas) + ")");
  CoefficientReference out;
  out.body = body;
  out.area_name = name;
  out.area = found->second;
  out.length = *record->length;
  out.moment_reference_point =
      record->moment_point_b ? *record->moment_point_b : std::array<double, 3>{kNaN, kNaN, kNaN};
  return out;
}

}  // namespace

void CoefficientOptions::validate() const { (void)parse_selection(where, exclude_runs); }

RunCoefficients run_coefficients(const Database& database, const CoefficientOptions& options) {
  options.validate();
  const RunSelection selection = parse_selection(options.where, options.exclude_runs);
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  auto& store = impl.open_store();
  RunFilter filter;
  if (!options.body.empty()) filter.body = options.body;
  auto runs = store.runs(filter);
  std::erase_if(runs, [&](const StoredRun& run) { return !selection.matches(run.key, run.id); });
  std::map<std::string, BodyReferenceRecord> records;
  for (auto& record : store.body_references()) records.emplace(record.body, std::move(record));

  RunCoefficients out;
  out.database = impl.path;
  out.gravity = kStandardGravity;
  std::map<std::string, CoefficientReference> references;
  for (const auto& run : runs)
    if (!references.count(run.key.body)) {
      const auto found = records.find(run.key.body);
      references.emplace(
          run.key.body, reference_of(run.key.body, found == records.end() ? std::nullopt : std::optional(found->second),
                                     options.area, SourceLocation{impl.path}));
    }
  for (const auto& [name, reference] : references) out.references.push_back(reference);
  for (const auto& run : runs)
    for (const auto& [name, value] : run.key.disturbances) (void)out.disturbances[name];
  for (auto& [name, column] : out.disturbances) column.assign(runs.size(), kNaN);

  for (const auto& run : runs) {
    const CoefficientReference& ref = references.at(run.key.body);
    out.id.push_back(run.id);
    out.body.push_back(run.key.body);
    for (std::size_t c = 0; c < 6; ++c) out.velocity[c].push_back(run.key.nu_b[c]);
    for (const auto& [name, value] : run.key.disturbances) out.disturbances[name][out.id.size() - 1] = value;
    const double U = speed_through_water(run.key.nu_b);
    const double rho = run.fluid.density_kg_m3.value_or(kNaN);
    const double nu = run.fluid.kinematic_viscosity_m2_s.value_or(kNaN);
    out.speed.push_back(U);
    out.density.push_back(rho);
    out.kinematic_viscosity.push_back(nu);
    out.reynolds.push_back(std::isfinite(nu) ? reynolds_number(U, ref.length, nu) : kNaN);
    out.froude.push_back(froude_number(U, ref.length));

    std::vector<std::string> notes;
    if (!std::isfinite(rho))
      notes.push_back("no density: no coefficient (import the run with --rho, or rho in its settings)");
    else if (U == 0.0)
      notes.push_back("U = 0: no dynamic pressure, no coefficient");
    if (!std::isfinite(nu))
      notes.push_back("no kinematic viscosity: no Re (import the run with --nu, or nu in its settings)");
    // Forces on the body: a damping magnitude as tabulated is negated.
    std::array<double, 6> tau{kNaN, kNaN, kNaN, kNaN, kNaN, kNaN};
    for (std::size_t c = 0; c < 6; ++c)
      if (run.tau_b[c]) tau[c] = to_on_body(run.tau_b[c]->value.total, run.tau_b[c]->sign);
    // Moments about the body's moment reference point: M_P = M_O + (O - P) x F,
    // which needs the force components the lever arm (O - P) multiplies.
    std::array<double, 3> moment{tau[3], tau[4], tau[5]};
    if (std::isfinite(ref.moment_reference_point[0])) {
      moment = moment_about(moment, {tau[0], tau[1], tau[2]}, run.reference_point_b, ref.moment_reference_point);
      std::string missing;
      for (std::size_t i = 0; i < 3; ++i)
        if (std::isfinite(tau[3 + i]) && !std::isfinite(moment[i]))
          missing += std::string(missing.empty() ? "" : ", ") + kCoefficientNames[3 + i];
      if (!missing.empty())
        notes.push_back("no " + missing +
                        ": moving the moment from the run's reference point to the body's needs "
                        "the force components the run lacks");
    }
    const bool dimensional = std::isfinite(rho) && U != 0.0;
    for (std::size_t c = 0; c < 6; ++c) {
      const double value = c < 3 ? tau[c] : moment[c - 3];
      double coefficient = kNaN;
      if (dimensional && std::isfinite(value))
        coefficient = c < 3 ? force_coefficient(value, rho, U, ref.area)
                            : moment_coefficient(value, rho, U, ref.area, ref.length);
      out.coefficient[c].push_back(coefficient);
    }
    std::string note;
    for (const auto& n : notes) note += (note.empty() ? "" : "; ") + n;
    out.note.push_back(note);
  }
  return out;
}

// ---- text, JSON, CSV ------------------------------------------------------------

namespace {

constexpr const char* kFormulas =
    "C_F = F / (1/2 rho U^2 A) (X, Y, Z), C_M = M / (1/2 rho U^2 A L) (K, M, N), Re = U L / nu, Fn = U / sqrt(g L), "
    "g = 9.80665 m/s^2; U = |(u, v, w)|, the speed through the water; rho and nu the run's";
constexpr const char* kAxes =
    "body axes (x forward, y starboard, z down), forces on the body (C_X < 0: a drag for u > 0)";

nlohmann::json optional_json(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(); }

std::string point_text(const std::array<double, 3>& p) {
  if (!std::isfinite(p[0])) return "each run's own reference point";
  return "(" + significant(p[0], 8) + ", " + significant(p[1], 8) + ", " + significant(p[2], 8) + ") m";
}

std::string cell(const std::string& text, std::size_t width) {
  return text.size() >= width ? text + " " : text + std::string(width - text.size(), ' ');
}

std::string number_cell(double value, std::size_t width) {
  return cell(std::isfinite(value) ? significant(value, 6) : "-", width);
}

}  // namespace

std::string RunCoefficients::text() const {
  if (id.empty()) return "no runs selected in " + escape::one_line(database) + "\n";
  std::ostringstream out;
  out << "coefficients of " << id.size() << (id.size() == 1 ? " run" : " runs") << " in " << escape::one_line(database)
      << '\n';
  for (const auto& r : references)
    out << "body '" << escape::one_line(r.body) << "': area '" << escape::one_line(r.area_name)
        << "' A = " << significant(r.area, 8) << " m^2, L = " << significant(r.length, 8) << " m, moments about "
        << point_text(r.moment_reference_point) << '\n';
  std::array<bool, 6> velocity_used{}, coefficient_used{};
  for (std::size_t i = 0; i < id.size(); ++i)
    for (std::size_t c = 0; c < 6; ++c) {
      velocity_used[c] = velocity_used[c] || velocity[c][i] != 0.0;
      coefficient_used[c] = coefficient_used[c] || std::isfinite(coefficient[c][i]);
    }
  bool any_note = false;
  for (const auto& n : note) any_note = any_note || !n.empty();
  std::ostringstream header;
  header << std::left << std::setw(6) << "id" << std::setw(12) << "body";
  for (std::size_t c = 0; c < 6; ++c)
    if (velocity_used[c]) header << std::setw(11) << kVelocityNames[c];
  header << std::setw(11) << "U" << std::setw(11) << "rho" << std::setw(13) << "Re" << std::setw(11) << "Fn";
  for (std::size_t c = 0; c < 6; ++c)
    if (coefficient_used[c]) header << std::setw(13) << kCoefficientNames[c];
  if (!disturbances.empty()) header << std::setw(24) << "disturbances";
  header << (any_note ? "note" : "");
  std::string head = header.str();
  while (!head.empty() && head.back() == ' ') head.pop_back();
  out << head << '\n';
  for (std::size_t i = 0; i < id.size(); ++i) {
    std::string line = cell(std::to_string(id[i]), 6) + cell(escape::one_line(body[i]), 12);
    for (std::size_t c = 0; c < 6; ++c)
      if (velocity_used[c]) line += number_cell(velocity[c][i], 11);
    line += number_cell(speed[i], 11) + number_cell(density[i], 11) + number_cell(reynolds[i], 13) +
            number_cell(froude[i], 11);
    for (std::size_t c = 0; c < 6; ++c)
      if (coefficient_used[c]) line += number_cell(coefficient[c][i], 13);
    if (!disturbances.empty()) {
      std::string text;
      for (const auto& [name, column] : disturbances)
        if (std::isfinite(column[i])) text += (text.empty() ? "" : " ") + name + "=" + significant(column[i], 6);
      line += cell(escape::one_line(text), 24);
    }
    line += escape::one_line(note[i]);
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out << line << '\n';
  }
  out << kFormulas << "; " << kAxes << "; '-': not defined (see the note)\n";
  return out.str();
}

std::string RunCoefficients::json() const {
  nlohmann::json refs = nlohmann::json::array();
  for (const auto& r : references)
    refs.push_back(
        {{"body", r.body},
         {"area_name", r.area_name},
         {"area", r.area},
         {"length", r.length},
         {"moment_reference_point",
          std::isfinite(r.moment_reference_point[0]) ? nlohmann::json(r.moment_reference_point) : nlohmann::json()}});
  nlohmann::json list = nlohmann::json::array();
  for (std::size_t i = 0; i < id.size(); ++i) {
    nlohmann::json run = {{"id", id[i]}, {"body", body[i]}};
    for (std::size_t c = 0; c < 6; ++c) run[std::string(kVelocityNames[c])] = velocity[c][i];
    run["disturbances"] = nlohmann::json::object();
    for (const auto& [name, column] : disturbances)
      if (std::isfinite(column[i])) run["disturbances"][name] = column[i];
    run["speed"] = speed[i];
    run["density"] = optional_json(density[i]);
    run["kinematic_viscosity"] = optional_json(kinematic_viscosity[i]);
    run["reynolds"] = optional_json(reynolds[i]);
    run["froude"] = optional_json(froude[i]);
    run["coefficients"] = nlohmann::json::object();
    for (std::size_t c = 0; c < 6; ++c) run["coefficients"][kCoefficientNames[c]] = optional_json(coefficient[c][i]);
    run["note"] = note[i];
    list.push_back(std::move(run));
  }
  return escape::json_text({{"database", database},
                            {"formulas", kFormulas},
                            {"axes", kAxes},
                            {"gravity", gravity},
                            {"references", refs},
                            {"runs", list}},
                           2) +
         '\n';
}

std::string RunCoefficients::csv() const {
  std::map<std::string, const CoefficientReference*> by_body;
  for (const auto& r : references) by_body[r.body] = &r;
  std::string out = "id,body,u,v,w,p,q,r";
  for (const auto& [name, column] : disturbances) out += "," + escape::csv_text(name);
  out += ",U,rho,nu,area_name,A,L,Re,Fn,C_X,C_Y,C_Z,C_K,C_M,C_N,note\n";
  const auto number = [&](double value) {
    out += ',';
    if (std::isfinite(value)) append_shortest_number(out, value);
  };
  for (std::size_t i = 0; i < id.size(); ++i) {
    out += std::to_string(id[i]) + "," + escape::csv_text(body[i]);
    for (std::size_t c = 0; c < 6; ++c) number(velocity[c][i]);
    for (const auto& [name, column] : disturbances) number(column[i]);
    number(speed[i]);
    number(density[i]);
    number(kinematic_viscosity[i]);
    const CoefficientReference& ref = *by_body.at(body[i]);
    out += "," + escape::csv_text(ref.area_name);
    number(ref.area);
    number(ref.length);
    number(reynolds[i]);
    number(froude[i]);
    for (std::size_t c = 0; c < 6; ++c) number(coefficient[c][i]);
    out += "," + escape::csv_text(note[i]) + "\n";
  }
  return out;
}

}  // namespace api
}  // namespace hydrocoef
