#include "src/dynamics/vehicle.hpp"

#include <Eigen/Eigenvalues>

#include "src/core/dense_decompositions.hpp"
#include "src/core/error.hpp"
#include "src/core/sign_convention.hpp"
#include "src/dynamics/json_input.hpp"

namespace hydrocoef {
namespace {

namespace ji = json_input;
using ji::Json;

std::string notes_text(const Json& value, const std::string& file) {
  if (value.is_string()) return value.get<std::string>();
  if (!value.is_array())
    ji::fail(file, "notes", "found " + ji::describe(value) + ", expected a string or an array of strings");
  std::string out;
  for (std::size_t i = 0; i < value.size(); ++i)
    out += (out.empty() ? "" : "\n") + ji::string(value[i], file, "notes[" + std::to_string(i) + "]");
  return out;
}

std::string smallest_eigenvalue_text(const Eigen::MatrixXd& m) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver = symmetric_eigen(0.5 * (m + m.transpose()));
  return std::to_string(solver.eigenvalues().minCoeff());
}

Matrix3 read_inertia(const Json& value, const std::string& file) {
  Matrix3 inertia = Matrix3::Zero();
  if (value.is_array() && !value.empty() && value[0].is_number()) {
    const auto d = ji::numbers(value, file, "inertia", 3);
    inertia.diagonal() << d[0], d[1], d[2];
  } else if (value.is_array()) {
    inertia = ji::matrix(value, file, "inertia", 3);
  } else {
    ji::fail(file, "inertia", "found " + ji::describe(value) + ", expected [Ixx, Iyy, Izz] or a 3x3 array [kg m^2]");
  }
  if ((inertia - inertia.transpose()).cwiseAbs().maxCoeff() > 1e-12 * inertia.cwiseAbs().maxCoeff())
    ji::fail(file, "inertia", "found a non-symmetric tensor, expected I = I^T");
  const Eigen::SelfAdjointEigenSolver<Matrix3> solver(inertia);
  if (!(solver.eigenvalues().minCoeff() > 0.0))
    ji::fail(file, "inertia",
             "found a smallest principal moment of " + std::to_string(solver.eigenvalues().minCoeff()) +
                 " kg m^2, expected a positive definite tensor");
  return inertia;
}

VehicleDescription::AddedMassFromDatabase read_added_mass_reference(const Json& value, const std::string& file) {
  VehicleDescription::AddedMassFromDatabase out;
  out.body = ji::string(value.at("from_database"), file, "added_mass.from_database");
  if (const Json* same = ji::find(value, "same")) {
    if (!same->is_object())
      ji::fail(file, "added_mass.same", "found " + ji::describe(*same) + ", expected an object {\"sway\": \"surge\"}");
    for (const auto& [dof, from] : same->items())
      out.same.emplace_back(dof, ji::string(from, file, "added_mass.same." + dof));
  }
  if (const Json* zero = ji::find(value, "zero")) {
    if (!zero->is_array()) ji::fail(file, "added_mass.zero", "found " + ji::describe(*zero) + ", expected an array");
    for (std::size_t k = 0; k < zero->size(); ++k)
      out.zero.push_back(ji::string((*zero)[k], file, "added_mass.zero[" + std::to_string(k) + "]"));
  }
  if (const Json* period = ji::find(value, "period")) out.period = ji::number(*period, file, "added_mass.period");
  return out;
}

Matrix6 read_added_mass(const Json& value, const std::string& file, double rho) {
  ji::expect_object(value, file, "added_mass",
                    {"sphere_radius", "diagonal", "matrix", "from_database", "same", "zero", "period"});
  if (ji::find(value, "from_database") == nullptr &&
      (ji::find(value, "same") || ji::find(value, "zero") || ji::find(value, "period")))
    ji::fail(file, "added_mass", "found same or zero without from_database, expected them with from_database");
  if (value.size() != 1 && ji::find(value, "from_database") == nullptr)
    ji::fail(file, "added_mass", "expected exactly one of sphere_radius, diagonal, matrix, from_database");
  if (ji::find(value, "from_database") &&
      (ji::find(value, "sphere_radius") || ji::find(value, "diagonal") || ji::find(value, "matrix")))
    ji::fail(file, "added_mass", "expected exactly one of sphere_radius, diagonal, matrix, from_database");
  if (const Json* r = ji::find(value, "sphere_radius"))
    return sphere_added_mass(rho, ji::positive(*r, file, "added_mass.sphere_radius"));
  if (const Json* d = ji::find(value, "diagonal")) {
    const auto v = ji::numbers(*d, file, "added_mass.diagonal", 6);
    Matrix6 m = Matrix6::Zero();
    for (Eigen::Index i = 0; i < 6; ++i) m(i, i) = v[static_cast<std::size_t>(i)];
    return m;
  }
  if (ji::find(value, "from_database")) return Matrix6::Zero();  // filled from the database later
  const Matrix6 m = ji::matrix(value.at("matrix"), file, "added_mass.matrix", 6);
  if ((m - m.transpose()).cwiseAbs().maxCoeff() > 1e-9 * std::max(1.0, m.cwiseAbs().maxCoeff()))
    ji::fail(file, "added_mass.matrix", "found a non-symmetric matrix, expected M_A = M_A^T");
  return m;
}

Thruster read_thruster(const Json& value, const std::string& file, std::size_t index) {
  const std::string path = "thrusters[" + std::to_string(index) + "]";
  ji::expect_object(value, file, path, {"name", "position", "direction", "min_thrust", "max_thrust"});
  Thruster t;
  t.name = ji::string(ji::require(value, file, path, "name"), file, ji::join(path, "name"));
  t.position_b = ji::vector3(ji::require(value, file, path, "position"), file, ji::join(path, "position"));
  const Vector3 d = ji::vector3(ji::require(value, file, path, "direction"), file, ji::join(path, "direction"));
  if (!(d.norm() > 0.0)) ji::fail(file, ji::join(path, "direction"), "found a zero vector, expected a direction");
  t.direction_b = d / d.norm();
  t.min_thrust_N = ji::number(ji::require(value, file, path, "min_thrust"), file, ji::join(path, "min_thrust"));
  t.max_thrust_N = ji::number(ji::require(value, file, path, "max_thrust"), file, ji::join(path, "max_thrust"));
  if (t.min_thrust_N > t.max_thrust_N)
    ji::fail(file, path,
             "found min_thrust " + std::to_string(t.min_thrust_N) + " > max_thrust " + std::to_string(t.max_thrust_N) +
                 ", expected min_thrust <= max_thrust");
  return t;
}

SignConvention read_sign(const Json& object, const std::string& file, const std::string& path) {
  const std::string text = ji::string(ji::require(object, file, path, "sign"), file, ji::join(path, "sign"));
  if (const auto convention = sign_convention_named(text)) return *convention;
  ji::fail(file, ji::join(path, "sign"), "found \"" + text + "\", expected \"on-body\" or \"opposing\"");
}

// "derivatives": {"terms": "v, r, v*|v|", "coefficients": [...], "covariance": [[...], ...]}
// into d (terms, coefficients, covariance), every size and value checked; or
// {"model": NAME}, a stored model's name, filled by resolve_stored_records.
void read_derivatives(const Json& value, const std::string& file, const std::string& path, DofDamping& d) {
  if (value.is_object() && value.contains("model")) {
    ji::expect_object(value, file, path, {"model"});
    d.derivative_model = ji::string(value["model"], file, ji::join(path, "model"));
    if (d.derivative_model.empty())
      ji::fail(file, ji::join(path, "model"),
               "found an empty name, expected a stored derivative model's name (hydrocoef derivatives list)");
    return;
  }
  ji::expect_object(value, file, path, {"terms", "coefficients", "covariance"});
  const std::string terms_path = ji::join(path, "terms");
  const Json& terms = ji::require(value, file, path, "terms");
  std::string list;
  if (terms.is_array()) {
    for (std::size_t k = 0; k < terms.size(); ++k)
      list += (k ? ", " : "") + ji::string(terms[k], file, terms_path + "[" + std::to_string(k) + "]");
  } else if (terms.is_string()) {
    list = terms.get<std::string>();
  } else {
    ji::fail(file, terms_path,
             "found " + ji::describe(terms) + ", expected a list of terms such as \"v, r, v*|v|, u*v\"");
  }
  set_derivative_terms(d, list, file, path);
  const Json& coefficients = ji::require(value, file, path, "coefficients");
  d.coefficients = ji::numbers(coefficients, file, ji::join(path, "coefficients"), d.terms.size());
  if (const Json* covariance = ji::find(value, "covariance")) {
    const auto k = static_cast<Eigen::Index>(d.terms.size());
    const Eigen::MatrixXd c = ji::matrix(*covariance, file, ji::join(path, "covariance"), k);
    d.covariance.assign(c.data(), c.data() + c.size());  // symmetric: column-major = row-major
    if (const auto problem = covariance_problem(d.covariance, d.coefficients.size()))
      ji::fail(file, ji::join(path, "covariance"), *problem);
  }
}

DofDamping read_dof_damping(const Json& value, const std::string& file, const std::string& path) {
  ji::expect_object(
      value, file, path,
      {"law", "covariance", "fit", "surface", "derivatives", "output", "axes", "sign", "allow_unphysical"});
  DofDamping d;
  const Json* law = ji::find(value, "law");
  const Json* fit = ji::find(value, "fit");
  const Json* surface = ji::find(value, "surface");
  const Json* derivatives = ji::find(value, "derivatives");
  if ((law != nullptr) + (fit != nullptr) + (surface != nullptr) + (derivatives != nullptr) != 1)
    ji::fail(file, path, "expected exactly one of \"law\", \"fit\", \"derivatives\" and \"surface\"");
  if (!surface && ji::find(value, "allow_unphysical"))
    ji::fail(file, ji::join(path, "allow_unphysical"),
             "belongs to a surface; a law is checked when it is fitted and by export-gazebo");
  if (fit) {
    // A stored fit brings its terms, coefficients, covariance and sign
    // (resolve_stored_records, src/dynamics/surface_source.hpp).
    for (const char* key : {"sign", "covariance", "output", "axes"})
      if (ji::find(value, key))
        ji::fail(file, ji::join(path, key), "a stored fit brings its own terms, sign and covariance");
    d.fit = ji::string(*fit, file, ji::join(path, "fit"));
    if (d.fit.empty()) ji::fail(file, ji::join(path, "fit"), "found an empty name, expected a stored fit's name");
    d.kind = DofDamping::Kind::Law;
    return d;
  }
  if (derivatives && derivatives->is_object() && derivatives->contains("model")) {
    // A stored derivative model brings its terms, coefficients, covariance
    // and sign (forces on the body), as a stored fit does.
    for (const char* key : {"sign", "covariance", "output", "axes"})
      if (ji::find(value, key))
        ji::fail(file, ji::join(path, key), "a stored derivative model brings its own terms, sign and covariance");
    read_derivatives(*derivatives, file, ji::join(path, "derivatives"), d);
    d.kind = DofDamping::Kind::Derivatives;
    return d;
  }
  d.sign = read_sign(value, file, path);
  if (derivatives) {
    for (const char* key : {"covariance", "output", "axes"})
      if (ji::find(value, key))
        ji::fail(file, ji::join(path, key),
                 "does not belong beside \"derivatives\" (its covariance goes inside: derivatives.covariance)");
    read_derivatives(*derivatives, file, ji::join(path, "derivatives"), d);
    d.kind = DofDamping::Kind::Derivatives;
    return d;
  }
  if (law) {
    if (ji::find(value, "output") || ji::find(value, "axes"))
      ji::fail(file, path, "\"output\" and \"axes\" belong to a surface, not to a law");
    const std::string law_path = ji::join(path, "law");
    if (!law->is_object() || law->empty())
      ji::fail(file, law_path,
               "found " + ji::describe(*law) +
                   ", expected an object of terms and coefficients, e.g. {\"u\": -0.0155, \"u|u|\": -11.04}");
    std::string terms;
    for (const auto& item : law->items()) terms += (terms.empty() ? "" : ",") + item.key();
    try {
      d.law = parse_damping_terms(terms);
    } catch (const InputError& e) {
      ji::fail(file, law_path, e.what());
    }
    // parse_damping_terms keeps the order of the text, i.e. the object's key order.
    for (const auto& item : law->items())
      d.coefficients.push_back(ji::number(item.value(), file, ji::join(law_path, item.key())));
    if (const Json* covariance = ji::find(value, "covariance")) {
      const auto k = static_cast<Eigen::Index>(d.coefficients.size());
      const Eigen::MatrixXd c = ji::matrix(*covariance, file, ji::join(path, "covariance"), k);
      d.covariance.assign(c.data(), c.data() + c.size());  // symmetric: column-major = row-major
      if (const auto problem = covariance_problem(d.covariance, d.coefficients.size()))
        ji::fail(file, ji::join(path, "covariance"), *problem);
    }
    d.kind = DofDamping::Kind::Law;
    return d;
  }
  if (ji::find(value, "covariance"))
    ji::fail(file, ji::join(path, "covariance"), "a covariance belongs to a law; a surface states its own uncertainty");
  d.kind = DofDamping::Kind::Surface;
  d.surface = ji::string(*surface, file, ji::join(path, "surface"));
  if (const Json* allow = ji::find(value, "allow_unphysical")) {
    if (!allow->is_boolean())
      ji::fail(file, ji::join(path, "allow_unphysical"), "found " + ji::describe(*allow) + ", expected true or false");
    d.allow_unphysical = allow->get<bool>();
  }
  d.output = ji::string(ji::require(value, file, path, "output"), file, ji::join(path, "output"));
  if (const Json* axes = ji::find(value, "axes")) {
    if (!axes->is_object())
      ji::fail(file, ji::join(path, "axes"),
               "found " + ji::describe(*axes) + ", expected an object {surface axis: source}");
    for (const auto& item : axes->items())
      d.axis_sources[item.key()] = ji::string(item.value(), file, ji::join(ji::join(path, "axes"), item.key()));
  }
  return d;
}

}  // namespace

