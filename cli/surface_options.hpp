// The command-line options shared by the commands that read surface exports
// and force histories (integrate, import): which arrays, their kind and
// units, frames, and the run key. Registered once here so both commands spell
// them the same way; they fill the import's options, which check themselves.
#pragma once

#include <CLI/CLI.hpp>

#include "hydrocoef/database.hpp"

namespace hydrocoef::cli {

/// Adds --location, --pressure, --shear, ..., --set, --at-rest, --no-sidecar to a command.
void add_surface_options(CLI::App& command, ImportOptions& options);

}  // namespace hydrocoef::cli
