// The 6x6 added-mass matrix M_A (and the linear damping D) of a body from
// its stored forced-oscillation analyses (src/store/pmm_record.hpp). A run
// that moves DOF j gives column j: M_A[i][j] for every force component i
// its history holds.
//
// Assembly rules:
// - Several runs of one entry (amplitudes, frequencies) are combined by
//   their inverse-variance weighted mean (plain mean when a standard error is
//   zero); its standard error is scaled by the Birge ratio
//   sqrt(chi^2 / (n - 1)) when the runs scatter more than their own standard
//   errors say. The spread of the runs is kept, with the range of
//   frequencies and KC numbers that went in.
// - Symmetry: M_A = M_A^T for a body in an ideal fluid. When both M_A[i][j]
//   and M_A[j][i] are measured, both become their mean (and their
//   difference, in standard errors, is reported); when only one is, it
//   stands for both (said in the notes).
// - Entries no run gives are missing, named, and zero. `same` fills a DOF's
//   column from another's (a symmetric body: sway as surge), `zero` states
//   that a DOF's column is zero (a sphere's rotations in potential flow).
// - The matrix over the DOFs with a non-zero diagonal is checked positive
//   definite (its smallest eigenvalue is reported), and, when no entry is
//   missing, the whole matrix for no eigenvalue below -1e-9 of its largest
//   entry: a DOF stated zero whose row holds measured couplings of weight
//   fails it.
//
// One frequency: added mass and damping depend on the frequency, so the
// matrices are made from the runs of one frequency (chosen by its period
// when there are several; refused, listing them, when none is chosen), and
// the in-line entries of every frequency are listed apart (by_frequency).
//
// Quadratic damping: runs of one DOF at one frequency and two or more
// amplitudes give the linear and quadratic parts of the diagonal damping
// from D_eq(A) = b1 + b2 (8 / (3 pi)) A omega (fit_quadratic_damping).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "src/core/matrix6.hpp"
#include "src/pmm/harmonic_analysis.hpp"
#include "src/store/pmm_record.hpp"

namespace hydrocoef {

struct AddedMassOptions {
  std::map<std::size_t, std::size_t> same;  ///< DOF -> the DOF whose column it takes
  std::vector<std::size_t> zero;            ///< DOFs whose column is zero
  /// The period [s] whose runs make the matrix (matched to 1e-9); none: the
  /// body's runs must all be at one frequency.
  std::optional<double> period;
};

/// One entry as measured, before symmetry.
struct PmmEntry {
  std::size_t runs = 0;  ///< 0: not measured
  double added_mass = 0.0, added_mass_se = 0.0, added_mass_spread = 0.0;
  double damping = 0.0, damping_se = 0.0;
  double omega_min = 0.0, omega_max = 0.0;  ///< rad/s
  std::optional<double> kc_min, kc_max;     ///< when the runs state a size
  std::vector<std::int64_t> record_ids;     ///< pmm_run ids
};

struct QuadraticDampingRow {
  std::size_t dof = 0;
  double omega = 0.0;
  std::vector<double> amplitudes;
  QuadraticDamping fit;
};

/// The in-line entries M_A[j][j] and D[j][j] of the runs of one DOF at one
/// frequency (all the body's runs, whatever frequency the matrix uses).
struct FrequencyRow {
  std::size_t dof = 0;
  double omega = 0.0;  ///< rad/s
  std::size_t runs = 0;
  double amplitude_min = 0.0, amplitude_max = 0.0;
  double added_mass = 0.0, added_mass_se = 0.0;  ///< combined as the matrix's entries are
  double damping = 0.0, damping_se = 0.0;
};

struct AddedMassAssembly {
  std::string body;
  double omega = 0.0;                       ///< rad/s: the frequency of the runs that make the matrices
  Matrix6 added_mass = Matrix6::Zero();     ///< M_A, symmetric (kg, kg m, kg m^2)
  Matrix6 added_mass_se = Matrix6::Zero();  ///< standard errors of the entries
  Matrix6 damping = Matrix6::Zero();        ///< D, as measured (not symmetrised)
  Matrix6 damping_se = Matrix6::Zero();
  std::array<std::array<PmmEntry, 6>, 6> measured{};  ///< [i][j]
  std::array<std::array<bool, 6>, 6> known{};         ///< measured, mirrored, or filled by same/zero
  std::vector<std::string> missing;                   ///< "M_A[sway][sway] (Y from a sway run)"
  std::vector<std::string> notes;
  bool positive_definite = false;
  double smallest_eigenvalue = 0.0;            ///< over the DOFs with a non-zero diagonal
  std::vector<QuadraticDampingRow> quadratic;  ///< per DOF and frequency, from all the body's runs
  std::vector<FrequencyRow> by_frequency;      ///< by DOF, then frequency
  std::size_t records = 0;                     ///< runs at the chosen frequency
  std::size_t other_frequency_records = 0;     ///< the body's runs at other frequencies (left out)
};

/// The estimate of one entry from several runs: the inverse-variance
/// weighted mean and its standard error, scaled up by the Birge ratio
/// sqrt(chi^2 / (n - 1)) when the runs scatter more than their standard
/// errors say; the plain mean and the standard error of the spread when a
/// standard error is zero; one run's own value and standard error.
/// {value, standard error}; `values` and `standard_errors` of one length > 0.
std::pair<double, double> combine_pmm_estimates(const std::vector<double>& values,
                                                const std::vector<double>& standard_errors);

/// The distinct frequencies [rad/s] of a body's runs (equal to 1e-9), ascending.
std::vector<double> pmm_frequencies(const std::string& body, const std::vector<PmmRecord>& records);

/// Assembles the body's matrices from its records at one frequency (those of
/// other bodies are ignored): the added mass and damping depend on the
/// frequency, so runs at different frequencies are never combined. InputError
/// when there are none, naming the body; when the runs are at several
/// frequencies and `options.period` chooses none, or a period no run has
/// (the message lists the periods and their runs); or for a `same`/`zero`
/// DOF that the runs measure themselves.
/// The options as `added-mass` and `export-gazebo --added-mass-from-database`
/// take them: --same DOF=DOF entries (DOF -> the DOF whose column it takes)
/// and --zero DOFs, by name (surge ... yaw). InputError naming the option and
/// the text for a name that is not a DOF.
AddedMassOptions added_mass_options(const std::map<std::string, std::string>& same,
                                    const std::vector<std::string>& zero, std::optional<double> period);

AddedMassAssembly assemble_added_mass(const std::string& body, const std::vector<PmmRecord>& records,
                                      const AddedMassOptions& options = {});

/// "M_A[surge][sway]" for row i, column j.
std::string added_mass_entry_name(std::size_t i, std::size_t j);

}  // namespace hydrocoef