void set_derivative_terms(DofDamping& d, const std::string& terms, const std::string& file, const std::string& path) {
  const std::string terms_path = ji::join(path, "terms");
  try {
    d.terms = parse_terms(terms);
  } catch (const InputError& e) {
    ji::fail(file, terms_path, e.what());
  }
  if (d.terms.size() > DampingModel::kMaxDerivativeTerms)
    ji::fail(file, terms_path,
             "found " + std::to_string(d.terms.size()) + " terms, expected at most " +
                 std::to_string(DampingModel::kMaxDerivativeTerms));
  for (const auto& term : d.terms)
    for (const auto& f : term.factors())
      if (f.variable == "alpha" || f.variable == "beta" || f.variable == "du")
        ji::fail(file, terms_path,
                 "term '" + term.text() + "' reads '" + f.variable +
                     "', which the dynamics model does not supply; expected terms in u, v, w, p, q, r and "
                     "disturbance parameters");
}

VehicleDescription parse_vehicle(std::string_view json_text, const std::string& file) {
  const Json doc = ji::parse(json_text, file);
  ji::expect_object(
      doc, file, "",
      {"name", "notes", "sources", "gravity", "rho", "mass", "inertia", "center_of_gravity", "center_of_buoyancy",
       "buoyancy_force", "displaced_volume", "neutrally_buoyant", "added_mass", "thrusters", "damping"});
  VehicleDescription v;
  v.file = file;
  if (const Json* name = ji::find(doc, "name")) v.name = ji::string(*name, file, "name");
  if (const Json* notes = ji::find(doc, "notes")) v.notes = notes_text(*notes, file);
  if (const Json* g = ji::find(doc, "gravity")) v.gravity_m_s2 = ji::positive(*g, file, "gravity");
  if (const Json* rho = ji::find(doc, "rho")) v.rho_kg_m3 = ji::positive(*rho, file, "rho");
  v.mass_kg = ji::positive(ji::require(doc, file, "", "mass"), file, "mass");
  v.inertia_cg_b = read_inertia(ji::require(doc, file, "", "inertia"), file);
  v.r_g_b = ji::vector3(ji::require(doc, file, "", "center_of_gravity"), file, "center_of_gravity");
  if (const Json* cb = ji::find(doc, "center_of_buoyancy")) v.r_b_b = ji::vector3(*cb, file, "center_of_buoyancy");

  const Json* force = ji::find(doc, "buoyancy_force");
  const Json* volume = ji::find(doc, "displaced_volume");
  const Json* neutral = ji::find(doc, "neutrally_buoyant");
  if ((force != nullptr) + (volume != nullptr) + (neutral != nullptr) != 1)
    ji::fail(file, "buoyancy_force",
             "expected exactly one of buoyancy_force [N], displaced_volume [m^3], neutrally_buoyant");
  if (force) v.buoyancy_N = ji::positive(*force, file, "buoyancy_force", true);
  if (volume) v.buoyancy_N = v.rho_kg_m3 * v.gravity_m_s2 * ji::positive(*volume, file, "displaced_volume", true);
  if (neutral) {
    if (!ji::boolean(*neutral, file, "neutrally_buoyant"))
      ji::fail(file, "neutrally_buoyant", "found false, expected true (or give buoyancy_force or displaced_volume)");
    v.buoyancy_N = v.mass_kg * v.gravity_m_s2;
  }

  const Json* am = ji::find(doc, "added_mass");
  if (am && am->is_object() && ji::find(*am, "from_database")) {
    read_added_mass(*am, file, v.rho_kg_m3);  // checks the keys
    v.added_mass_from_database = read_added_mass_reference(*am, file);
  } else if (am) {
    v.added_mass_b = read_added_mass(*am, file, v.rho_kg_m3);
  }
  const Matrix6 total = rigid_body_mass_matrix(v.mass_kg, v.inertia_cg_b, v.r_g_b) + v.added_mass_b;
  if (!v.added_mass_from_database && !symmetric_positive_definite(total))
    ji::fail(file, "added_mass",
             "the mass matrix M_RB + M_A has smallest eigenvalue " + smallest_eigenvalue_text(total) +
                 ", expected it symmetric positive definite");

  if (const Json* thrusters = ji::find(doc, "thrusters")) {
    if (!thrusters->is_array())
      ji::fail(file, "thrusters", "found " + ji::describe(*thrusters) + ", expected an array");
    for (std::size_t i = 0; i < thrusters->size(); ++i) {
      v.thrusters.push_back(read_thruster((*thrusters)[i], file, i));
      for (std::size_t j = 0; j < i; ++j)
        if (v.thrusters[j].name == v.thrusters[i].name)
          ji::fail(file, "thrusters[" + std::to_string(i) + "].name",
                   "found \"" + v.thrusters[i].name + "\" twice, expected unique names");
    }
  }

  if (const Json* damping = ji::find(doc, "damping")) {
    ji::expect_object(*damping, file, "damping", {"X", "Y", "Z", "K", "M", "N"});
    for (const auto& item : damping->items())
      v.damping[*force_index(item.key())] = read_dof_damping(item.value(), file, "damping." + item.key());
  }
  return v;
}

VehicleDescription load_vehicle(const std::filesystem::path& path) {
  return parse_vehicle(ji::read_file(path.string()), path.string());
}

}  // namespace hydrocoef
