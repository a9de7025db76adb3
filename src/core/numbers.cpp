#include "src/core/numbers.hpp"

#include <array>
#include <charconv>

namespace hydrocoef {
namespace {

// The longest shortest form of a double is 24 characters
// ("-2.2250738585072014e-308"), of a float 15: to_chars cannot fail here.
using Buffer = std::array<char, 32>;

}  // namespace

std::string shortest_number(double value) {
  Buffer buffer;
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

void append_shortest_number(std::string& out, double value) {
  Buffer buffer;
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  out.append(buffer.data(), result.ptr);
}

std::string shortest_float(float value) {
  Buffer buffer;
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

}  // namespace hydrocoef
