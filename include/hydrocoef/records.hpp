// The records of a run database and what is done to them, as the commands
// `hydrocoef import`, `runs` (list, show, delete), `fit` (a law, per-level
// fits, refits), `fits` (list, evaluate), `merge`, `copy`, `migrate` and
// `report` do them: each command parses its options into the options types
// here (or in hydrocoef/database.hpp), calls one function, and prints the
// result's text() or, with --json, its json(). So C++, Python and the CLI
// give the same numbers.
//
// Units and frames as in hydrocoef/database.hpp: SI; body axes x forward, y
// starboard, z down; velocity u, v, w [m/s], p, q, r [rad/s]; forces X, Y, Z
// [N], K, M, N [N m] on the body unless a record says otherwise (a fit's
// sign_convention "opposing": a damping magnitude, positive opposes motion).
//
// Errors: bad input (an option, a name that is not there, a file that cannot
// be read) is an InputError with the message the command-line tool prints;
// every write is one transaction, and a read-only Database refuses writes
// before anything is read or written.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "hydrocoef/database.hpp"
#include "hydrocoef/export.hpp"

namespace hydrocoef {
inline namespace api {

// ---- import in two steps ----------------------------------------------------

/// Inputs planned and read, not yet stored: what prepare_import returns and
/// import_prepared stores. Move-only.
class HYDROCOEF_EXPORT PreparedImport {
 public:
  PreparedImport(PreparedImport&&) noexcept;
  PreparedImport& operator=(PreparedImport&&) noexcept;
  ~PreparedImport();

  struct Impl;    ///< the library's own
  struct Access;  ///< the library's own

 private:
  explicit PreparedImport(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

/// Plans and reads every input as Database::import_files does, touching no
/// database: a bad input is an InputError before one is opened (or made).
HYDROCOEF_EXPORT PreparedImport prepare_import(const std::vector<std::string>& paths,
                                               const ImportOptions& options = {});
/// Stores what prepare_import read, in one transaction. InputError for a
/// conflict (the database is then as it was), a read-only or closed
/// database, or a PreparedImport stored before.
HYDROCOEF_EXPORT ImportSummary import_prepared(Database& database, PreparedImport&& prepared);

// ---- runs show, runs delete --------------------------------------------------

/// An import a run's forces came from (`hydrocoef runs show`).
struct RunImport {
  std::int64_t id = 0;
  std::string path;         ///< as given at import
  std::string sha256;       ///< of the file's bytes
  std::string importer;     ///< e.g. "table"
  std::string imported_at;  ///< UTC, ISO 8601
  std::string reading;      ///< "" or the --also name
};

/// One run with its provenance: `hydrocoef runs show ID`.
struct HYDROCOEF_EXPORT RunDetails {
  std::int64_t id = 0;
  std::string body;
  std::array<double, 6> velocity{};  ///< u, v, w [m/s], p, q, r [rad/s]
  std::map<std::string, double> disturbances;
  /// X..N [N, N m] as stored (see sign_convention); NaN where the run has no such component.
  std::array<double, 6> force{};
  /// Standard error of a mean over a force history [N, N m]; NaN where none.
  std::array<double, 6> force_std_error{};
  std::array<std::string, 6> sign_convention;  ///< "on-body" or "opposing"; "" where no component
  std::array<std::string, 6> source;           ///< the file each component came from; "" where none
  double density = 0.0;                        ///< [kg m^-3]; NaN when not given
  double kinematic_viscosity = 0.0;            ///< [m^2 s^-1]; NaN when not given
  std::array<double, 3> reference_point{};     ///< moment reference point [m], body axes
  std::vector<std::string> flags;              ///< the history's convergence flags
  std::vector<RunImport> imports;

  std::string text() const;
  std::string json() const;

  struct Access;  ///< the library's own

 private:
  std::string text_, json_;
};

/// The run of this id. InputError "DB: no run ID; ..." when there is none.
HYDROCOEF_EXPORT RunDetails show_run(const Database& database, std::int64_t id);

/// Which runs `hydrocoef runs delete` removes: those named by id, and those
/// `where`/`source` select (of `body` when given).
struct HYDROCOEF_EXPORT DeleteRunsOptions {
  std::vector<std::int64_t> ids;
  std::string body;                        ///< "" every body
  std::vector<std::string> where;          ///< selection clauses, as for runs()
  std::vector<std::int64_t> exclude_runs;  ///< left out of the selection
  /// Runs with a force component from this file (the path as stored, or the
  /// same file by canonical path); "" none.
  std::string source;

  /// InputError for a selection clause that does not parse.
  void validate() const;
};

struct HYDROCOEF_EXPORT DeleteSummary {
  std::string database;
  std::size_t runs = 0;
  std::size_t components = 0;  ///< force components deleted
  std::size_t fits_made_stale = 0;
  std::size_t surfaces_made_stale = 0;
  std::size_t imports_removed = 0;  ///< imports that no longer give any run

  std::string text() const;
  std::string json() const;
};

/// Deletes the runs in one transaction; fits and surfaces built from them
/// become stale. InputError (nothing deleted) when nothing is selected, a
/// selection matches no run, or an id is not a run.
HYDROCOEF_EXPORT DeleteSummary delete_runs(Database& database, const DeleteRunsOptions& options);

// ---- fits: per level, refit, list, evaluate ------------------------------------

/// The law fitted at one level of FitOptions::by.
struct LevelFitSummary {
  double level = 0.0;  ///< [SI of `by`]
  std::string name;    ///< BASE[by=LEVEL]
  std::size_t n = 0;
  double rmse = 0.0;
  double r2 = 0.0;  ///< NaN when the force does not vary over the level's runs
  std::vector<FitCoefficient> coefficients;
  std::int64_t id = 0;  ///< 0 when not stored
};

/// A level left out (too few runs for the law).
struct SkippedFitLevel {
  double level = 0.0;
  std::size_t runs = 0;
  std::string reason;
};

/// One coefficient as a curve of the level.
struct LevelCurve {
  std::string term;
  std::string kind;                ///< "polynomial" or "pchip"
  int degree = 0;                  ///< of the polynomial (3 for pchip)
  std::vector<double> polynomial;  ///< a_0 + a_1 x + ... (polynomial)
  std::vector<double> levels;      ///< the levels fitted
  std::vector<double> values;      ///< the coefficient at each level
  double rmse = 0.0;               ///< of the curve through the values
  std::string unit;                ///< the coefficient's unit
};

/// What `hydrocoef fit --by` makes.
struct HYDROCOEF_EXPORT LevelFits {
  std::string name;  ///< the base name; each level's is BASE[by=LEVEL]
  std::string body;
  std::string output;
  std::string variable;
  std::string terms;
  std::string by;
  std::string curve;
  std::string where;
  std::string sign_convention;
  std::vector<LevelFitSummary> levels;
  std::vector<SkippedFitLevel> skipped;
  std::vector<LevelCurve> curves;
  std::vector<std::string> warnings;  ///< "kind: message"
  bool stored = false;

  std::string text() const;
  std::string json() const;

  struct Access;  ///< the library's own

 private:
  std::string text_, json_;
};

/// Fits the law at each level of options.by, then each coefficient as a
/// curve of the level, storing the per-level fits (unless options.store is
/// false). InputError as Database::fit, and for a bad --by or --curve.
HYDROCOEF_EXPORT LevelFits fit_by_level(Database& database, const FitOptions& options);

/// What `hydrocoef fit --refit` did: each fit as it was and as made again.
struct HYDROCOEF_EXPORT Refits {
  std::string database;
  std::vector<FitSummary> previous;
  std::vector<FitSummary> made;

  std::string text() const;
  std::string json() const;
};

/// Stored fits made again from the runs their selections pick now: the one
/// options.name names, else every stale one (of options.body when given);
/// stored, replacing them. Only name and body may be set in options.
HYDROCOEF_EXPORT Refits refit_fits(Database& database, const FitOptions& options);

/// The stored fits, as `hydrocoef fits` lists them.
struct HYDROCOEF_EXPORT FitList {
  std::string database;
  std::vector<FitSummary> fits;  ///< by name

  std::string text() const;
  std::string json() const;
};

/// The stored fits of one body (all when body is "").
HYDROCOEF_EXPORT FitList list_fits(const Database& database, const std::string& body = "");

/// Where to evaluate a stored fit's law: `hydrocoef fits evaluate NAME --at X`.
struct HYDROCOEF_EXPORT FitEvaluationOptions {
  std::string name;        ///< the stored fit
  std::vector<double> at;  ///< values of the law's velocity component [m/s or rad/s]

  /// InputError when the name is empty, no value is given, or one is not finite.
  void validate() const;
};

/// A stored law at given velocities, with the standard error of its value
/// from the coefficients' covariance C: sqrt(b(x)^T C b(x)), b(x) the law's
/// terms at x. Values in the fit's sign convention.
struct HYDROCOEF_EXPORT FitEvaluation {
  std::string name;
  std::string output;           ///< X..N
  std::string variable;         ///< u..r
  std::string sign_convention;  ///< "on-body" or "opposing"
  std::string unit;             ///< of value and std_error: "N" or "N m"
  std::string variable_unit;    ///< of at: "m/s" or "rad/s"
  std::vector<double> at;
  std::vector<double> value;
  /// One sigma; NaN when the fit has no covariance (made by an older
  /// hydrocoef) or it is undefined (as many runs as terms).
  std::vector<double> std_error;
  /// The range of the variable over the fit's runs; values outside it are extrapolations.
  double fitted_min = 0.0, fitted_max = 0.0;
  bool stale = false;

  std::string text() const;
  std::string json() const;
};

/// InputError listing the stored fits when there is none of that name.
HYDROCOEF_EXPORT FitEvaluation evaluate_fit(const Database& database, const FitEvaluationOptions& options);

// ---- merge, copy, migrate ------------------------------------------------------

struct HYDROCOEF_EXPORT MergeOptions {
  /// Shard databases: SQLite paths, sqlite:PATH or postgresql:// URLs.
  std::vector<std::string> shards;
  /// Called after each shard is read (may be empty): shards done, shards in all.
  std::function<void(std::size_t done, std::size_t total)> progress;

  /// InputError when no shard is given.
  void validate() const;
};

/// What merging one shard added.
struct MergedShard {
  std::string shard;
  std::size_t imports_added = 0, imports_already = 0;
  std::size_t runs_created = 0, runs_extended = 0;
  std::size_t components = 0;  ///< force components added
  std::size_t fits_added = 0, fits_already = 0;
  std::size_t surfaces_added = 0, surfaces_already = 0;
  std::size_t mesh_studies_added = 0, mesh_studies_already = 0;
  std::size_t pmm_added = 0, pmm_already = 0;
  std::size_t body_references_added = 0, body_references_already = 0;  ///< bodies' reference data
  std::size_t derivative_models_added = 0, derivative_models_already = 0;
};

struct HYDROCOEF_EXPORT MergeSummary {
  std::string into;  ///< the database merged into
  std::vector<MergedShard> shards;

  std::string text() const;
  std::string json() const;
};

/// Merges the shards into `into` in one transaction (`hydrocoef merge`).
/// What is there already adds nothing; a conflict is refused naming the
/// shard, and nothing is merged.
HYDROCOEF_EXPORT MergeSummary merge_databases(Database& into, const MergeOptions& options);

struct HYDROCOEF_EXPORT CopySummary {
  std::string from, to;
  std::vector<std::pair<std::string, std::size_t>> rows;  ///< rows copied, by table

  std::string text() const;
  std::string json() const;
};

/// Copies every row of `from` into the empty database `to`, ids included, in
/// one transaction (`hydrocoef copy`). InputError when `to` is not empty or
/// is `from`.
HYDROCOEF_EXPORT CopySummary copy_database(const Database& from, Database& to);

struct HYDROCOEF_EXPORT MigrationSummary {
  std::string database;
  int from = 0;  ///< the schema version the database was at when opened
  int to = 0;    ///< its version now

  std::string text() const;
  std::string json() const;
};

/// The schema versions of a database opened for writing (which brings it up
/// to date): `hydrocoef migrate`.
HYDROCOEF_EXPORT MigrationSummary migration(const Database& database);

// ---- report ----------------------------------------------------------------------

/// `hydrocoef report`: one self-contained HTML page of the database.
struct HYDROCOEF_EXPORT ReportOptions {
  std::string output;                      ///< directory for index.html and plots/ (created if needed)
  std::string body;                        ///< "" every body
  std::vector<std::string> where;          ///< selection clauses: only these runs, and what is built from them
  std::vector<std::int64_t> exclude_runs;  ///< run ids left out
  std::vector<std::string> trajectories;   ///< simulated trajectory CSVs to plot
  std::string experiment;                  ///< a measured CSV overlaid on them ("" none)
  std::string component = "r";             ///< velocity component drawn for trajectories

  /// InputError for an empty output directory or a selection clause that does not parse.
  void validate() const;
};

struct HYDROCOEF_EXPORT ReportSummary {
  std::string database;
  std::string index;               ///< OUTPUT/index.html
  std::vector<std::string> plots;  ///< the SVG files embedded
  std::vector<std::string> notes;  ///< plots that could not be drawn, and why
  std::size_t runs = 0, fits = 0, surfaces = 0;
  std::size_t histories = 0;   ///< runs' history figures drawn
  std::size_t sigma_maps = 0;  ///< surfaces' standard-deviation figures drawn
  std::size_t mesh_study_rows = 0;
  std::size_t pmm_fits = 0;

  std::string text() const;
  std::string json() const;
};

/// Writes the report. InputError when the database (or the body) has no
/// runs, or a file cannot be written.
HYDROCOEF_EXPORT ReportSummary write_report(const Database& database, const ReportOptions& options);

}  // namespace api
}  // namespace hydrocoef
