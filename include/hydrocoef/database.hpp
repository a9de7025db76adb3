// A hydrocoef run database (an SQLite file): CFD runs keyed by body, body
// velocity and disturbance, with their forces and provenance; the damping laws
// fitted to them; the coefficient surfaces built from them. This is what the
// `hydrocoef` command-line tool reads and writes (--db), through the same
// library calls: an import, a fit or a query here gives what the same command
// gives.
//
// Units and frames: SI everywhere. Body axes after Fossen/SNAME (x forward, y
// starboard, z down). Velocity u, v, w [m/s], p, q, r [rad/s], of the body
// through the water, in body axes. Generalized force X, Y, Z [N], K, M, N
// [N m], in body axes about the run's reference point, signed as the force the
// fluid exerts on the body (a damping force opposes the motion: X < 0 for
// u > 0), unless a record says otherwise (FitSummary::sign_convention).
//
// Errors: bad input (a file that cannot be read, a bad option, a selection
// clause that does not parse, a damaged or foreign database, a name that is
// not there) is an InputError with the message the command-line tool prints.
// Every write is one transaction: after an exception the file is as it was.
//
// A Database may be used from several threads; its calls are serialized. A
// received database is untrusted input: it is checked on open (integrity,
// schema, every value read back).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hydrocoef/error.hpp"
#include "hydrocoef/export.hpp"
#include "hydrocoef/surface.hpp"

