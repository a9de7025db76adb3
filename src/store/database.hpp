// The run database: CFD runs keyed by body, body velocity and disturbance,
// their force components with provenance, and the damping laws fitted to
// them. The only module that speaks SQL. Every write is one transaction: a
// failure anywhere leaves the file exactly as it was.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "src/core/error.hpp"
#include "src/core/run.hpp"
#include "src/store/connection.hpp"
#include "src/store/location.hpp"

namespace hydrocoef {

namespace store {
class RunRows;  // src/store/run_rows.hpp
}

/// A force component as stored, with where it came from.
/// A force component that is a mean over a window of a force history: the
/// window, its statistics and the history's convergence flags.
struct StoredStatistics {
  std::string abscissa;       ///< "time" or "iteration"
  std::string window_method;  ///< how the window was found
  double window_first = 0.0;  ///< abscissa of the first and last averaged sample
  double window_last = 0.0;
  std::size_t samples = 0;
  std::vector<std::string> flags;  ///< this component's; empty when there is nothing to act on
  ComponentStatistics values;      ///< standard error, spread, drift, effective samples
  /// The run's convergence kind ("converged", "steady-window",
  /// "transient-window", "given-window"; "" when stored before it was
  /// recorded) and why (src/core/run.hpp RunStatistics).
  std::string convergence;
  std::string convergence_reason;
};

struct StoredForce {
  ForceComponent value;  ///< N or N m, about the run's reference point
  SignConvention sign = SignConvention::OnBody;
  std::int64_t source_id = 0;
  std::string source_path;
  std::size_t source_line = 0;
  std::int64_t import_id = 0;                  ///< the import it came from (0: none recorded)
  std::optional<StoredStatistics> statistics;  ///< when the value is a mean over a force history
  /// The numerical (discretization) standard uncertainty of the value from a
  /// mesh study of its key (hydrocoef gci: GCI_fine |phi1| / 2) when the run
  /// is on the study's finest mesh [N or N m]; empty otherwise.
  std::optional<double> numerical_uncertainty;

