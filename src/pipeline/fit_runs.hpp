// Damping laws fitted to stored runs: the runs a selection picks (with, for a
// body with planes of symmetry, their mirror images), their values of one
// force component brought to one sign convention, the law fitted, and the
// record that is stored. `hydrocoef fit` and `fit --refit` are thin layers
// over this; a fit can be made again from what its record says.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "src/core/body_symmetry.hpp"
#include "src/core/run_selection.hpp"
#include "src/fit/damping_law.hpp"
#include "src/store/database.hpp"

namespace hydrocoef {

/// The planes of symmetry a fit or surface lets each run stand for its
/// mirror image in, and the disturbances that change sign in them.
struct MirrorSpec {
  std::vector<std::string> planes;  ///< "u", "v", "w" (the velocity component reversed)
  std::vector<std::string> odd;     ///< disturbance parameters that change sign

  bool empty() const { return planes.empty(); }
  /// Canonical text, "v,w" or "v/current_v" ("" when empty); parse_mirror_spec reads it back.
  std::string text() const;
  /// The reflections: one per plane and, with two or three planes, their compositions.
  std::vector<std::vector<BodyMirror>> images() const;
};

/// Checks planes (u, v, w, each once) and odd names; InputError naming the option.
MirrorSpec make_mirror_spec(const std::vector<std::string>& planes, const std::vector<std::string>& odd);
MirrorSpec parse_mirror_spec(std::string_view text);

/// The runs of `filter` that the selection keeps, in the database's order.
std::vector<StoredRun> selected_runs(RunDatabase& database, const RunFilter& filter, const RunSelection& selection);

/// The runs and, after them, the mirror images of each under every
/// reflection of `mirror` (and their compositions): the key and every force
/// component mapped by the reflection (src/core/body_symmetry.hpp), the id of
/// the run it is the image of, no surface integrals. A run on a plane is its
/// own image and is not repeated; an image at the key of a measured run is
/// left out (the measured run is used) and counted in `skipped`.
std::vector<StoredRun> with_mirror_images(const std::vector<StoredRun>& runs, const MirrorSpec& mirror,
                                          std::size_t* skipped = nullptr);

/// The samples a law is fitted to.
struct FitSamples {
  std::vector<StoredRun> runs;        ///< the selected (measured) runs
  std::vector<RunKey> keys;           ///< per sample: the run's key, or its mirror image's
  std::vector<double> x, y;           ///< the law's velocity component; the force in `sign`
  std::vector<double> sigma;          ///< per sample: the force's standard uncertainty (0: none known)
  std::vector<std::int64_t> run_ids;  ///< per sample: the run it is (or is the image of)
  std::vector<bool> mirrored;         ///< per sample
  std::size_t images_skipped = 0;     ///< images at the key of a measured run (the run is used)
  SignConvention sign = SignConvention::OnBody;
};

/// The runs of `body` that have component `dof` (0..5 = X..N) and match the
/// selection, and their mirror images under `mirror`. Values keep the sign
/// convention they were imported in when all runs agree; mixed conventions are
/// brought to forces on the body. InputError when no run is selected.
FitSamples gather_fit_samples(RunDatabase& database, const std::string& body, std::size_t dof, std::size_t variable,
                              const RunSelection& selection, const MirrorSpec& mirror = {});

/// The uncertainties a weighted fit uses: the samples' standard uncertainties
/// (StoredForce::standard_uncertainty) when `wanted` and every sample has
/// one, else none (an unweighted fit). When wanted but only some samples
/// have one, `note` says so.
std::vector<double> fit_weights(const FitSamples& samples, bool wanted, std::string* note = nullptr);

/// A warning when some selected runs' values of `dof` are means over force
/// histories that did not converge (no steady window, drifting, ...); "" when
/// none is flagged.
std::string unconverged_runs_warning(const std::vector<StoredRun>& runs, std::size_t dof);

/// The record of a fit, as stored.
FitRecord make_fit_record(const std::string& name, const std::string& body, std::size_t dof, const DampingLawSpec& spec,
                          const DampingLawFit& fit, const std::string& selection_text, const MirrorSpec& mirror,
                          const FitSamples& samples, const std::vector<std::int64_t>& run_ids);

/// The fit a stored record describes, made again from the runs its selection
/// picks now (same name, law, loss, selection, mirror). InputError when its
/// runs are gone.
FitRecord refit(RunDatabase& database, const FitRecord& record);

}  // namespace hydrocoef
