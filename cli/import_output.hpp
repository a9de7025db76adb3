// How the CLI reports an import (text or JSON).
#pragma once

#include <string>

#include "src/pipeline/import_files.hpp"

namespace hydrocoef::cli {

/// One line per stored input (unless quiet), the notes, and a summary line;
/// or the JSON of every input, the totals, the stage times and the notes.
void print_import(const ImportResult& result, const std::string& database, bool json, bool quiet);

}  // namespace hydrocoef::cli
