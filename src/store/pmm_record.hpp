// A forced-oscillation analysis as the database stores it (tables pmm_run
// and pmm_coefficient, schema/0012_pmm.sql): plain data, written by
// src/pipeline/pmm_runs and read by the added-mass assembly
// (src/pmm/added_mass_assembly), the report and the CLI.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "src/core/run.hpp"

namespace hydrocoef {

/// The largest kept-window history a record holds (rows of t and six
/// components); a longer window is stored as every k-th row.
inline constexpr std::size_t kMaxPmmHistoryRows = 4096;
inline constexpr std::size_t kPmmHistoryColumns = 7;

/// How the run was set up: the body moved through still water, or stood in
/// a stream that oscillated (the Froude-Krylov force was then removed).
enum class PmmMedium { StillWater, OscillatingStream };
std::string pmm_medium_name(PmmMedium medium);  ///< "still water" or "oscillating stream"

/// One force component's result, in body axes. Signs are Fossen's: the
/// force on the body is F_i = -M_A[i][dof] x'' - D[i][dof] x'.
struct PmmCoefficient {
  std::size_t component = 0;  ///< 0..5 = X, Y, Z, K, M, N
  double mean = 0.0;          ///< N or N m
  double added_mass = 0.0;    ///< M_A[component][dof]: kg, kg m or kg m^2
  double added_mass_se = 0.0;
  double damping = 0.0;  ///< D[component][dof]: N s/m, N s or N m s
  double damping_se = 0.0;
  double explained = 0.0;         ///< fraction of the variance about the mean the fit explains
  std::vector<double> harmonics;  ///< s1, c1, s2, c2, ... (N or N m)
};

struct PmmRecord {
  std::int64_t id = 0;  ///< 0 before it is stored
  std::string body;
  std::array<double, 6> nu_b{};  ///< the run's mean body velocity u..r (m/s, rad/s)
  std::size_t dof = 0;           ///< the oscillated degree of freedom, 0..5 = surge..yaw
  double amplitude = 0.0;        ///< m or rad, > 0
  double omega = 0.0;            ///< rad/s, > 0
  double phase = 0.0;            ///< rad: x(t) = amplitude sin(omega t + phase)
  PmmMedium medium = PmmMedium::StillWater;
  std::string motion_source;  ///< where the motion was read: "case/constant/dynamicMeshDict:21", "--motion"
  double window_start = 0.0, window_end = 0.0;  ///< s
  std::size_t periods = 0, transient_periods = 0, samples = 0;
  int harmonics = 1;
  std::optional<double> size;                 ///< body size D for KC and Stokes numbers [m]
  std::optional<double> keulegan_carpenter;   ///< 2 pi A / D (translations)
  std::optional<double> kinematic_viscosity;  ///< m^2/s
  std::optional<double> stokes_number;        ///< D^2 / (nu T)
  std::optional<double> rho;                  ///< kg/m^3
  std::optional<double> displaced_volume;     ///< m^3, for the Froude-Krylov force of a stream
  std::optional<double> restoring;            ///< C of F = -C x removed before the fit (N/m or N m/rad)
  std::string source_path, source_sha256, importer;
  /// The kept window, kPmmHistoryColumns per row (t, X, Y, Z, K, M, N); a
  /// component without a coefficient holds zeros.
  std::vector<double> history;
  std::string created_at;
  std::vector<PmmCoefficient> coefficients;  ///< by component, those the source gave
};

/// What storing one record did.
struct PmmSaved {
  std::int64_t id = 0;
  bool replaced = false;  ///< the same file with the same motion was stored before; its rows were replaced
};

/// A deleted record, as stored (not checked: it may be one no reader accepts).
struct PmmDeleted {
  std::int64_t id = 0;
  std::string body;
  std::int64_t dof = 0;
  std::string source_path;
};

}  // namespace hydrocoef