  /// The value's standard uncertainty [N or N m]: the standard error of a
  /// mean over a force history, an uncertainty given at import and the
  /// numerical uncertainty of a mesh study, combined in quadrature; 0 when
  /// none is known.
  double standard_uncertainty() const;
};

struct StoredRun {
  std::int64_t id = 0;
  RunKey key;
  Fluid fluid;
  std::array<double, 3> reference_point_b{};
  std::array<std::optional<StoredForce>, 6> tau_b;  ///< X..N
  std::optional<SurfaceIntegrals> surface;          ///< when the forces came from an integrated surface
};

/// The convergence flags of a run's components, each once, in the order
/// first met ("no-steady-window", "drifting", ...); empty when every averaged
/// component converged or none was averaged.
std::vector<std::string> run_flags(const StoredRun& run);

/// The disturbance parameters that say which mesh a run was computed on
/// (hydrocoef gci): the level parameter (by default "mesh", any number that
/// tells the meshes apart) and the mesh's size, either its cell count
/// (kCellCountParameter) or its representative cell size in m
/// (kCellSizeParameter). They are part of a run's key, so runs of one flow
/// condition on different meshes are different runs.
inline constexpr std::string_view kDefaultMeshParameter = "mesh";
inline constexpr std::string_view kCellCountParameter = "cells";
inline constexpr std::string_view kCellSizeParameter = "cell_size";

/// A key's disturbances without its mesh parameters (mesh_parameter, cells,
/// cell_size): what makes the flow condition, whatever the mesh.
std::map<std::string, double> physical_disturbances(const std::map<std::string, double>& disturbances,
                                                    const std::string& mesh_parameter);

/// The numerical uncertainty of one force component of one physical key from
/// a mesh study (table numerical_uncertainty, migration 11).
struct NumericalUncertaintyRecord {
  RunKey key;                 ///< the physical key: its disturbances without the mesh parameters
  std::size_t component = 0;  ///< 0..5 = X..N
  std::string mesh_parameter;
  double fine_level = 0.0;      ///< the mesh parameter's value on the finest mesh: the runs it applies to
  std::size_t levels = 0;       ///< mesh levels of the key (the three finest are used)
  std::array<double, 3> h{};    ///< representative cell sizes, fine to coarse
  std::array<double, 3> phi{};  ///< the component's values, fine to coarse
  std::string convergence;      ///< grid_convergence_name()
  std::optional<double> apparent_order, extrapolated, relative_error, extrapolated_relative_error, gci_fine;
  std::optional<double> numerical_uncertainty;  ///< GCI_fine |phi1| / 2 [N or N m]
  std::string note;
  std::string created_at;
};

/// Which runs to list. Values are compared with a tolerance of 1e-9 (SI).
struct RunFilter {
  std::optional<std::string> body;
  std::map<std::string, double> equal;    ///< velocity component or disturbance name -> value
  std::optional<std::size_t> with_force;  ///< only runs that have this component (0..5 = X..N)
};

/// What to do when a file brings a force component that a run already has
/// from another file.
enum class ConflictPolicy { Error, Replace };

/// How an import treats what the database already has.
struct ImportPolicy {
  /// A force component a run already has from another file.
  ConflictPolicy components = ConflictPolicy::Error;
  /// The same file (bytes) imported before with other settings: replace the
  /// runs of that import in the same transaction (otherwise refused).
  bool replace = false;
  /// A second, separately named reading of a file imported before (e.g.
  /// "mean" for pMean beside p); "" for the file's main reading. An identifier.
  std::string also;
};

/// One import: a file's bytes read with one set of effective settings.
struct ImportRecord {
  std::int64_t id = 0;
  std::int64_t source_id = 0;
  std::string sha256;
  std::uint64_t size_bytes = 0;
  std::string reading;        ///< "" or the --also name
  std::string settings;       ///< JSON: every setting with value, source and place
  std::string settings_key;   ///< canonical values: with the bytes, the import's identity
  std::string path;           ///< as given
  std::string resolved_path;  ///< absolute, links resolved ("" when not recorded)
  std::string importer;
  std::string importer_version;
  std::string hydrocoef_version;  ///< "" for imports older than migration 5
  std::string imported_at;
};

/// What runs delete did.
struct DeleteOutcome {
  std::size_t runs = 0;
  std::size_t components = 0;
  std::size_t fits_made_stale = 0;
  std::size_t surfaces_made_stale = 0;
  std::size_t imports_removed = 0;  ///< imports that no longer give any run
};

struct ImportOutcome {
  std::string path;
  std::string sha256;
  bool already_imported = false;  ///< the same bytes with the same settings were imported before: nothing added
  bool replaced = false;          ///< an import of the same bytes with other settings was replaced (--replace)
  std::int64_t import_id = 0;
  std::string reading;                 ///< "" or the --also name
  std::string previously_imported_at;  ///< when already_imported
  std::string previous_path;           ///< when already_imported
  std::size_t runs_created = 0;
  std::size_t runs_extended = 0;  ///< existing runs that gained components
  std::size_t components_written = 0;
};

struct SourceRecord {
  std::int64_t id = 0;
  Provenance provenance;
  std::string imported_at;
};

/// A fitted damping law as stored: plain numbers and names, no fitting code.
struct FitRecord {
  struct Coefficient {
    std::string term;
    double value = 0.0;
    std::optional<double> std_error;
  };
  std::int64_t id = 0;
  std::string name;
  std::string body;
  std::string dof;       ///< X..N
  std::string variable;  ///< u..r
  std::string terms;     ///< e.g. "1,u,u|u|"
  std::string loss;
  std::string run_filter;
  std::string mirror;  ///< planes of symmetry whose mirror images were used ("" none; src/pipeline/fit_runs)
  SignConvention sign = SignConvention::OnBody;
  std::size_t n = 0;
  double rmse = 0.0;
  double r2 = 0.0;
  /// "none", or "uncertainty": each run weighted by its standard
  /// uncertainty (StoredForce::standard_uncertainty; src/fit/damping_law.hpp).
  std::string weighting = "none";
  std::optional<double> chi2_reduced;  ///< weighted fits with n > k
  /// The coefficients' covariance, k x k row by row; empty when not recorded.
  std::vector<double> covariance;
  std::string created_at;
  bool stale = false;  ///< a force of a run it was built from changed or was deleted since
  std::vector<Coefficient> coefficients;
  std::vector<std::int64_t> run_ids;
};

/// The largest surface a database may hold: values in its data blob, and
/// bytes of its definition or quality JSON. Larger records in a received
/// database are refused before anything is allocated for them.
inline constexpr std::size_t kMaxSurfaceValues = std::size_t{1} << 26;
inline constexpr std::size_t kMaxSurfaceDefinitionBytes = std::size_t{1} << 26;

/// A coefficient surface as stored: what src/surface needs to rebuild it,
/// as plain data (the store knows no interpolation).
struct SurfaceRecord {
  std::int64_t id = 0;
  std::string name;
  std::string body;
  std::string kind;          ///< "grid", "rbf" or "gp"
  std::string method;        ///< e.g. "pchip", or the RBF kernel
  std::string definition;    ///< JSON: axes, breakpoints, outputs, units, options
  std::vector<double> data;  ///< values in the layout the definition states
  std::string quality;       ///< JSON: leave-one-out max and RMS per output
  std::string created_at;
  bool stale = false;  ///< a force of the body changed since the surface was built
  std::vector<std::int64_t> run_ids;
  std::string database;  ///< the file it was read from, for messages ("" when not read from one)
};

struct PmmRecord;
struct PmmSaved;
struct DerivativeModelRecord;  // src/store/derivative_store.hpp
struct PmmDeleted;
struct BodyReferenceRecord;  // src/store/body_reference.hpp

/// What merging one shard did (RunDatabase::merge).
struct MergeOutcome {
  std::string shard;                ///< its location
  std::size_t imports_added = 0;    ///< imports (a file's bytes with its settings) new here
  std::size_t imports_already = 0;  ///< imports here before: nothing of them added
  std::size_t runs_created = 0;
  std::size_t runs_extended = 0;  ///< runs here before that gained components
  std::size_t components = 0;     ///< force components added
  std::size_t fits_added = 0, fits_already = 0;
  std::size_t surfaces_added = 0, surfaces_already = 0;
  std::size_t mesh_studies_added = 0, mesh_studies_already = 0;  ///< rows of numerical uncertainty
  std::size_t pmm_added = 0, pmm_already = 0;                    ///< forced-oscillation analyses
  std::size_t body_references_added = 0, body_references_already = 0;
  std::size_t derivative_models_added = 0, derivative_models_already = 0;
};

class RunDatabase {
 public:
  /// CreateIfMissing and MustExist open for writing; ReadOnly never writes
  /// (a database on a read-only share or in a read-only folder is read as
  /// immutable when SQLite cannot make its -shm file there, and refused when
  /// a -wal file beside it would then go unread). A ReadOnly database of an
  /// older schema is not upgraded: an SQLite file is read through a private
  /// upgraded copy (deleted on close), a PostgreSQL database is refused.
  enum class OpenMode { CreateIfMissing, MustExist, ReadOnly };

