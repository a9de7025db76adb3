// Force histories: the forces and moments a CFD solver wrote at every time
// step or iteration, as plain SI data in the axes the source wrote them in,
// with the file and line of every sample so that any later message can point
// into the files. Importers make them (importers/openfoam_forces,
// importers/force_history_csv); src/history/history_analysis turns one into a
// run's mean forces with their uncertainty. Nothing here knows file formats,
// body axes or the database: turning the source's axes into body axes is the
// frame transform's job, with the frame recorded here.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hydrocoef {

/// What a history's abscissa counts.
enum class HistoryAbscissa {
  Time,       ///< physical time [s] of a transient run
  Iteration,  ///< iteration number of a steady run (pseudo-time), dimensionless
};
std::string_view abscissa_name(HistoryAbscissa abscissa);  ///< "time" or "iteration"
std::string_view abscissa_unit(HistoryAbscissa abscissa);  ///< "s" or "" (dimensionless)

/// The six components in the history's own axes (HistoryFrame): forces Fx, Fy,
/// Fz [N] and moments Mx, My, Mz [N m] about the frame's moment centre.
enum class HistoryComponent : std::size_t { Fx = 0, Fy, Fz, Mx, My, Mz };
inline constexpr std::size_t kHistoryComponents = 6;
inline constexpr std::array<HistoryComponent, kHistoryComponents> kAllHistoryComponents{
    HistoryComponent::Fx, HistoryComponent::Fy, HistoryComponent::Fz,
    HistoryComponent::Mx, HistoryComponent::My, HistoryComponent::Mz};

/// The parts of a force or moment as the solver splits it, following
/// OpenFOAM's forces function object: total = pressure + viscous + porous
/// (porous: the resistance of porous zones, "internal" in newer OpenFOAM).
enum class ForcePart : std::size_t { Total = 0, Pressure, Viscous, Porous };
inline constexpr std::size_t kForceParts = 4;
inline constexpr std::array<ForcePart, kForceParts> kAllForceParts{ForcePart::Total, ForcePart::Pressure,
                                                                   ForcePart::Viscous, ForcePart::Porous};

/// How the source named its components. A solver's force file gives Fx..Mz in
/// the solver's axes; a table whose columns are the SNAME letters X Y Z K M N
/// says they are already body-axis components (x forward, y starboard, z down).
enum class ComponentNaming { SourceAxes, BodyAxes };

std::string_view component_name(HistoryComponent component, ComponentNaming naming = ComponentNaming::SourceAxes);
std::string_view part_name(ForcePart part);  ///< "total", "pressure", "viscous", "porous"

/// The axes and moment centre the components are given in.
struct HistoryFrame {
  ComponentNaming naming = ComponentNaming::SourceAxes;
  /// Rows: the history's x, y and z axes as unit vectors in the solver's
  /// global axes, when the source states them (forceCoeffs' dragDir, sideDir
  /// and liftDir). Empty: the axes as written, which for OpenFOAM's force.dat
  /// are the global axes unless the forces function object was given a
  /// coordinateSystem (the case settings say; the file does not).
  std::optional<std::array<std::array<double, 3>, 3>> axes_in_global;
  /// The moment centre [m] in the solver's global coordinates (OpenFOAM's
  /// CofR), when the source states it.
  std::optional<std::array<double, 3>> moment_centre;
  /// One line for people: where the axes and the centre come from.
  std::string description;
};

/// One file a history was read from, for provenance and messages.
struct HistorySourceFile {
  std::filesystem::path path;
  /// What it was read as: "openfoam-force", "openfoam-moment",
  /// "openfoam-forces", "openfoam-coefficient", "force-history-csv".
  std::string format;
  std::string sha256;  ///< lower-case hex SHA-256 of the bytes read; empty when not computed
  std::uint64_t size_bytes = 0;
  std::size_t rows = 0;       ///< data rows in the file
  std::size_t rows_used = 0;  ///< rows kept in the history (a restart that starts earlier replaces the rest)
};

/// Where a sample's values were read: files[file], 1-based line.
struct SampleOrigin {
  std::uint32_t file = 0;
  std::uint32_t line = 0;
};

/// A force history. Plain data: every vector that is not empty has size()
/// elements; the abscissa is finite and strictly increasing; values are
/// finite, in N and N m.
struct ForceHistory {
  HistoryAbscissa abscissa = HistoryAbscissa::Time;
  std::vector<double> abscissa_values;  ///< [s] or iteration number
  /// series[part][component]. An empty vector: the source does not give that
  /// part of that component (a coefficient file has totals only; a table may
  /// hold only Fx).
  std::array<std::array<std::vector<double>, kHistoryComponents>, kForceParts> series;
  std::vector<SampleOrigin> force_origin;   ///< where each sample's forces were read; empty without forces
  std::vector<SampleOrigin> moment_origin;  ///< where its moments were read; empty without moments
  std::vector<HistorySourceFile> files;
  HistoryFrame frame;
  /// What a reader should know about how the history was assembled (restarts
  /// joined and the rows they replaced, units assumed, columns not used).
  std::vector<std::string> notes;

  std::size_t size() const { return abscissa_values.size(); }
  bool has(ForcePart part, HistoryComponent component) const {
    return !series[static_cast<std::size_t>(part)][static_cast<std::size_t>(component)].empty();
  }
  const std::vector<double>& values(ForcePart part, HistoryComponent component) const {
    return series[static_cast<std::size_t>(part)][static_cast<std::size_t>(component)];
  }
  std::vector<double>& values(ForcePart part, HistoryComponent component) {
    return series[static_cast<std::size_t>(part)][static_cast<std::size_t>(component)];
  }
};

/// "path:line" of the file a sample's component was read from (its forces'
/// file for Fx..Fz, its moments' file for Mx..Mz), for messages; "sample N"
/// when the history has no origins.
std::string sample_location(const ForceHistory& history, std::size_t sample, HistoryComponent component);

/// The magnitudes a history's abscissa and values may have besides 0: their
/// squares, and sums of a billion of them, stay normal finite doubles, so that
/// every statistic of the history is finite (a denormal force or time step, or
/// a time of 1e300, made a NaN standard error).
inline constexpr double kMinHistoryMagnitude = 1e-100;
inline constexpr double kMaxHistoryMagnitude = 1e100;

/// Checks the invariants above and throws std::invalid_argument naming the
/// first one broken; and throws InputError naming the sample's file and line
/// for an abscissa or a value that is neither 0 nor of a magnitude from
/// kMinHistoryMagnitude to kMaxHistoryMagnitude (bad input, not a broken
/// invariant). Importers call it on what they return; code that builds a
/// history by hand can too.
void check_force_history(const ForceHistory& history);

/// The history with its components turned into the solver's global axes by
/// frame.axes_in_global (a force's or moment's three components are needed
/// together; a vector with a missing component cannot be turned and is
/// refused with an InputError). A history without stated axes is returned
/// unchanged.
ForceHistory rotated_to_global_axes(const ForceHistory& history);

}  // namespace hydrocoef
