// Reads the free stream, fluid and reference pressure of a CFX case from its CCL
// (see cfx_case.hpp).
#include "src/pipeline/cfx_case.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>

#include "src/core/error.hpp"
#include "src/core/file_bytes.hpp"
#include "src/core/text.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

constexpr Dimension kDynamicViscosity{{1, -1, -1, 0}};

/// True when a parameter's value is `expected`, ignoring case and taking runs
/// of blanks as one space, as CCL compares names.
bool same_option(const CclParameter* option, std::string_view expected) {
  if (!option) return false;
  std::string value;
  bool blank = false;
  for (const char c : option->value) {
    if (c == ' ' || c == '\t') {
      blank = true;
      continue;
    }
    if (blank && !value.empty()) value += ' ';
    blank = false;
    value += c;
  }
  return lower(value) == lower(std::string(expected));
}

std::string name_of(std::string_view name) { return "'" + printable_text(name, 80) + "'"; }

std::string join_names(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& name : names) out += (out.empty() ? "" : ", ") + printable_text(name, 80);
  return out;
}

bool nearly_equal(double a, double b) { return std::abs(a - b) <= 1e-12 * std::max({1.0, std::abs(a), std::abs(b)}); }

std::string format_number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", x);
  return buffer;
}

/// What one inlet states about the free stream.
struct InletStatement {
  enum class Kind { Vector, NormalSpeed } kind = Kind::Vector;
  std::array<double, 3> velocity{};
  double speed = 0.0;
  std::string boundary;
  std::size_t line = 0;  ///< MASS AND MOMENTUM (vector) or Normal Speed (speed)

  std::string describe() const {
    if (kind == Kind::NormalSpeed) return "a normal speed of " + format_number(speed) + " m/s";
    return "(" + format_number(velocity[0]) + ", " + format_number(velocity[1]) + ", " + format_number(velocity[2]) +
           ") m/s";
  }
  bool same_as(const InletStatement& other) const {
    if (kind != other.kind) return false;
    if (kind == Kind::NormalSpeed) return nearly_equal(speed, other.speed);
    for (int i = 0; i < 3; ++i)
      if (!nearly_equal(velocity[i], other.velocity[i])) return false;
    return true;
  }
};

/// A property read from one domain, kept to compare domains.
struct DomainValue {
  double value = 0.0;
  std::string where;
  std::string domain;
};

class CaseReader {
 public:
  explicit CaseReader(const CclDocument& ccl) : ccl_(ccl), cel_(ccl) {
    out_.layer.origin = {SettingSource::CaseFiles, ccl.file};
  }

