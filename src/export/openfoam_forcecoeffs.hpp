// A run's forces as OpenFOAM's forceCoeffs function object writes them: the
// coefficient.dat of OpenFOAM v1912 (ESI), headed
//
//   # Force coefficients
//   # dragDir         : (1 0 0)     sideDir, liftDir, rollAxis, pitchAxis, yawAxis
//   # magUInf         : ...         lRef, Aref, CofR
//   #
//   # Time            	Cd	Cs	Cl	CmRoll	CmPitch	CmYaw	Cd(f)	Cd(r)	Cs(f)	Cs(r)	Cl(f)	Cl(r)
//
// then one row per time: the time padded to OpenFOAM's column width, each
// value after a tab in scientific notation. The layout is OpenFOAM's to the
// byte (writeFile: a column width of the precision plus 8, the labels padded
// to it, left-aligned), with hydrocoef's own comment lines between CofR and
// the '#' line (free text: no "name : value" form the reader would take).
//
// The coefficient axes are the case's own axes: dragDir, sideDir, liftDir =
// x, y, z of the case (rollAxis, pitchAxis, yawAxis the same), so
//   Cd = F_x / (1/2 rho magUInf^2 Aref), Cs = F_y / (...), Cl = F_z / (...),
//   CmRoll = M_x / (1/2 rho magUInf^2 Aref lRef), CmPitch = M_y / (...), CmYaw = M_z / (...),
// forces and moments on the body (the fluid's force, OpenFOAM's sign),
// moments about CofR; and the front/rear parts as v1912 forms them:
//   Cd(f) = Cd/2 + CmRoll, Cd(r) = Cd/2 - CmRoll, Cs(f) = Cs/2 + CmYaw,
//   Cs(r) = Cs/2 - CmYaw, Cl(f) = Cl/2 + CmPitch, Cl(r) = Cl/2 - CmPitch,
// formed, as OpenFOAM forms them, before the coefficients are rounded to the
// precision.
//
// Exactness. importers/openfoam_forces turns a coefficient back into a
// force as F = C * (q Aref) (moments C * (q Aref lRef)), q = 0.5 rho magUInf
// magUInf, all in double. With precision 16 (17 significant digits) the
// writer picks, among the doubles next to F / (q Aref), the one that the
// reader's product turns back into F itself; where no double does (the
// product skips some doubles when the scale's significand is the larger),
// the one whose product is next to F (1 ulp). ForceCoeffsText counts both.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace hydrocoef {

/// What one coefficient.dat holds. Forces [N] and moments [N m] in the case's
/// axes, on the body, moments about `cofr`; SI.
struct ForceCoeffsInput {
  double rho = 0.0;        ///< density [kg/m^3] (not in OpenFOAM's header; stated in a comment)
  double mag_u_inf = 0.0;  ///< magUInf [m/s]
  double l_ref = 0.0;      ///< lRef [m]
  double a_ref = 0.0;      ///< Aref [m^2]
  std::array<double, 3> cofr{};
  std::vector<double> time;                 ///< increasing
  std::array<std::vector<double>, 6> load;  ///< Fx, Fy, Fz, Mx, My, Mz, each the size of `time`
  /// Digits after the point of the scientific notation (OpenFOAM's
  /// writePrecision): 16 gives 17 significant digits, every double exactly.
  int precision = 16;
  /// hydrocoef's comment lines (each written after "# "), already one line of
  /// printable text each; the writer refuses a line holding ':' or a control
  /// character (it would read as a header value or break the header).
  std::vector<std::string> comments;
};

struct ForceCoeffsText {
  std::string text;
  std::size_t values = 0;                          ///< coefficients of Cd..CmYaw written
  std::size_t exact = 0;                           ///< of them, read back (F = C * scale) as the force itself
  std::size_t one_ulp = 0;                         ///< read back as the double next to the force
  std::array<std::vector<double>, 6> coefficient;  ///< Cd, Cs, Cl, CmRoll, CmPitch, CmYaw as written (parsed back)
};

/// The coefficient C whose product C * scale is `value` (or, where none is,
/// the double next to it), among the doubles within a few ulps of value /
/// scale. `exact` says which.
double inverse_of_product(double value, double scale, bool& exact);

/// The file. InputError, one line, for a reference value that is not finite
/// and positive, times that are not finite and increasing, a load that is
/// not finite or of another length, a precision outside 1..16, or a comment
/// line a reader would misread.
ForceCoeffsText openfoam_forcecoeffs(const ForceCoeffsInput& input);

/// The time as OpenFOAM names it, in the shortest text that reads back as
/// the same double ("199", "0.0125", "1e-05").
std::string openfoam_time_name(double time);

}  // namespace hydrocoef
