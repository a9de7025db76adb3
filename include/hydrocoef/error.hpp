// The one exception type hydrocoef throws for bad input: a malformed or
// unreadable file, a wrong unit, a bad option or argument, a query point
// outside a surface, a damaged or foreign database. Its message is one line
// saying what was found, what was expected and where (file, line, column when
// they apply); the hydrocoef command-line tool prints exactly this message
// after "hydrocoef: error: " and exits with code 2.
//
// Anything else the library throws (std::invalid_argument for a call that
// breaks a documented precondition, std::bad_alloc) is a bug in the caller or
// in hydrocoef, not a property of the input.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

#include "hydrocoef/export.hpp"

namespace hydrocoef {

/// Where in a file a problem was found. line and column are 1-based; 0 means
/// "not applicable" (for example a whole-file problem has neither).
struct SourceLocation {
  std::string file;
  std::size_t line = 0;
  std::size_t column = 0;
};

/// Bad input: what was found and what was expected, and where. The message is
/// made printable: control characters, bidirectional formatting characters
/// and bytes that are not UTF-8 become \xNN, so that text quoted from a binary
/// or damaged file still gives one readable line; it is cut at 2,000
/// characters.
class HYDROCOEF_EXPORT InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message);
  /// The message becomes "file:line:column: message" (parts that are unset are left out).
  InputError(const SourceLocation& where, const std::string& message);

  /// The location given to the constructor (empty when none was).
  const SourceLocation& where() const noexcept { return where_; }

 private:
  SourceLocation where_;
};

}  // namespace hydrocoef
