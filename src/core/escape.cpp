#include "src/core/escape.hpp"

#include <array>
#include <cstdint>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "src/core/utf8.hpp"

namespace hydrocoef::escape {
namespace {

constexpr std::string_view kReplacement = "\xEF\xBF\xBD";  // U+FFFD

/// Calls visit(code point, its bytes) for each valid code point of `text`
/// and visit(0xFFFD, kReplacement) for each invalid byte.
template <typename Visit>
void for_each_code_point(std::string_view text, Visit&& visit) {
  for (std::size_t i = 0; i < text.size();) {
    if (const auto decoded = decode_utf8(text, i)) {
      visit(decoded->value, text.substr(i, decoded->length));
      i += decoded->length;
    } else {
      visit(0xFFFDu, kReplacement);
      ++i;
    }
  }
}

void replace_all(std::string& text, std::string_view from, std::string_view to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
}

std::string hex_byte(unsigned char byte) {
  std::array<char, 8> text{};
  std::snprintf(text.data(), text.size(), "\\x%02X", static_cast<unsigned>(byte));
  return text.data();
}

}  // namespace

std::string one_line(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for_each_code_point(text, [&](std::uint32_t value, std::string_view bytes) {
    out += is_format_or_control(value) ? kReplacement : bytes;
  });
  return out;
}

std::string gnuplot_string(std::string_view text) {
  std::string body = one_line(text);
  replace_all(body, "]]>", "]] >");
  // A quote is written as the one-character double-quoted string "'" joined
  // by gnuplot's '.' operator: doubling it inside single quotes ('') is
  // documented but gnuplot 5.4 misreads a string that starts with it.
  std::string out = "'";
  for (const char c : body) {
    if (c == '\'')
      out += "'.\"'\".'";
    else
      out += c;
  }
  return out + "'";
}

std::string gnuplot_comment(std::string_view text) {
  std::string out = one_line(text);
  if (!out.empty() && out.back() == '\\') out += ' ';
  return out;
}

std::string matlab_comment(std::string_view text) { return one_line(text); }

std::string matlab_string(std::string_view text) {
  std::string out = "'";
  for (const char c : one_line(text)) {
    if (c == '\'') out += '\'';
    out += c;
  }
  return out + "'";
}

std::string c_comment(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for_each_code_point(text, [&](std::uint32_t value, std::string_view bytes) {
    if (value >= 0x20 && value < 0x7F && value != '\\') {
      out += bytes;
    } else if (value < 0x80) {
      out += hex_byte(static_cast<unsigned char>(value));  // controls and the backslash
    } else {
      std::array<char, 16> code{};
      std::snprintf(code.data(), code.size(), "\\u{%X}", static_cast<unsigned>(value));
      out += code.data();
    }
  });
  replace_all(out, "*/", "* /");
  replace_all(out, "/*", "/ *");
  replace_all(out, "??", "? ?");
  return out;
}

std::string c_string(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7F && c != '"' && c != '\\' && c != '?') {
      out += c;
    } else {
      // Three octal digits always: an escape never swallows a following digit.
      std::array<char, 8> code{};
      std::snprintf(code.data(), code.size(), "\\%03o", static_cast<unsigned>(byte));
      out += code.data();
    }
  }
  return out + "\"";
}

namespace {

/// Whether a spreadsheet would evaluate a cell of this text (OWASP, CSV
/// injection), or csv_text_value would take its first quote for the guard.
bool formula_like(std::string_view text) {
  while (!text.empty() && text.front() == '\'') text.remove_prefix(1);
  return !text.empty() && std::string_view("=+-@\t\r").find(text.front()) != std::string_view::npos;
}

}  // namespace

std::string csv_text(std::string_view text) {
  std::string line = one_line(text);
  const bool guard = formula_like(line);
  if (guard) line.insert(line.begin(), '\'');
  const bool quote = guard || line.find_first_of(",\"") != std::string::npos ||
                     (!line.empty() && (line.front() == ' ' || line.back() == ' '));
  if (!quote) return line;
  std::string out = "\"";
  for (const char c : line) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string csv_text_value(std::string_view cell) {
  if (!cell.empty() && cell.front() == '\'' && formula_like(cell)) cell.remove_prefix(1);
  return std::string(cell);
}

std::string csv_comment(std::string_view text) { return one_line(text); }

std::string xml_text(std::string_view text, bool keep_newlines) {
  std::string out;
  out.reserve(text.size());
  for_each_code_point(text, [&](std::uint32_t value, std::string_view bytes) {
    switch (value) {
      case '&': out += "&amp;"; return;
      case '<': out += "&lt;"; return;
      case '>': out += "&gt;"; return;
      case '"': out += "&quot;"; return;
      case '\'': out += "&apos;"; return;
      case '\n':
      case '\t': out += keep_newlines ? bytes : kReplacement; return;
      default: break;
    }
    // XML 1.0 cannot hold C0 controls (but tab, LF, CR), U+FFFE or U+FFFF;
    // the other formatting characters are legal but would reorder or break
    // what a reader sees, so they go too.
    out += is_format_or_control(value) ? kReplacement : bytes;
  });
  return out;
}

std::string xml_comment(std::string_view text) {
  // Inside a comment nothing is markup: only "--" and the characters XML 1.0
  // cannot hold are a problem, and entities would show as written.
  std::string out;
  out.reserve(text.size());
  for_each_code_point(text, [&](std::uint32_t value, std::string_view bytes) {
    out += is_format_or_control(value) ? kReplacement : bytes;
  });
  replace_all(out, "--", "- -");
  if (!out.empty() && out.back() == '-') out += ' ';
  return out;
}

std::string json_text(const nlohmann::json& document, int indent) {
  return document.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace hydrocoef::escape
