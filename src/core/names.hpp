// Names are data, never code. One rule for every name that enters
// hydrocoef (command line, sidecar, table header, CFD-Post location, VTK
// array or block, monitor column, and every name read back from a
// database), checked where it enters, so that everything downstream can
// rely on it: a name is valid UTF-8 of printable characters (no control,
// bidirectional-formatting or line-separator characters), has no leading or
// trailing space, and is not longer than its kind allows.
//
// Passing the rule does not make a name safe to paste into a script or a
// file format: backquotes, quotes, '%', '*/' and ']]>' are printable.
// Every generator escapes names for its own language (src/core/escape.hpp).
//
// What each kind allows:
//   body, surface   1..128 characters
//   fit             1..160 characters (per-level fits append "@name=value")
//   parameter       a disturbance parameter or surface axis: an identifier,
//                   [A-Za-z_][A-Za-z0-9_]*, 1..64 characters. Parameters are
//                   part of run keys ("a=1;b=2"), --where clauses and
//                   generated identifiers, so '=', ';', spaces and the like
//                   are refused rather than encoded.
//   field           a name a CFD file gives (array, column, location,
//                   monitor, VTK block): 1..256 characters
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "src/core/error.hpp"

namespace hydrocoef {

enum class NameKind { Body, Surface, Fit, Parameter, Field };

/// "body", "surface", "fit", "parameter", "field".
std::string_view name_kind_text(NameKind kind);

/// The largest number of characters (code points) a name of this kind may have.
std::size_t max_name_characters(NameKind kind);

/// What is wrong with `name` as a name of this kind ("contains a control
/// character (U+000A) at character 4", "is empty", ...), or nullopt when it
/// follows the rule.
std::optional<std::string> name_problem(NameKind kind, std::string_view name);

/// Returns `name` when it follows the rule; otherwise throws InputError at
/// `where` naming the kind, quoting the name (printably, cut short) and
/// saying what is wrong and what is expected. `origin` says where the name
/// came from when `where` does not ("--body", "sidecar key 'body'").
std::string_view check_name(NameKind kind, std::string_view name, const SourceLocation& where,
                            std::string_view origin = {});

}  // namespace hydrocoef
