#include "importers/case_motion.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <numbers>
#include <system_error>
#include <utility>
#include <vector>

#include "importers/openfoam_dictionary.hpp"
#include "src/core/error.hpp"
#include "src/core/numbers.hpp"

namespace hydrocoef {
namespace fs = std::filesystem;

namespace {

// ---- OpenFOAM -------------------------------------------------------------

SourceLocation at(const FoamValue& value) { return SourceLocation{value.file, value.line, 0}; }

std::string vector_text(const std::array<double, 3>& v) {
  return "(" + shortest_number(v[0]) + " " + shortest_number(v[1]) + " " + shortest_number(v[2]) + ")";
}

/// The dictionary that names the solidBody motion function: the file itself
/// or one of its sub-dictionaries (solidBodyCoeffs, solidBodyMotionFvMeshCoeffs ...).
std::vector<const FoamDictionary*> motion_dictionaries(const FoamDictionary& root) {
  std::vector<const FoamDictionary*> out;
  if (root.value("solidBodyMotionFunction")) out.push_back(&root);
  for (const auto& key : root.dictionary_keys())
    if (const FoamDictionary* d = root.dictionary(key); d && d->value("solidBodyMotionFunction")) out.push_back(d);
  return out;
}

}  // namespace

std::optional<CaseOscillation> read_openfoam_motion(const fs::path& case_dir) {
  const fs::path file = case_dir / "constant" / "dynamicMeshDict";
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return std::nullopt;
  const FoamDictionary root = FoamDictionary::read(file, case_dir);
  const auto dictionaries = motion_dictionaries(root);
  if (dictionaries.empty()) {
    const FoamValue* mesh = root.value("dynamicFvMesh");
    if (!mesh || foam_word(mesh).value_or("") == "staticFvMesh") return std::nullopt;
    throw InputError(at(*mesh),
                     "found no solidBodyMotionFunction; expected a solidBody motion "
                     "(oscillatingLinearMotion or oscillatingRotatingMotion), or give the motion with "
                     "--motion, --amplitude and --period");
  }
  if (dictionaries.size() > 1) {
    const FoamValue& second = *dictionaries[1]->value("solidBodyMotionFunction");
    throw InputError(at(second),
                     "found a second solidBodyMotionFunction (several moving bodies); expected one "
                     "oscillating body");
  }
  const FoamDictionary& d = *dictionaries.front();
  const FoamValue& function_entry = *d.value("solidBodyMotionFunction");
  const std::string function = foam_word(&function_entry).value_or("");
  if (function != "oscillatingLinearMotion" && function != "oscillatingRotatingMotion")
    throw InputError(at(function_entry),
                     "solidBodyMotionFunction '" + printable_text(function, 80) +
                         "': expected oscillatingLinearMotion or oscillatingRotatingMotion (a harmonic motion), or "
                         "give the motion with --motion, --amplitude and --period");
  const FoamDictionary* coefficients = d.dictionary(function + "Coeffs");
  if (!coefficients) coefficients = &d;
  const auto entry = [&](const char* key) -> const FoamValue& {
    const FoamValue* value = coefficients->value(key);
    if (!value)
      throw InputError(at(function_entry), function + ": found no '" + key + "' entry; expected it in " + function +
                                               "Coeffs or beside " + "solidBodyMotionFunction");
    return *value;
  };
  CaseOscillation out;
  out.rotation = function == "oscillatingRotatingMotion";
  out.amplitude = foam_vector(entry("amplitude"), "amplitude");
  out.omega = foam_scalar(entry("omega"), "omega");
  if (!(out.omega > 0.0))
    throw InputError(at(entry("omega")), "omega " + shortest_number(out.omega) + ": expected > 0");
  // Newer OpenFOAM releases read amplitude sin(omega t + phaseShift) + verticalShift;
  // the offset does not change velocities or accelerations.
  if (const FoamValue* shift = coefficients->value("phaseShift")) out.phase = foam_scalar(*shift, "phaseShift");
  if (out.rotation) {
    out.origin = foam_vector(entry("origin"), "origin");
    for (double& a : out.amplitude) a *= std::numbers::pi / 180.0;  // OpenFOAM reads degrees
  }
  out.where = function_entry.file + ":" + std::to_string(function_entry.line);
  out.description = function + ", amplitude " + vector_text(foam_vector(entry("amplitude"), "amplitude")) +
                    (out.rotation ? " deg about " + vector_text(out.origin) : std::string(" m")) + ", omega " +
                    shortest_number(out.omega) + " rad/s" +
                    (out.phase != 0.0 ? ", phaseShift " + shortest_number(out.phase) + " rad" : std::string());
  return out;
}

// ---- CFX ------------------------------------------------------------------

namespace {

bool identifier_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

/// Walks `text` in pieces: `on_text` gets what is copied as written (unit
/// brackets, numbers, operators), `on_identifier` every identifier outside
/// unit brackets (one not glued to a number such as the e of 1e3).
template <typename OnText, typename OnIdentifier>
void for_each_piece(std::string_view text, OnText&& on_text, OnIdentifier&& on_identifier) {
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '[') {  // a unit: copied as written
      const std::size_t end = text.find(']', i);
      const std::size_t stop = end == std::string_view::npos ? text.size() : end + 1;
      on_text(text.substr(i, stop - i));
      i = stop;
    } else if (identifier_start(c) &&
               (i == 0 || !(std::isdigit(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '.'))) {
      std::size_t j = i;
      while (j < text.size() && identifier_char(text[j])) ++j;
      on_identifier(std::string(text.substr(i, j - i)));
      i = j;
    } else {
      on_text(text.substr(i, 1));
      ++i;
    }
  }
}

/// `text` with every identifier outside unit brackets replaced by what
/// `replace` returns for it (nullopt keeps it).
template <typename Replace>
std::string replace_identifiers(std::string_view text, Replace&& replace) {
  std::string out;
  for_each_piece(
      text, [&](std::string_view piece) { out.append(piece); },
      [&](const std::string& name) {
        const auto replacement = replace(name);
        out += replacement ? *replacement : name;
      });
  return out;
}

/// Named expressions written out and `pi` as a number, so that t can be
/// found wherever it hides. Each named expression is written out once and
/// remembered; every text is bounded while it is written (an expression that
/// repeats another 20,000 times stops at the bound, not after it is built:
/// 216 KB of CCL took 224 s and then all memory), and references are
/// followed at most 64 deep.
class ExpressionExpander {
 public:
  ExpressionExpander(const CelEvaluator& cel, const CclDocument& document) : cel_(cel), document_(document) {
    for (const auto* library : document.root.children_of_type("LIBRARY"))
      for (const auto* cel_object : library->children_of_type("CEL"))
        for (const auto* expressions : cel_object->children_of_type("EXPRESSIONS"))
          for (const auto& parameter : expressions->parameters) named_.emplace(parameter.name, &parameter);
  }

