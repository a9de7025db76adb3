// The wall force and moment summary that the ANSYS CFX solver writes into its
// output file (.out) at the end of a run: for each domain group, the pressure
// and viscous force and the pressure and viscous moment on each wall
// boundary, in the solver's global axes, with the group's totals. With it a
// run whose only file is its .out imports without monitor exports.
//
// The layout read (tests/data/cfx/PROVENANCE.md says which parts were seen
// in public sources and which are assumed):
//
//    +--------------------------------------------------------------------+
//    |                   Wall Force and Moment Summary                    |
//    +--------------------------------------------------------------------+
//
//    Notes: ...                               (any text before the first table)
//
//                                 Pressure Force (N)
//
//    Domain Group: Default Domain
//
//                               x-Comp.       y-Comp.       z-Comp.
//
//    hull                   -1.2000E+00    3.0000E-02    0.0000E+00
//    rudder                 ...
//    ----------------------------------------------------------------
//    Domain Group Totals :  ...
//
//                                 Viscous Force (N)
//    ... (the same for Pressure Moment (N m) and Viscous Moment (N m))
//
// A table's title names its part (Pressure, Viscous) and quantity (Force,
// Moment) and its unit in parentheses or brackets (N, kN, N m, ...), which is
// converted to SI and checked against the quantity. A row is a name (blanks
// allowed inside) followed by three numbers. Importers turn bytes into domain
// objects and nothing else: choosing a location, axes and the moment centre
// is the pipeline's job.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hydrocoef {

inline constexpr std::string_view kCfxOutImporter = "cfx-out-summary";
inline constexpr std::string_view kCfxOutImporterVersion = "1";

/// The four vectors of one location, SI (N, N m), in the solver's global
/// axes; a vector the summary does not give is empty.
struct CfxWallLoads {
  std::optional<std::array<double, 3>> pressure_force, viscous_force, pressure_moment, viscous_moment;
  std::size_t line = 0;  ///< 1-based line of the location's first row
};

/// One domain group of the summary: its wall boundaries in the order of the
/// file and its totals.
struct CfxDomainGroup {
  std::string name;
  std::vector<std::pair<std::string, CfxWallLoads>> boundaries;
  CfxWallLoads totals;
};

struct CfxWallForceSummary {
  std::string file;
  std::size_t line = 0;       ///< the summary's banner
  std::size_t summaries = 0;  ///< summaries in the file (a transient run writes one per time step); the last is read
  std::vector<CfxDomainGroup> groups;
};

/// Reads the last wall force and moment summary of a CFX solver output file.
/// InputError naming FILE:LINE:COLUMN for a file without a summary, a table
/// title whose unit is not a force (or moment) unit, a row that is not a name
/// and three numbers, a row before any "Domain Group:" line, a location
/// given twice in one table, and a group without its totals row.
CfxWallForceSummary read_cfx_wall_forces(const std::filesystem::path& file);

/// The same from the file's text (`file` names it in messages).
CfxWallForceSummary parse_cfx_wall_forces(std::string_view text, const std::string& file);

/// True when the text holds a wall force and moment summary banner. Never throws.
bool has_cfx_wall_forces(std::string_view text);

/// The same for a file (false for a file that cannot be read). Never throws.
bool file_has_cfx_wall_forces(const std::filesystem::path& file);

}  // namespace hydrocoef
