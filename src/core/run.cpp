#include "src/core/run.hpp"

#include "src/core/numbers.hpp"

namespace hydrocoef {
namespace {

template <std::size_t N>
std::optional<std::size_t> index_of(const std::array<std::string_view, N>& names, std::string_view name) {
  for (std::size_t i = 0; i < N; ++i)
    if (names[i] == name) return i;
  return std::nullopt;
}

}  // namespace

std::optional<std::size_t> velocity_index(std::string_view name) { return index_of(kVelocityNames, name); }
std::optional<std::size_t> force_index(std::string_view name) { return index_of(kForceNames, name); }

std::string disturbance_signature(const std::map<std::string, double>& disturbances) {
  std::string out;
  for (const auto& [name, value] : disturbances) {
    if (!out.empty()) out += ';';
    out += name + '=' + shortest_number(value == 0.0 ? 0.0 : value);  // folds -0 into 0
  }
  return out;
}

std::string describe(const RunKey& key) {
  std::string out = key.body;
  for (std::size_t i = 0; i < 6; ++i)
    if (key.nu_b[i] != 0.0) out += ' ' + std::string(kVelocityNames[i]) + '=' + shortest_number(key.nu_b[i]);
  for (const auto& [name, value] : key.disturbances)
    out += ' ' + name + '=' + shortest_number(value == 0.0 ? 0.0 : value);
  if (key.nu_b == std::array<double, 6>{} && key.disturbances.empty()) out += " (at rest)";
  return out;
}

}  // namespace hydrocoef