  std::string expand(std::string_view text, std::size_t line) {
    std::string out;
    (void)expand_into(out, text, line, 0);
    return out;
  }

 private:
  static constexpr std::size_t kMaxExpandedBytes = 1 << 16;
  static constexpr int kMaxDepth = 64;

  struct Written {
    std::string text;
    int height = 0;  ///< levels of references below it
  };

  [[noreturn]] void too_deep(std::size_t line) const {
    throw InputError(document_.location(line), "expressions nested more than 64 deep; expected fewer");
  }

  void append(std::string& out, std::string_view piece, std::size_t line) const {
    if (piece.size() > kMaxExpandedBytes - out.size())
      throw InputError(document_.location(line),
                       "the expression expands to more than 64 kB of CEL; expected a displacement "
                       "of the form A*sin(omega*t + phi)");
    out.append(piece);
  }

  /// Appends `text` (written on `line`, `depth` references down) expanded;
  /// returns how many levels of references it went down.
  int expand_into(std::string& out, std::string_view text, std::size_t line, int depth) {
    if (depth > kMaxDepth) too_deep(line);
    int height = 0;
    for_each_piece(
        text, [&](std::string_view piece) { append(out, piece, line); },
        [&](const std::string& name) {
          const auto found = named_.find(name);
          if (name == "pi") {
            append(out, "(" + shortest_number(std::numbers::pi) + ")", line);
          } else if (!cel_.has_expression(name) || found == named_.end()) {
            append(out, name, line);
          } else {
            const Written& written = written_out(name, *found->second, depth + 1);
            height = std::max(height, written.height + 1);
            append(out, "(", line);
            append(out, written.text, line);
            append(out, ")", line);
          }
        });
    return height;
  }

