// Gazebo hydrodynamics parameters from stored damping-law fits: the `fossen`
// hydrodynamic model of uuv_simulator's underwater-object plugin and the
// Hydrodynamics system of gz-sim. Both apply a Fossen-form damping
//
//   tau_i = sum_j Dlin(i,j) nu_j + sum_j Dquad(i,j) |nu_j| nu_j     (on body)
//
// with constant coefficients, plus an added-mass matrix. hydrocoef's laws of
// the form F = a x + b x|x| (x one velocity component) map onto it term by
// term; anything else (a constant, x^2, x^3, |x|) is refused, naming the fit
// and term, because neither plugin can express it.
//
// Signs and frames. Everything in GazeboCoefficients is in hydrocoef's body
// axes (Fossen/SNAME: x forward, y starboard, z down; FRD) and "on-body"
// sign: the force of the fluid on the body, so damping is negative. Fits
// stored "opposing" are negated on the way in. The added mass Ma is the
// positive matrix (kg, kg m, kg m^2), symmetric positive definite.
//   - uuv_simulator converts the link's velocities to NED/FRD itself, so its
//     `linear_damping` and `quadratic_damping` take the on-body FRD numbers
//     unchanged and `added_mass` the positive Ma.
//   - gz-sim works in the link frame, usually FLU (x forward, y left, z up):
//     with T = diag(1,-1,-1,1,-1,-1) every matrix becomes T M T, which leaves
//     diagonal terms alone and flips the sign of couplings between an axis
//     that changes (y, z, q, r) and one that does not (x, p). Its parameters
//     are SNAME derivatives: xU, xUabsU (on body, negative) and xDotU = -Ma.
//
// Exports never touch the database; a refused export writes nothing.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "src/core/matrix6.hpp"
#include "src/core/run.hpp"
#include "src/store/database.hpp"

