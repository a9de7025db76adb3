// ANSYS CFX Command Language (CCL), the text in which CFX-Pre writes a case
// (.ccl) and the CFX-Solver echoes the run's settings at the top of its
// output file (.out), read into a tree of objects and parameters, and a small
// evaluator of the CFX Expression Language (CEL) for constant expressions, so
// that the case's free stream, fluid and reference pressure can be read in SI
// with their dimension (src/pipeline/cfx_case.hpp uses both).
//
// Syntax (ANSYS CFX-Solver Manager User's Guide, "Command Language File
// Rules", cfx_solv/i1302657, and "RULES and VARIABLES Files", cfx_solv/i3302781):
//   NAME:            an object without a label (a singleton: LIBRARY:, CEL:)
//   NAME: Label      a named object (DOMAIN: Default Domain, BOUNDARY: inlet)
//   ...              its parameters and child objects
//   END
//   Key = Value      a parameter; a line ending in '\' continues on the next
//   # comment        everything right of '#' is ignored
// Indentation is irrelevant; runs of spaces and tabs in a name count as one
// space; CRLF line ends are accepted. A singleton or a named object that
// appears twice under the same parent is one object (the solver merges them),
// and a parameter set twice keeps its last value ("the latter definition
// overrides the first"). Lookups match object types and parameter names
// without regard to case (an exact match first); labels and CEL names are
// case-sensitive, as in CFX, so parameters whose names differ only in case
// (expressions Uinf and uinf) are kept apart.
//
// The solver output echoes the CCL after a banner (cfx_solv/i1299644,
// "CFX-Solver Output File"; the layout of real .out files as public parsers
// read them: HendrikBorgelt/Json_Segmenation_for_Ontology,
// CFD_Data_extraction20220707.py, which splits a .out at five-line banners
// " +---+ / |   | / | title | / |   | / +---+" and reads the CCL from the
// "CFX Command Language for Run" section up to the next banner):
//
//    +--------------------------------------------------------------------+
//    |                                                                    |
//    |                    CFX Command Language for Run                    |
//    |                                                                    |
//    +--------------------------------------------------------------------+
//
//    LIBRARY:
//      MATERIAL: Water
//   ...
//    +--------------------------------------------------------------------+   (the next section)
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "src/core/error.hpp"
#include "src/core/units.hpp"

namespace hydrocoef {

struct CclParameter {
  std::string name;      ///< as written, runs of blanks as one space ("Boundary Type")
  std::string value;     ///< trimmed, continuation lines joined ("INLET", "2 [m s^-1]")
  std::size_t line = 0;  ///< 1-based line of the parameter's first line in the file
};

struct CclObject {
  std::string type;   ///< "BOUNDARY", "LIBRARY" (as written; "" for the file's root)
  std::string label;  ///< "inlet"; empty for a singleton
  std::size_t line = 0;
  std::vector<CclParameter> parameters;  ///< in file order, each (case-sensitive) name once
  std::vector<CclObject> children;       ///< in file order

  /// The parameter of that name: the one spelt exactly so, else the first
  /// that differs only in case; nullptr when there is none.
  const CclParameter* parameter(std::string_view name) const;
  /// The children of that type (case-insensitive), in file order.
  std::vector<const CclObject*> children_of_type(std::string_view of_type) const;
  /// The first child of that type (and label, when one is given), or nullptr.
  const CclObject* child(std::string_view of_type, std::optional<std::string_view> with_label = std::nullopt) const;
  /// "BOUNDARY: inlet" or "LIBRARY", for messages.
  std::string title() const;
};

struct CclDocument {
  std::string file;  ///< the name used in messages and in "file:line" places
  CclObject root;    ///< type "", holding the top-level objects (LIBRARY, FLOW, ...)

