// Names are data, never code: every generated text that holds a name (a
// body, fit, surface, axis, output or array name, a file path, a note) puts
// it through one of these functions, one per target language, so that no
// name can end a comment or a string early, run a command, or make the file
// ill-formed. Each function is total: it accepts any bytes (names read back
// from a received database included) and returns text that is inert in its
// language. Invalid UTF-8 and characters a language cannot hold become
// U+FFFD; nothing is dropped silently, so the reader sees where a character
// was.
//
// Each escape is tested against the hostile-name corpus in
// tests/data/hostile/names.txt by running the real consumer (gnuplot, a C
// compiler, an XML parser, a CSV reader, a MATLAB-syntax checker).
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>

namespace hydrocoef::escape {

/// Valid UTF-8 on one line: every invalid byte sequence and every control,
/// bidirectional-formatting or line-separator character (src/core/utf8.hpp)
/// becomes U+FFFD. The basis of every escape below.
std::string one_line(std::string_view text);

// --- gnuplot ---------------------------------------------------------------
/// A gnuplot string expression of single-quoted strings: gnuplot does no
/// backquote command substitution, no macro (@) expansion and no backslash
/// escapes inside single quotes; a quote itself is the double-quoted "'",
/// joined with '.' ('it'."'".'s'). "]]>" is broken ("]] >") because
/// gnuplot's SVG terminal writes text into CDATA sections.
std::string gnuplot_string(std::string_view text);
/// Text for the end of a '#' comment line: one line, and never ending in a
/// backslash (gnuplot continues a comment that ends in one onto the next line).
std::string gnuplot_comment(std::string_view text);

// --- MATLAB ----------------------------------------------------------------
/// Text for the end of a '%' comment line: one line. (A line holding only
/// "%{" or "%}" would open or close a block comment; text after "% " never is.)
std::string matlab_comment(std::string_view text);
/// A single-quoted MATLAB character vector literal ('' for a quote).
std::string matlab_string(std::string_view text);

// --- C ---------------------------------------------------------------------
/// Text for inside a /* */ comment: printable ASCII only (anything else is
/// written as \xNN or \u{...} text), no "*/" or "/*" (GCC warns "/*" within
/// comment), no "??" (trigraphs), no backslash (line splices in // comments).
std::string c_comment(std::string_view text);
/// A C string literal, "..." with every byte outside printable ASCII, the
/// quote, the backslash and '?' (trigraphs) written as an octal escape.
std::string c_string(std::string_view text);

// --- CSV -------------------------------------------------------------------
/// One CSV text cell (RFC 4180): one line always; quoted when it holds a
/// comma or a quote, or starts or ends with a space. A cell a spreadsheet
/// would take for a formula (starting with '=', '+', '-', '@', tab or
/// carriage return, as OWASP's CSV-injection guidance lists) gets a single
/// quote before it and is quoted: "=1+1" is written "'=1+1". A cell already
/// starting with a quote before such a character gets one more quote, so
/// that csv_text_value gives every text back exactly. Numbers never come
/// here: a number cell is written by shortest_number (src/core/numbers.hpp),
/// so -0.5 stays a number; only names and other texts are neutralized.
std::string csv_text(std::string_view text);
/// The text a csv_text cell was written for (after RFC 4180 unquoting): the
/// cell without the single quote csv_text put before a formula-like text.
/// For readers of CSV hydrocoef wrote (a sweep manifest read back).
std::string csv_text_value(std::string_view cell);
/// Text for a '#' comment line of a CSV file: one line.
std::string csv_comment(std::string_view text);

// --- XML, SVG, HTML --------------------------------------------------------
/// Character data or an attribute value of XML 1.0 (also HTML): & < > " '
/// as entities, and the characters XML 1.0 cannot hold even escaped (C0
/// controls but tab, line feed and carriage return; U+FFFE, U+FFFF) as U+FFFD.
/// Line breaks are kept only when `keep_newlines`.
std::string xml_text(std::string_view text, bool keep_newlines = false);
/// Text for inside <!-- -->: one line of characters XML 1.0 can hold, no
/// "--", not ending in '-'; quotes, '<' and '&' stay as they are (a comment
/// has no markup, and an entity there would show as written).
std::string xml_comment(std::string_view text);
/// HTML character data or a double-quoted attribute value.
inline std::string html_text(std::string_view text) { return xml_text(text, true); }

// --- JSON ------------------------------------------------------------------
/// The JSON text of a document (indent < 0: one line). Strings are escaped by
/// nlohmann::json; invalid UTF-8 (a name read back from a damaged database)
/// becomes U+FFFD instead of throwing.
std::string json_text(const nlohmann::json& document, int indent = -1);

}  // namespace hydrocoef::escape
