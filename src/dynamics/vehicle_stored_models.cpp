#include "src/dynamics/vehicle_stored_models.hpp"

#include <algorithm>

#include "src/core/covariance.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/run.hpp"
#include "src/store/database.hpp"
#include "src/store/derivative_store.hpp"

namespace hydrocoef {

bool names_derivative_models(const VehicleDescription& vehicle) {
  return std::any_of(vehicle.damping.begin(), vehicle.damping.end(),
                     [](const DofDamping& d) { return !d.derivative_model.empty(); });
}

void resolve_derivative_models(VehicleDescription& vehicle, RunDatabase& store, const std::string& database) {
  const std::vector<DerivativeModelRecord> models = store.derivative_models();
  for (std::size_t dof = 0; dof < 6; ++dof) {
    DofDamping& d = vehicle.damping[dof];
    if (d.derivative_model.empty()) continue;
    const std::string output(kForceNames[dof]);
    const std::string path = "damping." + output + ".derivatives";
    const std::string where = "key '" + path + ".model': ";
    const auto found = std::find_if(models.begin(), models.end(),
                                    [&](const DerivativeModelRecord& m) { return m.name == d.derivative_model; });
    if (found == models.end()) {
      std::string same_output;
      for (const auto& m : models)
        if (m.output == output) same_output += (same_output.empty() ? "" : ", ") + escape::one_line(m.name);
      throw InputError(SourceLocation{vehicle.file}, where + "found \"" + escape::one_line(d.derivative_model) +
                                                         "\", expected a derivative model stored in " +
                                                         escape::one_line(database) + " (models of " + output + ": " +
                                                         (same_output.empty() ? "none" : same_output) + ")");
    }
    if (found->output != output)
      throw InputError(SourceLocation{vehicle.file}, where + "the derivative model \"" +
                                                         escape::one_line(d.derivative_model) + "\" is of " +
                                                         found->output + ", expected a model of " + output);
    set_derivative_terms(d, found->terms, vehicle.file, path);
    if (d.terms.size() != found->coefficients.size())
      throw InputError(SourceLocation{vehicle.file},
                       where + "the derivative model \"" + escape::one_line(d.derivative_model) + "\" has " +
                           std::to_string(found->coefficients.size()) + " coefficients for " +
                           std::to_string(d.terms.size()) + " terms; expected one a term");
    d.coefficients.clear();
    for (const auto& c : found->coefficients) d.coefficients.push_back(c.value);
    d.covariance = found->covariance;
    if (!d.covariance.empty())
      if (const auto problem = covariance_problem(d.covariance, d.coefficients.size()))
        throw InputError(SourceLocation{vehicle.file}, where + "the derivative model \"" +
                                                           escape::one_line(d.derivative_model) +
                                                           "\" has a covariance that is not one: " + *problem);
    d.sign = SignConvention::OnBody;
  }
}

}  // namespace hydrocoef
