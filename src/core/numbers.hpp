// Numbers as text that reads back exactly: the one formatter behind every
// number hydrocoef writes for a machine or quotes in a message (exports,
// stored selections and keys, fit names, trajectories, messages).
//
// The text is std::to_chars' shortest round-trip form: the fewest
// significant digits that std::from_chars (or strtod) reads back as the same
// double, "0.1", "1e+21", "1e-07". Every double has one: denormals are exact
// ("5e-324"), the sign of zero is kept ("-0"; callers that want one zero fold
// it first, value == 0.0 ? 0.0 : value), and the special values are "inf",
// "-inf", "nan" and "-nan" (a NaN with its sign bit set).
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <string_view>

namespace hydrocoef {

/// The quiet NaN that stands for a number that is not defined (a statistic
/// of too few runs, a field a record does not have); written "nan".
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The shortest text that reads back as `value` (see the file comment).
std::string shortest_number(double value);

/// A number for people to read: printf's %.*g with `digits` significant
/// digits ("0.0155077", "1.2e+05"), "n/a" for NaN (an undefined statistic,
/// such as R^2 of a constant force). Not for text a program reads back.
std::string significant(double value, int digits = 6);

/// Appends shortest_number(value) to `out` without a temporary string, for
/// writers of many numbers.
void append_shortest_number(std::string& out, double value);

/// The shortest text that reads back as the same float, e.g. 0.1f -> "0.1"
/// (the double nearest 0.1f would need "0.10000000149011612").
std::string shortest_float(float value);

/// The whole of `text` read as a finite double (std::from_chars; a leading
/// '+' is allowed, blanks are not); nullopt for anything else ("", "1x",
/// "inf", "nan", 1e999). Callers say in their own message what was expected.
std::optional<double> parse_finite_number(std::string_view text);

}  // namespace hydrocoef
