// hydrocoef pmm: forced-oscillation runs (a virtual planar motion mechanism)
// into added mass and damping, printed and stored; pmm-runs lists and
// deletes the stored ones. The commands parse their options into
// hydrocoef::PmmOptions and print what the API returns (analyse_pmm,
// store_pmm, pmm_runs, delete_pmm_runs: include/hydrocoef/analysis.hpp).
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "hydrocoef/analysis.hpp"
#include "src/core/escape.hpp"

namespace hydrocoef::cli {
namespace {

struct PmmArgs {
  std::vector<std::string> inputs;
  PmmOptions options;
  std::optional<std::string> origin, ref_point;
  std::vector<std::string> set, columns, units;
  bool json = false, store = true;
};

void run_pmm(PmmArgs& args, const GlobalOptions& global) {
  PmmOptions& options = args.options;
  if (args.ref_point) options.ref_point = parse_triple(*args.ref_point, "--ref-point");
  if (args.origin) options.origin = parse_triple(*args.origin, "--origin");
  for (const auto& text : args.set) {
    const auto [name, value] = parse_assignment(text, "--set");
    options.set[name] = value;
  }
  for (const auto& text : args.columns) {
    const auto [name, value] = parse_text_assignment(text, "--column");
    options.columns[name] = value;
  }
  for (const auto& text : args.units) {
    const auto [name, value] = parse_text_assignment(text, "--unit");
    options.units[name] = value;
  }
  const bool progress = isatty(STDERR_FILENO) != 0;
  if (progress)
    options.progress = [](std::size_t done, std::size_t total, const std::string& path) {
      std::cerr << "\r\033[K[" << done << "/" << total << "] "
                << escape::one_line(std::filesystem::path(path).filename().string()) << std::flush;
    };
  // Everything is read and analysed before the database is opened: a bad
  // input leaves it as it was (and makes none).
  PmmAnalysis analysis = analyse_pmm(args.inputs, options);
  if (progress) std::cerr << "\r\033[K" << std::flush;
  if (args.store) {
    auto database = Database::open(global.database, OpenMode::Create);
    store_pmm(database, analysis);
  }
  std::cout << (args.json ? analysis.json() + "\n" : analysis.text());
}

}  // namespace

void add_pmm_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<PmmArgs>();
  auto& o = args->options;
  auto* command = app.add_subcommand(
      "pmm",
      "Added mass and damping from forced-oscillation runs (a virtual planar motion mechanism): each force "
      "history (OpenFOAM case folder or force files, CFX monitor, CSV of time and forces) is fitted over whole "
      "periods after the start-up transient to its mean and harmonics; the part in phase with the acceleration "
      "gives M_A[i][j], the part with the velocity D[i][j]. The motion comes from the case (OpenFOAM "
      "constant/dynamicMeshDict solidBody oscillatingLinearMotion or oscillatingRotatingMotion; CFX CCL with "
      "--ccl) or from --motion, --amplitude, --period");
  command->add_option("inputs", args->inputs, "Force histories or case folders, one run each")->required();
  command->add_option("--body", o.body, "Body name (default vehicle)");
  command->add_option("--axes", o.axes,
                      "Body axes in CFD axes, e.g. -x,y,-z (body x = -CFD x ...); a rotation (default x,y,z)");
  command->add_option("--origin", args->origin, "Body origin in CFD coordinates x,y,z [m] (default 0,0,0)");
  command->add_option("--ref-point", args->ref_point, "Moment reference point x,y,z [m], body axes");
  command->add_option("--rho", o.rho, "Fluid density [kg m^-3] (for the coefficient and a stream)");
  command->add_option("--nu", o.nu, "Kinematic viscosity [m^2 s^-1] (for the Stokes number)");
  command->add_option("--set", args->set, "Run key: mean velocity or disturbance, NAME=VALUE (repeatable)");
  command->add_option("--column", args->columns, "CSV histories: COMPONENT=HEADER (repeatable)");
  command->add_option("--unit", args->units, "CSV histories: unit of a column without one, NAME=UNIT (repeatable)");
  command->add_option("--sign", o.sign, "on-body (the default: the force of the fluid on the body) or opposing");
  command->add_option("--motion", o.motion, "The oscillated DOF: surge, sway, heave, roll, pitch or yaw (body axes)");
  command->add_option("--amplitude", o.amplitude, "Motion amplitude A [m, or rad for rotations]");
  command->add_option("--period", o.period, "Motion period T [s]");
  command->add_option("--phase", o.phase, "Motion phase [rad]: x(t) = A sin(2 pi t / T + phase)")
      ->capture_default_str();
  command->add_option("--ccl", o.ccl, "CFX: the case's CCL or solver output (.out) stating the mesh motion");
  command->add_option("--harmonics", o.harmonics, "Harmonics fitted, 1..10")->capture_default_str();
  command->add_option("--start", o.start,
                      "Keep whole periods from this time [s] (default: the start-up transient is detected)");
  command->add_flag("--stream", o.stream,
                    "The body stood in an oscillating stream (the motion is the stream's): the Froude-Krylov force "
                    "rho V a is removed (needs --rho and --volume)");
  command->add_option("--volume", o.volume, "Displaced volume V [m^3]: the coefficient M_A/(rho V), and a stream");
  command->add_option("--restoring", o.restoring,
                      "Restoring coefficient C [N/m, or N m/rad for a rotation] of a force F = -C x on the moved DOF's "
                      "own component (a floating body's hydrostatics), removed before the added mass is fitted");
  command->add_option("--size", o.size, "Body size D [m] for the Keulegan-Carpenter and Stokes numbers");
  command->add_option("--jobs", o.jobs, "Inputs read in parallel (default: the number of cores)");
  command->add_flag("--store,!--no-store", args->store, "Store the analyses in the database (default)");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] { run_pmm(*args, global); });
}

namespace {

struct PmmRunsArgs {
  std::string body;
  std::vector<std::int64_t> ids;
  bool json = false, delete_json = false;
};

}  // namespace

void add_pmm_runs_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<PmmRunsArgs>();
  auto* command = app.add_subcommand(
      "pmm-runs",
      "List the stored forced-oscillation analyses (hydrocoef pmm), one line each; pmm-runs delete ID... "
      "removes some");
  command->add_option("--body", args->body, "Only the analyses of this body");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, command, &global] {
    if (!command->get_subcommands().empty()) return;  // pmm-runs delete
    const auto database = Database::open(global.database, OpenMode::ReadOnly);
    const PmmRunList list = pmm_runs(database, args->body);
    std::cout << (args->json ? list.json() + "\n" : list.text());
  });
  auto* delete_command = command->add_subcommand(
      "delete",
      "Delete forced-oscillation analyses by id (pmm-runs lists them; pmm prints the id it stored) in one "
      "transaction; an id that is not stored deletes nothing. Works on records no other command can read");
  delete_command->add_option("ids", args->ids, "pmm run ids")->required();
  delete_command->add_flag("--json", args->delete_json, "Print JSON");
  delete_command->callback([args, &global] {
    auto database = Database::open(global.database, OpenMode::ReadWrite);
    const PmmDeletion deletion = delete_pmm_runs(database, args->ids);
    std::cout << (args->delete_json ? deletion.json() + "\n" : deletion.text());
  });
}

}  // namespace hydrocoef::cli