  const Written& written_out(const std::string& name, const CclParameter& parameter, int depth) {
    if (const auto known = written_.find(name); known != written_.end()) {
      if (depth + known->second.height > kMaxDepth) too_deep(parameter.line);
      return known->second;
    }
    Written written;
    written.height = expand_into(written.text, parameter.value, parameter.line, depth);
    return written_.emplace(name, std::move(written)).first->second;
  }

  const CelEvaluator& cel_;
  const CclDocument& document_;
  std::map<std::string, const CclParameter*> named_;  ///< the first definition, as the document holds one
  std::map<std::string, Written> written_;
};

/// A * sin(omega t + phi) read from one displacement component.
struct Component {
  double amplitude = 0.0, omega = 0.0, phase = 0.0;
};

Component displacement_component(const CelEvaluator& cel, ExpressionExpander& expander, const CclDocument& document,
                                 const CclParameter& parameter) {
  const std::string text = expander.expand(parameter.value, parameter.line);
  const auto location = document.location(parameter.line);
  const std::string expected = "; expected a constant 0 or A*sin(omega*t + phi) with constant A, omega, phi";
  const std::size_t sin_at = text.find("sin(");
  if (sin_at == std::string::npos) {
    const CelValue value = cel.evaluate(text, parameter.line);  // must be constant
    if (value.value != 0.0)
      throw InputError(location, "'" + printable_text(parameter.name, 80) + " = " +
                                     printable_text(parameter.value, 120) + "' is a constant offset" + expected);
    return {};
  }
  int depth = 0;
  std::size_t close = std::string::npos;
  for (std::size_t i = sin_at + 3; i < text.size(); ++i) {
    if (text[i] == '(') ++depth;
    if (text[i] == ')' && --depth == 0) {
      close = i;
      break;
    }
  }
  if (close == std::string::npos)
    throw InputError(location, "unbalanced parentheses in '" + printable_text(parameter.value, 120) + "'");
  std::string prefix = text.substr(0, sin_at), suffix = text.substr(close + 1);
  const auto trim = [](std::string& s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.erase(s.begin());
  };
  trim(prefix);
  trim(suffix);
  if (!prefix.empty() && prefix.back() == '*') prefix.pop_back();
  if (!suffix.empty() && suffix.front() == '*') suffix.erase(suffix.begin());
  if (prefix.empty()) prefix = "1";
  if (suffix.empty()) suffix = "1";
  if (prefix == "-") prefix = "-1";
  const std::string argument = text.substr(sin_at + 4, close - sin_at - 4);
  double amplitude = 0.0;
  std::array<double, 3> values{};
  try {
    const CelValue a = cel.evaluate("(" + prefix + ")*(" + suffix + ")", parameter.line);
    if (!(a.dimension == Dimension{} || a.dimension == parse_unit("m").dimension))
      throw InputError(
          location, "the amplitude of '" + printable_text(parameter.value, 120) + "' is not a length; expected metres");
    amplitude = a.value;
    for (int k = 0; k < 3; ++k) {
      const std::string at_time =
          replace_identifiers(argument, [&](const std::string& name) -> std::optional<std::string> {
            if (name == "t") return "(" + std::to_string(k) + " [s])";
            return std::nullopt;
          });
      values[static_cast<std::size_t>(k)] = cel.evaluate(at_time, parameter.line).value;
    }
  } catch (const CelNotConstant& e) {
    throw InputError(location, "'" + printable_text(parameter.name, 80) + " = " + printable_text(parameter.value, 120) +
                                   "' is not a harmonic motion (" + e.what() + ")" + expected);
  }
  const double omega = values[1] - values[0];
  if (std::abs((values[2] - values[1]) - omega) > 1e-9 * std::max(1.0, std::abs(omega)) || omega == 0.0 ||
      !std::isfinite(omega))
    throw InputError(location, "the argument of sin in '" + printable_text(parameter.value, 120) +
                                   "' is not omega*t + phi with omega != 0" + expected);
  Component out{amplitude, omega, values[0]};
  // Fold signs into the phase: A sin(x) = |A| sin(x + pi) for A < 0, and
  // sin(-w t + phi) = sin(w t - phi + pi).
  if (out.omega < 0.0) {
    out.omega = -out.omega;
    out.phase = std::numbers::pi - out.phase;
  }
  return out;
}

void collect_displacements(const CclObject& object, std::vector<std::pair<const CclObject*, const CclObject*>>& out,
                           const CclObject* boundary) {
  const CclObject* owner = object.type == "BOUNDARY" || object.type == "DOMAIN" ? &object : boundary;
  if (object.parameter("Displacement X Component") || object.parameter("Displacement Y Component") ||
      object.parameter("Displacement Z Component"))
    out.emplace_back(&object, owner);
  for (const auto& child : object.children) collect_displacements(child, out, owner);
}

}  // namespace

