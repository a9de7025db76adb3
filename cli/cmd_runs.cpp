// hydrocoef runs: list stored runs with their key and force components.
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "cli/common.hpp"
#include "src/core/escape.hpp"
#include "src/store/database.hpp"

namespace hydrocoef::cli {
namespace {

struct RunsArgs {
  std::optional<std::string> body;
  std::vector<std::string> where;
  bool json = false;
};

nlohmann::json run_json(const StoredRun& run) {
  nlohmann::json out = key_json(run.key);
  out["id"] = run.id;
  out["density"] = run.fluid.density_kg_m3 ? nlohmann::json(*run.fluid.density_kg_m3) : nlohmann::json();
  out["kinematic_viscosity"] =
      run.fluid.kinematic_viscosity_m2_s ? nlohmann::json(*run.fluid.kinematic_viscosity_m2_s) : nlohmann::json();
  out["reference_point"] = run.reference_point_b;
  out["forces"] = nlohmann::json::object();
  for (std::size_t i = 0; i < 6; ++i) {
    if (!run.tau_b[i]) continue;
    const auto& f = *run.tau_b[i];
    out["forces"][std::string(kForceNames[i])] = {
        {"total", f.value.total},
        {"pressure", f.value.pressure ? nlohmann::json(*f.value.pressure) : nlohmann::json()},
        {"viscous", f.value.viscous ? nlohmann::json(*f.value.viscous) : nlohmann::json()},
        {"sign_convention", std::string(to_string(f.sign))},
        {"source", f.source_path},
        {"source_line", f.source_line}};
  }
  return out;
}

void run_runs(const RunsArgs& args, const GlobalOptions& global) {
  Database database(global.database, Database::OpenMode::ReadOnly);
  RunFilter filter;
  filter.body = args.body;
  for (const auto& text : args.where) filter.equal.insert(parse_assignment(text, "--where"));
  const auto runs = database.runs(filter);
  if (args.json) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& run : runs) out.push_back(run_json(run));
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  if (runs.empty()) {
    std::cout << "no runs" << (args.body ? " of body '" + *args.body + "'" : std::string()) << " in "
              << global.database << '\n';
    return;
  }
  // Only the velocity and force columns some run uses are shown.
  std::array<bool, 6> velocity_used{}, force_used{};
  for (const auto& run : runs)
    for (std::size_t i = 0; i < 6; ++i) {
      velocity_used[i] = velocity_used[i] || run.key.nu_b[i] != 0.0;
      force_used[i] = force_used[i] || run.tau_b[i].has_value();
    }
  std::ostringstream table;
  table << std::left << std::setw(6) << "id" << std::setw(12) << "body";
  for (std::size_t i = 0; i < 6; ++i)
    if (velocity_used[i]) table << std::setw(11) << kVelocityNames[i];
  for (std::size_t i = 0; i < 6; ++i)
    if (force_used[i]) table << std::setw(13) << kForceNames[i];
  table << "disturbances\n";
  for (const auto& run : runs) {
    table << std::setw(6) << run.id << std::setw(12) << run.key.body;
    for (std::size_t i = 0; i < 6; ++i)
      if (velocity_used[i]) table << std::setw(11) << significant(run.key.nu_b[i], 6);
    for (std::size_t i = 0; i < 6; ++i) {
      if (!force_used[i]) continue;
      std::string cell = run.tau_b[i] ? significant(run.tau_b[i]->value.total, 6) : "-";
      if (run.tau_b[i] && run.tau_b[i]->sign == SignConvention::OpposingMotion) cell += "*";
      table << std::setw(13) << cell;
    }
    std::string disturbances;
    for (const auto& [name, value] : run.key.disturbances)
      disturbances += (disturbances.empty() ? "" : " ") + name + "=" + significant(value, 6);
    table << disturbances << '\n';
  }
  std::cout << table.str() << runs.size() << " runs; SI units (m/s, rad/s, N, N m); forces on the body, "
            << "* = as tabulated, positive opposes motion\n";
}

}  // namespace

void add_runs_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<RunsArgs>();
  auto* command = app.add_subcommand("runs", "List the runs in the database");
  command->add_option("--body", args->body, "Only runs of this body");
  command->add_option("--where", args->where,
                      "Only runs whose velocity component or disturbance equals a value, NAME=VALUE (repeatable)");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] { run_runs(*args, global); });
}

}  // namespace hydrocoef::cli