  /// Opens the database and brings its schema up to date (schema/ migrations,
  /// recorded in PRAGMA user_version). A received database is untrusted: it
  /// is refused with InputError (one line naming the file and what is wrong)
  /// when the file is not an SQLite database, fails its integrity check,
  /// belongs to another program, has a schema version outside 0..latest or
  /// a schema that is not exactly the one the migrations create for its
  /// version (an added trigger, view or index, a dropped column), or was
  /// written by a newer hydrocoef. Several processes may open a new file at
  /// once: the migration re-reads the version inside its transaction.
  ///
  /// `path` may also be a location (src/store/location.hpp): "sqlite:PATH",
  /// or a "postgresql://" URL. A PostgreSQL database is checked the same way
  /// (its schema, every value read) and behaves the same: each write is one
  /// transaction, writers wait for each other (HYDROCOEF_DB_TIMEOUT).
  explicit RunDatabase(const std::filesystem::path& path, OpenMode mode = OpenMode::CreateIfMissing);
  RunDatabase(const store::DatabaseLocation& location, OpenMode mode);

  /// The migration number the database is at.
  int schema_version();
  /// The migration number the database was at when opened (before it was
  /// brought up to date; a read-only database is upgraded only in a private
  /// copy, see OpenMode).
  int opened_at_version() const { return opened_at_version_; }
  /// The number of migrations this build knows.
  static int latest_schema_version();

  /// Imports batches in one transaction. A batch whose file (by SHA-256) is
  /// already in the database adds nothing and says so in its outcome. Throws
  /// InputError on a conflict (policy Error), leaving the database unchanged.
  std::vector<ImportOutcome> import(const std::vector<ImportBatch>& batches, ConflictPolicy policy);
  /// The same, with the identity of an import: a file's bytes and its
  /// effective settings (Provenance::settings_key). The same bytes with the
  /// same settings add nothing and say so; with other settings they are
  /// refused (InputError naming the earlier import and the settings that
  /// differ), replaced (options.replace) or kept as another reading
  /// (options.also).
  std::vector<ImportOutcome> import(const std::vector<ImportBatch>& batches, const ImportPolicy& options);

