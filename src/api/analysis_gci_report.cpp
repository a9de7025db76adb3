// GciStudy::text and json (include/hydrocoef/analysis.hpp): what `hydrocoef
// gci` prints, a table (one row per key and force component, with the notes)
// or JSON, made from the study's public fields.
#include "src/api/internal.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

#include "hydrocoef/analysis.hpp"
#include "src/api/analysis_format.hpp"
#include "src/core/escape.hpp"

namespace hydrocoef {
inline namespace api {
namespace {

using analysis_format::optional_json;
using analysis_format::significant;

nlohmann::json key_json(const GciKey& key) {
  nlohmann::json out;
  out["body"] = key.body;
  for (std::size_t i = 0; i < 6; ++i) out[std::string(kVelocityNames[i])] = key.velocity[i];
  out["disturbances"] = nlohmann::json::object();
  for (const auto& [name, value] : key.disturbances) out["disturbances"][name] = value;
  return out;
}

std::string cell(const std::optional<double>& value, int digits = 6) {
  return value ? significant(*value, digits) : "-";
}

}  // namespace

std::string GciStudy::json() const {
  nlohmann::json out = {{"body", body},
                        {"mesh_parameter", mesh_parameter},
                        {"safety_factor", safety_factor},
                        {"coverage_factor", coverage_factor},
                        {"single_level_keys", single_level_keys},
                        {"runs_without_level", runs_without_level},
                        {"stored", stored},
                        {"fits_made_stale", fits_made_stale},
                        {"surfaces_made_stale", surfaces_made_stale},
                        {"keys", nlohmann::json::array()}};
  for (const auto& key : keys) {
    nlohmann::json entry = {{"key", key_json(key)},
                            {"levels", key.levels},
                            {"cell_sizes", key.cell_sizes},
                            {"runs", key.runs},
                            {"cell_size_from", key.cell_size_from},
                            {"notes", key.notes},
                            {"components", nlohmann::json::object()}};
    for (const auto& c : key.components)
      entry["components"][c.component] = {{"phi", c.phi},
                                          {"h", {key.cell_sizes.at(0), key.cell_sizes.at(1), key.cell_sizes.at(2)}},
                                          {"r21", c.r21},
                                          {"r32", c.r32},
                                          {"convergence", c.convergence},
                                          {"apparent_order", optional_json(c.apparent_order)},
                                          {"extrapolated", optional_json(c.extrapolated)},
                                          {"relative_error", optional_json(c.relative_error)},
                                          {"extrapolated_relative_error", optional_json(c.extrapolated_relative_error)},
                                          {"gci_fine", optional_json(c.gci_fine)},
                                          {"gci_medium", optional_json(c.gci_medium)},
                                          {"asymptotic_ratio", optional_json(c.asymptotic_ratio)},
                                          {"numerical_uncertainty", optional_json(c.numerical_uncertainty)},
                                          {"values_convergence", c.values_convergence},
                                          {"values_error", c.values_error},
                                          {"note", c.note}};
    out["keys"].push_back(entry);
  }
  return escape::json_text(out, 2);
}

std::string GciStudy::text() const {
  std::ostringstream out;
  out << "grid convergence of body " << escape::one_line(body) << " (Celik et al. 2008, Fs = 1.25), mesh "
      << "levels by '" << escape::one_line(mesh_parameter) << "', fine (1) to coarse (3)\n";
  out << std::left << std::setw(28) << "key" << std::setw(3) << "F" << std::setw(11) << "h1" << std::setw(11) << "h2"
      << std::setw(11) << "h3" << std::setw(8) << "r21" << std::setw(8) << "r32" << std::setw(9) << "p" << std::setw(13)
      << " phi1" << std::setw(13) << "phi_ext" << std::setw(11) << "e_a" << std::setw(11) << "e_ext" << std::setw(11)
      << "GCI_fine" << std::setw(11) << "u_num" << std::setw(12) << "convergence"
      << "notes\n";
  for (const auto& key : keys) {
    std::ostringstream text;
    text << escape::one_line(key.description) << " (" << escape::one_line(mesh_parameter) << "=";
    for (std::size_t i = 0; i < key.levels.size() && i < 3; ++i) text << (i ? "," : "") << significant(key.levels[i]);
    text << ")";
    for (const auto& c : key.components) {
      out << std::setw(28) << text.str() << ' ' << std::setw(2) << c.component << std::setw(11)
          << significant(key.cell_sizes.at(0), 4) << std::setw(11) << significant(key.cell_sizes.at(1), 4)
          << std::setw(11) << significant(key.cell_sizes.at(2), 4) << std::setw(8) << significant(c.r21, 4)
          << std::setw(8) << significant(c.r32, 4) << std::setw(9) << cell(c.apparent_order, 4) << ' ' << std::setw(12)
          << significant(c.phi[0], 6) << std::setw(13) << cell(c.extrapolated, 6) << std::setw(11)
          << cell(c.relative_error, 3) << std::setw(11) << cell(c.extrapolated_relative_error, 3) << std::setw(11)
          << cell(c.gci_fine, 3) << std::setw(11) << cell(c.numerical_uncertainty, 3) << std::setw(12) << c.convergence
          << escape::one_line(c.note) << '\n';
    }
    if (!key.components.empty()) {
      const auto& kinds = key.components.front().values_convergence;
      out << "  values of " << escape::one_line(key.description) << ", fine to coarse: " << escape::one_line(kinds[0])
          << ", " << escape::one_line(kinds[1]) << ", " << escape::one_line(kinds[2]) << '\n';
    }
    for (const auto& note : key.notes)
      out << "  note: " << escape::one_line(key.description) << ": " << escape::one_line(note) << '\n';
  }
  if (!volume_given &&
      std::any_of(keys.begin(), keys.end(), [](const GciKey& k) { return k.cell_size_from == kCellCountParameter; }))
    out << "  h = (1/cells)^(1/" << dimension
        << ") without --volume: relative sizes (the ratios, p, phi_ext and GCI do not depend on the volume)\n";
  if (single_level_keys > 0)
    out << "  " << single_level_keys << " key(s) with '" << escape::one_line(mesh_parameter)
        << "' at one mesh level only: not mesh studies\n";
  if (runs_without_level > 0)
    out << "  " << runs_without_level << " run(s) without '" << escape::one_line(mesh_parameter)
        << "': not part of a mesh study\n";
  out << "  u_num = GCI_fine |phi1| / " << significant(coverage_factor, 2) << " (standard uncertainty), "
      << (stored ? "stored and applied to the runs on each key's finest mesh" : "not stored (--no-store)") << '\n';
  if (stored && fits_made_stale + surfaces_made_stale > 0)
    out << "  made stale (their runs' uncertainty changed): " << fits_made_stale << " fit(s), " << surfaces_made_stale
        << " surface(s); fit --refit and surface rebuild --stale make them again\n";
  return out.str();
}

}  // namespace api
}  // namespace hydrocoef
