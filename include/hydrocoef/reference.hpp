// A body's reference data and the non-dimensional coefficients of its runs,
// as `hydrocoef body set`, `body show` and `runs --coefficients` give them:
// each command parses its options into the types here, calls one function
// and prints the result's text() or, with --json, its json() (and csv()). So
// C++, Python and the CLI give the same numbers.
//
// Reference data (stored with the body): a reference length L [m], named
// reference areas A [m^2] (frontal, wetted, planform, "L*d", "L^2": any
// name, several per body) with one of them the default, the draft [m], the
// displaced volume [m^3] and the moment reference point [m] in body axes.
//
// Coefficients of a run, for one of its body's areas A and its length L:
//   C_X = X / (1/2 rho U^2 A)   (and C_Y, C_Z)
//   C_K = K / (1/2 rho U^2 A L) (and C_M, C_N)
//   Re = U L / nu,  Fn = U / sqrt(g L),  g = 9.80665 m/s^2 (standard gravity)
// U = |(u, v, w)|, the run's speed through the water; rho and nu the run's
// own (as imported: --rho, --nu, the case's files). The coefficients keep the
// runs' axes and signs: body axes (x forward, y starboard, z down), forces on
// the body (a drag is negative along the motion: C_X < 0 for u > 0). Moments
// are taken about the body's moment reference point when it has one (moved
// there from the run's own reference point: M_P = M_O + (O - P) x F), else
// about the run's own.
//
// Nothing is guessed: a run without a density has no coefficient, one
// without a viscosity no Reynolds number, a run at rest (U = 0) no
// coefficient (no dynamic pressure); each says so in its note.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hydrocoef/database.hpp"
#include "hydrocoef/export.hpp"

namespace hydrocoef {
inline namespace api {

/// A body's reference data. NaN where a value is not given.
struct HYDROCOEF_EXPORT BodyReference {
  std::string body;
  double length = std::numeric_limits<double>::quiet_NaN();            ///< reference length L [m]
  std::map<std::string, double> areas;                                 ///< reference areas by name [m^2]
  std::string default_area;                                            ///< one of `areas`; "" when none is
  double draft = std::numeric_limits<double>::quiet_NaN();             ///< [m]
  double displaced_volume = std::numeric_limits<double>::quiet_NaN();  ///< [m^3]
  /// [m], body axes; NaN (all three) when not given: moments about each run's own reference point.
  std::array<double, 3> moment_reference_point{std::numeric_limits<double>::quiet_NaN(),
                                               std::numeric_limits<double>::quiet_NaN(),
                                               std::numeric_limits<double>::quiet_NaN()};
  std::string updated_at;  ///< UTC, ISO 8601; "" when the body has no reference data

  std::string text() const;
  std::string json() const;
};

/// The reference data of the database's bodies (`hydrocoef body show`).
struct HYDROCOEF_EXPORT BodyReferences {
  std::string database;
  std::vector<BodyReference> bodies;  ///< by name; one without reference data has updated_at ""

  std::string text() const;
  std::string json() const;
};

/// The body named (all bodies when body is ""). InputError listing the
/// bodies when there is none of that name.
HYDROCOEF_EXPORT BodyReferences body_references(const Database& database, const std::string& body = "");

/// What `hydrocoef body set NAME` changes; what is not given stays as it was.
struct HYDROCOEF_EXPORT BodyReferenceOptions {
  std::string body;                        ///< a body of the database (made by importing its runs)
  std::optional<double> length;            ///< --length L [m]
  std::map<std::string, double> areas;     ///< --area NAME=A [m^2]: added, or replacing one of that name
  std::vector<std::string> remove_areas;   ///< --remove-area NAME
  std::string default_area;                ///< --default-area NAME ("" unchanged)
  std::optional<double> draft;             ///< --draft [m]
  std::optional<double> displaced_volume;  ///< --volume [m^3]
  std::optional<std::array<double, 3>> moment_reference_point;  ///< --moment-point x,y,z [m], body axes
  /// --unset: values taken away: "length", "draft", "volume", "moment-point".
  std::vector<std::string> unset;

  /// InputError, naming the option, for an empty body name, a value that is
  /// not positive and finite, an area name that breaks the name rule, a name
  /// both set and removed, or an --unset of something else.
  void validate() const;
};

/// Changes the body's reference data in one transaction and returns it as
/// stored. When the body ends with one area and no default, that area
/// becomes the default. InputError (nothing changed) for a bad option, a
/// body that is not there, an area removed that it does not have, a default
/// area that is not one of its areas (or removed without naming another),
/// and a read-only database.
HYDROCOEF_EXPORT BodyReference set_body_reference(Database& database, const BodyReferenceOptions& options);

/// Which runs `hydrocoef runs --coefficients` gives coefficients of.
struct HYDROCOEF_EXPORT CoefficientOptions {
  std::string body;                        ///< "" every body
  std::vector<std::string> where;          ///< selection clauses, as for Database::runs
  std::vector<std::int64_t> exclude_runs;  ///< left out of the selection
  std::string area;                        ///< --area NAME: "" the body's default area

  /// InputError for a selection clause that does not parse.
  void validate() const;
};

/// The reference one body's coefficients use.
struct CoefficientReference {
  std::string body;
  std::string area_name;
  double area = 0.0;    ///< [m^2]
  double length = 0.0;  ///< [m]
  /// The point moments are taken about [m], body axes; NaN (all three) when
  /// each run's own reference point is used.
  std::array<double, 3> moment_reference_point{};
};

/// Runs as columns: entry i of every column is run i, ordered as `hydrocoef
/// runs` lists them. NaN where a value cannot be given (the run's note says why).
struct HYDROCOEF_EXPORT RunCoefficients {
  std::string database;
  double gravity = 9.80665;                      ///< g of the Froude number [m/s^2]
  std::vector<CoefficientReference> references;  ///< one per body of the runs, by name
  std::vector<std::int64_t> id;
  std::vector<std::string> body;
  std::array<std::vector<double>, 6> velocity;  ///< u, v, w [m/s], p, q, r [rad/s]
  /// Disturbance parameters by name [SI]; NaN for a run without that disturbance.
  std::map<std::string, std::vector<double>> disturbances;
  std::vector<double> speed;                ///< U = |(u, v, w)| [m/s]
  std::vector<double> density;              ///< rho [kg/m^3], the run's
  std::vector<double> kinematic_viscosity;  ///< nu [m^2/s], the run's
  std::vector<double> reynolds;             ///< U L / nu
  std::vector<double> froude;               ///< U / sqrt(g L)
  /// C_X, C_Y, C_Z, C_K, C_M, C_N: body axes, forces on the body.
  std::array<std::vector<double>, 6> coefficient;
  /// Why values of the run are missing ("no density: import the run with
  /// --rho", "U = 0: no dynamic pressure, no coefficient"); "" when none is.
  std::vector<std::string> note;

  std::size_t size() const noexcept { return id.size(); }

  std::string text() const;
  std::string json() const;
  std::string csv() const;
};

/// The coefficients of the selected runs (none selected: an empty table,
/// whose text says so). InputError (one line) when a body of the runs has no
/// reference length or area (saying what to give `hydrocoef body set`), or
/// options.area is not one of a body's areas (listing them).
HYDROCOEF_EXPORT RunCoefficients run_coefficients(const Database& database, const CoefficientOptions& options = {});

}  // namespace api
}  // namespace hydrocoef