  CfxCaseSettings read() {
    const auto flows = ccl_.root.children_of_type("FLOW");
    if (flows.empty()) {
      out_.notes.push_back(printable_text(ccl_.file, 200) +
                           " has no FLOW object (only a library?): no free stream, fluid or reference pressure read");
      return std::move(out_);
    }
    for (const CclObject* flow : flows) {
      for (const CclObject* domain : flow->children_of_type("DOMAIN")) {
        const CclParameter* type = domain->parameter("Domain Type");
        if (type && !same_option(type, "Fluid") && !same_option(type, "Porous")) continue;  // a solid domain
        read_boundaries(*domain);
        read_domain_motion(*domain);
        read_reference_pressure(*domain);
        read_fluid(*domain);
      }
    }
    set_free_stream();
    set_consistent("p_ref", p_ref_, "reference pressures");
    set_consistent("rho", rho_, "densities");
    set_consistent("nu", nu_, "kinematic viscosities");
    if (!symmetry_.empty())
      out_.notes.push_back("symmetry boundaries (" + join_names(symmetry_) + ") in " + printable_text(ccl_.file, 200) +
                           ": the forces are the modelled part's (a half or quarter model); give --symmetry PLANE "
                           "for the whole body's");
    if (!walls_.empty())
      out_.notes.push_back("wall boundaries in " + printable_text(ccl_.file, 200) + ": " + join_names(walls_));
    return std::move(out_);
  }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& message) const {
    throw InputError(ccl_.location(line), message);
  }

  std::string where(std::size_t line) const { return ccl_.where(line); }
  std::string printable_where(std::size_t line) const { return printable_text(where(line), 200); }

  static const CclObject* mass_and_momentum(const CclObject& boundary) {
    const CclObject* conditions = boundary.child("BOUNDARY CONDITIONS");
    return conditions ? conditions->child("MASS AND MOMENTUM") : nullptr;
  }

  void read_boundaries(const CclObject& domain) {
    for (const CclObject* boundary : domain.children_of_type("BOUNDARY")) {
      const CclParameter* type = boundary->parameter("Boundary Type");
      if (same_option(type, "INLET"))
        read_inlet(domain, *boundary);
      else if (same_option(type, "OPENING"))
        read_opening(*boundary);
      else if (same_option(type, "SYMMETRY"))
        symmetry_.push_back(boundary->label);
      else if (same_option(type, "WALL"))
        walls_.push_back(boundary->label);
    }
  }

  void read_inlet(const CclObject& domain, const CclObject& boundary) {
    const CclObject* mm = mass_and_momentum(boundary);
    const CclParameter* option = mm ? mm->parameter("Option") : nullptr;
    const std::string inlet = "inlet " + name_of(boundary.label) + " of domain " + name_of(domain.label);
    if (!option) {
      out_.notes.push_back(inlet + " (" + printable_where(boundary.line) +
                           ") states no MASS AND MOMENTUM option: no free stream read from it");
      return;
    }
    InletStatement statement;
    statement.boundary = boundary.label;
    if (same_option(option, "Cartesian Velocity Components")) {
      statement.kind = InletStatement::Kind::Vector;
      statement.line = mm->line;
      const char* components[] = {"U", "V", "W"};
      for (int i = 0; i < 3; ++i) {
        const CclParameter* p = mm->parameter(components[i]);
        if (!p)
          fail(mm->line,
               inlet + " gives Cartesian Velocity Components without " + components[i] + "; expected U, V and W");
        statement.velocity[i] = cel_.evaluate_as(*p, kVelocity, "a velocity");
      }
    } else if (same_option(option, "Normal Speed")) {
      const CclParameter* p = mm->parameter("Normal Speed");
      if (!p) fail(mm->line, inlet + " gives Option = Normal Speed without a Normal Speed; expected one");
      statement.kind = InletStatement::Kind::NormalSpeed;
      statement.speed = cel_.evaluate_as(*p, kVelocity, "a speed");
      statement.line = p->line;
    } else {
      out_.notes.push_back(inlet + " (" + printable_where(option->line) +
                           ") gives Option = " + printable_text(option->value, 80) +
                           ", which states no velocity hydrocoef reads: give the run's flow if it matters");
      return;
    }
    for (const auto& earlier : inlets_)
      if (!earlier.same_as(statement))
        fail(statement.line, "inlets " + name_of(earlier.boundary) + " (" + printable_where(earlier.line) + ") and " +
                                 name_of(statement.boundary) + " state different free streams, " + earlier.describe() +
                                 " and " + statement.describe() + "; expected one (give the run's flow in a sidecar)");
    inlets_.push_back(statement);
  }

  // A pressure opening (a far field or an outlet that lets flow back in)
  // states no velocity: fine beside an inlet that does, refused when it is
  // the only place the free stream could come from (set_free_stream).
  void read_opening(const CclObject& boundary) {
    const CclObject* mm = mass_and_momentum(boundary);
    const CclParameter* option = mm ? mm->parameter("Option") : nullptr;
    if (option && same_option(option, "Opening Pressure and Direction"))
      pressure_openings_.push_back({boundary.label, option->line});
  }

  void read_domain_motion(const CclObject& domain) {
    const CclObject* models = domain.child("DOMAIN MODELS");
    const CclObject* motion = models ? models->child("DOMAIN MOTION") : nullptr;
    const CclParameter* option = motion ? motion->parameter("Option") : nullptr;
    if (!option || same_option(option, "Stationary")) return;
    out_.notes.push_back("domain " + name_of(domain.label) + " moves (DOMAIN MOTION: Option = " +
                         printable_text(option->value, 80) + ", " + printable_where(option->line) +
                         "): the inlet velocity is read as the free stream in CFD axes; check that it is the "
                         "velocity relative to the body");
  }

  void read_reference_pressure(const CclObject& domain) {
    const CclObject* models = domain.child("DOMAIN MODELS");
    const CclObject* reference = models ? models->child("REFERENCE PRESSURE") : nullptr;
    const CclParameter* p = reference ? reference->parameter("Reference Pressure") : nullptr;
    if (!p) return;
    if (const auto value =
            constant_property(*p, kPressure, "a pressure", "the reference pressure of domain " + name_of(domain.label)))
      p_ref_.push_back(DomainValue{*value, where(p->line), domain.label});
  }

  /// A property's value, or nullopt with a note when it is not a constant.
  std::optional<double> constant_property(const CclParameter& p, const Dimension& dimension, std::string_view kind,
                                          const std::string& what) {
    try {
      return cel_.evaluate_as(p, dimension, kind);
    } catch (const CelNotConstant& error) {
      out_.notes.push_back(what + " is not a constant (" + error.what() + "): not set");
      return std::nullopt;
    }
  }

  void read_fluid(const CclObject& domain) {
    const auto fluids = domain.children_of_type("FLUID DEFINITION");
    if (fluids.empty()) return;
    if (fluids.size() > 1) {
      std::vector<std::string> names;
      for (const CclObject* f : fluids) names.push_back(f->label);
      out_.notes.push_back("domain " + name_of(domain.label) + " holds several fluids (" + join_names(names) + ", " +
                           printable_where(fluids.front()->line) + "): rho and nu not set");
      ambiguous_fluid_ = true;
      return;
    }
    const CclParameter* material_name = fluids.front()->parameter("Material");
    if (!material_name) return;
    const CclObject* material = nullptr;
    for (const CclObject* library : ccl_.root.children_of_type("LIBRARY"))
      if (!material) material = library->child("MATERIAL", material_name->value);
    if (!material) {
      out_.notes.push_back("material " + name_of(material_name->value) + " (" + printable_where(material_name->line) +
                           ") is not defined in the file's LIBRARY (CFX's own material library is not read): rho "
                           "and nu not set");
      return;
    }
    const CclObject* properties = material->child("PROPERTIES");
    if (!properties) properties = material->child("MATERIAL PROPERTIES");
    if (!properties) return;
    const std::string material_text = "material " + name_of(material->label);

    std::optional<double> rho;
    if (const CclObject* state = properties->child("EQUATION OF STATE")) {
      const CclParameter* option = state->parameter("Option");
      const CclParameter* density = state->parameter("Density");
      if (same_option(option, "Value") && density) {
        rho = constant_property(*density, kDensity, "a density", "the density of " + material_text);
        if (rho) rho_.push_back(DomainValue{*rho, where(density->line), domain.label});
      } else if (option && !same_option(option, "Value")) {
        out_.notes.push_back("the density of " + material_text +
                             " is not a constant (EQUATION OF STATE: Option = " + printable_text(option->value, 80) +
                             ", " + printable_where(option->line) + "): rho and nu not set");
      }
    }
    if (const CclObject* viscosity = properties->child("DYNAMIC VISCOSITY")) {
      const CclParameter* option = viscosity->parameter("Option");
      const CclParameter* mu = viscosity->parameter("Dynamic Viscosity");
      if (same_option(option, "Value") && mu) {
        const auto value = constant_property(*mu, kDynamicViscosity, "a dynamic viscosity",
                                             "the dynamic viscosity of " + material_text);
        if (value && rho) {
          nu_.push_back(DomainValue{*value / *rho, where(mu->line), domain.label});
        } else if (value) {
          out_.notes.push_back("the dynamic viscosity of " + material_text + " (" + printable_where(mu->line) +
                               ") is known but no constant density: nu not set");
        }
      } else if (option && !same_option(option, "Value")) {
        out_.notes.push_back("the viscosity of " + material_text +
                             " is not a constant (DYNAMIC VISCOSITY: Option = " + printable_text(option->value, 80) +
                             ", " + printable_where(option->line) + "): nu not set");
      }
    }
  }

  void set_free_stream() {
    // A pressure-driven case states no free stream. Whether one is given
    // elsewhere (command line, sidecar, manifest, name pattern) is known only
    // once the settings are merged: the import refuses there, at this line,
    // when none is (see flow_unstated in cfx_case.hpp).
    if (inlets_.empty() && !pressure_openings_.empty()) {
      const auto& opening = pressure_openings_.front();
      const std::string why = "opening " + name_of(opening.label) +
                              " gives Option = Opening Pressure and Direction and no inlet states a velocity: the "
                              "flow is driven by a pressure, so the free stream is not stated";
      out_.layer.set("flow_unstated", why, where(opening.line));
      out_.notes.push_back(why + " (" + printable_where(opening.line) +
                           "): the run's flow is taken from --flow, a sidecar, the manifest or the name pattern");
      return;
    }
    for (const auto& opening : pressure_openings_)
      out_.notes.push_back("opening " + name_of(opening.label) + " (" + printable_where(opening.line) +
                           ") is a pressure opening; the free stream is the inlet's");
    if (inlets_.empty()) return;
    const InletStatement& inlet = inlets_.front();
    if (inlet.kind == InletStatement::Kind::Vector) {
      out_.layer.set("flow", std::vector<double>(inlet.velocity.begin(), inlet.velocity.end()), where(inlet.line));
      return;
    }
    out_.layer.set("flow_speed", inlet.speed, where(inlet.line));
    out_.notes.push_back("inlet " + name_of(inlet.boundary) + " (" + printable_where(inlet.line) + ") gives " +
                         inlet.describe() +
                         "; the direction is the inlet's normal, which the CCL does not state: give the run's flow "
                         "(--flow U,V,W or a sidecar) to import it");
  }

  void set_consistent(const std::string& setting, const std::vector<DomainValue>& values, const std::string& what) {
    if (values.empty()) return;
    if ((setting == "rho" || setting == "nu") && ambiguous_fluid_) return;
    for (const auto& v : values) {
      if (!nearly_equal(v.value, values.front().value)) {
        out_.notes.push_back("domains " + name_of(values.front().domain) + " (" +
                             printable_text(values.front().where, 200) + ") and " + name_of(v.domain) + " (" +
                             printable_text(v.where, 200) + ") state different " + what + ": " + setting + " not set");
        return;
      }
    }
    out_.layer.set(setting, values.front().value, values.front().where);
  }

  const CclDocument& ccl_;
  CelEvaluator cel_;
  CfxCaseSettings out_;
  std::vector<InletStatement> inlets_;
  struct Opening {
    std::string label;
    std::size_t line = 0;
  };
  std::vector<Opening> pressure_openings_;
  std::vector<std::string> symmetry_, walls_;
  std::vector<DomainValue> p_ref_, rho_, nu_;
  bool ambiguous_fluid_ = false;
};

