// hydrocoef pmm: forced-oscillation runs (a virtual planar motion mechanism)
// into added mass and damping, printed and stored. The logic is in
// src/pipeline/pmm_runs, the output in cli/pmm_output.
#include <unistd.h>

#include <iostream>
#include <memory>
#include <optional>

#include "cli/common.hpp"
#include "cli/pmm_output.hpp"
#include "cli/surface_options.hpp"
#include "src/core/escape.hpp"
#include "src/pipeline/pmm_runs.hpp"
#include "src/pmm/imposed_motion.hpp"

namespace hydrocoef::cli {
namespace {

struct PmmArgs {
  std::vector<std::string> inputs;
  SurfaceArgs settings;
  std::optional<std::string> sign, ccl, motion;
  std::optional<double> amplitude, period, start, size, volume, restoring;
  double phase = 0.0;
  std::vector<std::string> columns, units;
  int harmonics = 1;
  bool stream = false, json = false, store = true;
  unsigned jobs = 0;
};

void run_pmm(const PmmArgs& args, const GlobalOptions& global) {
  PmmRequest request;
  for (const auto& input : args.inputs) request.import.inputs.emplace_back(input);
  request.import.command_line = command_line_settings(args.settings);
  if (args.sign) request.import.command_line.set("sign", *args.sign, "--sign");
  request.import.format = "auto";  // read_body_history refuses what is not a history
  for (const auto& text : args.columns) {
    auto [name, value] = parse_text_assignment(text, "--column");
    request.import.columns.columns[name] = value;
  }
  for (const auto& text : args.units) {
    auto [name, value] = parse_text_assignment(text, "--unit");
    request.import.columns.units[name] = value;
  }
  request.import.jobs = args.jobs;
  const int given = int(args.motion.has_value()) + int(args.amplitude.has_value()) + int(args.period.has_value());
  if (given != 0 && given != 3)
    throw InputError("--motion, --amplitude and --period: found " + std::to_string(given) +
                     " of them; expected all three or none (none: the motion stated by the case)");
  if (given == 3) request.motion = motion_from_options(*args.motion, *args.amplitude, *args.period, args.phase);
  if (args.ccl) request.ccl = *args.ccl;
  request.fit.harmonics = args.harmonics;
  request.fit.start_time = args.start;
  request.medium = args.stream ? PmmMedium::OscillatingStream : PmmMedium::StillWater;
  request.size = args.size;
  request.displaced_volume = args.volume;
  request.restoring = args.restoring;
  const bool progress = isatty(STDERR_FILENO) != 0;
  if (progress)
    request.import.progress = [](std::size_t done, std::size_t total, const std::filesystem::path& path) {
      std::cerr << "\r\033[K[" << done << "/" << total << "] " << escape::one_line(path.filename().string())
                << std::flush;
    };
  // Everything is read and analysed before the database is opened: a bad
  // input leaves it as it was.
  const std::vector<PmmRun> runs = analyse_pmm_runs(request);
  if (progress) std::cerr << "\r\033[K" << std::flush;
  std::vector<PmmSaved> saved;
  if (args.store) {
    RunDatabase database(global.database);
    saved = store_pmm_runs(database, runs);
  }
  print_pmm_runs(runs, saved, global.database, args.json);
}

}  // namespace

void add_pmm_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<PmmArgs>();
  auto* command = app.add_subcommand(
      "pmm",
      "Added mass and damping from forced-oscillation runs (a virtual planar motion mechanism): each force "
      "history (OpenFOAM case folder or force files, CFX monitor, CSV of time and forces) is fitted over whole "
      "periods after the start-up transient to its mean and harmonics; the part in phase with the acceleration "
      "gives M_A[i][j], the part with the velocity D[i][j]. The motion comes from the case (OpenFOAM "
      "constant/dynamicMeshDict solidBody oscillatingLinearMotion or oscillatingRotatingMotion; CFX CCL with "
      "--ccl) or from --motion, --amplitude, --period");
  command->add_option("inputs", args->inputs, "Force histories or case folders, one run each")->required();
  command->add_option("--body", args->settings.body, "Body name (default vehicle)");
  command->add_option("--axes", args->settings.axes,
                      "Body axes in CFD axes, e.g. -x,y,-z (body x = -CFD x ...); a rotation (default x,y,z)");
  command->add_option("--origin", args->settings.origin, "Body origin in CFD coordinates x,y,z [m] (default 0,0,0)");
  command->add_option("--ref-point", args->settings.ref_point, "Moment reference point x,y,z [m], body axes");
  command->add_option("--rho", args->settings.rho, "Fluid density [kg m^-3] (for the coefficient and a stream)");
  command->add_option("--nu", args->settings.nu, "Kinematic viscosity [m^2 s^-1] (for the Stokes number)");
  command->add_option("--set", args->settings.set, "Run key: mean velocity or disturbance, NAME=VALUE (repeatable)");
  command->add_option("--column", args->columns, "CSV histories: COMPONENT=HEADER (repeatable)");
  command->add_option("--unit", args->units, "CSV histories: unit of a column without one, NAME=UNIT (repeatable)");
  command->add_option("--sign", args->sign, "on-body (the default: the force of the fluid on the body) or opposing");
  command->add_option("--motion", args->motion,
                      "The oscillated DOF: surge, sway, heave, roll, pitch or yaw (body axes)");
  command->add_option("--amplitude", args->amplitude, "Motion amplitude A [m, or rad for rotations]");
  command->add_option("--period", args->period, "Motion period T [s]");
  command->add_option("--phase", args->phase, "Motion phase [rad]: x(t) = A sin(2 pi t / T + phase)")
      ->capture_default_str();
  command->add_option("--ccl", args->ccl, "CFX: the case's CCL or solver output (.out) stating the mesh motion");
  command->add_option("--harmonics", args->harmonics, "Harmonics fitted, 1..10")->capture_default_str();
  command->add_option("--start", args->start,
                      "Keep whole periods from this time [s] (default: the start-up transient is detected)");
  command->add_flag("--stream", args->stream,
                    "The body stood in an oscillating stream (the motion is the stream's): the Froude-Krylov force "
                    "rho V a is removed (needs --rho and --volume)");
  command->add_option("--volume", args->volume, "Displaced volume V [m^3]: the coefficient M_A/(rho V), and a stream");
  command->add_option("--restoring", args->restoring,
                      "Restoring coefficient C [N/m, or N m/rad for a rotation] of a force F = -C x on the moved DOF's "
                      "own component (a floating body's hydrostatics), removed before the added mass is fitted");
  command->add_option("--size", args->size, "Body size D [m] for the Keulegan-Carpenter and Stokes numbers");
  command->add_option("--jobs", args->jobs, "Inputs read in parallel (default: the number of cores)");
  command->add_flag("--store,!--no-store", args->store, "Store the analyses in the database (default)");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] { run_pmm(*args, global); });
}

namespace {

struct PmmRunsArgs {
  std::optional<std::string> body;
  bool json = false;
};

struct PmmDeleteArgs {
  std::vector<std::int64_t> ids;
  bool json = false;
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
    RunDatabase database(global.database, RunDatabase::OpenMode::ReadOnly);
    print_pmm_records(database.pmm_records(args->body, false), args->json);
  });
  auto remove = std::make_shared<PmmDeleteArgs>();
  auto* delete_command = command->add_subcommand(
      "delete",
      "Delete forced-oscillation analyses by id (pmm-runs lists them; pmm prints the id it stored) in one "
      "transaction; an id that is not stored deletes nothing. Works on records no other command can read");
  delete_command->add_option("ids", remove->ids, "pmm run ids")->required();
  delete_command->add_flag("--json", remove->json, "Print JSON");
  delete_command->callback([remove, &global] {
    RunDatabase database(global.database, RunDatabase::OpenMode::MustExist);
    print_pmm_deleted(database.delete_pmm_runs(remove->ids), global.database, remove->json);
  });
}

}  // namespace hydrocoef::cli
