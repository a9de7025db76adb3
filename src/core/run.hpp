// The domain vocabulary of one CFD run: its key (body, body velocity,
// disturbance), the generalized force it produced, and where it came from.
//
// Frames and units: body axes after Fossen/SNAME (x forward, y starboard,
// z down); velocity nu_b = (u, v, w) in m/s and (p, q, r) in rad/s; generalized
// force tau_b = (X, Y, Z) in N and (K, M, N) in N m about the run's reference
// point. Everything inside the library is SI.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "src/core/sign_convention.hpp"

namespace hydrocoef {

/// Velocity component names, in the order of nu_b.
inline constexpr std::array<std::string_view, 6> kVelocityNames = {"u", "v", "w", "p", "q", "r"};
/// Generalized force component names, in the order of tau_b.
inline constexpr std::array<std::string_view, 6> kForceNames = {"X", "Y", "Z", "K", "M", "N"};
/// The SI units of the velocity components, in the order of nu_b.
inline constexpr std::array<const char*, 6> kVelocityUnits = {"m/s", "m/s", "m/s", "rad/s", "rad/s", "rad/s"};
/// The SI units of the generalized force components, in the order of tau_b.
inline constexpr std::array<const char*, 6> kForceUnits = {"N", "N", "N", "N m", "N m", "N m"};

/// "N" for X, Y, Z; "N m" for K, M, N (dof 0..5).
inline std::string force_unit(std::size_t dof) { return kForceUnits[dof]; }
/// "m/s" for u, v, w; "rad/s" for p, q, r (component 0..5).
inline std::string velocity_unit(std::size_t component) { return kVelocityUnits[component]; }

/// Index 0..5 of a velocity name ("u".."r"), or nullopt.
std::optional<std::size_t> velocity_index(std::string_view name);
/// Index 0..5 of a force name ("X".."N"), or nullopt.
std::optional<std::size_t> force_index(std::string_view name);

/// What identifies a run: the body, its velocity in body axes, and any number
/// of named disturbance parameters (for example current_v = 0.05 m/s).
struct RunKey {
  std::string body;
  std::array<double, 6> nu_b{};                ///< u, v, w [m/s]; p, q, r [rad/s]
  std::map<std::string, double> disturbances;  ///< SI values, by name
};

/// A canonical text form of a key's disturbances ("a=0.05;b=1"), sorted by
/// name and printed with round-trip precision; "" when there are none.
std::string disturbance_signature(const std::map<std::string, double>& disturbances);

/// One-line human form of a key: "asr-v u=0.1 r=0.2 current_v=0.05" (zero
/// velocity components are left out).
std::string describe(const RunKey& key);

/// One generalized force component with its parts where known.
struct ForceComponent {
  double total = 0.0;
  std::optional<double> pressure;
  std::optional<double> viscous;
  /// A standard uncertainty of total stated by the user at import
  /// (--uncertainty X=0.01 or X=2%) [N or N m]; empty when none was.
  std::optional<double> uncertainty;
};

/// The fluid a run was computed in; unknown values stay empty.
struct Fluid {
  std::optional<double> density_kg_m3;
  std::optional<double> kinematic_viscosity_m2_s;
};

/// What is kept of an integrated surface, so that forces can be recomputed
/// for another reference pressure or moment point without the mesh.
/// Body axes, SI.
struct SurfaceIntegrals {
  std::size_t faces = 0;
  double area = 0.0;           ///< m^2
  double signed_volume = 0.0;  ///< m^3, > 0 for a closed surface with outward normals
  bool closed = false;
  std::size_t boundary_edges = 0;
  std::size_t degenerate_faces = 0;
  bool normals_flipped = false;
  std::array<double, 3> integral_n_dA_b{};          ///< ∫ n dA [m^2]
  std::array<double, 3> integral_x_cross_n_dA_b{};  ///< ∫ x × n dA about the body origin [m^3]
  double reference_pressure = 0.0;                  ///< Pa, subtracted from the pressure
  std::string pressure_array;
  std::string shear_array;       ///< "" when no viscous part was integrated
  std::string pressure_kind;     ///< "static" or "kinematic" (as in the file)
  std::string shear_convention;  ///< "on-wall" or "on-fluid" (as in the file)
  std::string axes;              ///< CFD axes to body axes, e.g. "-x,y,-z"
};

/// A force component that is the mean over a window of a force history, with
/// what its uncertainty and convergence rest on. Body axes, as the component.
struct ComponentStatistics {
  double standard_error = 0.0;     ///< of the mean, corrected for autocorrelation [N or N m]
  double spread = 0.0;             ///< standard deviation over the window [N or N m]
  double drift = 0.0;              ///< change across the window by its least-squares slope [N or N m]
  double effective_samples = 0.0;  ///< window samples / integrated autocorrelation time
};

/// The samples of a force history one component's value comes from.
struct ComponentWindow {
  std::string method;  ///< e.g. "MSER-5 (White 1997)", "range 601:1000", "final iterate"
  double first = 0.0;  ///< abscissa of the first and last sample used
  double last = 0.0;
  std::size_t samples = 0;
  /// Convergence flags of this component: "no-steady-window", "drifting",
  /// "too-few-effective-samples", "uneven-sampling"; empty when there is
  /// nothing to act on.
  std::vector<std::string> flags;
};

/// How a run's forces were obtained from a force history.
struct RunStatistics {
  std::string abscissa;  ///< "time" [s] or "iteration"
  /// The run's convergence kind: "converged" (final iterate, standard error
  /// = iterative error), "steady-window", "transient-window", "given-window"
  /// (means over windows); src/history/history_analysis.hpp.
  std::string convergence;
  /// Why, with the files and lines of the evidence.
  std::string convergence_reason;
  /// The union of the components' flags.
  std::vector<std::string> flags;
  std::array<std::optional<ComponentStatistics>, 6> components;  ///< X..N
  std::array<ComponentWindow, 6> windows;                        ///< X..N, where components are
};

/// A force history in brief, kept with its run so that its picture can be
/// drawn from the database alone (the report's run quality section, `plot
/// history`): the total force and moment components over the whole record,
/// in at most kMaxBins bins of consecutive samples, each bin's least and
/// largest value and the abscissa of its last sample. A record of at most
/// kMaxBins samples is kept whole (low = high). src/history/history_trace.hpp
/// makes one.
struct HistoryTrace {
  static constexpr std::size_t kMaxBins = 256;
  std::string abscissa_name;                     ///< "time" [s] or "iteration"
  std::size_t samples = 0;                       ///< in the whole record
  std::vector<double> abscissa;                  ///< per bin: its last sample's abscissa, increasing
  std::array<std::vector<double>, 6> low, high;  ///< X..N in body axes, on the body; empty where absent
};

/// One run as an importer produced it.
struct ImportedRun {
  RunKey key;
  Fluid fluid;
  std::array<double, 3> reference_point_b{};           ///< moment centre [m], body axes
  std::array<std::optional<ForceComponent>, 6> tau_b;  ///< X..N; empty where the source has none
  SignConvention sign = SignConvention::OnBody;
  std::size_t source_line = 0;              ///< 1-based line in the source, 0 if n/a
  std::optional<SurfaceIntegrals> surface;  ///< when the forces came from a surface
  std::optional<RunStatistics> statistics;  ///< when the forces are means over a history
  std::optional<HistoryTrace> trace;        ///< that history in brief
};

/// Where a batch of runs came from.
struct Provenance {
  std::string path;    ///< as given by the user
  std::string sha256;  ///< of the file's bytes, lower-case hex
  std::uint64_t size_bytes = 0;
  std::string importer;  ///< importer name, e.g. "force-table"
  std::string importer_version;
  /// The absolute path with symbolic links resolved ("" when not known).
  std::string resolved_path;
  /// Every effective setting with its value, source and place (JSON); "" when
  /// the importer took no settings.
  std::string settings;
  /// The effective settings' values alone, canonical: with the bytes, what
  /// identifies an import.
  std::string settings_key;
};

/// Everything one source file contributes, imported in one go.
struct ImportBatch {
  Provenance source;
  std::vector<ImportedRun> runs;
};

}  // namespace hydrocoef
