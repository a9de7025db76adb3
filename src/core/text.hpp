// Small text helpers shared by the parsers, the importers and the CLI:
// trimming and splitting, on string_views into the caller's text (nothing
// is copied; the views live as long as that text).
//
// Which characters count as blank is the caller's choice and part of its
// format: a CSV cell trims spaces and tabs only (a stray \r or \f is
// content, and an error in a number), a free-format file every white-space
// character. kWhitespace and kSpaceTab name the two sets most formats use.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace hydrocoef {

/// Every white-space character of std::isspace in the "C" locale.
inline constexpr std::string_view kWhitespace = " \t\r\n\v\f";
/// Space and tab: the blanks within one line.
inline constexpr std::string_view kSpaceTab = " \t";

/// `text` without the characters of `blanks` at either end. The result is a
/// view into `text` (an empty one when only blanks are left), so its
/// position in `text` is result.data() - text.data().
std::string_view trim(std::string_view text, std::string_view blanks = kWhitespace);
/// `text` without the characters of `blanks` at its start.
std::string_view trim_left(std::string_view text, std::string_view blanks = kWhitespace);
/// `text` without the characters of `blanks` at its end.
std::string_view trim_right(std::string_view text, std::string_view blanks = kWhitespace);

/// `text` with every character of `blanks` left out, wherever it is: "u | u |" -> "u|u|".
std::string without_blanks(std::string_view text, std::string_view blanks = kWhitespace);

/// The items with `separator` between them: {"u", "v"}, ", " -> "u, v".
std::string join(const std::vector<std::string>& items, std::string_view separator);

/// `text` with the ASCII letters A-Z as a-z and every other byte as it is:
/// no locale, so a name or a file's keyword compares the same everywhere.
std::string lower(std::string_view text);
/// `c` as lower(text) turns it.
constexpr char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

/// The fields between `separator`s, empty ones kept: "a,,b" -> {"a", "", "b"},
/// "a," -> {"a", ""}, "" -> {""}. Fields are not trimmed.
std::vector<std::string_view> split(std::string_view text, char separator);

}  // namespace hydrocoef
