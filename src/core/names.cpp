#include "src/core/names.hpp"

#include <array>
#include <cstdio>

#include "src/core/utf8.hpp"

namespace hydrocoef {
namespace {

std::string code_point_text(std::uint32_t value) {
  std::array<char, 16> text{};
  std::snprintf(text.data(), text.size(), "U+%04X", static_cast<unsigned>(value));
  return text.data();
}

bool is_identifier_start(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
bool is_identifier_char(char c) { return is_identifier_start(c) || (c >= '0' && c <= '9'); }

std::string expected_text(NameKind kind) {
  const std::string most = std::to_string(max_name_characters(kind));
  if (kind == NameKind::Parameter)
    return "expected an identifier of 1 to " + most + " characters: a letter or '_', then letters, digits or '_'";
  return "expected printable UTF-8 of 1 to " + most +
         " characters, without control or formatting characters and without leading or trailing spaces";
}

}  // namespace

std::string_view name_kind_text(NameKind kind) {
  switch (kind) {
    case NameKind::Body: return "body";
    case NameKind::Surface: return "surface";
    case NameKind::Fit: return "fit";
    case NameKind::Parameter: return "parameter";
    case NameKind::Field: return "field";
  }
  return "name";
}

std::size_t max_name_characters(NameKind kind) {
  switch (kind) {
    case NameKind::Body: return 128;
    case NameKind::Surface: return 128;
    case NameKind::Fit: return 160;
    case NameKind::Parameter: return 64;
    case NameKind::Field: return 256;
  }
  return 128;
}

std::optional<std::string> name_problem(NameKind kind, std::string_view name) {
  if (name.empty()) return "is empty";
  std::size_t characters = 0;
  for (std::size_t i = 0; i < name.size(); ++characters) {
    const auto decoded = decode_utf8(name, i);
    const std::string at = " at character " + std::to_string(characters + 1);
    if (!decoded) return "is not valid UTF-8 (byte " + std::to_string(i + 1) + ")";
    if (is_format_or_control(decoded->value))
      return "contains a control or formatting character (" + code_point_text(decoded->value) + ")" + at;
    if (kind == NameKind::Parameter) {
      const char c = name[i];
      if (decoded->length != 1 || !(characters == 0 ? is_identifier_start(c) : is_identifier_char(c)))
        return "contains '" + std::string(name.substr(i, decoded->length)) + "'" + at + ", which an identifier cannot";
    }
    i += decoded->length;
  }
  if (characters > max_name_characters(kind)) return "is " + std::to_string(characters) + " characters long";
  if (name.front() == ' ' || name.back() == ' ') return "begins or ends with a space";
  return std::nullopt;
}

std::string_view check_name(NameKind kind, std::string_view name, const SourceLocation& where,
                            std::string_view origin) {
  if (const auto problem = name_problem(kind, name)) {
    std::string message = std::string(name_kind_text(kind)) + " name";
    if (!origin.empty()) message += " from " + std::string(origin);
    message += " '" + printable_text(name, 40) + "' " + *problem + "; " + expected_text(kind);
    throw InputError(where, message);
  }
  return name;
}

}  // namespace hydrocoef
