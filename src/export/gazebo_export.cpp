#include "src/export/gazebo_export.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>

#include "src/core/damping_terms.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/core/sign_convention.hpp"
#include "src/core/version.hpp"
#include "src/export/export.hpp"

namespace hydrocoef {

namespace {

// gz-sim's SNAME parameter letters: force (lower case) then velocity (upper case).
constexpr std::array<char, 6> kGzForce{'x', 'y', 'z', 'k', 'm', 'n'};
constexpr std::array<char, 6> kGzVelocity{'U', 'V', 'W', 'P', 'Q', 'R'};
// FRD -> FLU: y, z and the rotations about them change sign.
constexpr std::array<double, 6> kFrdToFlu{1.0, -1.0, -1.0, 1.0, -1.0, -1.0};

std::string join_ids(const std::vector<std::int64_t>& ids) {
  std::string out;
  for (std::size_t i = 0; i < ids.size(); ++i) out += (i ? "," : "") + std::to_string(ids[i]);
  return out;
}

std::string sdf_comment(const std::string& text, const std::string& indent = "") {
  return indent + "<!-- " + escape::xml_comment(text) + " -->\n";
}

std::string added_mass_unit(std::size_t i, std::size_t j) {
  if (i < 3 && j < 3) return "kg";
  if (i >= 3 && j >= 3) return "kg m^2";
  return "kg m";
}

std::string describe_fit(const FitRecord& fit) {
  return "fit '" + fit.name + "' (" + fit.dof + " in " + fit.variable + ", terms " + fit.terms + ")";
}

// Why a term of a law cannot go into a Fossen damping matrix.
std::string refusal_reason(const std::string& term, const std::string& x) {
  if (term == x + "^2" || term == "|" + x + "|")
    return "is even in " + x + " (the same force forwards and backwards), but Fossen damping is odd; expected " + x +
           " and " + x + "|" + x + "| only (refit with --terms " + x + "," + x + "|" + x + "|)";
  if (term == x + "^3")
    return "is cubic, but the Gazebo plugins have only linear and " + x + "|" + x + "| damping; expected " + x +
           " and " + x + "|" + x + "| only (refit with --terms " + x + "," + x + "|" + x + "|)";
  return "is not a term the Gazebo plugins know; expected " + x + " and " + x + "|" + x + "| only";
}

const FitRecord& find_fit(const std::vector<const FitRecord*>& fits, const std::string& name, const std::string& body,
                          const std::string& option) {
  for (const FitRecord* fit : fits)
    if (fit->name == name) return *fit;
  std::string names;
  for (const FitRecord* fit : fits) names += (names.empty() ? "" : ", ") + fit->name;
  throw InputError(option + ": body '" + body + "' has no fit named '" + name + "'; expected one of: " +
                   (names.empty() ? "(none: make one with hydrocoef fit --body " + body + ")" : names));
}

}  // namespace

std::string_view gazebo_dof_name(std::size_t dof) { return kForceNames.at(dof); }
std::string_view gazebo_velocity_name(std::size_t variable) { return kVelocityNames.at(variable); }

std::string damping_unit(std::size_t dof, std::size_t variable, bool quadratic) {
  return force_unit(dof) + "/(" + velocity_unit(variable) + ")" + (quadratic ? "^2" : "");
}

std::string_view gazebo_flavor_name(GazeboFlavor flavor) { return flavor == GazeboFlavor::Uuv ? "uuv" : "gz"; }

GazeboFlavor parse_gazebo_flavor(std::string_view text) {
  if (text == "uuv") return GazeboFlavor::Uuv;
  if (text == "gz") return GazeboFlavor::Gz;
  throw InputError("unknown Gazebo flavor '" + std::string(text) +
                   "'; expected uuv (uuv_simulator fossen model) or gz (gz-sim Hydrodynamics system)");
}

std::string_view gazebo_link_axes_name(GazeboLinkAxes axes) { return axes == GazeboLinkAxes::Flu ? "flu" : "frd"; }

GazeboLinkAxes parse_gazebo_link_axes(std::string_view text) {
  if (text == "flu") return GazeboLinkAxes::Flu;
  if (text == "frd") return GazeboLinkAxes::Frd;
  throw InputError("unknown link axes '" + std::string(text) +
                   "'; expected flu (x forward, y left, z up: the ROS/Gazebo habit) or frd (x forward, y starboard, "
                   "z down)");
}

std::string check_added_mass(const Matrix6& added_mass) {
  double largest = 0.0;
  for (std::size_t i = 0; i < 6; ++i) {
    for (std::size_t j = 0; j < 6; ++j) {
      const double value = added_mass(i, j);
      if (!std::isfinite(value)) {
        throw InputError("added-mass entry (" + std::string(kForceNames[i]) + ", " + std::string(kVelocityNames[j]) +
                         ") is " + shortest_number(value) + "; expected finite numbers");
      }
      largest = std::max(largest, std::abs(value));
    }
  }
  for (std::size_t i = 0; i < 6; ++i) {
    for (std::size_t j = i + 1; j < 6; ++j) {
      const double a = added_mass(i, j);
      const double b = added_mass(j, i);
      if (std::abs(a - b) > 1e-9 * largest) {
        throw InputError("added-mass matrix is not symmetric: entry (" + std::to_string(i + 1) + "," +
                         std::to_string(j + 1) + ") = " + shortest_number(a) + " but (" + std::to_string(j + 1) + "," +
                         std::to_string(i + 1) + ") = " + shortest_number(b) + " " + added_mass_unit(i, j) +
                         "; expected a symmetric matrix (to 1e-9 relative)");
      }
    }
  }
  const Matrix6 symmetric = 0.5 * (added_mass + added_mass.transpose());
  const Eigen::LLT<Matrix6> cholesky(symmetric);
  if (cholesky.info() == Eigen::Success) return {};
  const Eigen::SelfAdjointEigenSolver<Matrix6> eigen(symmetric, Eigen::EigenvaluesOnly);
  const double smallest = eigen.eigenvalues()(0);
  if (smallest < -1e-12 * largest || largest == 0.0)
    throw InputError("added-mass matrix is not positive semi-definite: smallest eigenvalue " +
                     shortest_number(smallest) +
                     "; expected a symmetric Ma (kg, kg m, kg m^2) with every eigenvalue >= 0 and some > 0");
  return "Ma is singular (smallest eigenvalue " + shortest_number(smallest) +
         ", e.g. no rotational added mass, as for a sphere): accepted, since the plugin adds -Ma times the "
         "acceleration and never inverts Ma";
}

Matrix6 added_mass_diagonal(const std::array<double, 6>& diagonal) {
  Matrix6 out = Matrix6::Zero();
  for (std::size_t i = 0; i < 6; ++i) out(i, i) = diagonal[i];
  return out;
}

Matrix6 read_added_mass_matrix(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read added-mass matrix '" + path.string() + "'; expected a readable text file");
  std::vector<double> values;
  std::string line;
  std::size_t line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::size_t at = 0;
    while (at < line.size()) {
      const auto start = line.find_first_not_of(" \t\r,;", at);
      if (start == std::string::npos) break;
      auto end = line.find_first_of(" \t\r,;", start);
      if (end == std::string::npos) end = line.size();
      const std::string_view token(line.data() + start, end - start);
      double value = 0.0;
      const auto [stop, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
      if (ec != std::errc() || stop != token.data() + token.size() || !std::isfinite(value)) {
        throw InputError(SourceLocation{path.string(), line_number, start + 1},
                         "found '" + std::string(token) + "', expected a finite number (kg, kg m or kg m^2)");
      }
      values.push_back(value);
      at = end;
    }
  }
  if (values.size() != 36) {
    throw InputError(SourceLocation{path.string(), 0, 0},
                     std::to_string(values.size()) + " numbers; expected 36, the 6x6 added-mass matrix row by row");
  }
  std::array<double, 36> row_by_row{};
  std::copy(values.begin(), values.end(), row_by_row.begin());
  return from_row_major(row_by_row);
}

GazeboCoefficients gazebo_coefficients(const std::vector<FitRecord>& fits, const GazeboRequest& request) {
  if (request.linearize_at && !std::isfinite(*request.linearize_at))
    throw InputError("--linearize-at " + shortest_number(*request.linearize_at) + ": expected a finite speed in m/s");
  std::vector<const FitRecord*> body_fits;
  for (const FitRecord& fit : fits)
    if (fit.body == request.body) body_fits.push_back(&fit);

  // (DOF, velocity) -> the fit that gives it.
  std::map<std::pair<std::size_t, std::size_t>, const FitRecord*> chosen;
  for (const auto& [dof_text, name] : request.fits) {
    const std::string option = "--fit " + dof_text + "=" + name;
    const auto dof = force_index(dof_text);
    if (!dof) throw InputError(option + ": '" + dof_text + "' is not a force component; expected X, Y, Z, K, M or N");
    const FitRecord& fit = find_fit(body_fits, name, request.body, option);
    if (fit.dof != dof_text) {
      throw InputError(option + ": " + describe_fit(fit) + " is a law of " + fit.dof + ", not " + dof_text +
                       "; expected a fit of " + dof_text);
    }
    const auto variable = velocity_index(fit.variable);
    if (!variable) throw InputError(option + ": " + describe_fit(fit) + " has an unknown variable; expected u..r");
    const auto [at, inserted] = chosen.emplace(std::pair{*dof, *variable}, &fit);
    if (!inserted) {
      throw InputError(option + ": " + dof_text + " in " + fit.variable + " is already given by fit '" +
                       at->second->name + "'; expected one fit per force component and velocity");
    }
  }

  GazeboCoefficients out;
  out.body = request.body;
  out.linearized_at = request.linearize_at;
  for (std::size_t dof = 0; dof < 6; ++dof) {
    if (chosen.contains({dof, dof})) continue;
    std::vector<const FitRecord*> candidates;
    for (const FitRecord* fit : body_fits)
      if (fit->dof == kForceNames[dof] && fit->variable == kVelocityNames[dof]) candidates.push_back(fit);
    if (candidates.size() > 1) {
      std::string names;
      for (const FitRecord* fit : candidates) names += (names.empty() ? "'" : ", '") + fit->name + "'";
      throw InputError("body '" + request.body + "' has " + std::to_string(candidates.size()) + " fits of " +
                       std::string(kForceNames[dof]) + " in " + std::string(kVelocityNames[dof]) + " (" + names +
                       "); expected one: choose with --fit " + std::string(kForceNames[dof]) + "=NAME");
    }
    if (candidates.size() == 1)
      chosen.emplace(std::pair{dof, dof}, candidates.front());
    else
      out.missing_dofs.push_back(dof);
  }
  if (!out.missing_dofs.empty() && !request.allow_missing) {
    std::string missing;
    for (std::size_t dof : out.missing_dofs)
      missing +=
          (missing.empty() ? "" : ", ") + std::string(kForceNames[dof]) + " in " + std::string(kVelocityNames[dof]);
    throw InputError("body '" + request.body + "' has no damping law of " + missing +
                     "; expected a fit of each force component in its own velocity (hydrocoef fit --body " +
                     request.body +
                     " --dof DOF --terms x,x|x|), --fit DOF=NAME, or --allow-missing to write 0 for "
                     "those");
  }

  for (const auto& [key, fit] : chosen) {
    const auto [dof, variable] = key;
    const std::string& x = fit->variable;
    GazeboFitSource source;
    source.dof = dof;
    source.variable = variable;
    source.fit_name = fit->name;
    source.fit_id = fit->id;
    source.terms = fit->terms;
    source.stored_sign = fit->sign;
    source.run_ids = fit->run_ids;
    source.n = fit->n;
    source.rmse = fit->rmse;
    source.created_at = fit->created_at;
    for (const FitRecord::Coefficient& c : fit->coefficients) {
      if (!std::isfinite(c.value)) {
        throw InputError(describe_fit(*fit) + ": coefficient of '" + c.term + "' is " + shortest_number(c.value) +
                         "; expected a finite number");
      }
      const double on_body = to_on_body(c.value, fit->sign);
      if (c.term == term_name(DampingTerm::Linear, x)) {
        source.linear = on_body;
      } else if (c.term == term_name(DampingTerm::SignedQuadratic, x)) {
        source.quadratic = on_body;
      } else if (c.term == term_name(DampingTerm::Constant, x)) {
        if (!request.drop_constant) {
          throw InputError(describe_fit(*fit) + " has the constant term '1' = " + shortest_number(c.value) + " " +
                           (dof < 3 ? "N" : "N m") +
                           " (a force at rest, e.g. a CFD bias) that Fossen damping cannot express; expected "
                           "--drop-constant to drop it (reported in the output), or a fit without '1'");
        }
        source.dropped_constant = on_body;
      } else {
        throw InputError(describe_fit(*fit) + ": term '" + c.term + "' " + refusal_reason(c.term, x));
      }
    }
    double linear = source.linear;
    double quadratic = source.quadratic;
    if (request.linearize_at) {
      // d(b x|x|)/dx at x0 = 2 b |x0|; the operating point moves forward only.
      const double x0 = variable == 0 ? std::abs(*request.linearize_at) : 0.0;
      linear += 2.0 * quadratic * x0;
      quadratic = 0.0;
    }
    out.linear_b(dof, variable) = linear;
    out.quadratic_b(dof, variable) = quadratic;
    const std::string law = std::string(kForceNames[dof]) + " in " + x;
    if (source.dropped_constant) {
      out.notes.push_back(law + ": constant term " + shortest_number(*source.dropped_constant) + " " +
                          (dof < 3 ? "N" : "N m") + " (on-body) of fit '" + fit->name +
                          "' dropped on request (drop-constant)");
    }
    if (dof == variable && (linear > 0.0 || quadratic > 0.0)) {
      // F x = x^2 (linear + quadratic |x|): positive near 0 when linear > 0,
      // at large speed when quadratic > 0. A plugin would gain energy there.
      const std::string what = law + ": an on-body damping coefficient of fit '" + fit->name +
                               "' is positive (linear " + shortest_number(linear) + ", quadratic " +
                               shortest_number(quadratic) + "): it pushes the body along its motion";
      if (!request.allow_unphysical)
        throw InputError(what +
                         "; expected damping that takes energy out of the motion (check the fit's sign "
                         "convention or fit again; --allow-unphysical writes it anyway)");
      out.notes.push_back(what + " (written on request: allow-unphysical)");
    }
    out.sources.push_back(std::move(source));
  }
  for (std::size_t dof : out.missing_dofs) {
    out.notes.push_back(std::string(kForceNames[dof]) + " in " + std::string(kVelocityNames[dof]) +
                        ": no damping law; written as 0 on request (allow-missing)");
  }
  if (request.linearize_at) {
    out.notes.push_back("linearised about forward speed U0 = " + shortest_number(*request.linearize_at) +
                        " m/s (other velocities 0): each b x|x| replaced by its slope 2 b |x0| added to the linear "
                        "term (x0 = U0 for laws in u, 0 otherwise), quadratic terms written as 0; the force at U0 "
                        "itself is not included");
  }
  if (const std::string note = check_added_mass(request.added_mass); !note.empty()) out.notes.push_back(note);
  out.added_mass_b = request.added_mass;
  out.added_mass_source = request.added_mass_source;
  return out;
}

std::vector<GazeboElement> gazebo_elements(const GazeboCoefficients& c, const GazeboWriteOptions& options) {
  std::vector<GazeboElement> out;
  if (options.flavor == GazeboFlavor::Uuv) {
    bool coupled_linear = false;
    for (std::size_t i = 0; i < 6; ++i) {
      for (std::size_t j = 0; j < 6; ++j) {
        if (i == j) continue;
        if (c.linear_b(i, j) != 0.0) coupled_linear = true;
        if (c.quadratic_b(i, j) != 0.0) {
          const std::string x(kVelocityNames[j]);
          throw InputError("flavor uuv: the law of " + std::string(kForceNames[i]) + " in " + x + "|" + x +
                           "| (a cross-coupling quadratic term, " + shortest_number(c.quadratic_b(i, j)) + " " +
                           damping_unit(i, j, true) +
                           ") cannot be written: uuv_simulator's fossen model uses only the diagonal of "
                           "quadratic_damping; expected --flavor gz (which takes it as " +
                           kGzForce[i] + kGzVelocity[j] + "abs" + kGzVelocity[j] +
                           "), --linearize-at U0, or no such fit");
        }
      }
    }
    const std::array<double, 36> added_mass = row_major(c.added_mass_b);
    out.push_back({"added_mass", std::vector<double>(added_mass.begin(), added_mass.end()),
                   "positive Ma, 6x6 row-major, rows X..N, columns u..r derivatives; kg, kg m, kg m^2"});
    GazeboElement linear{"linear_damping", {}, ""};
    if (coupled_linear) {
      const std::array<double, 36> linear_b = row_major(c.linear_b);
      linear.values.assign(linear_b.begin(), linear_b.end());
      linear.unit =
          "on-body, 6x6 row-major (cross-coupling laws present), rows X..N, columns u..r; N/(m/s), "
          "N/(rad/s), N m/(m/s), N m/(rad/s)";
    } else {
      for (std::size_t i = 0; i < 6; ++i) linear.values.push_back(c.linear_b(i, i));
      linear.unit = "on-body diagonal Xu Yv Zw Kp Mq Nr; N/(m/s) x3, N m/(rad/s) x3";
    }
    out.push_back(std::move(linear));
    out.push_back({"linear_damping_forward_speed", std::vector<double>(6, 0.0),
                   "0: hydrocoef's laws are of one velocity component, so none is proportional to u nu_j"});
    GazeboElement quadratic{"quadratic_damping",
                            {},
                            "on-body diagonal Xu|u| Yv|v| Zw|w| Kp|p| Mq|q| Nr|r|; "
                            "N/(m/s)^2 x3, N m/(rad/s)^2 x3"};
    for (std::size_t i = 0; i < 6; ++i) quadratic.values.push_back(c.quadratic_b(i, i));
    out.push_back(std::move(quadratic));
    return out;
  }
  const std::array<double, 6> t =
      options.link_axes == GazeboLinkAxes::Flu ? kFrdToFlu : std::array<double, 6>{1, 1, 1, 1, 1, 1};
  const auto name = [](std::size_t i, std::size_t j, const std::string& middle, bool abs) {
    std::string text{kGzForce[i]};
    text += middle;
    text += kGzVelocity[j];
    if (abs) text += std::string("abs") + kGzVelocity[j];
    return text;
  };
  for (std::size_t i = 0; i < 6; ++i) {
    for (std::size_t j = 0; j < 6; ++j) {
      // SNAME derivative X_udot = -Ma(0,0); "+ 0.0" keeps -0 out of the file.
      const double value = -t[i] * t[j] * c.added_mass_b(i, j) + 0.0;
      if (i == j || value != 0.0) out.push_back({name(i, j, "Dot", false), {value}, added_mass_unit(i, j)});
    }
  }
  for (std::size_t i = 0; i < 6; ++i) {
    for (std::size_t j = 0; j < 6; ++j) {
      const double value = t[i] * t[j] * c.linear_b(i, j) + 0.0;
      if (i == j || value != 0.0) out.push_back({name(i, j, "", false), {value}, damping_unit(i, j, false)});
    }
  }
  for (std::size_t i = 0; i < 6; ++i) {
    for (std::size_t j = 0; j < 6; ++j) {
      const double value = t[i] * t[j] * c.quadratic_b(i, j) + 0.0;
      if (i == j || value != 0.0) out.push_back({name(i, j, "", true), {value}, damping_unit(i, j, true)});
    }
  }
  return out;
}

std::string gazebo_text(const GazeboCoefficients& c, const GazeboWriteOptions& options) {
  if (options.flavor == GazeboFlavor::Gz && options.link_name.empty())
    throw InputError("flavor gz: empty link name; expected the name of the link the plugin acts on (--link NAME)");
  const std::vector<GazeboElement> elements = gazebo_elements(c, options);
  const bool uuv = options.flavor == GazeboFlavor::Uuv;
  const bool flu = options.link_axes == GazeboLinkAxes::Flu;
  std::string text = "<?xml version=\"1.0\"?>\n";
  text += sdf_comment("hydrocoef " + std::string(kVersion) + ": " +
                      (uuv ? "uuv_simulator 'fossen' hydrodynamic model" : "gz-sim Hydrodynamics system parameters") +
                      " of body '" + c.body + "', from damping-law fits");
  if (uuv) {
    text += sdf_comment(
        "Paste the <hydrodynamic_model> element inside the <link name=...> element of the "
        "uuv_underwater_object plugin, beside <volume> and <center_of_buoyancy>.");
    text += sdf_comment(
        "Frame: body axes x forward, y starboard, z down (FRD, the NED convention); the plugin turns the "
        "link's FLU velocities into FRD itself, so nothing is converted here.");
    text += sdf_comment(
        "Sign convention: on-body (SNAME), damping is negative. The plugin's damping force is "
        "linear_damping nu + u linear_damping_forward_speed nu + diag(quadratic_damping) |nu| nu; "
        "added_mass is the positive Ma.");
  } else {
    text += sdf_comment("Frame: the parameters are in the link's axes, " +
                        std::string(flu ? "FLU (x forward, y left, z up): hydrocoef's FRD body-axis matrices M were "
                                          "written as T M T with T = diag(1,-1,-1,1,-1,-1), so diagonal terms are "
                                          "unchanged and couplings between (y, z, q, r) and (x, p) change sign."
                                        : "FRD (x forward, y starboard, z down), as hydrocoef's body axes: nothing "
                                          "converted."));
    text += sdf_comment(
        "Sign convention: SNAME derivatives on the body. xU, xUabsU...: force = xU u + xUabsU |u| u, "
        "negative for damping; xDotU... = -Ma (negative). Every diagonal term is written (older gz-sim "
        "defaults are not 0); couplings only where non-zero. gz-sim uses only Ma's diagonal in its "
        "Coriolis term.");
  }
  text += sdf_comment("Units: SI; each element's unit is in the comment beside it.");
  for (const GazeboFitSource& s : c.sources) {
    std::string line = std::string(kForceNames[s.dof]) + " in " + std::string(kVelocityNames[s.variable]) + ": fit '" +
                       s.fit_name + "' (id " + std::to_string(s.fit_id) + ", terms " + s.terms + ", stored " +
                       std::string(to_string(s.stored_sign)) +
                       (s.stored_sign == SignConvention::OpposingMotion ? ", negated to on-body" : "") + ", n " +
                       std::to_string(s.n) + ", rmse " + shortest_number(s.rmse) +
                       (s.created_at.empty() ? "" : ", fitted " + s.created_at) + "): linear " +
                       shortest_number(s.linear) + " " + damping_unit(s.dof, s.variable, false) + ", quadratic " +
                       shortest_number(s.quadratic) + " " + damping_unit(s.dof, s.variable, true) + "; runs [" +
                       join_ids(s.run_ids) + "]";
    text += sdf_comment(line);
  }
  text += sdf_comment("Added mass: " + (c.added_mass_source.empty() ? std::string("given") : c.added_mass_source) +
                      "; symmetric positive semi-definite (checked).");
  for (const std::string& note : c.notes) text += sdf_comment("Note: " + note);
  if (!uuv) {
    // Gazebo Ionic moved added mass into the link's inertial; offer the same numbers there.
    const std::array<double, 6> t = flu ? kFrdToFlu : std::array<double, 6>{1, 1, 1, 1, 1, 1};
    std::string block =
        "Gazebo Ionic and later deprecate the *Dot* parameters in favour of the link's "
        "<inertial><fluid_added_mass> (positive Ma, link axes). The same matrix there: "
        "<fluid_added_mass>";
    static constexpr std::array<char, 6> kSdf{'x', 'y', 'z', 'p', 'q', 'r'};
    for (std::size_t i = 0; i < 6; ++i) {
      for (std::size_t j = i; j < 6; ++j) {
        const std::string tag = std::string{kSdf[i]} + kSdf[j];
        block += "<" + tag + ">" + shortest_number(t[i] * t[j] * c.added_mass_b(i, j) + 0.0) + "</" + tag + ">";
      }
    }
    text += sdf_comment(block + "</fluid_added_mass>");
  }
  if (uuv) {
    text += "<hydrodynamic_model>\n  <type>fossen</type>\n";
    for (const GazeboElement& e : elements) {
      text += sdf_comment(e.name + ": " + e.unit, "  ");
      text += "  <" + e.name + ">";
      if (e.values.size() == 36) {
        text += "\n";
        for (std::size_t i = 0; i < 6; ++i) {
          text += "   ";
          for (std::size_t j = 0; j < 6; ++j) text += " " + shortest_number(e.values[6 * i + j]);
          text += "\n";
        }
        text += "  ";
      } else {
        for (std::size_t k = 0; k < e.values.size(); ++k) text += (k ? " " : "") + shortest_number(e.values[k]);
      }
      text += "</" + e.name + ">\n";
    }
    text += "</hydrodynamic_model>\n";
  } else {
    text += "<plugin filename=\"gz-sim-hydrodynamics-system\" name=\"gz::sim::systems::Hydrodynamics\">\n";
    text += "  <link_name>" + escape::xml_text(options.link_name) + "</link_name>\n";
    for (const GazeboElement& e : elements) {
      text += "  <" + e.name + ">" + shortest_number(e.values.front()) + "</" + e.name + ">  <!-- " +
              escape::xml_comment(e.unit) + " -->\n";
    }
    text += "</plugin>\n";
  }
  return text;
}

void write_gazebo(const GazeboCoefficients& coefficients, const GazeboWriteOptions& options,
                  const std::filesystem::path& path) {
  write_file_atomically(path, gazebo_text(coefficients, options));
}

}  // namespace hydrocoef
