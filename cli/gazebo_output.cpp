// How the CLI reports a Gazebo export: the coefficients per degree of
// freedom with the fits they came from, or JSON.
#include "cli/gazebo_output.hpp"

#include <iostream>

#include "cli/common.hpp"
#include "src/core/escape.hpp"

namespace hydrocoef::cli {

void print_gazebo_export(const GazeboCoefficients& coefficients, const std::vector<GazeboElement>& elements,
                         const GazeboWriteOptions& options, const std::string& output, bool json) {
  const bool gz = options.flavor == GazeboFlavor::Gz;
  if (json) {
    nlohmann::json out = {{"body", coefficients.body},
                          {"flavor", std::string(gazebo_flavor_name(options.flavor))},
                          {"file", output},
                          {"sign_convention", "on-body"},
                          {"frame", gz ? (options.link_axes == GazeboLinkAxes::Flu ? "flu" : "frd") : "frd"},
                          {"linear_b", row_major(coefficients.linear_b)},
                          {"quadratic_b", row_major(coefficients.quadratic_b)},
                          {"added_mass_b", row_major(coefficients.added_mass_b)},
                          {"added_mass_source", coefficients.added_mass_source},
                          {"notes", coefficients.notes}};
    if (gz) out["link_name"] = options.link_name;
    out["linearized_at"] = coefficients.linearized_at ? nlohmann::json(*coefficients.linearized_at) : nlohmann::json();
    out["fits"] = nlohmann::json::array();
    for (const GazeboFitSource& s : coefficients.sources) {
      nlohmann::json fit = {
          {"dof", std::string(gazebo_dof_name(s.dof))},
          {"variable", std::string(gazebo_velocity_name(s.variable))},
          {"name", s.fit_name},
          {"id", s.fit_id},
          {"terms", s.terms},
          {"stored_sign", std::string(to_string(s.stored_sign))},
          {"linear", s.linear},
          {"quadratic", s.quadratic},
          {"units",
           {{"linear", damping_unit(s.dof, s.variable, false)}, {"quadratic", damping_unit(s.dof, s.variable, true)}}},
          {"runs", s.run_ids}};
      fit["dropped_constant"] = s.dropped_constant ? nlohmann::json(*s.dropped_constant) : nlohmann::json();
      out["fits"].push_back(fit);
    }
    out["missing"] = nlohmann::json::array();
    for (std::size_t dof : coefficients.missing_dofs) out["missing"].push_back(std::string(gazebo_dof_name(dof)));
    for (const GazeboElement& e : elements) {
      out["elements"][e.name] = e.values.size() == 1 ? nlohmann::json(e.values.front()) : nlohmann::json(e.values);
      out["units"][e.name] = e.unit;
    }
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }

  std::cout << "exported body " << escape::one_line(coefficients.body) << " as "
            << (gz ? "gz-sim Hydrodynamics parameters (link '" + escape::one_line(options.link_name) + "', link axes " +
                         (options.link_axes == GazeboLinkAxes::Flu ? "FLU" : "FRD") + ")"
                   : std::string("a uuv_simulator fossen model (FRD)"))
            << ", on-body SNAME signs (damping negative)\n";
  static const std::string kForceLetters = "xyzkmn";
  for (std::size_t dof = 0; dof < 6; ++dof) {
    std::cout << "  " << gazebo_dof_name(dof) << ":";
    if (gz) {
      bool first = true;
      for (const GazeboElement& e : elements) {
        if (kForceLetters.find(e.name.front()) != dof) continue;
        std::cout << (first ? " " : ", ") << escape::one_line(e.name) << " = " << significant(e.values.front()) << " "
                  << escape::one_line(e.unit);
        first = false;
      }
    } else {
      std::cout << " linear " << significant(coefficients.linear_b(dof, dof)) << " " << damping_unit(dof, dof, false)
                << ", quadratic " << significant(coefficients.quadratic_b(dof, dof)) << " "
                << damping_unit(dof, dof, true) << ", added mass " << significant(coefficients.added_mass_b(dof, dof))
                << " " << (dof < 3 ? "kg" : "kg m^2");
    }
    std::cout << '\n';
    for (const GazeboFitSource& s : coefficients.sources) {
      if (s.dof != dof) continue;
      std::cout << "     " << gazebo_dof_name(s.dof) << " in " << gazebo_velocity_name(s.variable) << " from fit '"
                << escape::one_line(s.fit_name) << "' (" << to_string(s.stored_sign)
                << (s.stored_sign == SignConvention::OpposingMotion ? ", negated to on-body" : "") << ", "
                << s.run_ids.size() << " runs)\n";
    }
  }
  std::cout << "  added mass: " << escape::one_line(coefficients.added_mass_source)
            << "; symmetric positive semi-definite\n";
  for (const std::string& note : coefficients.notes) std::cout << "  note: " << escape::one_line(note) << '\n';
  std::cout << "  wrote " << escape::one_line(output) << '\n';
}

}  // namespace hydrocoef::cli
