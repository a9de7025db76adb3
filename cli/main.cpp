// hydrocoef: one binary, one subcommand per job. Errors in input or usage are
// printed as one line on stderr with exit code 2; internal errors exit 1.
#include <cstdio>
#include <exception>
#include <iostream>

#include "cli/common.hpp"
#include "src/core/error.hpp"
#include "src/core/version.hpp"

int main(int argc, char** argv) {
  using namespace hydrocoef;
  CLI::App app{
      "hydrocoef: CFD results to hydrodynamic coefficient databases.\n"
      "Body axes x forward, y starboard, z down; SI units; forces on the body unless a record says "
      "otherwise.",
      "hydrocoef"};
  app.set_version_flag("--version", std::string("hydrocoef ") + kVersion);
  app.require_subcommand(1);
  app.fallthrough();
  cli::GlobalOptions global;
  app.add_option("--db", global.database,
                 "Run database: a file path or sqlite:PATH (SQLite), or postgresql://[user@]host[:port]/name[?...] "
                 "(a PostgreSQL server; its password from ~/.pgpass or $PGPASSFILE, never in the URL). Default: "
                 "$HYDROCOEF_DB, else hydrocoef.db")
      ->envname("HYDROCOEF_DB")
      ->capture_default_str();
  cli::add_import_command(app, global);
  cli::add_runs_command(app, global);
  cli::add_body_command(app, global);
  cli::add_fit_command(app, global);
  cli::add_integrate_command(app);
  cli::add_simulate_command(app, global);
  cli::add_equilibrium_command(app, global);
  cli::add_surface_command(app, global);
  cli::add_query_command(app, global);
  cli::add_suggest_command(app, global);
  cli::add_gci_command(app, global);
  cli::add_pmm_command(app, global);
  cli::add_pmm_runs_command(app, global);
  cli::add_added_mass_command(app, global);
  cli::add_merge_command(app, global);
  cli::add_derivatives_command(app, global);
  cli::add_scale_command(app, global);
  cli::add_export_command(app, global);
  cli::add_export_gazebo_command(app, global);
  cli::add_export_fmu_command(app, global);
  cli::add_plot_command(app, global);
  cli::add_report_command(app, global);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // CLI11 quotes the arguments it refuses as given.
    std::cerr << "hydrocoef: " << printable_text(e.what(), kMaxMessageCharacters) << " (see hydrocoef --help)\n";
    return 2;
  } catch (const InputError& e) {
    std::cerr << "hydrocoef: error: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "hydrocoef: internal error: " << printable_text(e.what(), kMaxMessageCharacters) << '\n';
    return 1;
  }
  return 0;
}
