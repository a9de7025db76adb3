#include "src/fit/fit_names.hpp"

#include <charconv>
#include <system_error>

#include "src/core/numbers.hpp"

namespace hydrocoef {

std::string default_fit_name(const std::string& body, const std::string& dof, const std::string& terms,
                             const std::string& selection) {
  return body + ":" + dof + "(" + terms + ")" + (selection.empty() ? "" : "@" + selection);
}

std::string per_level_fit_name(const std::string& base, const std::string& by, double level) {
  return base + "[" + by + "=" + shortest_number(level) + "]";
}

std::optional<std::pair<std::string, double>> fit_level(const std::string& fit_name, const std::string& base) {
  if (fit_name.size() < base.size() + 4 || fit_name.compare(0, base.size(), base) != 0 ||
      fit_name[base.size()] != '[' || fit_name.back() != ']')
    return std::nullopt;
  const std::string condition = fit_name.substr(base.size() + 1, fit_name.size() - base.size() - 2);
  const auto eq = condition.find('=');
  if (eq == std::string::npos || eq == 0 || condition.find_first_of("[]=", eq + 1) != std::string::npos)
    return std::nullopt;
  double value = 0.0;
  const char* first = condition.data() + eq + 1;
  const char* last = condition.data() + condition.size();
  const auto [end, ec] = std::from_chars(first, last, value);
  if (ec != std::errc() || end != last || first == last) return std::nullopt;
  return std::make_pair(condition.substr(0, eq), value);
}

std::string fit_family_name(const std::string& fit_name) {
  const auto open = fit_name.rfind('[');
  if (open == std::string::npos || open == 0) return fit_name;
  const std::string base = fit_name.substr(0, open);
  return fit_level(fit_name, base) ? base : fit_name;
}

}  // namespace hydrocoef
