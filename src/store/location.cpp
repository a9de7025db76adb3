#include "src/store/location.hpp"

#include <algorithm>
#include <cctype>

#include "src/core/error.hpp"
#include "src/core/text.hpp"

namespace hydrocoef::store {
namespace {

bool starts_with(std::string_view text, std::string_view prefix) { return text.substr(0, prefix.size()) == prefix; }

/// %XX sequences decoded (others left as they are).
std::string percent_decoded(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '%' && i + 2 < text.size() && std::isxdigit(static_cast<unsigned char>(text[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(text[i + 2]))) {
      out += static_cast<char>(std::stoi(std::string(text.substr(i + 1, 2)), nullptr, 16));
      i += 2;
    } else {
      out += text[i];
    }
  }
  return out;
}

constexpr std::string_view kPasswordAdvice =
    "a password in the database URL is visible to other users of the machine (ps, shell history); expected it in "
    "~/.pgpass, the file $PGPASSFILE names, or $PGPASSWORD (and a key's passphrase not in the URL either)";

}  // namespace

DatabaseLocation parse_database_location(std::string_view text) {
  DatabaseLocation out;
  const std::string scheme_part = lower(text.substr(0, std::min<std::size_t>(text.size(), 16)));
  if (starts_with(scheme_part, "postgresql://") || starts_with(scheme_part, "postgres://")) {
    // Parsed as libpq parses it: user information runs to the first '@'
    // before any '/' (a '?' inside it included), and parameter names are
    // percent-decoded.
    const std::size_t authority = text.find("://") + 3;
    const std::size_t at_or_slash = text.find_first_of("@/", authority);
    const bool has_user = at_or_slash != std::string_view::npos && text[at_or_slash] == '@';
    if (has_user && text.substr(authority, at_or_slash - authority).find(':') != std::string_view::npos)
      throw InputError(SourceLocation{"--db"}, std::string(kPasswordAdvice));
    const std::size_t query = text.find('?', has_user ? at_or_slash + 1 : authority);
    if (query != std::string_view::npos) {
      std::string_view rest = text.substr(query + 1);
      while (!rest.empty()) {
        const std::size_t amp = rest.find('&');
        const std::string_view pair = rest.substr(0, amp);
        rest = amp == std::string_view::npos ? std::string_view{} : rest.substr(amp + 1);
        const std::string name = lower(percent_decoded(pair.substr(0, pair.find('='))));
        if (name == "password" || name == "sslpassword")
          throw InputError(SourceLocation{"--db"}, std::string(kPasswordAdvice));
      }
    }
    out.backend = Backend::PostgreSQL;
    out.target = std::string(text);
    out.display = printable_text(text, 200);
    return out;
  }
  std::string_view path = text;
  if (starts_with(scheme_part, "sqlite:")) {
    path = text.substr(7);
    if (starts_with(path, "//")) path = path.substr(2);
  } else if (const std::size_t colon = text.find("://");
             colon != std::string_view::npos && colon > 0 && colon < 16 &&
             std::all_of(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(colon), [](char c) {
               return std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.';
             })) {
    throw InputError(SourceLocation{"--db"}, "database '" + printable_text(text, 80) + "' has an unknown scheme '" +
                                                 printable_text(text.substr(0, colon), 20) +
                                                 "'; expected a file path, sqlite:PATH or postgresql://...");
  }
  if (path.empty())
    throw InputError(SourceLocation{"--db"},
                     "the database path is empty; expected a file path, sqlite:PATH or "
                     "postgresql://...");
  out.target = std::string(path);
  out.display = out.target;
  return out;
}

}  // namespace hydrocoef::store
