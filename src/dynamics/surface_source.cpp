#include "src/dynamics/surface_source.hpp"

#include <Eigen/Eigenvalues>

#include <memory>

#include "src/core/damping_terms.hpp"
#include "src/core/error.hpp"
#include "src/core/numbers.hpp"
#include "src/core/run.hpp"
#include "src/dynamics/rigid_body.hpp"
#include "src/dynamics/vehicle_stored_models.hpp"
#include "src/pmm/added_mass_assembly.hpp"
#include "src/pmm/imposed_motion.hpp"
#include "src/store/database.hpp"
#include "src/store/pmm_record.hpp"
#include "src/surface/stored_surface.hpp"

namespace hydrocoef {

SurfaceResolver database_surface_resolver(const std::filesystem::path& database) {
  // Shared by the resolver's copies: one connection for all the surfaces a vehicle names.
  auto opened = std::make_shared<std::unique_ptr<RunDatabase>>();
  return [opened, database](const std::string& name) {
    if (!*opened) *opened = std::make_unique<RunDatabase>(database, RunDatabase::OpenMode::ReadOnly);
    return load_surface(**opened, name).surface;
  };
}

namespace {

/// The vehicle's added mass from the body's forced-oscillation runs.
void resolve_added_mass(VehicleDescription& vehicle, RunDatabase& db) {
  const auto& reference = *vehicle.added_mass_from_database;
  const std::string where = "key 'added_mass.from_database': ";
  const auto dof = [&](const std::string& name, const std::string& key) {
    const auto index = dof_named(name);
    if (!index)
      throw InputError(SourceLocation{vehicle.file},
                       "key '" + key + "': found \"" + name + "\", expected surge, sway, heave, roll, pitch or yaw");
    return *index;
  };
  AddedMassOptions options;
  for (const auto& [to, from] : reference.same) options.same[dof(to, "added_mass.same")] = dof(from, "added_mass.same");
  for (const auto& name : reference.zero) options.zero.push_back(dof(name, "added_mass.zero"));
  options.period = reference.period;
  AddedMassAssembly assembly;
  try {
    assembly = assemble_added_mass(reference.body, db.pmm_records(reference.body, false), options);
  } catch (const InputError& e) {
    throw InputError(SourceLocation{vehicle.file}, where + e.what());
  }
  if (!assembly.missing.empty()) {
    std::string list;
    for (const auto& m : assembly.missing) list += (list.empty() ? "" : "; ") + m;
    throw InputError(SourceLocation{vehicle.file}, where + "body \"" + reference.body + "\" lacks " + list +
                                                       "; expected runs of those DOFs, or \"same\"/\"zero\" for them");
  }
  vehicle.added_mass_b = assembly.added_mass;
  const Matrix6 total =
      rigid_body_mass_matrix(vehicle.mass_kg, vehicle.inertia_cg_b, vehicle.r_g_b) + assembly.added_mass;
  if (!symmetric_positive_definite(total)) {
    const Eigen::SelfAdjointEigenSolver<Matrix6> eigen(total, Eigen::EigenvaluesOnly);
    throw InputError(SourceLocation{vehicle.file},
                     where + "M_RB + M_A from body \"" + reference.body + "\" has smallest eigenvalue " +
                         shortest_number(eigen.eigenvalues().minCoeff()) + ", expected it positive definite");
  }
}

}  // namespace

void resolve_stored_records(VehicleDescription& vehicle, const std::filesystem::path& database) {
  std::unique_ptr<RunDatabase> db;
  if (vehicle.added_mass_from_database) {
    try {
      db = std::make_unique<RunDatabase>(database, RunDatabase::OpenMode::ReadOnly);
    } catch (const InputError& e) {
      throw InputError(SourceLocation{vehicle.file}, std::string("key 'added_mass.from_database': ") + e.what());
    }
    resolve_added_mass(vehicle, *db);
  }
  if (names_derivative_models(vehicle)) {
    try {
      if (!db) db = std::make_unique<RunDatabase>(database, RunDatabase::OpenMode::ReadOnly);
    } catch (const InputError& e) {
      throw InputError(SourceLocation{vehicle.file}, std::string("a stored derivative model: ") + e.what());
    }
    resolve_derivative_models(vehicle, *db, database.string());
  }
  std::vector<FitRecord> fits;
  bool fits_loaded = false;
  for (std::size_t dof = 0; dof < 6; ++dof) {
    DofDamping& d = vehicle.damping[dof];
    if (d.fit.empty()) continue;
    const std::string where = "key 'damping." + std::string(kForceNames[dof]) + ".fit': ";
    if (!fits_loaded) {
      try {
        if (!db) db = std::make_unique<RunDatabase>(database, RunDatabase::OpenMode::ReadOnly);
        fits = db->fits();
        fits_loaded = true;
      } catch (const InputError& e) {
        throw InputError(SourceLocation{vehicle.file}, where + e.what());
      }
    }
    const FitRecord* found = nullptr;
    std::string same_dof;
    for (const FitRecord& f : fits) {
      if (f.name == d.fit) found = &f;
      if (f.dof == kForceNames[dof]) same_dof += (same_dof.empty() ? "" : ", ") + f.name;
    }
    if (!found)
      throw InputError(SourceLocation{vehicle.file},
                       where + "found \"" + d.fit + "\", expected a fit stored in " + database.string() + " (fits of " +
                           std::string(kForceNames[dof]) + ": " + (same_dof.empty() ? "none" : same_dof) + ")");
    if (found->dof != kForceNames[dof])
      throw InputError(SourceLocation{vehicle.file}, where + "the fit \"" + d.fit + "\" is of " + found->dof +
                                                         ", expected a fit of " + std::string(kForceNames[dof]));
    std::string terms;
    for (const auto& c : found->coefficients) terms += (terms.empty() ? "" : ",") + c.term;
    try {
      d.law = parse_damping_terms(terms);
    } catch (const InputError& e) {
      throw InputError(SourceLocation{vehicle.file}, where + "the stored fit \"" + d.fit + "\": " + e.what());
    }
    d.coefficients.clear();
    for (const auto& c : found->coefficients) d.coefficients.push_back(c.value);
    d.sign = found->sign;
    d.covariance = found->covariance;
    if (!d.covariance.empty())
      if (const auto problem = covariance_problem(d.covariance, d.coefficients.size()))
        throw InputError(SourceLocation{vehicle.file},
                         where + "the stored fit \"" + d.fit + "\" has a covariance that is not one: " + *problem);
  }
}

}  // namespace hydrocoef
