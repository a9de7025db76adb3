#include "src/surface/breakpoints.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

/// A double's shortest decimal as an integer mantissa and a count of decimal
/// places: 0.05 -> {5, 2}, 120 -> {120, 0}, 1e-20 -> nullopt beyond 30 places.
struct Decimal {
  std::int64_t mantissa = 0;
  int places = 0;
};

std::optional<Decimal> decimal_of(double value) {
  char text[64];
  const auto [end, ec] = std::to_chars(text, text + sizeof text, value, std::chars_format::scientific);
  if (ec != std::errc()) return std::nullopt;
  const std::string s(text, end);
  const auto e = s.find('e');
  const int exponent = std::stoi(s.substr(e + 1));
  std::string digits;
  bool negative = false;
  int fraction_digits = 0;
  bool after_point = false;
  for (std::size_t i = 0; i < e; ++i) {
    if (s[i] == '-')
      negative = true;
    else if (s[i] == '.')
      after_point = true;
    else
      digits += s[i], fraction_digits += after_point ? 1 : 0;
  }
  int places = fraction_digits - exponent;
  while (places < 0) digits += '0', ++places;
  if (places > 30 || digits.size() > 18) return std::nullopt;
  std::int64_t mantissa = 0;
  std::from_chars(digits.data(), digits.data() + digits.size(), mantissa);
  return Decimal{negative ? -mantissa : mantissa, places};
}

std::optional<std::int64_t> scaled(const Decimal& d, int places) {
  std::int64_t out = d.mantissa;
  for (int i = d.places; i < places; ++i)
    if (__builtin_mul_overflow(out, std::int64_t{10}, &out)) return std::nullopt;
  return out;
}

double from_decimal(std::int64_t mantissa, int places) {
  const std::string text = std::to_string(mantissa) + "e-" + std::to_string(places);
  double value = 0.0;
  std::from_chars(text.data(), text.data() + text.size(), value);
  return value;
}

}  // namespace

std::vector<double> evenly_spaced(double from, double to, std::size_t count) {
  if (!std::isfinite(from) || !std::isfinite(to) || !(from < to) || count < 2)
    throw InputError("evenly spaced points: expected finite FROM < TO and at least 2 points");
  const auto steps = static_cast<std::int64_t>(count - 1);
  std::vector<double> out(count);
  const auto a = decimal_of(from), b = decimal_of(to);
  if (a && b) {
    // The fewest decimal places at which the ends and the step are whole
    // numbers: -0.3:0.3:13 needs 2 (step 0.05), though the ends need 1.
    for (int places = std::max(a->places, b->places); places <= 30; ++places) {
      const auto first = scaled(*a, places), last = scaled(*b, places);
      std::int64_t span = 0;
      if (!first || !last || __builtin_sub_overflow(*last, *first, &span)) break;
      if (span % steps != 0) continue;
      const std::int64_t step = span / steps;
      for (std::size_t i = 0; i < count; ++i)
        out[i] = from_decimal(*first + step * static_cast<std::int64_t>(i), places);
      return out;
    }
  }
  const double span = to - from;
  for (std::size_t i = 0; i < count; ++i) {
    double x = i + 1 == count ? to : from + span * static_cast<double>(i) / static_cast<double>(steps);
    if (std::abs(x) < 1e-12 * span) x = 0.0;
    out[i] = x;
  }
  return out;
}

}  // namespace hydrocoef