  /// "file:line".
  std::string where(std::size_t line) const { return file + ":" + std::to_string(line); }
  SourceLocation location(std::size_t line) const { return SourceLocation{file, line, 0}; }
};

/// Parses CCL text. `file` names it in messages; `first_line` is the number
/// of the text's first line in that file (the CCL echoed in a .out starts
/// further down). InputError "file:line: ..." for: a line that is neither an
/// object, a parameter nor END, an END without its object, an object without
/// its END (naming the object's line), a parameter outside every object, a
/// continuation at the end of the text, Perl (lines starting with '!') or
/// action lines ('>'), and binary data.
CclDocument parse_ccl(std::string_view text, const std::string& file, std::size_t first_line = 1);

/// Runs of blanks as one space, trimmed: CCL names (and the names of the
/// solver output's tables) compare this way.
std::string collapse_blanks(std::string_view text);

/// The CCL a CFX solver output file echoes: its text and the 1-based line of
/// the .out on which that text starts (pass it to parse_ccl as first_line).
struct CclExcerpt {
  std::string_view text;
  std::size_t first_line = 1;
};

/// The block after the "CFX Command Language for Run" banner up to the next
/// banner (a line of '+' and '-' only) or the end of the text; nullopt when
/// the text has no such banner.
std::optional<CclExcerpt> ccl_from_solver_output(std::string_view out_text);

/// True when one of the first `max_lines` lines of the text is the banner
/// line "| CFX Command Language for Run |" of a CFX solver output file.
bool looks_like_cfx_solver_output(std::string_view head, std::size_t max_lines = 200);

/// A CEL value in SI and its dimension (src/core/units.hpp).
struct CelValue {
  double value = 0.0;
  Dimension dimension;
};

/// Thrown for CEL that is valid but not constant (a function call, a
/// variable such as x, t or Temperature, a locator '@', a name that is no
/// expression of the file): callers that can do without the value may turn
/// it into a note. Everything else (syntax, dimensions, cycles, units) is a
/// plain InputError.
class CelNotConstant : public InputError {
 public:
  CelNotConstant(const SourceLocation& where, const std::string& message) : InputError(where, message) {}
};

/// Evaluates constant CEL against the expressions of a document's
/// LIBRARY: CEL: EXPRESSIONS: objects (all of them; a name defined twice
/// takes its last definition).
///
/// Grammar: numbers (1, 2.5, .5, 8.899E-4), a number followed by a unit in
/// brackets (2 [m s^-1], 1 [atm], 0 [Pa], 3 []), names of expressions,
/// + - * / ^, unary + and -, parentheses. ^ binds tighter than unary minus
/// and to the right (-2^2 = -4, 2^3^2 = 2^9); its exponent must be a
/// dimensionless constant, a whole number unless the base is dimensionless.
/// Sums and differences need equal dimensions. Units are read by parse_unit,
/// after `atm` (101325 Pa) and `psi` (6894.757293168361 Pa), which it lacks,
/// are turned into pascals here. Expression references are followed
/// recursively (each evaluated once), at most 64 deep; a cycle is refused
/// naming it. Every error names the file and the line of the text that holds
/// the offending token. The evaluator keeps a reference to the document, which
/// must outlive it.
class CelEvaluator {
 public:
  explicit CelEvaluator(const CclDocument& document);

  /// Evaluates `text`, written on `line` of the document's file.
  CelValue evaluate(std::string_view text, std::size_t line) const;
  /// Evaluates a parameter's value.
  CelValue evaluate(const CclParameter& parameter) const { return evaluate(parameter.value, parameter.line); }
  /// Evaluates a parameter and checks its dimension: InputError at its line
  /// ("'U = 2 [Pa]' is a pressure (kg m^-1 s^-2); expected a velocity
  /// (m s^-1)") unless it matches. A dimensionless 0 passes as any dimension.
  double evaluate_as(const CclParameter& parameter, const Dimension& expected, std::string_view what) const;
  /// The value of the expression of that name; CelNotConstant when there is none.
  CelValue expression(const std::string& name, std::size_t used_on_line) const;
  bool has_expression(const std::string& name) const { return expressions_.count(name) != 0; }

 private:
  friend class CelParser;
  const CclDocument& document_;
  std::map<std::string, CclParameter> expressions_;
  mutable std::map<std::string, CelValue> cache_;
  mutable std::vector<std::string> evaluating_;
};

}  // namespace hydrocoef
