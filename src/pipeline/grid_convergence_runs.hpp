// Numerical uncertainty of a body's runs from mesh studies (hydrocoef gci).
//
// How a run states its mesh: disturbance parameters, set at import like any
// other (`--set mesh=2 --set cells=1.2e6`, table columns with
// `--disturbance mesh --disturbance cells`, or manifest columns):
//   - the level parameter (default "mesh"): any number that tells the meshes
//     of a study apart (1, 2, 3 or a name's number); and
//   - the mesh's size: `cells` (cell count N, with the domain's volume V and
//     dimension D given to gci: h = (V / N)^(1/D), Celik et al. step 1; V
//     defaults to 1, which changes h but not its ratios, the order, the
//     extrapolation nor the GCI), or `cell_size` (h in m) directly.
// They are part of the run's key, so runs of one flow condition on different
// meshes are different runs (never "the same run" at import), and fits and
// surfaces see them as different conditions: a fit warns that `mesh` varies
// and a surface refuses two runs at one point; select the production mesh
// with `--where mesh=1`.
//
// A key's mesh study: the runs of one physical key (body, velocity and the
// disturbances other than mesh, cells and cell_size) that carry the level
// parameter. Keys at one level only are not studies (counted, not an error);
// two levels are an error; of four or more the three finest are used. Every
// force component the three runs have goes through Celik et al.'s procedure
// (src/uncertainty/gci.hpp), oscillatory convergence included.
//
// What is stored and applied: each component's result with its physical key
// (table numerical_uncertainty); runs of that key on the finest mesh (its
// level value) get the numerical standard uncertainty
//     u_num = GCI_fine |phi1| / k,  k = 2,
// since the GCI with the safety factor 1.25 of a three-mesh study is read as
// an expanded uncertainty of about 95 % coverage (Roache; Celik et al.), and
// k = 2 is the coverage factor of about 95 % of a normal distribution (GUM).
// It is combined with the statistical and given uncertainties in quadrature
// (StoredForce::standard_uncertainty).
//
// Celik et al.'s procedure assumes the values are converged solutions whose
// iterative error is small against the discretisation error. Each value's
// convergence kind is stated (src/history/history_analysis.hpp), and a study
// is refused unless every value of a history converged ("converged") or is a
// mean over a window chosen for a transient or given on purpose, and its
// stated error (iterative error or standard error) is at most
// kMaxIterativeFraction of the change to the adjacent mesh level(s): a
// steady run averaged over a window did not converge. Values with no history
// (tables, surfaces) are taken as they are, and said so. --allow-unconverged
// runs such a study anyway, with a note on each component concerned.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "src/core/run.hpp"
#include "src/store/database.hpp"
#include "src/uncertainty/gci.hpp"

namespace hydrocoef {

/// The coverage factor that turns a GCI (about 95 %) into a standard uncertainty.
inline constexpr double kGciCoverageFactor = 2.0;
/// The largest iterative (or statistical) error of a value, as a fraction of
/// the change between it and an adjacent mesh level's value.
inline constexpr double kMaxIterativeFraction = 0.1;
/// The smallest refinement ratio h_coarse / h_fine between adjacent levels
/// (Celik et al. ask for more than 1.3; below this the difference of the
/// values is mostly iterative and round-off error, and the order and the
/// GCI come out at any size).
inline constexpr double kMinRefinementRatio = 1.1;

struct GridConvergenceRequest {
  std::string body;
  std::string mesh_parameter = std::string(kDefaultMeshParameter);
  /// The domain's volume (m^D) for cell counts; 1 when not given.
  std::optional<double> volume;
  int dimension = 3;  ///< D of h = (V / N)^(1/D)
  /// Run a study whose values did not converge (or whose iterative error is
  /// not small against the mesh changes), with a note, instead of refusing it.
  bool allow_unconverged = false;
};

/// One force component of one key's study.
struct ComponentConvergence {
  std::size_t component = 0;    ///< 0..5 = X..N
  std::array<double, 3> phi{};  ///< fine to coarse, on the body (sign convention on-body)
  GciResult result;
  std::optional<double> numerical_uncertainty;  ///< GCI_fine |phi1| / k; empty when no GCI was found
  /// Each value's convergence kind, fine to coarse ("converged",
  /// "steady-window", "transient-window", "given-window"; "no history" for a
  /// value from a table or surface; "not recorded" for one stored before
  /// kinds were) and its stated error (iterative or standard error; 0 when
  /// none).
  std::array<std::string, 3> convergence;
  std::array<double, 3> iterative_error{};
};

/// One physical key's mesh study.
struct KeyConvergence {
  RunKey key;                         ///< the physical key (mesh parameters left out)
  std::vector<double> levels;         ///< every level's parameter value, fine to coarse
  std::vector<double> cell_sizes;     ///< every level's h, fine to coarse
  std::vector<std::int64_t> run_ids;  ///< every level's run, fine to coarse
  std::string size_from;              ///< "cell_size" or "cells"
  std::vector<ComponentConvergence> components;
  std::vector<std::string> notes;  ///< levels left out, components some levels lack
};

struct GridConvergenceStudy {
  std::string body;
  std::string mesh_parameter;
  std::vector<KeyConvergence> keys;
  std::size_t single_level_keys = 0;   ///< keys with the level parameter at one level: not studies
  std::size_t runs_without_level = 0;  ///< runs of the body without the level parameter
};

/// Finds the body's mesh studies and runs the procedure on each. InputError
/// (one line naming the key or run, what was found and what was expected)
/// for a key at two levels, two levels of one key with the same cell size, a
/// run of a study without a cell size (or with both), or no key at three
/// levels or more.
GridConvergenceStudy grid_convergence_of_runs(RunDatabase& database, const GridConvergenceRequest& request);

/// The study's results as records to store (one per key and component).
std::vector<NumericalUncertaintyRecord> numerical_uncertainty_records(const GridConvergenceStudy& study);

/// What storing a study changed besides its own rows.
struct StoredStudy {
  std::size_t fits_made_stale = 0;      ///< the body's fits that became stale
  std::size_t surfaces_made_stale = 0;  ///< the body's surfaces that became stale
};
/// Stores the study's results (replacing those of its keys) and counts the
/// body's fits and surfaces this made stale (their runs' uncertainty changed).
StoredStudy store_grid_convergence(RunDatabase& database, const GridConvergenceStudy& study);

}  // namespace hydrocoef
