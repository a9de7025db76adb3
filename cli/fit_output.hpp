// How the CLI shows fits (text and JSON).
#pragma once

#include <string>
#include <vector>

#include "src/pipeline/fit_stored_runs.hpp"

namespace hydrocoef::cli {

void print_fit(const FitResult& result, const std::string& dof, const std::string& body, const std::string& database,
               bool json);
void print_level_fit(const LevelFitResult& result, const LevelFitRequest& request, const std::string& database,
                     bool json);
void print_refit(const RefitResult& result, const std::string& database, bool json);
void print_fits(const std::vector<FitRecord>& fits, const std::string& database, bool json);

}  // namespace hydrocoef::cli
