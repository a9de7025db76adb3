#include "src/core/numbers.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>

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

std::string significant(double value, int digits) {
  if (std::isnan(value)) return "n/a";
  std::array<char, 48> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.*g", digits, value);
  return buffer.data();
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

std::optional<double> parse_finite_number(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    return std::nullopt;
  return value;
}

}  // namespace hydrocoef