bool has_out_extension(const fs::path& file) { return lower(file.extension().string()) == ".out"; }

}  // namespace

CfxCaseSettings cfx_case_settings(const CclDocument& ccl) { return CaseReader(ccl).read(); }

CfxCaseSettings cfx_case_settings(const fs::path& file) {
  const FileBytes bytes(file);
  const std::string_view text = bytes.view();
  const std::string name = file.string();
  const auto excerpt = ccl_from_solver_output(text);
  if (!excerpt && has_out_extension(file))
    throw InputError(SourceLocation{name, 0, 0},
                     "no 'CFX Command Language for Run' section; expected a CFX solver output file (.out) that "
                     "echoes the run's CCL");
  const CclDocument ccl = excerpt ? parse_ccl(excerpt->text, name, excerpt->first_line) : parse_ccl(text, name);
  return cfx_case_settings(ccl);
}

bool is_cfx_case_file(const fs::path& file) {
  const std::string extension = lower(file.extension().string());
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return false;
  if (extension == ".ccl") return true;
  if (extension != ".out") return false;
  // The banner follows a header of a few dozen lines; 256 KiB holds 200
  // lines of any solver output and bounds what a binary file costs.
  std::ifstream in(file, std::ios::binary);
  if (!in) return false;
  std::string head(256 * 1024, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return looks_like_cfx_solver_output(head, 200);
}

}  // namespace hydrocoef
