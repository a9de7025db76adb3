// How `hydrocoef gci` reports a study: a table or JSON.
#include "cli/gci_output.hpp"

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "cli/common.hpp"
#include "src/core/escape.hpp"

namespace hydrocoef::cli {
namespace {

nlohmann::json optional_number(bool present, double value) {
  return present ? nlohmann::json(value) : nlohmann::json();
}

}  // namespace

nlohmann::json study_json(const GridConvergenceStudy& study, bool stored) {
  nlohmann::json out = {{"body", study.body},
                        {"mesh_parameter", study.mesh_parameter},
                        {"safety_factor", 1.25},
                        {"coverage_factor", kGciCoverageFactor},
                        {"single_level_keys", study.single_level_keys},
                        {"runs_without_level", study.runs_without_level},
                        {"stored", stored},
                        {"keys", nlohmann::json::array()}};
  for (const auto& key : study.keys) {
    nlohmann::json entry = {{"key", key_json(key.key)},
                            {"levels", key.levels},
                            {"cell_sizes", key.cell_sizes},
                            {"runs", key.run_ids},
                            {"cell_size_from", key.size_from},
                            {"notes", key.notes},
                            {"components", nlohmann::json::object()}};
    for (const auto& c : key.components) {
      const GciResult& r = c.result;
      const bool order = r.convergence == GridConvergence::Monotonic || r.convergence == GridConvergence::Oscillatory;
      const bool found = r.convergence != GridConvergence::NotFound;
      entry["components"][std::string(kForceNames[c.component])] = {
          {"phi", c.phi},
          {"h", {key.cell_sizes[0], key.cell_sizes[1], key.cell_sizes[2]}},
          {"r21", r.r21},
          {"r32", r.r32},
          {"convergence", grid_convergence_name(r.convergence)},
          {"apparent_order", optional_number(order, r.apparent_order)},
          {"extrapolated", optional_number(found, r.extrapolated)},
          {"relative_error", optional_number(found, r.relative_error)},
          {"extrapolated_relative_error", optional_number(found, r.extrapolated_relative_error)},
          {"gci_fine", optional_number(found, r.gci_fine)},
          {"gci_medium", optional_number(order, r.gci_medium)},
          {"asymptotic_ratio", optional_number(order, r.asymptotic_ratio)},
          {"numerical_uncertainty",
           optional_number(c.numerical_uncertainty.has_value(), c.numerical_uncertainty.value_or(0.0))},
          {"values_convergence", c.convergence},
          {"values_error", c.iterative_error},
          {"note", r.note}};
    }
    out["keys"].push_back(entry);
  }
  return out;
}

namespace {

std::string cell(bool present, double value, int digits = 6) { return present ? significant(value, digits) : "-"; }

}  // namespace

void print_study(const GridConvergenceStudy& study, const GridConvergenceRequest& request, bool stored) {
  std::cout << "grid convergence of body " << escape::one_line(study.body) << " (Celik et al. 2008, Fs = 1.25), mesh "
            << "levels by '" << escape::one_line(study.mesh_parameter) << "', fine (1) to coarse (3)\n";
  std::cout << std::left << std::setw(28) << "key" << std::setw(3) << "F" << std::setw(11) << "h1" << std::setw(11)
            << "h2" << std::setw(11) << "h3" << std::setw(8) << "r21" << std::setw(8) << "r32" << std::setw(9) << "p"
            << std::setw(13) << " phi1" << std::setw(13) << "phi_ext" << std::setw(11) << "e_a" << std::setw(11)
            << "e_ext" << std::setw(11) << "GCI_fine" << std::setw(11) << "u_num" << std::setw(12) << "convergence"
            << "notes\n";
  for (const auto& key : study.keys) {
    std::ostringstream text;
    text << escape::one_line(describe(key.key)) << " (" << escape::one_line(study.mesh_parameter) << "=";
    for (std::size_t i = 0; i < key.levels.size() && i < 3; ++i) text << (i ? "," : "") << significant(key.levels[i]);
    text << ")";
    for (const auto& c : key.components) {
      const GciResult& r = c.result;
      const bool order = r.convergence == GridConvergence::Monotonic || r.convergence == GridConvergence::Oscillatory;
      const bool found = r.convergence != GridConvergence::NotFound;
      std::cout << std::setw(28) << text.str() << ' ' << std::setw(2) << kForceNames[c.component] << std::setw(11)
                << significant(key.cell_sizes[0], 4) << std::setw(11) << significant(key.cell_sizes[1], 4)
                << std::setw(11) << significant(key.cell_sizes[2], 4) << std::setw(8) << significant(r.r21, 4)
                << std::setw(8) << significant(r.r32, 4) << std::setw(9) << cell(order, r.apparent_order, 4) << ' '
                << std::setw(12) << significant(c.phi[0], 6) << std::setw(13) << cell(found, r.extrapolated, 6)
                << std::setw(11) << cell(found, r.relative_error, 3) << std::setw(11)
                << cell(found, r.extrapolated_relative_error, 3) << std::setw(11) << cell(found, r.gci_fine, 3)
                << std::setw(11) << cell(c.numerical_uncertainty.has_value(), c.numerical_uncertainty.value_or(0.0), 3)
                << std::setw(12) << grid_convergence_name(r.convergence) << escape::one_line(r.note) << '\n';
    }
    if (!key.components.empty()) {
      const auto& kinds = key.components.front().convergence;
      std::cout << "  values of " << escape::one_line(describe(key.key))
                << ", fine to coarse: " << escape::one_line(kinds[0]) << ", " << escape::one_line(kinds[1]) << ", "
                << escape::one_line(kinds[2]) << '\n';
    }
    for (const auto& note : key.notes)
      std::cout << "  note: " << escape::one_line(describe(key.key)) << ": " << escape::one_line(note) << '\n';
  }
  if (!request.volume && std::any_of(study.keys.begin(), study.keys.end(),
                                     [](const KeyConvergence& k) { return k.size_from == kCellCountParameter; }))
    std::cout << "  h = (1/cells)^(1/" << request.dimension
              << ") without --volume: relative sizes (the ratios, p, phi_ext and GCI do not depend on the volume)\n";
  if (study.single_level_keys > 0)
    std::cout << "  " << study.single_level_keys << " key(s) with '" << escape::one_line(study.mesh_parameter)
              << "' at one mesh level only: not mesh studies\n";
  if (study.runs_without_level > 0)
    std::cout << "  " << study.runs_without_level << " run(s) without '" << escape::one_line(study.mesh_parameter)
              << "': not part of a mesh study\n";
  std::cout << "  u_num = GCI_fine |phi1| / " << significant(kGciCoverageFactor, 2) << " (standard uncertainty), "
            << (stored ? "stored and applied to the runs on each key's finest mesh" : "not stored (--no-store)")
            << '\n';
}

void print_gci(const GridConvergenceStudy& study, const GridConvergenceRequest& request,
               const std::optional<StoredStudy>& stored, bool json) {
  if (json) {
    auto out = study_json(study, stored.has_value());
    out["fits_made_stale"] = stored ? stored->fits_made_stale : 0;
    out["surfaces_made_stale"] = stored ? stored->surfaces_made_stale : 0;
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  print_study(study, request, stored.has_value());
  if (stored && stored->fits_made_stale + stored->surfaces_made_stale > 0)
    std::cout << "  made stale (their runs' uncertainty changed): " << stored->fits_made_stale << " fit(s), "
              << stored->surfaces_made_stale
              << " surface(s); fit --refit and surface rebuild --stale make them again\n";
}

}  // namespace hydrocoef::cli
