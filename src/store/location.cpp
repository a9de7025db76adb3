#include "src/store/location.hpp"

#include <algorithm>
#include <cctype>

#include "src/core/error.hpp"

namespace hydrocoef::store {
namespace {

bool starts_with(std::string_view text, std::string_view prefix) { return text.substr(0, prefix.size()) == prefix; }

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

constexpr std::string_view kPasswordAdvice =
    "a password in the database URL is visible to other users of the machine (ps, shell history); expected it in "
    "~/.pgpass, the file $PGPASSFILE names, or $PGPASSWORD";

}  // namespace

DatabaseLocation parse_database_location(std::string_view text) {
  DatabaseLocation out;
  const std::string scheme_part = lower(text.substr(0, std::min<std::size_t>(text.size(), 16)));
  if (starts_with(scheme_part, "postgresql://") || starts_with(scheme_part, "postgres://")) {
    const std::size_t authority = text.find("://") + 3;
    const std::size_t authority_end = std::min(text.find_first_of("/?", authority), text.size());
    const std::string_view host_part = text.substr(authority, authority_end - authority);
    const std::size_t at = host_part.rfind('@');
    if (at != std::string_view::npos && host_part.substr(0, at).find(':') != std::string_view::npos)
      throw InputError(SourceLocation{"--db"}, std::string(kPasswordAdvice));
    const std::size_t query = text.find('?');
    if (query != std::string_view::npos) {
      const std::string parameters = "&" + lower(text.substr(query + 1));
      if (parameters.find("&password=") != std::string::npos)
        throw InputError(SourceLocation{"--db"}, std::string(kPasswordAdvice));
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
