// The added mass `hydrocoef export-gazebo` is given on its command line.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/common.hpp"
#include "src/core/matrix6.hpp"

namespace hydrocoef::cli {

/// What the command line of export-gazebo gives.
struct GazeboArgs {
  std::string body;
  std::string flavor;
  std::string output;
  std::vector<std::string> fits;
  std::optional<std::string> added_mass;
  std::optional<std::string> added_mass_matrix;
  std::optional<double> sphere_radius;
  std::optional<double> rho;
  std::optional<std::string> rotation;
  std::optional<std::string> added_mass_from_database;  ///< BODY of stored forced-oscillation runs
  std::vector<std::string> same, zero;                  ///< with it: DOFs no run moves
  std::optional<double> added_mass_period;              ///< with it: the runs' period [s], when they have several
  bool drop_constant = false;
  bool allow_missing = false;
  bool allow_unphysical = false;
  std::optional<double> linearize_at;
  std::optional<std::string> link;
  std::optional<std::string> link_axes;
  SelectionArgs selection;
  bool json = false;
};

/// The added-mass matrix from exactly one of the four ways to give it
/// (--added-mass, --added-mass-matrix, --sphere-radius with --rho,
/// --added-mass-from-database BODY with the database at `database`), and a
/// sentence saying where it came from. InputError naming the option otherwise,
/// or naming the entries the stored runs do not give.
std::pair<Matrix6, std::string> added_mass_from(const GazeboArgs& args, const std::string& database);

}  // namespace hydrocoef::cli
