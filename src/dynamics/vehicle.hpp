// The description of a vehicle for the dynamics model, as read from a JSON
// file: mass properties, hydrostatics, added mass, thrusters and the source of
// each DOF's damping. Plain data: VehicleModel (vehicle_model.hpp) turns it
// into the immutable model the integrators call.
//
// File format (JSON; // comments allowed; SI units; body axes x forward,
// y starboard, z down, origin CO = the reference point of the damping data):
//   {
//     "name": "asr-v",                       optional
//     "notes": "..." | ["...", ...],         optional: where each number comes from
//     "sources": {...},                      optional, free form (ignored)
//     "gravity": 9.81,                       m/s^2, optional (9.81)
//     "rho": 998.2,                          kg/m^3, optional (998.2, fresh water at 20 C)
//     "mass": 6.7,                           kg, > 0
//     "inertia": [Ixx, Iyy, Izz] | [[3x3]],  kg m^2 about the CG, body axes; SPD
//     "center_of_gravity": [x, y, z],        m from CO (z > 0: below CO)
//     "center_of_buoyancy": [x, y, z],       m from CO, optional ([0, 0, 0])
//     one of "buoyancy_force": B (N), "displaced_volume": V (m^3, B = rho g V),
//            "neutrally_buoyant": true (B = m g),
//     "added_mass": {"sphere_radius": R} | {"diagonal": [6]} | {"matrix": [[6x6]]}
//                 | {"from_database": "BODY", "same": {"sway": "surge"}, "zero": ["roll"], "period": 2},
//                                            optional (none); positive entries,
//                                            M_A = -diag(X_udot, ...); symmetric;
//                                            from_database: assembled from the
//                                            body's stored forced-oscillation runs
//                                            (src/pmm/added_mass_assembly.hpp), with
//                                            "same"/"zero" for DOFs no run moves
//     "thrusters": [{"name": "port-fore", "position": [x, y, z], "direction": [dx, dy, dz],
//                    "min_thrust": -1.0, "max_thrust": 1.0}, ...],   optional; N
//     "damping": {"X": {"law": {"u": -0.0155, "u|u|": -11.0365}, "sign": "on-body"},
//                 "N": {"surface": "asr-v-yaw", "output": "N",
//                       "axes": {"r": "r", "current_u": "current_u"}, "sign": "on-body"},
//                 "Y": {"derivatives": {"terms": "v, r, v*|v|, u*v, u*r",
//                                       "coefficients": [...], "covariance": [[...], ...]},
//                       "sign": "on-body"}, ...}
//   }
// A law's keys are its terms (1, x, x|x|, x^2, x^3, |x| of one velocity
// component; see src/core/damping_terms.hpp), its values the coefficients. DOFs not in
// "damping" have none. "sign" is "on-body" (force on the body, damping
// negative) or "opposing" (damping magnitude, positive opposes motion).
// "derivatives" is a derivative model of several variables (terms as in
// src/derivatives/terms.hpp, a string "v, r, v*|v|" or an array of term
// strings; at most DampingModel::kMaxDerivativeTerms): u, v, w, p, q, r
// read the velocity relative to the water, other names the scenario's
// disturbance parameters; "coefficients" one per term [N or N m over the
// term's unit], "covariance" (optional, m x m, symmetric positive
// semi-definite) what Monte Carlo draws use; "sign" as for a law. Or
// "derivatives": {"model": NAME}, a model stored by `hydrocoef derivatives
// fit` in the simulation's database, without "sign": its terms, coefficients,
// covariance and sign (forces on the body) are used exactly as the inline
// form would use them (resolve_stored_records, src/dynamics/surface_source.hpp).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "src/dynamics/damping.hpp"
#include "src/dynamics/rigid_body.hpp"

namespace hydrocoef {

struct Thruster {
  std::string name;
  Vector3 position_b = Vector3::Zero();    ///< point of action from CO [m]
  Vector3 direction_b = Vector3::UnitX();  ///< unit vector of positive thrust
  double min_thrust_N = 0.0;               ///< most negative thrust [N]
  double max_thrust_N = 0.0;               ///< most positive thrust [N]
};

struct VehicleDescription {
  std::string name;
  std::string notes;
  std::string file;  ///< where it was read from, for messages ("" when built in code)
  double gravity_m_s2 = 9.81;
  double rho_kg_m3 = 998.2;
  double mass_kg = 0.0;
  Matrix3 inertia_cg_b = Matrix3::Zero();  ///< about the CG [kg m^2]
  Vector3 r_g_b = Vector3::Zero();         ///< CG from CO [m]
  Vector3 r_b_b = Vector3::Zero();         ///< CB from CO [m]
  double buoyancy_N = 0.0;
  Matrix6 added_mass_b = Matrix6::Zero();  ///< M_A about CO, positive definite-ish, symmetric
  /// "added_mass": {"from_database": BODY, ...}: added_mass_b is filled, and
  /// M_RB + M_A checked, by resolve_stored_records (src/dynamics/surface_source.hpp).
  struct AddedMassFromDatabase {
    std::string body;
    std::vector<std::pair<std::string, std::string>> same;  ///< DOF name -> DOF name
    std::vector<std::string> zero;                          ///< DOF names
    std::optional<double> period;                           ///< s: the runs' period, when they have several
  };
  std::optional<AddedMassFromDatabase> added_mass_from_database;
  std::vector<Thruster> thrusters;
  DampingSpec damping;
};

/// Sets d.terms from a list "v, r, v*|v|" as a vehicle file's "derivatives"
/// reads it: InputError "FILE: key 'PATH.terms': ..." for a term the parser
/// does not know, more than DampingModel::kMaxDerivativeTerms terms, or a
/// term in alpha, beta or du (which the dynamics model does not supply).
void set_derivative_terms(DofDamping& d, const std::string& terms, const std::string& file, const std::string& path);

/// Parses a vehicle description (format in the file comment). Throws
/// InputError "FILE: key 'PATH': found ..., expected ..." for a syntax error,
/// a missing key, a wrong type, an unknown key, a non-positive mass, an
/// inertia that is not symmetric positive definite, a mass matrix
/// M_RB + M_A that is not symmetric positive definite, a zero thruster
/// direction or min_thrust > max_thrust, a bad damping law or sign.
VehicleDescription parse_vehicle(std::string_view json_text, const std::string& file);
/// Reads and parses a vehicle file.
VehicleDescription load_vehicle(const std::filesystem::path& path);

}  // namespace hydrocoef