namespace hydrocoef {
inline namespace api {

/// How Database::open treats the file.
enum class OpenMode {
  ReadOnly,   ///< never writes (a database on a read-only share is read as immutable)
  ReadWrite,  ///< the file must exist; its schema is brought up to date
  Create      ///< as ReadWrite, and a new empty database is made when the file is missing
};

/// Runs as columns: entry i of every column is run i. Runs are ordered by
/// body and key, as `hydrocoef runs` lists them.
struct HYDROCOEF_EXPORT RunTable {
  std::vector<std::int64_t> id;  ///< the run's id in the database
  std::vector<std::string> body;
  /// u, v, w [m/s], p, q, r [rad/s]: the run's body velocity (0 where the run does not state it).
  std::array<std::vector<double>, 6> velocity;
  /// X, Y, Z [N], K, M, N [N m]: forces on the body (a damping magnitude
  /// imported with sign "opposing" is negated); NaN where the run has no such component.
  std::array<std::vector<double>, 6> force;
  /// Standard error of each force component's mean over its force history
  /// (corrected for autocorrelation) [N, N m]; NaN where the component is not
  /// such a mean or the run has no such component.
  std::array<std::vector<double>, 6> force_std_error;
  /// Disturbance parameters by name [SI]; NaN for a run without that disturbance.
  std::map<std::string, std::vector<double>> disturbances;
  /// The files the run's components came from, ';'-separated, as given at import.
  std::vector<std::string> source;
  /// The force history's convergence flags, ','-separated ("no-steady-window",
  /// "drifting", ...); "" when every averaged component converged or none was averaged.
  std::vector<std::string> history_flags;

  std::size_t size() const noexcept { return id.size(); }

  /// What `hydrocoef runs` prints: the table (text), every run with its
  /// fluid, reference point, forces and statistics (json), or the CSV (csv).
  std::string text() const;
  std::string json() const;
  std::string csv() const;

  struct Rendering;  ///< the library's own: the runs as read, for text(), json() and csv()
  struct Access;     ///< the library's own

 private:
  std::shared_ptr<const Rendering> rendering_;
};

/// How Database::import_files reads its inputs: the options of `hydrocoef import`.
struct HYDROCOEF_EXPORT ImportOptions {
  /// auto (by extension and content), table, monitor, history, cfdpost, vtk,
  /// cfx-out, or captive-table (never chosen by auto).
  std::string format = "auto";
  /// The body of runs whose settings name none ("" : "vehicle", as the CLI).
  std::string body;
  /// Run settings, as a sidecar file `hydrocoef-run.json` holds them, taking
  /// precedence over every other source (as the CLI's options do): keys
  /// body, u v w p q r, flow, disturbances, rho, nu, p_ref, ref_point, cofr,
  /// axes, origin, pressure, shear, pressure_kind, shear_convention,
  /// length_unit, pressure_unit, normals, locations, window, symmetry, sign,
  /// at_rest ("true": the body is at rest; a run whose velocity nothing gives
  /// is otherwise refused) (see the README). Each value is JSON ("998.2", "[0, 0, 0.1]",
  /// "{\"current_v\": 0.05}"), or a plain text when it is not JSON
  /// ("-x,y,-z", "opposing"); quote a text that would read as JSON ("\"1\"").
  std::map<std::string, std::string> settings;
  /// Tables and force histories: component -> header (e.g. X -> "Drag").
  std::map<std::string, std::string> columns;
  /// Unit of a column without one, name -> unit (e.g. X -> "kN").
  std::map<std::string, std::string> units;
  /// Tables: headers holding a disturbance parameter; headers to skip.
  std::vector<std::string> disturbance_columns;
  std::vector<std::string> ignored_columns;
  /// CFX monitors: component -> monitor column; average the last N iterations (1: the steady window).
  std::map<std::string, std::string> monitors;
  std::size_t average_last = 1;
  /// Folders: import only files matching one of `include` (globs), leaving out those matching `exclude`.
  std::vector<std::string> include;
  std::vector<std::string> exclude;
  /// Run keys from file or folder names, e.g. "u{u}_v{v}" ("" none).
  std::string key_from_name;
  /// A sweep manifest: CSV of path and key columns ("" none).
  std::string manifest;
  /// Read sidecar files (FILE.json, hydrocoef-run.json in the folders above).
  bool use_sidecars = true;
  /// Of a force history and surface exports of one run, import the surfaces.
  bool prefer_surfaces = false;
  /// Replace the runs of an earlier import of the same file with other
  /// settings, and supersede components runs already have from other files.
  bool replace = false;
  /// Keep this as a second, named reading of a file imported before (an identifier; "" none).
  std::string also;
  /// Inputs read in parallel (0: every core).
  unsigned jobs = 0;

  /// Run settings as the options of `hydrocoef import` give them (unset: not
  /// given), each checked as the CLI checks it and refused naming the option
  /// (e.g. "--rho: expected a finite number"). They stand beside `settings`:
  /// a setting given both ways is refused.
  std::vector<std::string> locations;           ///< --location: patches, zones, [Name]s integrated
  std::optional<std::string> pressure;          ///< --pressure: pressure array
  std::optional<std::string> shear;             ///< --shear: a vector array, three arrays x,y,z, or "none"
  std::optional<std::string> pressure_kind;     ///< --pressure-kind: static or kinematic
  std::optional<std::string> shear_convention;  ///< --shear-convention: on-wall or on-fluid
  std::optional<double> rho;                    ///< --rho [kg m^-3]
  std::optional<double> nu;                     ///< --nu [m^2 s^-1]
  std::optional<double> p_ref;                  ///< --p-ref [Pa]
  std::optional<std::string> ref_point;         ///< --ref-point "x,y,z" [m], body axes
  std::optional<std::string> length_unit;       ///< --length-unit
  std::optional<std::string> pressure_unit;     ///< --pressure-unit
  std::optional<std::string> axes;              ///< --axes: body axes in CFD axes, e.g. "-x,y,-z"
  std::optional<std::string> origin;            ///< --origin "x,y,z" [m], CFD coordinates
  std::optional<std::string> flow;              ///< --flow "x,y,z" [m/s], free stream in CFD axes
  std::optional<std::string> normals;           ///< --normals: auto, as-given or flip
  std::optional<std::string> symmetry;          ///< --symmetry, e.g. "y=0"
  std::optional<std::string> window;            ///< --window: auto, T0:T1 or last:N
  std::optional<std::string> sign;              ///< --sign: on-body or opposing
  std::vector<std::string> uncertainty;         ///< --uncertainty "X=0.01", "N=2%"
  std::vector<std::string> set;                 ///< --set "NAME=VALUE": run key (velocity or disturbance, SI)
  bool at_rest = false;                         ///< --at-rest
  /// Captive-test tables (format captive-table; docs/importing.md): the form
  /// of their non-dimensional forces and the reference values it needs, SI,
  /// taking precedence over the table's own `# NAME = VALUE` lines; each
  /// refused with any other format. `density` is --rho by another name (one or
  /// the other).
  std::optional<std::string> form;              ///< --form: prime, bis or mmg
  std::optional<std::string> drift_convention;  ///< --drift-convention: mmg (v = -U sin beta) or fossen
  std::optional<double> length;                 ///< --length L [m]
  std::optional<double> speed;                  ///< --speed U [m/s], for a table without a speed column
  std::optional<double> density;                ///< --density [kg m^-3]
  std::optional<double> draft;                  ///< --draft d [m] (mmg)
  std::optional<double> mass;                   ///< --mass m [kg] (bis)
  std::optional<double> volume;                 ///< --volume [m^3] (bis without a mass: m = rho volume)
  std::optional<double> gravity;                ///< --gravity g [m s^-2] (bis, Fn; default 9.80665)
  /// Captive-test tables: a database whose bodies' reference data (`body
  /// set`: length, draft, volume) stand in for values neither the options nor
  /// the table give ("" none; Database::import_files uses its own). One that
  /// cannot be opened read-only is passed over.
  std::string reference_database;
  /// Called after each input is read (from the reading threads, one at a
  /// time): inputs done, inputs in all, the input's path. May be empty.
  std::function<void(std::size_t done, std::size_t total, const std::string& path)> progress;

  /// InputError, with the CLI's message, for a malformed option.
  void validate() const;
};

/// What an import did with one input.
struct ImportedFile {
  std::string path;
  std::string format;             ///< table, monitor, cfdpost, vtk, openfoam-forces, force-history, openfoam-case
  std::size_t runs = 0;           ///< runs the input holds
  std::size_t runs_created = 0;   ///< new runs
  std::size_t runs_extended = 0;  ///< existing runs that gained components
  bool already_imported = false;  ///< the same bytes with the same settings were imported before: nothing added
  bool replaced = false;          ///< an earlier import of the same file with other settings was replaced
  std::vector<std::string> notes;
};

/// What Database::import_files did, as `hydrocoef import` reports it.
struct HYDROCOEF_EXPORT ImportSummary {
  std::vector<ImportedFile> files;  ///< in the order the inputs were planned (folders expanded)
  std::vector<std::string> notes;   ///< of the whole import (twins, settings a format ignores, ...)
  std::size_t excluded = 0;         ///< files left out by include/exclude
  std::size_t runs_created = 0;
  std::size_t runs_extended = 0;
  std::size_t already_imported = 0;
  std::size_t replaced = 0;  ///< inputs whose earlier import was replaced
  std::string database;      ///< the database's location, as opened

  /// What `hydrocoef import` prints: a line per input, the notes and the
  /// summary line (only the summary line when quiet); or its JSON (every
  /// input with its settings, statistics and integrated surface, the totals,
  /// the stage times and the notes).
  std::string text(bool quiet = false) const;
  std::string json() const;

  struct Access;  ///< the library's own

 private:
  std::string text_, summary_line_, json_;
};

/// A damping law to fit: the options of `hydrocoef fit`.
///   F_output(x) = sum_k c_k term_k(x), terms of one velocity component x.
struct HYDROCOEF_EXPORT FitOptions {
  std::string body;
  std::string output;  ///< force component: X Y Z K M N (the CLI's --dof)
  std::string terms;   ///< e.g. "1,u,u|u|": 1, x, x|x|, x^2, x^3, |x|
  /// Selection clauses on velocity components or disturbances, combined with
  /// AND: "u=0.1", "v!=0", "u>=0", "u=0.1:0.3" (the CLI's --where).
  std::vector<std::string> where;
  std::vector<std::int64_t> exclude_runs;
  /// Planes of symmetry ("u", "v", "w"): each run also stands for its mirror
  /// image; disturbances that change sign in them.
  std::vector<std::string> mirror;
  std::vector<std::string> mirror_odd;
  std::string loss = "squared";  ///< squared, huber:S, cauchy:S, soft-l1:S (S in N or N m)
  std::string name;              ///< "" : body:output(terms)[@selection], as the CLI names it
  bool replace = false;          ///< replace a stored fit of the same name (else refused)
  bool store = true;             ///< false: fit only (the CLI's --no-store)
  /// Weight each run by its standard uncertainty when every selected run
  /// states one (a mean over a force history, or an uncertainty given at
  /// import); false: ordinary least squares (the CLI's --unweighted).
  bool weighted = true;
  /// fit_by_level: the velocity component or disturbance whose levels are
  /// fitted separately (the CLI's --by); each coefficient is then fitted as a
  /// curve of the level: "polynomial:D" (degree D) or "pchip" (--curve).
  std::string by;
  std::string curve = "polynomial:2";
  bool strict = false;  ///< fit_by_level: refuse a level with too few runs (else skip it with a note)
  /// refit_fits: make stored fits again (the CLI's --refit): the one named,
  /// else every stale one (of `body` when given); no other field may be set.
  bool refit = false;

  /// InputError, with the CLI's message, for options that do not go
  /// together (--refit with a law to fit, --by without ...).
  void validate() const;
};

/// One coefficient of a fitted law.
struct FitCoefficient {
  std::string term;        ///< e.g. "u|u|"
  double value = 0.0;      ///< [unit]
  double std_error = 0.0;  ///< one sigma [unit]; NaN when undefined (as many runs as terms)
  std::string unit;        ///< e.g. "N/(m/s)^2"
};

/// A fitted damping law: what `hydrocoef fit --json` prints, or a stored fit.
struct HYDROCOEF_EXPORT FitSummary {
  std::string name;
  std::string body;
  std::string output;    ///< X..N
  std::string variable;  ///< u..r
  std::string terms;     ///< canonical, e.g. "1,u,u|u|"
  std::string loss;
  std::string where;   ///< the selection, canonical ("" all runs)
  std::string mirror;  ///< planes of symmetry used ("" none)
  /// "on-body" (force on the body) or "opposing" (a damping magnitude,
  /// positive opposes motion): the runs' own when they all agree.
  std::string sign_convention;
  std::vector<FitCoefficient> coefficients;
  double rmse = 0.0;                  ///< [N or N m]
  double r2 = 0.0;                    ///< NaN when the force does not vary over the runs
  std::size_t n = 0;                  ///< samples fitted (runs and mirror images)
  std::vector<std::int64_t> runs;     ///< the runs it was made from
  std::vector<std::string> warnings;  ///< physical checks, unconverged runs (fit only)
  std::int64_t id = 0;                ///< its id in the database; 0 when not stored
  bool stale = false;                 ///< a force of its runs changed since (fits() only)
  std::string created_at;             ///< UTC, ISO 8601 (fits() only)
  /// "uncertainty" (each run weighted by 1/s^2 of its standard uncertainty) or "none".
  std::string weighting = "none";
  /// Weighted fits: chi^2/(n-k); NaN for unweighted fits or n <= k.
  double chi2_reduced = std::numeric_limits<double>::quiet_NaN();
  /// What the covariance of a weighted fit was scaled by (the Birge ratio
  /// squared when above 1); 1 otherwise (fit only).
  double covariance_scale = 1.0;
  /// The coefficients' covariance, k x k row by row [unit_i unit_j]; its
  /// diagonal is the std_errors squared. Empty when not recorded (fits of an
  /// older hydrocoef).
  std::vector<double> covariance;
  std::size_t mirror_images = 0;                ///< samples that are mirror images (fit only)
  std::vector<std::string> varying_conditions;  ///< key parts that take several values over the runs (fit only)

  /// What `hydrocoef fit` prints of a fit just made, or `hydrocoef fits` of a
  /// stored one (its entry of the list; json(): its object of the array).
  std::string text() const;
  std::string json() const;

  struct Access;  ///< the library's own

 private:
  std::string text_, json_;
};

/// A stored surface, as `hydrocoef surface list` shows it.
struct SurfaceInfo {
  std::string name;
  std::string body;
  std::string kind;    ///< "grid" or "rbf"
  std::string method;  ///< as Surface::method()
  std::vector<std::string> axes;
  std::vector<std::string> outputs;
  bool stale = false;
  std::size_t run_count = 0;  ///< runs it was built from
  std::string created_at;     ///< UTC, ISO 8601
};

/// A surface to build from stored runs: the options of `hydrocoef surface
/// build`. Axes: velocity components (u..r) or disturbance names; outputs:
/// force components X..N (forces on the body, N or N m).
struct SurfaceBuildOptions {
  std::string name;
  std::string body;
  std::vector<std::string> axes;
  std::vector<std::string> outputs;
  /// nearest, linear, pchip, makima, natural-spline (runs on a grid), rbf or gp (scattered runs).
  std::string method = "linear";
  /// Out-of-range policy: one for every axis, or "AXIS=POLICY" entries
  /// (grid: error, clamp, linear, method; rbf, gp: error, clamp, extrapolate). Empty: error.
  std::vector<std::string> extrapolate;
  std::vector<std::string> where;          ///< selection clauses, as for runs()
  std::vector<std::int64_t> exclude_runs;  ///< run ids left out
  std::vector<std::string> mirror;         ///< planes of symmetry: each run also stands for its image
  std::vector<std::string> mirror_odd;     ///< disturbances that change sign in the mirror
  std::string rbf_kernel = "cubic";        ///< rbf: cubic, thin-plate, linear
  int rbf_degree = 1;                      ///< rbf: polynomial degree 0, 1, 2
  double rbf_smoothing = 0.0;              ///< rbf: 0 interpolates
  /// rbf: tabulate on these breakpoints (one list per axis, in axes order); empty: no grid.
  std::vector<std::vector<double>> resample;
  std::string resample_method = "linear";  ///< interpolation of the resampled grid
  double far_threshold = 0.25;             ///< resampled grids: report points farther than this from every run
  bool replace = false;                    ///< replace a stored surface of that name (else refused)
  std::string gp_kernel = "matern52";      ///< gp: matern52 or squared-exponential
  int gp_degree = 1;                       ///< gp: mean of degree 0, 1, 2
  int gp_starts = 5;                       ///< gp: optimiser starts (1 to 100)
  unsigned gp_seed = 1;                    ///< gp: seed of the optimiser starts after the third
  /// InputError, with `hydrocoef surface build`'s message, for a bad
  /// method, policy, kernel, degree, start count or resampling (defined with
  /// the surface operations, src/api/surface_build.cpp).
  HYDROCOEF_EXPORT void validate() const;
};

class HYDROCOEF_EXPORT Database {
 public:
  /// Opens (or with OpenMode::Create, makes) a run database. InputError when
  /// the file is missing (ReadOnly, ReadWrite), is not a hydrocoef database,
  /// is damaged, or was written by a newer hydrocoef.
  static Database open(const std::string& path, OpenMode mode = OpenMode::ReadWrite);

  Database(Database&&) noexcept;
  Database& operator=(Database&&) noexcept;
  ~Database();

  /// The path given to open().
  const std::string& path() const;
  bool is_open() const;
  bool read_only() const;
  /// Closes the file. Every later call but path(), is_open() and close()
  /// throws InputError "PATH: database is closed". Surfaces already read stay valid.
  void close();

  /// The runs (of one body, or all when body is ""), selected by `where`
  /// clauses and run ids left out, as `hydrocoef runs --where ...` lists them.
  RunTable runs(const std::vector<std::string>& where = {}, const std::string& body = "",
                const std::vector<std::int64_t>& exclude_runs = {}) const;

  /// Imports files, folders and case folders in one transaction, as
  /// `hydrocoef import` does (same planning, readers, settings precedence,
  /// identity of an import). Every input is read before the database is
  /// touched: a bad input leaves it as it was. (prepare_import and
  /// import_prepared, hydrocoef/records.hpp, do the same in two steps, to
  /// read before a database is even opened.)
  ImportSummary import_files(const std::vector<std::string>& paths, const ImportOptions& options = {});

  /// Fits a damping law to the selected runs and stores it (unless
  /// options.store is false), as `hydrocoef fit` does. InputError when no run
  /// is selected, a name is taken (without replace), or an option is bad.
  /// options.by and options.refit must be unset (std::invalid_argument
  /// otherwise): fit_by_level and refit_fits (hydrocoef/records.hpp) do those.
  FitSummary fit(const FitOptions& options);
  /// The stored fits (of one body, or all when body is ""), by name.
  std::vector<FitSummary> fits(const std::string& body = "") const;

  /// The stored surfaces (of one body, or all when body is ""), by name.
  std::vector<SurfaceInfo> surfaces(const std::string& body = "") const;
  /// Builds a surface from the selected runs and stores it with its build
  /// specification, as `hydrocoef surface build` does. InputError when no run
  /// is selected, the runs cannot make it, an option is bad, or the name is
  /// taken (without replace).
  SurfaceInfo build_surface(const SurfaceBuildOptions& options);
  /// Builds stored surfaces again from the current runs with the
  /// specification each was built with: the one named, else every surface
  /// (only the stale ones when stale_only), as `hydrocoef surface rebuild`.
  std::vector<SurfaceInfo> rebuild_surfaces(const std::string& name = "", bool stale_only = false);
  /// One stored surface, read whole: it stays valid after close(). InputError
  /// listing the stored names when there is none of that name.
  Surface surface(const std::string& name) const;

  struct Impl;    ///< the library's own
  struct Access;  ///< the library's own: how the operations of the other headers reach Impl

 private:
  explicit Database(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace api
}  // namespace hydrocoef
