// Test support: the hostile-name corpus (tests/data/hostile/names.txt), each
// line's escapes decoded into the bytes of one name.
#pragma once

#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace hydrocoef::test {

inline void append_utf8(std::string& out, std::uint32_t value) {
  if (value < 0x80) {
    out += static_cast<char>(value);
  } else if (value < 0x800) {
    out += static_cast<char>(0xC0 | (value >> 6));
    out += static_cast<char>(0x80 | (value & 0x3F));
  } else if (value < 0x10000) {
    out += static_cast<char>(0xE0 | (value >> 12));
    out += static_cast<char>(0x80 | ((value >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (value & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (value >> 18));
    out += static_cast<char>(0x80 | ((value >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((value >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (value & 0x3F));
  }
}

/// Decodes \n \r \t \0 \\ \xNN and \u{X...} in one corpus line.
inline std::string decode_hostile_line(const std::string& line) {
  std::string out;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] != '\\' || i + 1 == line.size()) {
      out += line[i];
      continue;
    }
    const char c = line[++i];
    switch (c) {
      case 'n': out += '\n'; break;
      case 'r': out += '\r'; break;
      case 't': out += '\t'; break;
      case '0': out += '\0'; break;
      case '\\': out += '\\'; break;
      case 'x':
        out += static_cast<char>(std::stoi(line.substr(i + 1, 2), nullptr, 16));
        i += 2;
        break;
      case 'u': {
        const std::size_t close = line.find('}', i);
        append_utf8(out, static_cast<std::uint32_t>(std::stoul(line.substr(i + 2, close - i - 2), nullptr, 16)));
        i = close;
        break;
      }
      default: throw std::runtime_error("hostile corpus: unknown escape \\" + std::string(1, c));
    }
  }
  return out;
}

/// Every name of the corpus, in file order.
inline std::vector<std::string> hostile_names() {
  std::ifstream in(std::string(HYDROCOEF_SOURCE_DIR) + "/tests/data/hostile/names.txt", std::ios::binary);
  if (!in) throw std::runtime_error("cannot read tests/data/hostile/names.txt");
  std::vector<std::string> names;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    names.push_back(decode_hostile_line(line));
  }
  return names;
}

/// True when a terminal shows `text` as it is: no control characters but
/// line ends, no DEL (what a hostile name must not bring into a readable output).
inline bool terminal_safe(const std::string& text) {
  for (const char c : text)
    if (!(c == '\n' || (static_cast<unsigned char>(c) >= 0x20 && c != 0x7f))) return false;
  return true;
}

}  // namespace hydrocoef::test
