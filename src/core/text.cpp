#include "src/core/text.hpp"

namespace hydrocoef {

std::string_view trim_left(std::string_view text, std::string_view blanks) {
  const auto first = text.find_first_not_of(blanks);
  return text.substr(first == std::string_view::npos ? text.size() : first);
}

std::string_view trim_right(std::string_view text, std::string_view blanks) {
  const auto last = text.find_last_not_of(blanks);
  return text.substr(0, last == std::string_view::npos ? 0 : last + 1);
}

std::string_view trim(std::string_view text, std::string_view blanks) {
  return trim_right(trim_left(text, blanks), blanks);
}

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = lower(c);
  return out;
}

std::string without_blanks(std::string_view text, std::string_view blanks) {
  std::string out;
  for (const char c : text)
    if (blanks.find(c) == std::string_view::npos) out += c;
  return out;
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> fields;
  for (std::size_t start = 0;;) {
    const std::size_t end = text.find(separator, start);
    if (end == std::string_view::npos) {
      fields.push_back(text.substr(start));
      return fields;
    }
    fields.push_back(text.substr(start, end - start));
    start = end + 1;
  }
}

std::string join(const std::vector<std::string>& items, std::string_view separator) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i) out += separator;
    out += items[i];
  }
  return out;
}

}  // namespace hydrocoef
