#include "src/dynamics/surface_source.hpp"

#include <memory>

#include "src/core/damping_terms.hpp"
#include "src/core/error.hpp"
#include "src/core/run.hpp"
#include "src/store/database.hpp"
#include "src/surface/stored_surface.hpp"

namespace hydrocoef {

SurfaceResolver database_surface_resolver(const std::filesystem::path& database) {
  // Shared by the resolver's copies: one connection for all the surfaces a vehicle names.
  auto opened = std::make_shared<std::unique_ptr<Database>>();
  return [opened, database](const std::string& name) {
    if (!*opened) *opened = std::make_unique<Database>(database, Database::OpenMode::ReadOnly);
    return load_surface(**opened, name).surface;
  };
}

void resolve_stored_fits(VehicleDescription& vehicle, const std::filesystem::path& database) {
  std::unique_ptr<Database> db;
  std::vector<FitRecord> fits;
  for (std::size_t dof = 0; dof < 6; ++dof) {
    DofDamping& d = vehicle.damping[dof];
    if (d.fit.empty()) continue;
    const std::string where = "key 'damping." + std::string(kForceNames[dof]) + ".fit': ";
    if (!db) {
      try {
        db = std::make_unique<Database>(database, Database::OpenMode::ReadOnly);
        fits = db->fits();
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
