// UTF-8 decoding (and encoding) for the checks that text from files, command lines and
// databases must pass before it is used (names, error messages).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace hydrocoef {

/// One decoded code point and the number of bytes it took.
struct Utf8CodePoint {
  std::uint32_t value = 0;
  std::size_t length = 0;  ///< 1..4
};

/// Decodes the UTF-8 sequence starting at text[i]. Returns nullopt for a
/// byte that does not start a valid, shortest-form sequence (stray
/// continuation bytes, overlong forms, surrogates, values beyond U+10FFFF,
/// sequences cut short by the end of the text).
std::optional<Utf8CodePoint> decode_utf8(std::string_view text, std::size_t i);

/// True for code points that change how the text around them is shown or
/// read rather than showing a character: C0 and C1 controls, DEL, the
/// bidirectional embedding, override and isolate controls (U+061C, U+200E,
/// U+200F, U+202A-U+202E, U+2066-U+2069), the line and paragraph separators
/// U+2028/U+2029, the byte-order mark U+FEFF and the noncharacters
/// U+FFFE/U+FFFF.
bool is_format_or_control(std::uint32_t code_point);

/// Appends code point `code` to `out` as UTF-8 (a character reference read
/// from XML, for example). Returns false, appending nothing, for 0, a
/// surrogate or a value beyond U+10FFFF.
bool append_utf8(std::uint32_t code, std::string& out);

}  // namespace hydrocoef
