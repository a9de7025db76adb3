// Stored derivative models as files for other tools
// (include/hydrocoef/exports.hpp, export_derivatives): `hydrocoef
// derivatives export` without its printing. The models are read as
// `derivatives show` reads them (show_derivative_model, which also refuses a
// non-dimensional form's missing reference values and unknown variables),
// made derivative sets and written by the library's exporters
// (src/export/derivative_export.hpp, derivative_gazebo_export.hpp,
// derivative_matlab_export.hpp). What the command prints is
// derivative_exports_report.cpp.
#include "src/api/internal.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <set>

#include "hydrocoef/derivatives.hpp"
#include "hydrocoef/exports.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/core/text.hpp"
#include "src/export/derivative_export.hpp"
#include "src/export/derivative_gazebo_export.hpp"
#include "src/export/derivative_matlab_export.hpp"

namespace hydrocoef {
inline namespace api {
namespace {

constexpr std::array<std::string_view, 4> kFormats{"csv", "json", "gazebo", "matlab"};

/// Six finite numbers "d1,...,d6" of an option.
std::array<double, 6> six_numbers(const std::string& text, const std::string& option, const std::string& what) {
  std::array<double, 6> out{};
  std::size_t count = 0;
  for (const std::string_view item : split(text, ',')) {
    double value = 0.0;
    const auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), value);
    if (item.empty() || ec != std::errc() || end != item.data() + item.size() || !std::isfinite(value))
      throw InputError(option + " '" + escape::one_line(text) + "': found '" + escape::one_line(item) + "', expected " +
                       what);
    if (count < 6) out[count] = value;
    ++count;
  }
  if (count != 6)
    throw InputError(option + " '" + escape::one_line(text) + "': " + std::to_string(count) + " numbers; expected " +
                     what);
  return out;
}

const std::string kAddedMassWhat = "six numbers Xu' Yv' Zw' (kg) Kp' Mq' Nr' (kg m^2), comma-separated";
const std::string kMassWhat =
    "six numbers m+Xu', m+Yv', m+Zw' (kg), Ixx+Kp', Iyy+Mq', Izz+Nr' (kg m^2), comma-separated";

DerivativeShowOptions show_options(const DerivativeExportOptions& o, const std::string& name, bool with_form) {
  DerivativeShowOptions show;
  show.name = name;
  if (!with_form) return show;
  show.form = o.form;
  show.length = o.length;
  show.speed = o.speed;
  show.density = o.density;
  show.draft = o.draft;
  show.mass = o.mass;
  show.volume = o.volume;
  show.gravity = o.gravity;
  return show;
}

/// show_derivative_model, its messages naming this command.
DerivativeModel read_model(const Database& db, const DerivativeShowOptions& show) {
  try {
    return show_derivative_model(db, show);
  } catch (const InputError& e) {
    std::string message = e.what();
    const std::string from = "derivatives show ";
    if (const auto at = message.find(from); at != std::string::npos)
      message.replace(at, from.size(), "derivatives export ");
    throw InputError(message);
  }
}

/// The stored (dimensional) model as the exporters' derivative set.
DerivativeSet derivative_set(const DerivativeModel& model, const DerivativeExportOptions& o) {
  DerivativeSet set;
  set.name = model.name;
  set.output = model.output;
  set.terms = parse_terms(model.terms);
  const std::size_t m = model.coefficients.size();
  for (const auto& c : model.coefficients) set.coefficients.push_back(c.value);
  if (model.covariance.size() == m * m && m > 0) {
    set.covariance = model.covariance;
  } else if (std::all_of(model.coefficients.begin(), model.coefficients.end(),
                         [](const DerivativeCoefficient& c) { return std::isfinite(c.std_error); })) {
    for (const auto& c : model.coefficients) set.std_errors.push_back(c.std_error);
  }
  set.sign = SignConvention::OnBody;  // fit_derivative_model stores forces on the body
  if (o.form != "dimensional") {
    set.system = parse_normalisation_system(o.form);
    const auto given = [](double value) { return std::isnan(value) ? std::nullopt : std::optional<double>(value); };
    set.reference.length = given(o.length);
    set.reference.speed = given(o.speed);
    set.reference.density = given(o.density);
    set.reference.draft = given(o.draft);
    set.reference.mass = given(o.mass);
    set.reference.displaced_volume = given(o.volume);
    set.reference.gravity = o.gravity;
  }
  return set;
}

Matrix6 diagonal(const std::array<double, 6>& d) {
  Matrix6 out = Matrix6::Zero();
  for (Eigen::Index i = 0; i < 6; ++i) out(i, i) = d[static_cast<std::size_t>(i)];
  return out;
}

/// A file of 36 numbers, row by row; its messages name the option.
Matrix6 read_matrix(const std::string& path, const std::string& option) {
  try {
    return read_added_mass_matrix(path);
  } catch (const InputError& e) {
    throw InputError(option + ": " + e.what());
  }
}

}  // namespace

