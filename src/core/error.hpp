// Errors that carry their context. Bad input (a malformed file, a wrong unit, a
// bad argument, a corrupt database) is an InputError: the CLI prints its
// message on one line and exits with code 2. Anything else is a bug.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "hydrocoef/error.hpp"

namespace hydrocoef {

/// Text as it may appear in a one-line message: control characters (newlines
/// included), bidirectional formatting characters and bytes that are not
/// UTF-8 become \xNN (byte by byte); valid UTF-8 such as "µN" is kept; text
/// longer than max_characters is cut and ends in "...".
std::string printable_text(std::string_view text, std::size_t max_characters = std::string_view::npos);

/// The most characters of an InputError's message (callers quote short
/// excerpts; this is the backstop). InputError itself is in the public header
/// hydrocoef/error.hpp, so that library users catch the type the library throws.
inline constexpr std::size_t kMaxMessageCharacters = 2000;

/// Formats a location the way compilers do: "file:line:column".
std::string format_location(const SourceLocation& where);

}  // namespace hydrocoef
