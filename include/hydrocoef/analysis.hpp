// Analyses of a run database beyond fits and surfaces, as the command-line
// tool runs them: the numerical uncertainty of mesh studies (`hydrocoef
// gci`), added mass and damping from forced-oscillation runs (`hydrocoef
// pmm`, `pmm-runs`, `pmm-runs delete`, `added-mass`), and where to run CFD
// next (`hydrocoef suggest`). Each operation takes an options struct whose
// defaults are the CLI's and whose validate() is the one check of its
// options (InputError with the message the CLI prints, naming the option as
// the CLI spells it); each returns a result with its numbers as public fields,
// text() (what the CLI prints) and json() (what --json prints).
//
// Units and frames: SI. Body axes after Fossen/SNAME (x forward, y starboard,
// z down). DOFs surge, sway, heave (translations along x, y, z [m]), roll,
// pitch, yaw (rotations about x, y, z [rad]); forces X, Y, Z [N], K, M, N
// [N m] on the body, about the run's reference point. Forced oscillation:
// the body is moved as x_j(t) = A sin(omega t + phase) in one DOF j and feels
// F_i = -M_A[i][j] x_j'' - D[i][j] x_j' (+ its mean): added mass M_A[i][j] in
// kg (two translations), kg m (one rotation), kg m^2 (two rotations); damping
// D[i][j] in N s/m, N s, N m s.
//
// Errors: bad input is an InputError with the CLI's message; every write is
// one transaction (after an exception the database is as it was), and an
// operation that writes refuses a Database opened read-only before it reads
// anything.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hydrocoef/database.hpp"
#include "hydrocoef/error.hpp"
#include "hydrocoef/export.hpp"