void DerivativeExportOptions::validate() const {
  if (names.empty())
    throw InputError(
        "derivatives export: expected the name of at least one stored model ('hydrocoef derivatives "
        "list' lists them)");
  for (const auto& name : names)
    if (name.empty()) throw InputError("derivatives export: found an empty model name, expected a stored model's name");
  if (std::find(kFormats.begin(), kFormats.end(), format) == kFormats.end())
    throw InputError("--format '" + escape::one_line(format) + "': expected csv, json, gazebo or matlab");
  if (output.empty()) throw InputError("derivatives export: expected the file to write (-o PATH)");
  // The reference values as `derivatives show` checks them.
  DerivativeShowOptions show = show_options(*this, names.front(), true);
  show.validate();
  const bool table = format == "csv" || format == "json";
  const bool reference_given = !std::isnan(length) || !std::isnan(speed) || !std::isnan(density) ||
                               !std::isnan(draft) || !std::isnan(mass) || !std::isnan(volume) || gravity != 9.80665;
  if (!table && (form != "dimensional" || reference_given))
    throw InputError("--format " + format +
                     " writes dimensional (SI) coefficients only; expected no --form and no reference values with it");
  if (table && names.size() != 1)
    throw InputError("--format " + format + " writes one model a file, found " + std::to_string(names.size()) +
                     "; expected one NAME (gazebo and matlab take several)");
  const bool gazebo = format == "gazebo", matlab = format == "matlab";
  if (!gazebo && (link || link_axes || drop_unrepresentable || added_mass || added_mass_matrix))
    throw InputError(
        "--link, --link-axes, --drop-unrepresentable, --added-mass and --added-mass-matrix apply to --format gazebo "
        "only; expected them with it");
  if (!matlab && (mass_diagonal || mass_matrix))
    throw InputError("--mass-diagonal and --mass-matrix apply to --format matlab only; expected them with it");
  if (gazebo) {
    if (added_mass && added_mass_matrix)
      throw InputError("both --added-mass and --added-mass-matrix given; expected at most one");
    if (link && link->empty()) throw InputError("--link: expected a link name, found an empty one");
    if (link_axes) (void)parse_gazebo_link_axes(*link_axes);
    if (added_mass) (void)six_numbers(*added_mass, "--added-mass", kAddedMassWhat);
  }
  if (matlab) {
    if (int(mass_diagonal.has_value()) + int(mass_matrix.has_value()) != 1)
      throw InputError(
          std::string(mass_diagonal ? "both --mass-diagonal and --mass-matrix given" : "no mass matrix given") +
          "; expected exactly one of --mass-diagonal d1,...,d6 and --mass-matrix FILE (M = M_RB + M_A)");
    if (mass_diagonal) (void)six_numbers(*mass_diagonal, "--mass-diagonal", kMassWhat);
    const std::filesystem::path path(output);
    if (path.extension() != ".m")
      throw InputError("-o '" + escape::one_line(output) +
                       "': a MATLAB function is written to NAME.m; expected a path ending in .m");
  }
}

DerivativeExportResult export_derivatives(const Database& db, const DerivativeExportOptions& options) {
  options.validate();
  DerivativeExportResult r;
  r.database = Database::Access::impl(db).path;
  r.format = options.format;
  r.form = options.form;
  r.file = options.output;
  const bool table = options.format == "csv" || options.format == "json";
  std::vector<DerivativeSet> sets;
  for (const auto& name : options.names) {
    const DerivativeModel model = read_model(db, show_options(options, name, false));
    // A non-dimensional form is refused as `show` refuses it (reference values, variables).
    if (table && options.form != "dimensional") (void)read_model(db, show_options(options, name, true));
    if (r.body.empty()) r.body = model.body;
    if (model.body != r.body)
      throw InputError("derivatives export --format " + options.format + ": model '" + escape::one_line(model.name) +
                       "' is of body '" + escape::one_line(model.body) + "', model '" +
                       escape::one_line(r.models.front()) + "' of body '" + escape::one_line(r.body) +
                       "'; expected models of one body");
    r.models.push_back(model.name);
    r.outputs.push_back(model.output);
    r.terms.push_back(model.terms);
    r.stale.push_back(model.stale);
    if (model.stale)
      r.notes.push_back("model '" + model.name + "' is stale: a force of its runs changed since it was fitted");
    sets.push_back(derivative_set(model, options));
  }

  const DerivativeForm form =
      options.form == "dimensional" ? DerivativeForm::Dimensional : DerivativeForm::NonDimensional;
  if (options.format == "csv") {
    r.content = derivative_csv(sets.front(), form);
  } else if (options.format == "json") {
    r.content = derivative_json(sets.front(), form);
  } else if (options.format == "gazebo") {
    DerivativeGazeboOptions gazebo;
    if (options.link) gazebo.link_name = *options.link;
    if (options.link_axes) gazebo.link_axes = parse_gazebo_link_axes(*options.link_axes);
    gazebo.drop_unrepresentable = options.drop_unrepresentable;
    if (options.added_mass)
      gazebo.added_mass = diagonal(six_numbers(*options.added_mass, "--added-mass", kAddedMassWhat));
    if (options.added_mass_matrix) gazebo.added_mass = read_matrix(*options.added_mass_matrix, "--added-mass-matrix");
    const DerivativeGazeboExport written = derivative_gazebo(sets, gazebo);
    r.content = written.text;
    r.dropped = written.dropped;
    for (const auto& note : written.notes)  // the dropped terms are listed in `dropped`
      if (note.rfind("dropped ", 0) != 0) r.notes.push_back(note);
  } else {
    const Matrix6 mass = options.mass_diagonal
                             ? diagonal(six_numbers(*options.mass_diagonal, "--mass-diagonal", kMassWhat))
                             : read_matrix(*options.mass_matrix, "--mass-matrix");
    r.function_name = std::filesystem::path(options.output).stem().string();
    r.content = derivative_matlab(r.function_name, sets, mass);
    r.inputs = derivative_matlab_inputs(sets);
  }
  write_derivative_export(options.output, r.content);
  r.bytes = r.content.size();
  return r;
}

}  // namespace api
}  // namespace hydrocoef
