// Test support: a file's bytes read whole, and bytes written as a file, for
// tests that write, cut or damage files.
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace hydrocoef::test {

inline std::string read_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void write_bytes(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream out(file, std::ios::binary);
  out << bytes;
}

}  // namespace hydrocoef::test
