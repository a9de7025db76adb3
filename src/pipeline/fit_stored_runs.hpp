// Fitting damping laws to stored runs as a library call shared by the CLI
// (`fit`, `fit --by`, `fit --refit`), the public API and the Python module:
//
//   select:  the body's runs with the force component, kept by the selection
//            (src/core/run_selection.hpp), with their mirror images
//            (src/pipeline/fit_runs.hpp);
//   fit:     the law by least squares (src/fit/damping_law.hpp), or the law
//            at each level of a velocity component or disturbance and each
//            coefficient as a curve of the level (src/fit/coefficient_curve);
//   check:   the physical checks (src/fit/physical_checks.hpp) and the runs'
//            convergence, as warnings;
//   store:   the fit record(s), all or none, unless asked not to.
// Units: velocities in m/s (u, v, w) or rad/s (p, q, r); forces in N (X, Y, Z)
// or N m (K, M, N); coefficient units from coefficient_unit. Signs: as the
// runs were imported when all agree (SignConvention), else forces on the body.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "src/fit/coefficient_curve.hpp"
#include "src/fit/damping_law.hpp"
#include "src/pipeline/fit_runs.hpp"
#include "src/store/database.hpp"

namespace hydrocoef {

/// What to fit (each text in the CLI's vocabulary, checked).
struct FitRequest {
  std::string body;
  std::string dof;                 ///< force component: "X".."N"
  std::string terms;               ///< e.g. "1,u,u|u|" (parse_damping_terms)
  std::string loss = "squared";    ///< or "huber:S", "cauchy:S", "soft-l1:S" (parse_loss)
  std::vector<std::string> where;  ///< selection clauses
  std::vector<std::int64_t> exclude_runs;
  std::vector<std::string> mirror_planes, mirror_odd;
  std::optional<std::string> name;  ///< default: default_fit_name (src/fit/fit_names.hpp)
  bool store = true;
  RunDatabase::NameTaken taken = RunDatabase::NameTaken::Refuse;
  /// Weight each run by its standard uncertainty when every selected run has
  /// one (a mean over a force history, or given at import); false: ordinary
  /// least squares.
  bool weighted = true;
};

/// A warning about a fit: kind ("unconverged-runs" or a law_problem_name)
/// and message.
struct FitWarning {
  std::string kind;
  std::string message;
};

/// What the law, its samples and its variable are, shared by both kinds of fit.
struct FitSetup {
  DampingLawSpec spec;
  std::size_t dof = 0;       ///< 0..5 = X..N
  std::size_t variable = 0;  ///< 0..5 = u..r
  std::string selection;     ///< the selection's canonical text ("" for all runs)
  MirrorSpec mirror;
  FitSamples samples;
  std::vector<std::string> coefficient_units;  ///< per term
  std::vector<FitWarning> warnings;
};

struct FitResult {
  std::string name;
  FitSetup setup;
  DampingLawFit fit;
  std::vector<std::string> varying_conditions;  ///< key parts that take several values among the runs
  std::optional<std::int64_t> fit_id;           ///< when stored
  std::vector<std::int64_t> run_ids() const;    ///< the measured runs used
  std::size_t mirror_images() const { return setup.samples.keys.size() - setup.samples.runs.size(); }
};

/// Fits the law to the selected runs (and their images), checks it, and
/// stores it unless `request.store` is false. InputError for bad names,
/// terms, loss or selection, no runs, too few runs, or a taken name.
FitResult fit_stored_runs(RunDatabase& database, const FitRequest& request);

/// The law at each level of `by`, then each coefficient as a curve of it.
struct LevelFitRequest {
  FitRequest fit;
  std::string by;                      ///< velocity component or disturbance
  std::string curve = "polynomial:2";  ///< parse_curve
  bool strict = false;                 ///< refuse when a level has too few runs (else skip it)
};

struct LevelFitResult {
  std::string base_name;
  FitSetup setup;
  std::vector<LevelFit> levels;
  std::vector<std::string> names;                ///< per level: BASE[by=LEVEL]
  std::vector<std::optional<std::int64_t>> ids;  ///< per level, when stored
  std::vector<SkippedLevel> skipped;
  std::vector<CoefficientCurve> curves;
};

LevelFitResult fit_stored_runs_by_level(RunDatabase& database, const LevelFitRequest& request);

/// Stored fits made again from the runs their selections pick now: the one
/// named, or every stale one (of `body` when given); stored, replacing them.
struct RefitResult {
  std::vector<FitRecord> previous;
  std::vector<FitRecord> made;
};
RefitResult refit_stored_fits(RunDatabase& database, const std::optional<std::string>& name,
                              const std::optional<std::string>& body);

/// The stored fits of `body` made from exactly this selection of runs (a
/// filtered fit, or one level of a per-level fit); every fit of the body for
/// an empty selection. InputError when the body is not in the database
/// (listing the bodies) or no fit was made from the selection.
std::vector<FitRecord> fits_made_from(RunDatabase& database, const std::string& body, const RunSelection& selection);

/// "polynomial:D" (least squares, degree D 0..9) or "pchip" (degree 3).
std::pair<CurveKind, int> parse_curve(const std::string& text);

/// The unit of a term's coefficient: the force's unit over the velocity's to
/// the term's power, e.g. "N/(m/s)^2" for u|u| in X.
std::string coefficient_unit(DampingTerm term, std::size_t dof, std::size_t variable);

}  // namespace hydrocoef
