// Exports as library calls: `hydrocoef export` (a stored gridded surface as a
// file another tool loads), `hydrocoef export-gazebo` (a body's damping-law
// fits and an added-mass matrix as Gazebo hydrodynamics parameters) and
// `hydrocoef derivatives export` (stored derivative models as CSV, JSON,
// gz-sim parameters or a MATLAB function) and `hydrocoef export --format
// openfoam-forcecoeffs` (runs as OpenFOAM forceCoeffs files, in the case's
// axes: the exception to the body axes below). The CLI commands are these
// functions and print their results' text() or json().
//
// Units and frames: SI; body axes x forward, y starboard, z down (FRD); the
// tables' outputs and the damping coefficients are forces on the body (a
// damping coefficient is negative, SNAME "on-body" signs). Every file is
// written whole or not at all; a refused export writes nothing and never
// touches the database.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "hydrocoef/database.hpp"
#include "hydrocoef/error.hpp"
#include "hydrocoef/export.hpp"

namespace hydrocoef {
inline namespace api {

/// What `hydrocoef export` writes: a stored gridded surface (a table, or an
/// RBF resampled with --resample) in one of the formats.
struct TableExportOptions {
  std::string name;  ///< the stored surface (with `vehicle`: the body)
  /// csv, csv-wide, json, c (C99 header), mat (MATLAB v5 + Simulink set-up
  /// script), jsbsim, vtk, daveml (with each node's standard deviation when
  /// the surface states one) or runtime (libhydrocoef_runtime's file,
  /// hydrocoef/runtime.h and docs/runtime.md: the surfaces as hydrocoef
  /// evaluates them, with their standard deviation's tables).
  std::string format;
  std::string output;             ///< the file to write (mat: a set-up script beside it)
  bool single_precision = false;  ///< c: float tables and arithmetic (--float)
  std::string identifier;         ///< c: prefix of its names ("" : from the surface name)
  /// runtime: further surfaces in the same file (--surface, repeated), of
  /// the same body as `name`; the file holds `name` first, then these.
  std::vector<std::string> surfaces;
  /// runtime: a vehicle file (or its JSON text; src/dynamics/vehicle.hpp,
  /// `hydrocoef simulate --vehicle`) whose whole dynamics model the file
  /// holds too (format version 2), its stored fits, derivative models and
  /// surfaces read from this database as simulate reads them; `name` is then
  /// the body, and the file holds the surfaces the vehicle's damping reads,
  /// then `surfaces` (--vehicle).
  std::string vehicle;
  /// InputError for an unknown format, --float / --identifier with a format
  /// other than c, or --surface or --vehicle with a format other than runtime.
  HYDROCOEF_EXPORT void validate() const;
};

/// One axis of an exported table.
struct TableExportAxis {
  std::string name;
  std::string unit;
  std::size_t breakpoints = 0;
  double lower = 0.0, upper = 0.0;  ///< the valid range: first and last breakpoint
  std::string extrapolation;        ///< out-of-range policy: error, clamp, linear, method
};

/// What an export wrote.
struct TableExportResult {
  std::string surface;
  std::string body;
  std::string format;          ///< as given, canonical
  std::string method;          ///< the table's interpolation
  std::string content_sha256;  ///< of the stored surface (provenance in every file)
  std::vector<std::int64_t> runs;
  bool stale = false;  ///< forces changed since the surface was built
  std::size_t nodes = 0;
  std::vector<std::string> files;  ///< the files written
  /// runtime: every surface in the file, `surface` first ({surface} otherwise).
  std::vector<std::string> surfaces;
  /// runtime with a vehicle: its name ("" otherwise); `surface` and the
  /// table's fields are then those of the file's first surface, empty when
  /// its damping reads none.
  std::string vehicle;
  std::vector<TableExportAxis> axes;
  std::vector<std::string> outputs;
  std::vector<std::string> output_units;
  /// Warnings: an axis refusing values outside a range that leaves out zero
  /// (a controller at rest would fail there).
  std::vector<std::string> notes;

  HYDROCOEF_EXPORT std::string text() const;  ///< what `export` prints
  HYDROCOEF_EXPORT std::string json() const;  ///< what `export --json` prints
};

/// Writes a stored gridded surface in a format, as `hydrocoef export`
/// (options.validate() first). InputError, nothing written, for a surface
/// that is not gridded (naming --resample), a format that cannot express the
/// table, or a path that cannot be written.
HYDROCOEF_EXPORT TableExportResult export_surface(const Database& db, const TableExportOptions& options);

/// What `hydrocoef export-gazebo` writes: the options of the command, text
/// as the command line gives it (the added mass's source sentence quotes it).
struct GazeboExportOptions {
  std::string body;    ///< whose fits are exported
  std::string flavor;  ///< "uuv" (uuv_simulator fossen model) or "gz" (gz-sim Hydrodynamics)
  std::string output;  ///< the file to write
  /// "DOF=FITNAME": the law of a force component (several per DOF when in
  /// different velocities). Default: the body's single fit of each DOF in its own velocity.
  std::vector<std::string> fits;
  // Exactly one source of the added mass Ma (positive, body axes):
  std::optional<std::string> added_mass;                ///< diagonal "d1,...,d6" (kg x3, kg m^2 x3)
  std::optional<std::string> added_mass_matrix;         ///< a file of 36 numbers, row by row
  std::optional<double> sphere_radius;                  ///< a sphere of this radius [m], with rho
  std::optional<double> rho;                            ///< fluid density for sphere_radius [kg/m^3]
  std::optional<std::string> added_mass_rotation;       ///< with sphere_radius: "a,b,c" [kg m^2]
  std::optional<std::string> added_mass_from_database;  ///< BODY: assembled from its forced-oscillation runs
  std::vector<std::string> same;                        ///< with it: "DOF=DOF" for a DOF no run moves
  std::vector<std::string> zero;                        ///< with it: DOFs whose added mass is zero
  std::optional<double> added_mass_period;              ///< with it: the runs' period [s]
  bool drop_constant = false;                           ///< drop a law's constant term instead of refusing
  bool allow_missing = false;                           ///< write 0 for a DOF without a law instead of refusing
  bool allow_unphysical = false;                        ///< write energy-feeding laws instead of refusing
  std::optional<double> linearize_at;                   ///< U0 [m/s]: each b x|x| replaced by its slope there
  std::optional<std::string> link;                      ///< gz: <link_name> (default base_link)
  std::optional<std::string> link_axes;                 ///< gz: "flu" (default) or "frd"
  std::vector<std::string> where;                       ///< only the fits made from this selection of runs
  std::vector<std::int64_t> exclude_runs;               ///< with where: the fits made with these runs left out
  /// InputError, with the CLI's message, for an unknown flavor or link axes,
  /// --link with uuv, a --fit that is not DOF=FIT, not exactly one added-mass
  /// source, options of one source given with another, or a malformed number list.
  HYDROCOEF_EXPORT void validate() const;
};

/// One damping law exported.
struct GazeboFitExport {
  std::string dof;       ///< X..N
  std::string variable;  ///< u..r
  std::string name;      ///< the fit
  std::int64_t id = 0;
  std::string terms;
  std::string stored_sign;  ///< "on-body" or "opposing" (negated to on-body)
  double linear = 0.0;      ///< on-body coefficient of x [linear_unit]
  double quadratic = 0.0;   ///< on-body coefficient of x|x| [quadratic_unit]
  std::string linear_unit;  ///< e.g. "N/(m/s)"
  std::string quadratic_unit;
  std::vector<std::int64_t> runs;
  double dropped_constant = 0.0;  ///< with drop_constant: the constant dropped [N or N m]; NaN when none
};

/// One SDF element written: name, numbers (1, 6 or 36), unit.
struct GazeboElementExport {
  std::string name;
  std::vector<double> values;
  std::string unit;
};

/// What export-gazebo wrote. Matrices are 6x6 row-major (36 numbers), rows
/// X..N, columns u..r, in hydrocoef's body axes (FRD), on-body signs.
struct GazeboExportResult {
  std::string body;
  std::string flavor;  ///< "uuv" or "gz"
  std::string file;
  std::string frame;      ///< of the written parameters: "frd" or "flu"
  std::string link_name;  ///< gz only ("" for uuv)
  std::vector<double> linear_b, quadratic_b, added_mass_b;
  std::string added_mass_source;
  double linearized_at = 0.0;  ///< U0 [m/s]; NaN when not linearised
  std::vector<GazeboFitExport> fits;
  std::vector<std::string> missing;  ///< DOFs written 0 (allow_missing)
  std::vector<GazeboElementExport> elements;
  std::vector<std::string> notes;

  HYDROCOEF_EXPORT std::string text() const;  ///< what `export-gazebo` prints
  HYDROCOEF_EXPORT std::string json() const;  ///< what `export-gazebo --json` prints
  struct Access;

 private:
  std::string text_, json_;
};

/// Writes a body's fits and an added mass as Gazebo parameters, as
/// `hydrocoef export-gazebo` (options.validate() first). InputError, nothing
/// written, for what the flavor cannot express (see the CLI's help).
HYDROCOEF_EXPORT GazeboExportResult export_gazebo(const Database& db, const GazeboExportOptions& options);

/// What `hydrocoef derivatives export NAME... --format F -o PATH` writes:
/// stored derivative models (include/hydrocoef/derivatives.hpp) as a file
/// another tool reads.
///   csv, json  one model, dimensional (SI) or in the prime, bis or MMG form
///              (the reference values as `derivatives show` takes them); the
///              dimensional JSON's terms, coefficients and covariance are
///              what a vehicle file's "derivatives" takes
///   gazebo     one gz-sim Hydrodynamics parameter file from models of one
///              body (one per output X..N), cross terms in gz-sim's names
///              (<yUabsV>, <nUR>), signs and axes as export-gazebo's
///   matlab     one MATLAB function [xdot, U] = NAME(x, ui) in the form of
///              Fossen's MSS vessel models (NAME the file's stem), from
///              models of one body (one per output), with the mass matrix
///              M = M_RB + M_A given
/// Coefficients are SNAME derivatives on the body [output unit / term unit].
struct DerivativeExportOptions {
  std::vector<std::string> names;    ///< the stored models (derivatives list)
  std::string format;                ///< csv, json, gazebo or matlab (--format)
  std::string output;                ///< the file to write (-o), whole or not at all
  std::string form = "dimensional";  ///< csv, json: dimensional, prime, bis or mmg (--form)
  /// csv, json in a non-dimensional form: the reference values (NaN: not
  /// given), as DerivativeShowOptions: --length L [m], --speed U [m/s],
  /// --density RHO [kg/m^3], --draft D [m] (mmg), --mass M [kg] (bis; else
  /// rho times --volume [m^3]), --gravity [m/s^2] (bis).
  double length = std::numeric_limits<double>::quiet_NaN();
  double speed = std::numeric_limits<double>::quiet_NaN();
  double density = std::numeric_limits<double>::quiet_NaN();
  double draft = std::numeric_limits<double>::quiet_NaN();
  double mass = std::numeric_limits<double>::quiet_NaN();
  double volume = std::numeric_limits<double>::quiet_NaN();
  double gravity = 9.80665;
  std::optional<std::string> link;       ///< gazebo: <link_name> (default base_link)
  std::optional<std::string> link_axes;  ///< gazebo: "flu" (default) or "frd"
  bool drop_unrepresentable = false;     ///< gazebo: leave out (and list) terms gz-sim cannot hold
  /// gazebo, optional: the added mass Ma (positive, body axes), a diagonal
  /// "d1,...,d6" (kg x3, kg m^2 x3) or a file of 36 numbers row by row; 0
  /// (with a note) when neither is given.
  std::optional<std::string> added_mass;
  std::optional<std::string> added_mass_matrix;
  /// matlab, exactly one: M = M_RB + M_A, a diagonal "d1,...,d6" or a file
  /// of 36 numbers row by row (kg, kg m, kg m^2), symmetric positive definite.
  std::optional<std::string> mass_diagonal;
  std::optional<std::string> mass_matrix;

  /// InputError, one line, for no model, an unknown format or form, a form
  /// other than dimensional or reference values with gazebo or matlab, more
  /// than one model for csv or json, no output file, an option of one
  /// format given with another, a reference value that is not finite and
  /// positive, or a malformed number list.
  HYDROCOEF_EXPORT void validate() const;
};

/// What a derivative export wrote.
struct DerivativeExportResult {
  std::string database;
  std::string format;                ///< csv, json, gazebo, matlab
  std::string form;                  ///< dimensional, prime, bis, mmg
  std::string file;                  ///< the file written
  std::string body;                  ///< the models' body
  std::vector<std::string> models;   ///< in the order given
  std::vector<std::string> outputs;  ///< each model's output X..N
  std::vector<std::string> terms;    ///< each model's terms, "v, r, v*|v|"
  std::vector<bool> stale;           ///< each model: a force of its runs changed since the fit
  std::string function_name;         ///< matlab: the function (the file's stem); "" otherwise
  std::vector<std::string> inputs;   ///< matlab: the inputs ui in order (controls, disturbances)
  std::vector<std::string> dropped;  ///< gazebo: terms left out (drop_unrepresentable)
  std::vector<std::string> notes;    ///< what the reader should know (added mass 0, Q terms, stale models)
  std::size_t bytes = 0;             ///< the file's size
  std::string content;               ///< the file's text, as written

  HYDROCOEF_EXPORT std::string text() const;  ///< what `derivatives export` prints
  HYDROCOEF_EXPORT std::string json() const;  ///< what `derivatives export --json` prints
};

/// Writes stored derivative models in a format, as `hydrocoef derivatives
/// export` (options.validate() first). InputError, one line, nothing
/// written, for an unknown model (listing the stored names), csv/json
/// reference values the form needs and lacks or a term variable without a
/// normalisation, models of several bodies or two of one output (gazebo,
/// matlab), a term the format cannot hold, a MATLAB function name that is
/// not an identifier, a mass matrix that is not one, or a path that cannot
/// be written. Never writes to the database.
HYDROCOEF_EXPORT DerivativeExportResult export_derivatives(const Database& db, const DerivativeExportOptions& options);

/// What `hydrocoef export --format openfoam-forcecoeffs -o DIR` writes: each
/// selected run's forces as the coefficient file OpenFOAM's forceCoeffs
/// function object writes (the v1912 coefficient.dat, its header and columns
/// to the byte), one per run at
/// DIR/run-<id>/postProcessing/forceCoeffs/<start time>/coefficient.dat.
///
/// Axes and signs: OpenFOAM's. The forces go back from body axes to the
/// case's axes through the map the run was imported with (import's --axes,
/// CFD axes to body axes: the one recorded with the import of its forces, or
/// `axes` here), forces on the body (the fluid's force), moments about CofR.
/// dragDir, sideDir, liftDir are the case's x, y, z (rollAxis, pitchAxis,
/// yawAxis too), so Cd = F_x / (1/2 rho U^2 A), Cs = F_y / ..., Cl = F_z / ...,
/// CmRoll = M_x / (1/2 rho U^2 A L), ... with A the body's reference area
/// (Aref), L its reference length (lRef), U = |(u, v, w)| (magUInf), rho the
/// run's density, CofR the body's moment reference point (else the run's own
/// reference point), in the case's axes. importers/openfoam_forces reads such
/// a file back into the same body-axis forces (import FILE --rho RHO --axes
/// MAP with the run's key): the writer is its inverse.
///
/// Rows: the run's force history when its stored trace holds every sample
/// (at most 256; HistoryTrace), else one row at the history's last time
/// (0 for a run imported without a history) with the run's stored forces.
struct ForceCoeffsExportOptions {
  std::string output;                      ///< the folder to write into (-o; made when missing)
  std::string body;                        ///< --body: "" every body
  std::vector<std::string> where;          ///< --where selection clauses, as for Database::runs
  std::vector<std::int64_t> exclude_runs;  ///< --exclude-run
  std::string area;                        ///< --area NAME: "" the body's default area
  /// --axes MAP: the case's axes for every run ("-x,y,-z": CFD axes to body
  /// axes, as import takes it); "" each run's own, as recorded with its import.
  std::string axes;
  /// --precision N: digits after the point (OpenFOAM's writePrecision); 16,
  /// 17 significant digits, reads back to the stored forces (see the result).
  int precision = 16;
  bool mean_only = false;  ///< --mean-only: one row with the stored forces, even with a history

  /// InputError, one line, for no output folder, a selection clause that
  /// does not parse, axes that are not a rotation of x,y,z, or a precision
  /// outside 1..16.
  HYDROCOEF_EXPORT void validate() const;
};

/// One run's file.
struct ForceCoeffsExportRun {
  std::int64_t id = 0;
  std::string body;
  std::string file;       ///< the file written
  std::string axes;       ///< the case's axes used ("-x,y,-z": CFD axes to body axes)
  std::string rows_from;  ///< "history" (the stored trace, every sample) or "stored forces" (one row)
  std::size_t rows = 0;
  double rho = 0.0;              ///< [kg/m^3] (give it to import as --rho)
  double mag_u_inf = 0.0;        ///< magUInf = |(u, v, w)| [m/s]
  double l_ref = 0.0;            ///< lRef [m]
  double a_ref = 0.0;            ///< Aref [m^2]
  std::string area_name;         ///< the body's area used as Aref
  std::array<double, 3> cofr{};  ///< [m], the case's axes
  /// Cd, Cs, Cl, CmRoll, CmPitch, CmYaw of the last row, as written.
  std::array<double, 6> last_coefficients{};
};

/// What the forceCoeffs export wrote.
struct ForceCoeffsExportResult {
  std::string database;
  std::string directory;
  int precision = 16;
  std::vector<ForceCoeffsExportRun> runs;
  /// Coefficients written (Cd..CmYaw, every row), and of them (precision 16)
  /// those the reader turns back into the force itself, and those it turns
  /// into the double next to it (no double coefficient times the reader's
  /// scale 1/2 rho U^2 A gives the force: the product skips some doubles).
  std::size_t values = 0, exact = 0, one_ulp = 0;
  std::vector<std::string> notes;

  HYDROCOEF_EXPORT std::string text() const;  ///< what `export --format openfoam-forcecoeffs` prints
  HYDROCOEF_EXPORT std::string json() const;  ///< with --json
};

/// Writes the selected runs' forceCoeffs files (options.validate() first).
/// InputError, one line, nothing written, for no run selected, a run without
/// a density, at rest (U = 0) or without one of X..N, a body without a
/// reference length or area (naming `body set`), an area the body does not
/// have, a run whose forces came from imports with different axes (naming
/// --axes), or a folder that cannot be written. Never writes to the database.
HYDROCOEF_EXPORT ForceCoeffsExportResult export_forcecoeffs(const Database& db,
                                                            const ForceCoeffsExportOptions& options);

}  // namespace api
}  // namespace hydrocoef