std::optional<CaseOscillation> cfx_motion(const CclDocument& document) {
  std::vector<std::pair<const CclObject*, const CclObject*>> found;
  collect_displacements(document.root, found, nullptr);
  if (found.empty()) return std::nullopt;
  const CelEvaluator cel(document);
  ExpressionExpander expander(cel, document);
  std::optional<CaseOscillation> motion;
  std::string motion_owner;
  for (const auto& [object, owner] : found) {
    CaseOscillation here;
    std::optional<std::pair<double, double>> frequency_phase;
    const char* names[3] = {"Displacement X Component", "Displacement Y Component", "Displacement Z Component"};
    std::size_t line = object->line;
    for (std::size_t axis = 0; axis < 3; ++axis) {
      const CclParameter* parameter = object->parameter(names[axis]);
      if (!parameter) continue;
      line = parameter->line;
      Component c = displacement_component(cel, expander, document, *parameter);
      if (c.amplitude == 0.0) continue;
      double phase = c.phase;
      if (c.amplitude < 0.0) {
        c.amplitude = -c.amplitude;
        phase += std::numbers::pi;
      }
      phase = std::remainder(phase, 2.0 * std::numbers::pi);
      if (frequency_phase && (std::abs(frequency_phase->first - c.omega) > 1e-12 * c.omega ||
                              std::abs(std::remainder(frequency_phase->second - phase, 2.0 * std::numbers::pi)) > 1e-9))
        throw InputError(document.location(parameter->line),
                         "the displacement components of " + object->title() +
                             " differ in frequency or phase; expected one harmonic motion along one direction");
      frequency_phase = {c.omega, phase};
      here.amplitude[axis] = c.amplitude;
    }
    if (!frequency_phase) continue;  // all components 0: this boundary does not move
    here.omega = frequency_phase->first;
    here.phase = frequency_phase->second;
    here.where = document.where(line);
    const std::string owner_title = owner ? owner->title() : object->title();
    here.description = "specified displacement of " + owner_title + ", amplitude " + vector_text(here.amplitude) +
                       " m, omega " + shortest_number(here.omega) + " rad/s, phase " + shortest_number(here.phase) +
                       " rad";
    if (!motion) {
      motion = here;
      motion_owner = owner_title;
    } else if (motion->amplitude != here.amplitude || std::abs(motion->omega - here.omega) > 1e-12 * here.omega ||
               std::abs(motion->phase - here.phase) > 1e-9) {
      throw InputError(document.location(line), owner_title + " moves otherwise than " + motion_owner + " (" +
                                                    motion->where + "); expected one rigid harmonic motion");
    }
  }
  return motion;
}

}  // namespace hydrocoef
