#include "src/core/error.hpp"

namespace hydrocoef {

std::string format_location(const SourceLocation& where) {
  std::string out = where.file;
  if (where.line > 0) {
    out += ':' + std::to_string(where.line);
    if (where.column > 0) out += ':' + std::to_string(where.column);
  }
  return out;
}

InputError::InputError(const std::string& message) : std::runtime_error(message) {}

InputError::InputError(const SourceLocation& where, const std::string& message)
    : std::runtime_error(where.file.empty() && where.line == 0 ? message
                                                               : format_location(where) + ": " + message),
      where_(where) {}

}  // namespace hydrocoef
