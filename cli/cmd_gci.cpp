// hydrocoef gci: numerical uncertainty from mesh studies (Celik et al. 2008),
// printed and stored with the key it applies to. The logic is in
// src/pipeline/grid_convergence_runs.
#include <algorithm>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "cli/common.hpp"
#include "src/core/escape.hpp"
#include "src/pipeline/grid_convergence_runs.hpp"

namespace hydrocoef::cli {
namespace {

struct GciArgs {
  GridConvergenceRequest request;
  bool json = false;
  bool store = true;
};

nlohmann::json optional_number(bool present, double value) {
  return present ? nlohmann::json(value) : nlohmann::json();
}

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
          {"note", r.note}};
    }
    out["keys"].push_back(entry);
  }
  return out;
}

std::string cell(bool present, double value, int digits = 6) { return present ? significant(value, digits) : "-"; }

void print_study(const GridConvergenceStudy& study, const GridConvergenceRequest& request, bool stored) {
  std::cout << "grid convergence of body " << escape::one_line(study.body) << " (Celik et al. 2008, Fs = 1.25), mesh "
            << "levels by '" << escape::one_line(study.mesh_parameter) << "', fine (1) to coarse (3)\n";
  std::cout << std::left << std::setw(28) << "key" << std::setw(3) << "F" << std::setw(11) << "h1" << std::setw(11)
            << "h2" << std::setw(11) << "h3" << std::setw(8) << "r21" << std::setw(8) << "r32" << std::setw(9) << "p"
            << std::setw(13) << "phi1" << std::setw(13) << "phi_ext" << std::setw(11) << "e_a" << std::setw(11)
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
                << std::setw(8) << significant(r.r32, 4) << std::setw(9) << cell(order, r.apparent_order, 4)
                << std::setw(13) << significant(c.phi[0], 6) << std::setw(13) << cell(found, r.extrapolated, 6)
                << std::setw(11) << cell(found, r.relative_error, 3) << std::setw(11)
                << cell(found, r.extrapolated_relative_error, 3) << std::setw(11) << cell(found, r.gci_fine, 3)
                << std::setw(11) << cell(c.numerical_uncertainty.has_value(), c.numerical_uncertainty.value_or(0.0), 3)
                << std::setw(12) << grid_convergence_name(r.convergence) << escape::one_line(r.note) << '\n';
    }
    for (const auto& note : key.notes)
      std::cout << "  note: " << escape::one_line(describe(key.key)) << ": " << note << '\n';
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

}  // namespace

void add_gci_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<GciArgs>();
  auto* command = app.add_subcommand(
      "gci",
      "Numerical uncertainty from mesh studies: for each key with runs at 3 or more mesh levels (disturbance "
      "parameter mesh=LEVEL with cells=N or cell_size=H), the observed order, Richardson extrapolation and "
      "grid-convergence index of each force component by Celik et al. (2008), oscillatory convergence included, "
      "on the three finest levels; stored and applied as GCI_fine |phi1| / 2 to the runs of the key's finest mesh");
  command->add_option("--body", args->request.body, "Body whose runs to study")->required();
  command->add_option("--mesh-param", args->request.mesh_parameter, "The disturbance parameter of the mesh level")
      ->capture_default_str();
  command->add_option("--volume", args->request.volume,
                      "Domain volume (m^D) for h = (V/N)^(1/D) from cells=N (default 1: h relative; ratios, order, "
                      "extrapolation and GCI are the same)");
  command->add_option("--dimension", args->request.dimension, "D of h = (V/N)^(1/D): 1, 2 or 3")->capture_default_str();
  command->add_flag("--store,!--no-store", args->store, "Store the result and apply it to the runs (default)");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] {
    const bool store = args->store;
    Database database(global.database, store ? Database::OpenMode::MustExist : Database::OpenMode::ReadOnly);
    const GridConvergenceStudy study = grid_convergence_of_runs(database, args->request);
    std::size_t fits_made_stale = 0, surfaces_made_stale = 0;
    if (store) {
      const auto stale = [&] {
        const auto fits = database.fits(args->request.body);
        const auto surfaces = database.surfaces(args->request.body);
        return std::pair<std::size_t, std::size_t>(
            std::count_if(fits.begin(), fits.end(), [](const FitRecord& f) { return f.stale; }),
            std::count_if(surfaces.begin(), surfaces.end(), [](const SurfaceRecord& s) { return s.stale; }));
      };
      const auto before = stale();
      database.save_numerical_uncertainties(numerical_uncertainty_records(study));
      const auto after = stale();
      fits_made_stale = after.first - before.first;
      surfaces_made_stale = after.second - before.second;
    }
    if (args->json) {
      auto out = study_json(study, store);
      out["fits_made_stale"] = fits_made_stale;
      out["surfaces_made_stale"] = surfaces_made_stale;
      std::cout << escape::json_text(out, 2) << '\n';
    } else {
      print_study(study, args->request, store);
      if (fits_made_stale + surfaces_made_stale > 0)
        std::cout << "  made stale (their runs' uncertainty changed): " << fits_made_stale << " fit(s), "
                  << surfaces_made_stale << " surface(s); fit --refit and surface rebuild --stale make them again\n";
    }
  });
}

}  // namespace hydrocoef::cli