  /// Deletes runs (their force components, surface records and
  /// disturbances) in one transaction; fits and surfaces built from them
  /// become stale; imports and files that no longer give a run are removed.
  /// InputError, deleting nothing, for an id that is not a run.
  DeleteOutcome delete_runs(const std::vector<std::int64_t>& ids);
  /// One import, for a run's provenance.
  std::optional<ImportRecord> import_record(std::int64_t id);

  std::vector<StoredRun> runs(const RunFilter& filter = {});
  std::optional<StoredRun> find_run(const RunKey& key);
  std::vector<SourceRecord> sources();
  std::vector<std::string> bodies();

  /// What to do with a fit whose name is taken.
  enum class NameTaken { Refuse, Replace };
  /// Stores a fit; returns its id. A fit of the same name is replaced with
  /// NameTaken::Replace, else an InputError names it (nothing stored).
  std::int64_t save_fit(const FitRecord& fit, NameTaken taken = NameTaken::Refuse);
  /// Stores several fits in one transaction (all or none); returns their ids.
  std::vector<std::int64_t> save_fits(const std::vector<FitRecord>& fits, NameTaken taken = NameTaken::Refuse);
  std::vector<FitRecord> fits(const std::optional<std::string>& body = std::nullopt);

  /// Stores a derivative model (src/store/derivative_store.hpp) in one
  /// transaction; returns its id. A model of the same name is replaced with
  /// NameTaken::Replace, else an InputError names it (nothing stored).
  std::int64_t save_derivative_model(const DerivativeModelRecord& model, NameTaken taken = NameTaken::Refuse);
  /// The stored derivative models of a body (all when empty), by name.
  std::vector<DerivativeModelRecord> derivative_models(const std::optional<std::string>& body = std::nullopt);
  /// Deletes the derivative model of this name in one transaction;
  /// InputError listing the stored names when there is none.
  void delete_derivative_model(const std::string& name);

  /// Stores a surface, replacing one of the same name (which clears its
  /// stale flag); returns its id.
  std::int64_t save_surface(const SurfaceRecord& surface);
  /// All surfaces (data included), or those of one body, by name.
  std::vector<SurfaceRecord> surfaces(const std::optional<std::string>& body = std::nullopt);
  /// One surface by name; InputError listing the names there are when absent.
  SurfaceRecord surface(const std::string& name);

  /// Stores mesh-study results in one transaction: the rows of each key
  /// (body and physical key) in `records` replace what was stored for it.
  /// Fits of a force whose numerical uncertainty changes, and the surfaces
  /// of its body, become stale.
  void save_numerical_uncertainties(const std::vector<NumericalUncertaintyRecord>& records);
  /// The stored mesh-study results of a body (all bodies when empty), by key and component.
  std::vector<NumericalUncertaintyRecord> numerical_uncertainties(
      const std::optional<std::string>& body = std::nullopt);

  /// A run's force history in brief (schema/0016_run_force_trace.sql), as
  /// its latest history import left it; nullopt for a run imported from a
  /// table, or stored before traces were kept. InputError naming the table
  /// and row when the stored trace is damaged (src/history/history_trace.hpp
  /// trace_problem).
  std::optional<HistoryTrace> run_trace(std::int64_t run_id);

  /// Stores forced-oscillation analyses in one transaction (all or none);
  /// the same file analysed with the same motion replaces its earlier rows.
  /// The bodies are created when missing. (PmmRecord: src/store/pmm_record.hpp.)
  std::vector<PmmSaved> save_pmm(const std::vector<PmmRecord>& records);
  /// The stored forced-oscillation analyses of a body (all bodies when
  /// empty), by body, degree of freedom, frequency and amplitude; with
  /// `with_history` false their history blobs are left empty.
  std::vector<PmmRecord> pmm_records(const std::optional<std::string>& body = std::nullopt, bool with_history = true);
  /// Deletes forced-oscillation analyses (pmm_run rows and their
  /// coefficients) by id in one transaction; an id that is not stored is
  /// refused (InputError) and nothing is deleted. The rows are not read
  /// through the checked readers, so a record that every reader refuses can
  /// still be removed. Returns what was deleted, in the order given.
  std::vector<PmmDeleted> delete_pmm_runs(const std::vector<std::int64_t>& ids);

  /// Stores a body's reference data (schema/0017_body_reference.sql),
  /// replacing what it had, in one transaction. InputError naming the body
  /// when there is no body of that name (the bodies there are listed) or the
  /// record has a problem (BodyReferenceRecord::problem).
  void save_body_reference(const BodyReferenceRecord& record);
  /// The reference data of one body, or of every body that has some (by
  /// name); a body without any is absent. Every value is checked: a damaged
  /// row is refused naming its table and row.
  std::vector<BodyReferenceRecord> body_references(const std::optional<std::string>& body = std::nullopt);

