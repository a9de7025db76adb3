#include "src/export/derivative_gazebo_export.hpp"

#include <array>
#include <map>

#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/core/run.hpp"
#include "src/core/version.hpp"

namespace hydrocoef {
namespace {

// gz-sim's SNAME letters: force (lower case) then velocity (upper case).
constexpr std::array<char, 6> kForce{'x', 'y', 'z', 'k', 'm', 'n'};
constexpr std::array<char, 6> kVelocity{'U', 'V', 'W', 'P', 'Q', 'R'};
// FRD -> FLU: y, z and the rotations about them change sign.
constexpr std::array<double, 6> kFrdToFlu{1.0, -1.0, -1.0, 1.0, -1.0, -1.0};

std::string xml_comment_line(const std::string& text) { return "<!-- " + escape::xml_comment(text) + " -->\n"; }

std::string gz_force_unit(std::size_t dof) { return dof < 3 ? "N" : "N m"; }
std::string gz_velocity_unit(std::size_t j) { return j < 3 ? "m/s" : "rad/s"; }

std::string gz_set_context(const DerivativeSet& set) {
  return "derivative set '" + escape::one_line(set.name) + "' (" + escape::one_line(set.output) + ")";
}

}  // namespace

std::optional<GzParameter> gz_parameter(std::size_t dof, const Term& term, std::string& why) {
  const auto& factors = term.factors();
  if (factors.empty()) {
    why = "is a constant force, which gz-sim's damping (zero at rest) cannot hold";
    return std::nullopt;
  }
  std::array<std::size_t, 2> index{};
  for (std::size_t k = 0; k < factors.size() && k < 2; ++k) {
    const auto v = velocity_index(factors[k].variable);
    if (!v) {
      why = "reads '" + factors[k].variable + "', but gz-sim's parameters read only u, v, w, p, q, r";
      return std::nullopt;
    }
    index[k] = *v;
  }
  const std::string f(1, kForce[dof]);
  const auto upper = [](std::size_t j) { return std::string(1, kVelocity[j]); };
  const double t_i = kFrdToFlu[dof];
  if (factors.size() == 1) {
    const auto& a = factors[0];
    const std::size_t j = index[0];
    if (a.power == 1 && a.odd) return GzParameter{f + upper(j), t_i * kFrdToFlu[j]};
    if (a.power == 2 && a.odd) return GzParameter{f + upper(j) + "abs" + upper(j), t_i * kFrdToFlu[j]};
    if (a.power == 2 && !a.odd) return GzParameter{f + upper(j) + upper(j), t_i};  // t_j^2 = 1
  } else if (factors.size() == 2 && factors[0].power == 1 && factors[1].power == 1) {
    const std::size_t a = index[0], b = index[1];  // canonical order: a before b in u..r
    if (factors[0].odd && factors[1].odd)
      return GzParameter{f + upper(a) + upper(b), t_i * kFrdToFlu[a] * kFrdToFlu[b]};
    if (factors[0].odd) return GzParameter{f + upper(a) + "abs" + upper(b), t_i * kFrdToFlu[a]};
    if (factors[1].odd) return GzParameter{f + upper(b) + "abs" + upper(a), t_i * kFrdToFlu[b]};
  }
  why =
      "is not of the forms gz-sim holds (a, a*|a|, a^2, a*b, a*|b| in u, v, w, p, q, r: at most quadratic, odd in "
      "one velocity)";
  return std::nullopt;
}

DerivativeGazeboExport derivative_gazebo(const std::vector<DerivativeSet>& sets,
                                         const DerivativeGazeboOptions& options) {
  if (options.link_name.empty())
    throw InputError("gz-sim export: empty link name; expected the name of the link the plugin acts on");
  DerivativeGazeboExport out;
  const bool flu = options.link_axes == GazeboLinkAxes::Flu;
  // name -> (value in the link's axes, unit); diagonal terms first, at 0.
  std::map<std::string, std::pair<double, std::string>> values;
  std::array<bool, 6> seen{};
  std::vector<std::string> sources;
  bool plain_quadratic = false;
  for (const DerivativeSet& set : sets) {
    check_derivative_set(set);
    const auto dof = force_index(set.output);
    if (!dof)
      throw InputError(gz_set_context(set) + ": output '" + escape::one_line(set.output) +
                       "' is not a force or moment of gz-sim; expected X, Y, Z, K, M or N");
    if (seen[*dof])
      throw InputError(gz_set_context(set) + ": a second set of output " + set.output + "; expected one per output");
    seen[*dof] = true;
    sources.push_back("'" + set.name + "' (" + set.output + "): terms " + format_terms(set.terms) + ", stated " +
                      std::string(to_string(set.sign)) +
                      (set.sign == SignConvention::OpposingMotion ? " (negated to on-body)" : ""));
    for (std::size_t k = 0; k < set.terms.size(); ++k) {
      std::string why;
      const auto parameter = gz_parameter(*dof, set.terms[k], why);
      if (!parameter) {
        if (!options.drop_unrepresentable)
          throw InputError(gz_set_context(set) + ": term '" + set.terms[k].text() + "' " + why +
                           "; refit without it, or drop it explicitly (drop unrepresentable terms)");
        out.dropped.push_back(set.output + ": " + set.terms[k].text() + " (" + why + ")");
        continue;
      }
      const double on_body = to_on_body(set.coefficients[k], set.sign);
      const double value = (flu ? parameter->flu_factor : 1.0) * on_body + 0.0;
      const std::string unit = derivative_unit(set.output, set.terms[k]);
      if (parameter->name.find("abs") == std::string::npos && parameter->name.size() == 3) plain_quadratic = true;
      values[parameter->name] = {value, unit};
    }
  }
  for (const auto& d : out.dropped) out.notes.push_back("dropped " + d);
  if (plain_quadratic)
    out.notes.push_back(
        "a parameter of the form s_j s_k (e.g. xUU, yUV) is written: gz-sim warns that these 'may cause "
        "instabilities' (they are not odd in the motion); the abs forms (xUabsU) are the usual damping");

  // Added mass: SNAME X_udot = -Ma.
  Matrix6 ma = Matrix6::Zero();
  if (options.added_mass) {
    if (const std::string note = check_added_mass(*options.added_mass); !note.empty()) out.notes.push_back(note);
    ma = *options.added_mass;
  } else {
    out.notes.push_back("no added mass given: the *Dot* parameters are written as 0");
  }
  const auto t = [&](std::size_t i) { return flu ? kFrdToFlu[i] : 1.0; };
  for (std::size_t i = 0; i < 6; ++i)
    for (std::size_t j = 0; j < 6; ++j) {
      const double value = -t(i) * t(j) * ma(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) + 0.0;
      if (i == j || value != 0.0) {
        const std::string unit = i < 3 && j < 3 ? "kg" : i >= 3 && j >= 3 ? "kg m^2" : "kg m";
        out.elements.push_back({std::string(1, kForce[i]) + "Dot" + kVelocity[j], {value}, unit});
      }
    }
  // Every diagonal linear and abs term (older gz-sim defaults are not 0), then the rest.
  for (std::size_t i = 0; i < 6; ++i)
    for (const bool abs : {false, true}) {
      const std::string name =
          std::string(1, kForce[i]) + kVelocity[i] + (abs ? std::string("abs") + kVelocity[i] : "");
      const std::string unit = gz_force_unit(i) + "/(" + gz_velocity_unit(i) + ")" + (abs ? "^2" : "");
      if (!values.count(name)) values[name] = {0.0, unit};
    }
  for (const char f : kForce)
    for (const auto& [name, value] : values)
      if (name.front() == f) out.elements.push_back({name, {value.first}, value.second});

  std::string& text = out.text;
  text = "<?xml version=\"1.0\"?>\n";
  text += xml_comment_line("hydrocoef " + std::string(kVersion) +
                           ": gz-sim Hydrodynamics system parameters from derivative sets of several variables");
  text += xml_comment_line(
      "Frame: the parameters are in the link's axes, " +
      std::string(flu ? "FLU (x forward, y left, z up): hydrocoef's FRD derivatives were multiplied by "
                        "t_i t_j (t_i t_j t_k for s_j s_k terms), t = (1,-1,-1,1,-1,-1)."
                      : "FRD (x forward, y starboard, z down), as hydrocoef's body axes: nothing "
                        "converted."));
  text += xml_comment_line(
      "Sign convention: SNAME derivatives on the body. F_i = sum_j {f}{J} s_j + sum_jk {f}{J}abs{K} s_j |s_k| + "
      "sum_jk {f}{J}{K} s_j s_k, s the velocity relative to the water; negative for damping. {f}Dot{J} = -Ma. "
      "Every diagonal term is written (older gz-sim defaults are not 0), other terms where the sets have them.");
  text += xml_comment_line("Units: SI; each element's unit is in the comment beside it.");
  for (const auto& s : sources) text += xml_comment_line("Derivative set " + s);
  for (const auto& note : out.notes) text += xml_comment_line("Note: " + note);
  text += "<plugin filename=\"gz-sim-hydrodynamics-system\" name=\"gz::sim::systems::Hydrodynamics\">\n";
  text += "  <link_name>" + escape::xml_text(options.link_name) + "</link_name>\n";
  for (const GazeboElement& e : out.elements)
    text += "  <" + e.name + ">" + shortest_number(e.values.front()) + "</" + e.name + ">  <!-- " +
            escape::xml_comment(e.unit) + " -->\n";
  text += "</plugin>\n";
  return out;
}

}  // namespace hydrocoef
