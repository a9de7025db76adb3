#include "src/core/error.hpp"

#include "src/core/utf8.hpp"

namespace hydrocoef {

std::string printable_text(std::string_view text, std::size_t max_characters) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  std::size_t shown = 0;
  for (std::size_t i = 0; i < text.size(); ++shown) {
    if (shown == max_characters) {
      out += "...";
      break;
    }
    const auto decoded = decode_utf8(text, i);
    if (decoded && !is_format_or_control(decoded->value)) {
      // Printable ASCII, or valid UTF-8 such as "µN".
      out.append(text.substr(i, decoded->length));
      i += decoded->length;
    } else {
      // Control and bidirectional formatting characters and stray bytes,
      // byte by byte, so that the message stays one line shown as written.
      const std::size_t length = decoded ? decoded->length : 1;
      for (std::size_t k = 0; k < length; ++k) {
        const auto c = static_cast<unsigned char>(text[i + k]);
        out += "\\x";
        out += kHex[c >> 4];
        out += kHex[c & 0x0F];
      }
      i += length;
    }
  }
  return out;
}

std::string format_location(const SourceLocation& where) {
  std::string out = where.file;
  if (where.line > 0) {
    out += ':' + std::to_string(where.line);
    if (where.column > 0) out += ':' + std::to_string(where.column);
  }
  return out;
}

InputError::InputError(const std::string& message)
    : std::runtime_error(printable_text(message, kMaxMessageCharacters)) {}

InputError::InputError(const SourceLocation& where, const std::string& message)
    : std::runtime_error(
          printable_text(where.file.empty() && where.line == 0 ? message : format_location(where) + ": " + message,
                         kMaxMessageCharacters)),
      where_(where) {}

}  // namespace hydrocoef
