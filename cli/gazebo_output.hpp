// How the CLI reports a Gazebo export (text or JSON).
#pragma once

#include <string>
#include <vector>

#include "src/export/gazebo_export.hpp"

namespace hydrocoef::cli {

void print_gazebo_export(const GazeboCoefficients& coefficients, const std::vector<GazeboElement>& elements,
                         const GazeboWriteOptions& options, const std::string& output, bool json);

}  // namespace hydrocoef::cli