namespace hydrocoef {

/// Where a damping coefficient came from.
struct GazeboFitSource {
  std::size_t dof = 0;       ///< 0..5 = X..N
  std::size_t variable = 0;  ///< 0..5 = u..r
  std::string fit_name;
  std::int64_t fit_id = 0;
  std::string terms;                                    ///< as stored, e.g. "1,u,u|u|"
  SignConvention stored_sign = SignConvention::OnBody;  ///< opposing fits were negated
  std::vector<std::int64_t> run_ids;
  std::size_t n = 0;
  double rmse = 0.0;       ///< N or N m, as stored
  std::string created_at;  ///< when the fit was made
  /// On-body coefficients of the fit's x and x|x| terms (0 when absent),
  /// before any linearisation. Units: force unit / velocity unit (^2).
  double linear = 0.0;
  double quadratic = 0.0;
  std::optional<double> dropped_constant;  ///< on-body, N or N m, with --drop-constant
};

/// The parameters both plugins are written from, in hydrocoef body axes.
struct GazeboCoefficients {
  std::string body;
  /// On-body damping: tau_i = linear_b(i,j) nu_j + quadratic_b(i,j) |nu_j| nu_j
  /// (rows X..N, columns u..r). After linearisation (linearized_at),
  /// quadratic_b is all zero.
  Matrix6 linear_b = Matrix6::Zero();
  Matrix6 quadratic_b = Matrix6::Zero();
  Matrix6 added_mass_b = Matrix6::Zero();  ///< Ma, positive, symmetric positive definite
  std::string added_mass_source;           ///< how Ma was given, for the file's comments
  std::optional<double> linearized_at;     ///< U0 [m/s] when quadratic terms were linearised
  std::vector<GazeboFitSource> sources;    ///< in DOF order
  std::vector<std::size_t> missing_dofs;   ///< DOFs with no own-velocity law (written 0; allow_missing)
  std::vector<std::string> notes;          ///< what a reader should know: drops, missing DOFs, odd signs
};

/// What to build: which fits, and what to do with what the plugins lack.
struct GazeboRequest {
  std::string body;
  /// Explicit choices "DOF=FITNAME" as pairs (DOF one of X..N). Several per
  /// DOF are allowed when their fits are in different velocity components
  /// (a cross-coupling law such as N(v) beside N(r)). A DOF without a choice
  /// in its own velocity takes the body's single fit of that DOF in that
  /// velocity; several candidates are refused, listing them.
  std::vector<std::pair<std::string, std::string>> fits;
  bool drop_constant = false;  ///< drop a "1" term (a CFD bias) instead of refusing
  bool allow_missing = false;  ///< DOFs without a law get 0 (with a note) instead of a refusal
  /// Laws that feed energy into the motion (a positive on-body damping
  /// coefficient) are written with a note instead of refused.
  bool allow_unphysical = false;
  /// Replace each b x|x| by its tangent at the operating point nu0 = (U0, 0,
  /// 0, 0, 0, 0): linear += 2 b |x0| (x0 = U0 for laws in u, 0 otherwise),
  /// quadratic = 0. The force at the operating point itself is not carried.
  std::optional<double> linearize_at;
  Matrix6 added_mass = Matrix6::Zero();  ///< positive Ma in body axes (kg, kg m, kg m^2)
  std::string added_mass_source;         ///< e.g. "--added-mass 1,2,3,4,5,6"
};

/// Builds the coefficients from the body's fits (fits of other bodies are
/// ignored). Throws InputError, naming the fit, term or DOF, when: a chosen
/// fit does not exist (listing the body's fits), is of another DOF, or two
/// choices share a DOF and velocity; several fits could serve a DOF; a DOF
/// has no law and allow_missing is off; a term is "1" (without
/// drop_constant), "x^2", "x^3" or "|x|"; a coefficient is not finite; or
/// the added mass is not symmetric positive semi-definite (check_added_mass).
GazeboCoefficients gazebo_coefficients(const std::vector<FitRecord>& fits, const GazeboRequest& request);

/// Checks that Ma is finite, symmetric to 1e-9 relative to its largest
/// entry, and positive semi-definite (no eigenvalue below -1e-12 of the
/// largest entry). InputError otherwise, with the unsymmetric pair or the
/// smallest eigenvalue found. A singular Ma (a sphere has no rotational added
/// mass) is accepted: both plugins add -Ma times the acceleration and never
/// invert Ma (the link's own inertia keeps the dynamics well posed); the
/// returned note says so. "" for a positive definite Ma.
std::string check_added_mass(const Matrix6& added_mass);

/// Ma = diag(d) (kg x3, kg m^2 x3).
Matrix6 added_mass_diagonal(const std::array<double, 6>& diagonal);

/// Reads 36 numbers, row-major (kg, kg m, kg m^2), separated by white space,
/// commas or semicolons; '#' starts a comment. InputError with file and line
/// on a bad number or a count other than 36.
Matrix6 read_added_mass_matrix(const std::filesystem::path& path);

enum class GazeboFlavor {
  Uuv,  ///< uuv_simulator `<hydrodynamic_model><type>fossen</type>...`
  Gz    ///< gz-sim `<plugin name="gz::sim::systems::Hydrodynamics">` parameters
};
/// "uuv", "gz"; and back (InputError listing them).
std::string_view gazebo_flavor_name(GazeboFlavor flavor);
GazeboFlavor parse_gazebo_flavor(std::string_view text);

/// The axes of the gz-sim link the plugin acts on. uuv_simulator always
/// assumes an FLU link and converts to FRD itself.
enum class GazeboLinkAxes { Flu, Frd };
std::string_view gazebo_link_axes_name(GazeboLinkAxes axes);  ///< "flu", "frd"
GazeboLinkAxes parse_gazebo_link_axes(std::string_view text);

struct GazeboWriteOptions {
  GazeboFlavor flavor = GazeboFlavor::Gz;
  std::string link_name = "base_link";             ///< gz: <link_name>
  GazeboLinkAxes link_axes = GazeboLinkAxes::Flu;  ///< gz: frame of the parameters
};

/// One SDF element as written: its name, its numbers (1, 6 or 36), their
/// unit and meaning.
struct GazeboElement {
  std::string name;  ///< e.g. "xUabsU", "linear_damping"
  std::vector<double> values;
  std::string unit;  ///< e.g. "N/(m/s)^2", or a description for mixed matrices
};

/// The elements the file holds, in file order. Throws InputError for what
/// the flavor cannot express: uuv_simulator reads only the diagonal of
/// quadratic_damping, so a cross-coupling x|x| law is refused there (gz-sim
/// takes it as e.g. nVabsV). gz writes every diagonal term (older gz-sim
/// defaults are not 0) and the non-zero couplings.
std::vector<GazeboElement> gazebo_elements(const GazeboCoefficients& coefficients, const GazeboWriteOptions& options);

/// The whole file: an XML prolog, comments with provenance, units, sign
/// convention and frames, then one root element (<hydrodynamic_model> for
/// uuv, <plugin> for gz) to paste into the model's SDF.
std::string gazebo_text(const GazeboCoefficients& coefficients, const GazeboWriteOptions& options);

/// Writes gazebo_text to `path` atomically (whole or not at all).
void write_gazebo(const GazeboCoefficients& coefficients, const GazeboWriteOptions& options,
                  const std::filesystem::path& path);

/// "X".."N" and "u".."r" by index; the unit of a force (N, N m) and of a
/// velocity (m/s, rad/s) by index.
std::string_view gazebo_dof_name(std::size_t dof);
std::string_view gazebo_velocity_name(std::size_t variable);
/// Unit of a damping coefficient of force `dof` per velocity `variable`,
/// linear ("N/(m/s)") or quadratic ("N m/(rad/s)^2").
std::string damping_unit(std::size_t dof, std::size_t variable, bool quadratic);

}  // namespace hydrocoef