  /// Merges shard databases (any locations: SQLite files made by cluster
  /// jobs, or PostgreSQL databases) into this one, in one transaction: their
  /// files, imports (with their provenance as recorded: paths, settings,
  /// times, versions), runs, force components with statistics, surface
  /// integrals, mesh studies, forced-oscillation analyses, fits, surfaces and derivative models
  /// (their run ids mapped to the runs here). What is here already adds
  /// nothing, so merging twice changes nothing. A conflict is refused as an
  /// import would refuse it (a component of a run from two files, a file
  /// imported with other settings, a fit or surface of one name that
  /// differs), with InputError naming the shard; nothing is then merged.
  /// `progress` (may be empty) is called after each shard.
  std::vector<MergeOutcome> merge(const std::vector<std::string>& shards,
                                  const std::function<void(std::size_t done, std::size_t total)>& progress = {});
  /// Copies every row of `source` into this database, which must be empty
  /// (InputError otherwise), ids and flags as they are, in one transaction;
  /// returns the rows copied per table. Between backends, a copy and a copy
  /// back hold the same rows as the original.
  std::vector<std::pair<std::string, std::size_t>> copy_from(RunDatabase& source);

  /// "ok", or SQLite's list of problems ("ok" on PostgreSQL, whose server keeps its pages whole).
  std::string integrity_check();
  /// True when the database was opened read-only (OpenMode::ReadOnly).
  bool read_only() const { return read_only_; }
  /// The file, or the PostgreSQL URL (how messages name the database).
  const std::filesystem::path& path() const { return path_; }
  store::Backend backend() const { return connection_.backend(); }

 private:
  void migrate();
  MergeOutcome merge_one(RunDatabase& shard);
  /// Switches the file to WAL mode, after a write has committed.
  void use_wal();
  /// The stored schema version, refused unless 0..latest.
  int checked_schema_version();
  /// Refuses a schema that is not the one migrations 1..version create.
  void check_schema(int version);
  std::int64_t body_id(const std::string& name, bool create);
  /// Removes the force components an import gave, and the runs left with none.
  void remove_import_forces(std::int64_t import_id);
  /// Inserts one fit (replacing one of its name) inside the caller's transaction.
  std::int64_t insert_fit(const FitRecord& fit);
  std::optional<std::int64_t> find_run_id(std::int64_t body, const RunKey& key);
  /// The run of `key`, its body made when new: an existing run's fluid and
  /// reference point are checked against what is stored and fill what it
  /// lacked (store::RunRows::check_and_fill), a new one is inserted. Its id,
  /// and whether it is new. (Imports and merges.)
  std::pair<std::int64_t, bool> find_or_insert_run(store::RunRows& rows, const RunKey& key, const Fluid& fluid,
                                                   const std::array<double, 3>& reference_point_b,
                                                   const SourceLocation& where);
  /// All runs, or those of one body, or one run; ordered by body and key.
  std::vector<StoredRun> load_runs(std::optional<std::int64_t> body, std::optional<std::int64_t> run);
  /// Sets the numerical uncertainty of the forces of runs on the finest mesh
  /// of a stored mesh study of their key.
  void apply_numerical_uncertainties(std::vector<StoredRun>& runs);
  /// The id of a body that must exist (InputError naming it otherwise).
  std::int64_t existing_body_id(const std::string& name);
  /// Records / reads the runs a fit or surface was built from, in a link
  /// table (fit_run, surface_run) whose owner column is `owner`.
  void link_runs(const char* table, const char* owner, std::int64_t id, const std::vector<std::int64_t>& run_ids);
  std::vector<std::int64_t> linked_runs(const char* table, const char* owner, std::int64_t id);
  /// Merges the shard's body reference data (merge_one).
  void merge_body_references(RunDatabase& shard, MergeOutcome& outcome);
  /// Surfaces of one body and/or one name (both optional), by name.
  std::vector<SurfaceRecord> load_surfaces(const std::optional<std::string>& body,
                                           const std::optional<std::string>& name);

  std::filesystem::path path_;
  store::Connection connection_;
  bool read_only_ = false;
  int opened_at_version_ = 0;
};

/// Now as UTC ISO 8601 ("2026-11-22T10:04:05Z").
std::string utc_timestamp_now();

}  // namespace hydrocoef
