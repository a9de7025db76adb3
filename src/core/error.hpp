// Errors that carry their context. Bad input (a malformed file, a wrong unit, a
// bad argument, a corrupt database) is an InputError: the CLI prints its
// message on one line and exits with code 2. Anything else is a bug.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace hydrocoef {

/// Where in a file a problem was found. line and column are 1-based; 0 means
/// "not applicable" (for example a whole-file problem has neither).
struct SourceLocation {
  std::string file;
  std::size_t line = 0;
  std::size_t column = 0;
};

/// Text as it may appear in a one-line message: control characters (newlines
/// included), bidirectional formatting characters and bytes that are not
/// UTF-8 become \xNN (byte by byte); valid UTF-8 such as "µN" is kept; text
/// longer than max_characters is cut and ends in "...".
std::string printable_text(std::string_view text, std::size_t max_characters = std::string_view::npos);

/// Bad input: what was found and what was expected, and where. The message
/// is made printable (printable_text), so that text quoted from a binary or
/// damaged file still gives one readable line, and is cut at
/// kMaxMessageCharacters (callers quote short excerpts; this is the backstop).
inline constexpr std::size_t kMaxMessageCharacters = 2000;

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message);
  /// The message becomes "file:line:column: message" (parts that are unset are left out).
  InputError(const SourceLocation& where, const std::string& message);

  const SourceLocation& where() const noexcept { return where_; }

 private:
  SourceLocation where_;
};

/// Formats a location the way compilers do: "file:line:column".
std::string format_location(const SourceLocation& where);

}  // namespace hydrocoef