namespace hydrocoef {
inline namespace api {

// ---------------------------------------------------------------------------
// Mesh studies: hydrocoef gci (Celik et al. 2008)

/// The options of `hydrocoef gci`. Runs state their mesh with disturbance
/// parameters: the level (mesh_parameter, default "mesh") and its size,
/// `cells` (cell count N: h = (volume / N)^(1/dimension)) or `cell_size` (h in m).
struct HYDROCOEF_EXPORT GciOptions {
  std::string body;                     ///< the body whose runs to study (required)
  std::string mesh_parameter = "mesh";  ///< the disturbance parameter of the mesh level (--mesh-param)
  std::optional<double> volume;         ///< domain volume [m^D] for h from cells (none: 1, h relative)
  int dimension = 3;                    ///< D of h = (V/N)^(1/D): 1, 2 or 3
  /// Run a study whose values did not converge (or whose iterative error is
  /// not below a tenth of the change to the adjacent mesh), with a note.
  bool allow_unconverged = false;
  /// Store the result and apply u_num to the runs of each key's finest mesh
  /// (needs a writable Database); false: study only (--no-store).
  bool store = true;

  /// InputError for a body or parameter name that is not one, a level
  /// parameter that names a size, a dimension outside 1..3, or a volume that
  /// is not finite and > 0.
  void validate() const;
};

/// One force component of one key's study. Optional numbers are empty when
/// the procedure found none (no convergence, or no order for converged values).
struct GciComponent {
  std::string component;        ///< X..N
  std::array<double, 3> phi{};  ///< the values, fine to coarse [N or N m], on the body
  double r21 = 0.0, r32 = 0.0;  ///< refinement ratios h2/h1, h3/h2
  /// "monotonic", "oscillatory", "converged" or "not found".
  std::string convergence;
  std::optional<double> apparent_order;               ///< p
  std::optional<double> extrapolated;                 ///< phi_ext21 [N or N m]
  std::optional<double> relative_error;               ///< e_a21 (a fraction)
  std::optional<double> extrapolated_relative_error;  ///< e_ext21 (a fraction)
  std::optional<double> gci_fine;                     ///< GCI_fine21 (a fraction)
  std::optional<double> gci_medium;                   ///< GCI_fine32 (a fraction)
  std::optional<double> asymptotic_ratio;             ///< GCI_fine32 / (r21^p GCI_fine21), about 1
  std::optional<double> numerical_uncertainty;        ///< u_num = GCI_fine |phi1| / 2 [N or N m]
  /// Each value's convergence kind, fine to coarse ("converged",
  /// "steady-window", "transient-window", "given-window", "no history",
  /// "not recorded") and its stated iterative or standard error [N or N m].
  std::array<std::string, 3> values_convergence;
  std::array<double, 3> values_error{};
  std::string note;  ///< why a result is missing, or a warning
};

/// One physical key's mesh study (the key without its mesh parameters).
struct GciKey {
  std::string body;
  std::array<double, 6> velocity{};  ///< u, v, w [m/s], p, q, r [rad/s]
  std::map<std::string, double> disturbances;
  std::string description;         ///< the key in words, as the CLI prints it
  std::vector<double> levels;      ///< every level's parameter value, fine to coarse
  std::vector<double> cell_sizes;  ///< every level's h, fine to coarse [m, or relative]
  std::vector<std::int64_t> runs;  ///< every level's run id, fine to coarse
  std::string cell_size_from;      ///< "cell_size" or "cells"
  std::vector<GciComponent> components;
  std::vector<std::string> notes;
};

/// A body's mesh studies: what `hydrocoef gci` prints.
struct HYDROCOEF_EXPORT GciStudy {
  std::string body;
  std::string mesh_parameter;
  double safety_factor = 1.25;   ///< Fs of the GCI
  double coverage_factor = 2.0;  ///< k of u_num = GCI_fine |phi1| / k
  int dimension = 3;             ///< as given
  bool volume_given = false;     ///< a volume was given (else h from cells is relative)
  std::vector<GciKey> keys;
  std::size_t single_level_keys = 0;   ///< keys at one level only: not studies
  std::size_t runs_without_level = 0;  ///< runs of the body without the level parameter
  bool stored = false;                 ///< stored and applied to the runs
  std::size_t fits_made_stale = 0;     ///< the body's fits that storing made stale
  std::size_t surfaces_made_stale = 0;

  std::string text() const;  ///< the table `hydrocoef gci` prints
  std::string json() const;  ///< what `hydrocoef gci --json` prints (without the final newline)
};

/// Runs the body's mesh studies and (options.store) stores them, as
/// `hydrocoef gci`. InputError for a bad option, a key at two levels, a run of
/// a study without a cell size, values that did not converge (without
/// allow_unconverged), no key at three levels or more; for store on a
/// read-only Database.
HYDROCOEF_EXPORT GciStudy grid_convergence(Database& database, const GciOptions& options);

// ---------------------------------------------------------------------------
// Forced oscillation: hydrocoef pmm, pmm-runs, added-mass

/// The options of `hydrocoef pmm`. The motion is the case's (OpenFOAM
/// constant/dynamicMeshDict; a CFX CCL with `ccl`) unless motion, amplitude
/// and period are all given (then it is checked against the case's).
struct HYDROCOEF_EXPORT PmmOptions {
  std::string body;                                ///< "" : "vehicle"
  std::string axes;                                ///< body axes in CFD axes, e.g. "-x,y,-z" ("" : x,y,z)
  std::optional<std::array<double, 3>> origin;     ///< body origin in CFD coordinates [m]
  std::optional<std::array<double, 3>> ref_point;  ///< moment reference point [m], body axes
  std::optional<double> rho;                       ///< fluid density [kg m^-3]
  std::optional<double> nu;                        ///< kinematic viscosity [m^2 s^-1]
  std::map<std::string, double> set;               ///< run key: velocity component or disturbance [SI]
  std::map<std::string, std::string> columns;      ///< CSV histories: component -> header
  std::map<std::string, std::string> units;        ///< CSV histories: unit of a column without one
  std::optional<std::string> sign;                 ///< "on-body" (default) or "opposing"
  std::optional<std::string> motion;               ///< the moved DOF: surge ... yaw
  std::optional<double> amplitude;                 ///< A [m, or rad]
  std::optional<double> period;                    ///< T [s]
  double phase = 0.0;                              ///< [rad]: x(t) = A sin(2 pi t / T + phase)
  std::optional<std::string> ccl;                  ///< CFX: the case's CCL or solver output (.out)
  int harmonics = 1;                               ///< harmonics fitted, 1..10
  std::optional<double> start;                     ///< keep whole periods from this time [s] (none: detected)
  bool stream = false;                             ///< the body stood in an oscillating stream
  std::optional<double> volume;                    ///< displaced volume V [m^3]
  std::optional<double> restoring;                 ///< C of F = -C x on the moved DOF [N/m, N m/rad]
  std::optional<double> size;                      ///< body size D [m] for KC and Stokes numbers
  unsigned jobs = 0;                               ///< inputs read in parallel (0: every core)
  /// Called after each input is analysed (from one thread at a time).
  std::function<void(std::size_t done, std::size_t total, const std::string& path)> progress;

  /// InputError (the CLI's message) for a bad setting, motion, amplitude,
  /// period, phase, harmonics, size, volume or restoring coefficient, or
  /// some but not all of motion, amplitude and period.
  void validate() const;
};

/// One force component of a forced-oscillation run: entry [component][dof].
struct PmmComponent {
  std::string component;       ///< X..N
  double mean = 0.0;           ///< [N or N m]
  double added_mass = 0.0;     ///< M_A[component][dof]
  double added_mass_se = 0.0;  ///< standard error, from the period-to-period spread
  std::string added_mass_unit;
  double damping = 0.0;  ///< D[component][dof]
  double damping_se = 0.0;
  std::string damping_unit;
  double explained = 0.0;                        ///< fraction of the variance the fit explains
  std::vector<double> harmonics;                 ///< s1, c1, s2, c2, ... [N or N m]
  std::optional<double> added_mass_coefficient;  ///< M_A / (rho V): the moved translation's own, rho and V given
  double in_phase_spread = 0.0;                  ///< standard deviation of s1 over the periods
  double quadrature_spread = 0.0;                ///< of c1
};

/// One forced-oscillation run analysed.
struct PmmRunResult {
  std::string path;
  std::string format;
  std::string body;
  std::array<double, 6> velocity{};  ///< the run's mean body velocity u..r
  std::string dof;                   ///< the moved DOF: surge ... yaw
  double amplitude = 0.0;            ///< [m or rad]
  double omega = 0.0;                ///< [rad/s]
  double period = 0.0;               ///< [s]
  double phase = 0.0;                ///< [rad]
  std::string motion_source;         ///< where the motion was read ("--motion", "case/constant/dynamicMeshDict:21")
  std::string medium;                ///< "still water" or "oscillating stream"
  double window_start = 0.0, window_end = 0.0;  ///< [s]
  std::size_t periods = 0, transient_periods = 0, samples = 0;
  int harmonics = 1;
  std::optional<double> size, keulegan_carpenter, stokes_number, rho, displaced_volume, restoring;
  std::vector<std::string> notes;
  std::vector<PmmComponent> components;  ///< those the history holds, X..N
  std::int64_t stored_id = 0;            ///< its pmm run id once stored (0 before)
  bool replaced = false;                 ///< storing replaced an earlier analysis of the same file and motion
};

/// What `hydrocoef pmm` prints: the runs analysed, and where they were stored.
struct HYDROCOEF_EXPORT PmmAnalysis {
  std::vector<PmmRunResult> runs;
  bool stored = false;   ///< store_pmm stored them
  std::string database;  ///< where ("" before)

  std::string text() const;
  std::string json() const;  ///< without the final newline

  struct Access;  ///< the library's own

 private:
  std::shared_ptr<const void> records_;  ///< what store_pmm stores
};

/// Reads and analyses forced-oscillation runs (force histories, OpenFOAM case
/// folders, CFX monitors, CSV of time and forces), storing nothing, as
/// `hydrocoef pmm --no-store`. InputError naming the file for an input that is
/// not a time history, a motion that cannot be found or that the options
/// contradict, fewer than 3 whole periods after the transient, a negative
/// in-line added mass, or a result that is not finite.
HYDROCOEF_EXPORT PmmAnalysis analyse_pmm(const std::vector<std::string>& inputs, const PmmOptions& options);

/// Stores an analysis's runs in one transaction (replacing earlier analyses
/// of the same file and motion) and notes their ids in it, as `hydrocoef pmm`
/// does after analysing. InputError for a read-only Database.
HYDROCOEF_EXPORT void store_pmm(Database& database, PmmAnalysis& analysis);

/// A stored forced-oscillation run, as `hydrocoef pmm-runs` lists it.
struct PmmRunSummary {
  std::int64_t id = 0;
  std::string body;
  std::string dof;
  double amplitude = 0.0;  ///< [m or rad]
  std::string amplitude_unit;
  double period = 0.0;  ///< [s]
  double omega = 0.0;   ///< [rad/s]
  std::string medium;
  std::optional<double> restoring;
  std::optional<double> added_mass;  ///< in-line M_A[dof][dof] (none when its component is not stored)
  std::optional<double> damping;     ///< in-line D[dof][dof]
  std::string added_mass_unit, damping_unit;
  std::string source_path;
  std::string created_at;  ///< UTC, ISO 8601
};

struct HYDROCOEF_EXPORT PmmRunList {
  std::vector<PmmRunSummary> runs;
  std::string text() const;
  std::string json() const;
};

/// The stored forced-oscillation runs (of one body, or all when body is ""), as `hydrocoef pmm-runs`.
HYDROCOEF_EXPORT PmmRunList pmm_runs(const Database& database, const std::string& body = "");

struct PmmDeletedRun {
  std::int64_t id = 0;
  std::string body;
  std::string dof;  ///< "" when the record's DOF is not one
  std::string source_path;
};

struct HYDROCOEF_EXPORT PmmDeletion {
  std::string database;
  std::vector<PmmDeletedRun> deleted;
  std::string text() const;
  std::string json() const;
};

/// Deletes stored forced-oscillation runs by id in one transaction, as
/// `hydrocoef pmm-runs delete`: an id that is not stored is an InputError and
/// deletes nothing. Works on records no other call can read.
HYDROCOEF_EXPORT PmmDeletion delete_pmm_runs(Database& database, const std::vector<std::int64_t>& ids);

/// The options of `hydrocoef added-mass`.
struct HYDROCOEF_EXPORT AddedMassMatrixOptions {
  std::string body;  ///< required
  /// DOF -> DOF: a DOF no run moves takes another's column ({"sway": "surge"}).
  std::map<std::string, std::string> same;
  std::vector<std::string> zero;  ///< DOFs whose added mass is zero
  /// The period [s] of the runs that make the matrices (needed when the runs are at several).
  std::optional<double> period;
  /// Return a matrix that is not positive definite instead of refusing it.
  bool allow_indefinite = false;

  /// InputError naming --same or --zero for a DOF name that is not one.
  void validate() const;
};

/// One measured entry, before symmetry.
struct AddedMassEntry {
  std::string row, column;  ///< DOF names
  std::string name;         ///< "M_A[surge][sway]"
  std::string unit;         ///< of M_A[row][column]
  std::size_t runs = 0;
  double added_mass = 0.0, added_mass_se = 0.0, added_mass_spread = 0.0;
  double damping = 0.0, damping_se = 0.0;
  double omega_min = 0.0, omega_max = 0.0;  ///< [rad/s]
  std::optional<double> kc_min, kc_max;
  std::vector<std::int64_t> pmm_runs;
};

/// The in-line M_A[j][j] and D[j][j] of the runs of one DOF at one frequency.
struct AddedMassFrequency {
  std::string dof;
  double omega = 0.0, period = 0.0;
  std::size_t runs = 0;
  double amplitude_min = 0.0, amplitude_max = 0.0;
  double added_mass = 0.0, added_mass_se = 0.0;
  double damping = 0.0, damping_se = 0.0;
  bool used = false;  ///< the frequency the matrices are made from
};

/// D_eq(A) = linear + quadratic (8 / (3 pi)) A omega from runs of one DOF at several amplitudes.
struct QuadraticDampingFit {
  std::string dof;
  double omega = 0.0;
  std::vector<double> amplitudes;
  double linear = 0.0, linear_se = 0.0;        ///< [N s/m or N m s]
  double quadratic = 0.0, quadratic_se = 0.0;  ///< [N s^2/m^2 or N m s^2]
};

using Matrix6x6 = std::array<std::array<double, 6>, 6>;

/// The assembled matrices: what `hydrocoef added-mass` prints. Rows and
/// columns surge, sway, heave, roll, pitch, yaw.
struct HYDROCOEF_EXPORT AddedMassMatrix {
  std::string body;
  double omega = 0.0, period = 0.0;  ///< of the runs that make the matrices
  std::size_t records = 0;           ///< runs at that frequency
  std::size_t other_frequency_records = 0;
  Matrix6x6 added_mass{}, added_mass_se{};  ///< M_A, symmetric
  Matrix6x6 damping{}, damping_se{};        ///< D, as measured
  std::vector<AddedMassEntry> entries;      ///< measured, row by row
  std::vector<std::string> missing;         ///< entries no run gives, named
  std::vector<std::string> notes;
  bool positive_definite = false;
  double smallest_eigenvalue = 0.0;  ///< over the DOFs with a non-zero diagonal
  std::vector<QuadraticDampingFit> quadratic_damping;
  std::vector<AddedMassFrequency> by_frequency;  ///< by DOF, then frequency

  std::string text() const;
  std::string json() const;
};

/// Assembles the body's 6x6 added-mass and damping matrices from its stored
/// forced-oscillation runs, as `hydrocoef added-mass`. InputError when the
/// body has none, the runs are at several frequencies and no period chooses
/// one, a same/zero DOF is measured, or (without allow_indefinite) M_A is not
/// positive definite.
HYDROCOEF_EXPORT AddedMassMatrix added_mass_matrix(const Database& database, const AddedMassMatrixOptions& options);

// ---------------------------------------------------------------------------
// Where to run CFD next: hydrocoef suggest

/// The options of `hydrocoef suggest`.
struct HYDROCOEF_EXPORT SuggestOptions {
  std::string surface;               ///< a GP surface's name (required)
  std::size_t count = 5;             ///< runs to propose, 1 to 1000
  std::vector<std::string> bounds;   ///< "AXIS=FROM:TO" [SI] (default: the surface's range)
  std::string output;                ///< whose uncertainty to reduce ("" : the first output) (--for)
  std::size_t candidates = 4096;     ///< candidate keys searched
  std::vector<std::string> round;    ///< "AXIS=STEP" [SI] (default: 1/100 of the bounds, 1-2-5)
  std::vector<std::string> running;  ///< sweep manifests of runs asked for and not imported yet
  std::string manifest;              ///< write the runs as a sweep manifest CSV here ("" : none)

  /// InputError for a count outside 1 to 1000 or a name that is not one.
  void validate() const;
};

struct SuggestedKey {
  std::vector<double> key;  ///< on the surface's axes, in their order [SI]
  double sd_before = 0.0;   ///< the standard deviation there before it was chosen
};

struct HYDROCOEF_EXPORT Suggestion {
  std::string surface;
  std::string output, unit;
  std::vector<std::string> axes;
  std::vector<double> lower, upper;    ///< the bounds searched, per axis
  std::vector<double> resolution;      ///< per axis: every key a multiple of it
  std::vector<bool> resolution_given;  ///< per axis: given (else the default)
  std::string mirror;                  ///< the surface's mirror planes ("" none)
  std::string domain;                  ///< the fundamental domain in words ("" without a mirror)
  std::size_t candidates = 0;
  std::size_t imported_skipped = 0, running_skipped = 0;
  std::vector<SuggestedKey> runs;  ///< in the order chosen
  double largest_sd_after = 0.0;   ///< over the candidates with all the runs added
  std::string manifest;            ///< the manifest written ("" none)

  std::string text() const;
  std::string json() const;
};

/// The next runs of a GP surface: the keys that most reduce its largest
/// standard deviation in the bounds, as `hydrocoef suggest` (and the sweep
/// manifest, written whole or not at all, when options.manifest names one).
HYDROCOEF_EXPORT Suggestion suggest_runs(const Database& database, const SuggestOptions& options);

}  // namespace api
}  // namespace hydrocoef
