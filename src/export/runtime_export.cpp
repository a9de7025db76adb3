#include "src/export/runtime_export.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "runtime/src/xxh64.h"
#include "src/core/error.hpp"
#include "src/core/version.hpp"
#include "src/dynamics/vehicle_model.hpp"

namespace hydrocoef {

namespace {

// The layout constants of docs/runtime.md (runtime/src/runtime_file.c reads them).
constexpr std::uint32_t kFormatVersion = 1;         // the model and surfaces
constexpr std::uint32_t kVehicleFormatVersion = 2;  // and a vehicle, the last section
constexpr std::size_t kHeaderSize = 64;
constexpr std::size_t kSectionEntrySize = 24;
constexpr std::uint32_t kSectionModel = 1;
constexpr std::uint32_t kSectionSurface = 2;
constexpr std::uint32_t kSectionVehicle = 3;
// The runtime's limits on what a vehicle's damping reads (runtime_internal.h).
constexpr std::size_t kMaxVehicleAxes = 6;
constexpr std::size_t kMaxVehicleOutputs = 32;
constexpr std::uint32_t kFlagSigma = 1;
constexpr std::size_t kMaxSurfaces = 4096;
constexpr std::size_t kMaxOutputs = 4096;
constexpr unsigned char kMagic[8] = {0x89, 'H', 'C', 'R', 'T', '\r', '\n', 0x1a};

// Little-endian writing, whatever the host.
class Writer {
 public:
  void u32(std::uint32_t value) {
    for (int i = 0; i < 4; ++i) bytes_.push_back(static_cast<char>((value >> (8 * i)) & 0xffu));
  }
  void u64(std::uint64_t value) {
    for (int i = 0; i < 8; ++i) bytes_.push_back(static_cast<char>((value >> (8 * i)) & 0xffu));
  }
  void number(double value) { u64(std::bit_cast<std::uint64_t>(value)); }
  void numbers(const double* values, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) number(values[i]);
  }
  // u32 length, the bytes, 1 to 8 zero bytes to the next multiple of 8.
  void text(const std::string& value, const std::string& what) {
    if (value.find('\0') != std::string::npos) throw InputError(what + " holds a NUL character; expected text");
    if (value.size() > 0xffff'ffffu) throw InputError(what + " is too long; expected under 4 GiB");
    u32(static_cast<std::uint32_t>(value.size()));
    bytes_ += value;
    do bytes_.push_back('\0');
    while (bytes_.size() % 8 != 0);
  }
  void texts(const RuntimeTexts& pairs, const std::string& what) {
    u32(static_cast<std::uint32_t>(pairs.size()));
    u32(0);
    for (const auto& [key, value] : pairs) {
      text(key, what + " key");
      text(value, what + " '" + key + "'");
    }
  }
  std::string& bytes() { return bytes_; }

 private:
  std::string bytes_;
};

bool is_cubic(Interpolation method) {
  return method == Interpolation::Pchip || method == Interpolation::Akima || method == Interpolation::NaturalSpline;
}

// What GridTable evaluates with: hermite_data() for the cubic methods, values() otherwise.
const std::vector<double>& evaluated(const GridTable& table) {
  return is_cubic(table.method()) ? table.hermite_data() : table.values();
}

void check_finite(const std::vector<double>& numbers, const std::string& what) {
  for (std::size_t i = 0; i < numbers.size(); ++i)
    if (!std::isfinite(numbers[i]))
      throw InputError(what + " number " + std::to_string(i) + " is not finite; expected finite numbers");
}

std::string surface_section(const RuntimeSurface& surface) {
  const GridTable& table = *surface.table;
  const std::string what = "runtime export of surface '" + surface.name + "'";
  if (surface.axis_units.size() != table.axis_count() || surface.output_units.size() != table.output_count())
    throw InputError(what + ": " + std::to_string(surface.axis_units.size()) + " axis units and " +
                     std::to_string(surface.output_units.size()) + " output units; expected " +
                     std::to_string(table.axis_count()) + " and " + std::to_string(table.output_count()));
  if (table.output_count() > kMaxOutputs)
    throw InputError(what + ": " + std::to_string(table.output_count()) + " outputs; expected at most 4096");
  const bool sigma = surface.sigma_table != nullptr;
  if (sigma) {
    const GridTable& s = *surface.sigma_table;
    bool same = s.method() == table.method() && s.axis_count() == table.axis_count() &&
                s.output_count() == table.output_count() && surface.loo.size() == table.output_count();
    for (std::size_t a = 0; same && a < table.axis_count(); ++a)
      same =
          s.axes()[a].breakpoints == table.axes()[a].breakpoints && s.axes()[a].extrapolation == Extrapolation::Clamp;
    if (!same)
      throw InputError(what +
                       ": its sigma table does not share the surface's breakpoints and method (clamped), or "
                       "the leave-one-out part has not one number per output; expected them to");
  }
  const std::size_t n = table.axis_count(), n_out = table.output_count();
  const std::size_t block = (is_cubic(table.method()) ? (std::size_t{1} << n) : 1) * n_out;
  Writer out;
  out.u32(static_cast<std::uint32_t>(n));
  out.u32(static_cast<std::uint32_t>(n_out));
  out.u32(static_cast<std::uint32_t>(table.method()));
  out.u32(sigma ? kFlagSigma : 0);
  out.u64(table.node_count());
  out.u64(block);
  out.text(surface.name, what + ": the name");
  out.texts(surface.metadata, what + ": metadata");
  for (std::size_t a = 0; a < n; ++a) {
    const GridAxis& axis = table.axes()[a];
    out.text(axis.name, what + ": an axis name");
    out.text(surface.axis_units[a], what + ": an axis unit");
    out.u32(static_cast<std::uint32_t>(axis.extrapolation));
    out.u32(0);
    out.u64(axis.breakpoints.size());
    out.numbers(axis.breakpoints.data(), axis.breakpoints.size());
  }
  for (std::size_t k = 0; k < n_out; ++k) {
    out.text(table.outputs()[k], what + ": an output name");
    out.text(surface.output_units[k], what + ": an output unit");
  }
  const std::vector<double>& data = evaluated(table);
  if (data.size() != table.node_count() * block)
    throw std::logic_error("runtime export: a table's evaluated array has an unexpected size");
  check_finite(data, what + ": the table's");
  out.numbers(data.data(), data.size());
  if (sigma) {
    out.numbers(surface.loo.data(), surface.loo.size());
    const std::vector<double>& sigma_data = evaluated(*surface.sigma_table);
    check_finite(sigma_data, what + ": the sigma table's");
    out.numbers(sigma_data.data(), sigma_data.size());
  }
  return std::move(out.bytes());
}

// A matrix row by row.
void matrix(Writer& out, const Matrix6& m, const std::string& what) {
  for (Eigen::Index i = 0; i < 6; ++i)
    for (Eigen::Index j = 0; j < 6; ++j) {
      if (!std::isfinite(m(i, j))) throw InputError("runtime export of the vehicle: " + what + " is not finite");
      out.number(m(i, j));
    }
}

// u32 words, then a zero word when their count is odd (to 8 bytes).
void words(Writer& out, const std::vector<std::uint32_t>& values) {
  for (const std::uint32_t v : values) out.u32(v);
  if (values.size() % 2 == 1) out.u32(0);
}

std::string vehicle_section(const RuntimeVehicle& vehicle, const std::vector<RuntimeSurface>& surfaces) {
  const VehicleModel& model = *vehicle.model;
  const VehicleDescription& d = model.description();
  const std::vector<std::string>& disturbances = model.disturbance_names();
  // The frames, units and signs of the state and inputs, stated in the file.
  RuntimeTexts texts = vehicle.metadata;
  texts.emplace_back("state",
                     "13 numbers: p_n, the body origin in NED [m] (3); q_nb, the body-to-NED quaternion, scalar "
                     "first (4); nu_b, the body velocity over ground u, v, w [m/s], p, q, r [rad/s], body axes x "
                     "forward, y starboard, z down (6)");
  texts.emplace_back("inputs",
                     "tau_b, the control force and moment on the body about its origin [N, N m] (6); current_n, "
                     "the water velocity in NED [m/s] (3); the disturbances [SI], in the file's order");
  texts.emplace_back("equation",
                     "M_RB nu' + C_RB(nu) nu + M_A nu_r' + C_A(nu_r) nu_r + D(nu_r) nu_r + g(eta) = tau, nu_r = nu - "
                     "nu_c (Fossen 2011, eq. 6.1 with current); damping and forces on the body (SNAME signs)");
  Writer out;
  out.texts(texts, "runtime export of the vehicle: metadata");
  out.u32(static_cast<std::uint32_t>(disturbances.size()));
  out.u32(static_cast<std::uint32_t>(d.thrusters.size()));
  matrix(out, model.rigid_body_mass(), "M_RB");
  matrix(out, model.added_mass(), "M_A");
  matrix(out, model.mass_matrix(), "M");
  matrix(out, model.mass_matrix_inverse(), "M^-1");
  out.number(model.weight_N());
  out.number(model.buoyancy_N());
  out.numbers(d.r_g_b.data(), 3);
  out.numbers(d.r_b_b.data(), 3);
  out.number(VehicleModel::kQuaternionNormGain);
  for (const std::string& name : disturbances) out.text(name, "runtime export of the vehicle: a disturbance name");
  for (const Thruster& t : d.thrusters) {
    out.text(t.name, "runtime export of the vehicle: a thruster name");
    // VehicleModel's allocation column: (d, r x d).
    const Vector3 moment = t.position_b.cross(t.direction_b);
    out.numbers(t.direction_b.data(), 3);
    out.numbers(moment.data(), 3);
    out.number(t.min_thrust_N);
    out.number(t.max_thrust_N);
  }
  const auto layout = model.damping().layout();
  for (std::size_t dof = 0; dof < 6; ++dof) {
    const DampingModel::DofLayout& l = layout[dof];
    const std::string what = "runtime export of the vehicle: damping of " + std::string(kForceNames[dof]);
    switch (l.kind) {
      case DofDamping::Kind::None:
        for (int i = 0; i < 4; ++i) out.u32(0);
        break;
      case DofDamping::Kind::Law: {
        out.u32(1);
        out.u32(static_cast<std::uint32_t>(l.codes.size()));
        out.u32(static_cast<std::uint32_t>(l.variable));
        out.u32(0);
        words(out, std::vector<std::uint32_t>(l.codes.begin(), l.codes.end()));
        out.numbers(l.coefficients.data(), l.coefficients.size());
        break;
      }
      case DofDamping::Kind::Derivatives: {
        out.u32(2);
        out.u32(static_cast<std::uint32_t>(l.coefficients.size()));
        out.u32(static_cast<std::uint32_t>(l.factors.size()));
        out.u32(0);
        std::vector<std::uint32_t> per_term;
        for (std::size_t k = 0; k + 1 < l.begin.size(); ++k)
          per_term.push_back(static_cast<std::uint32_t>(l.begin[k + 1] - l.begin[k]));
        words(out, per_term);
        for (const hc_damping_factor& f : l.factors) {
          out.u32(static_cast<std::uint32_t>(f.source));
          out.u32(static_cast<std::uint32_t>(f.power));
          out.u32(static_cast<std::uint32_t>(f.odd));
          out.u32(0);
        }
        out.numbers(l.coefficients.data(), l.coefficients.size());
        break;
      }
      case DofDamping::Kind::Surface: {
        const auto found = std::find_if(surfaces.begin(), surfaces.end(),
                                        [&](const RuntimeSurface& s) { return s.name == l.surface; });
        if (found == surfaces.end())
          throw InputError(what + ": surface '" + l.surface + "' is not among the file's surfaces; expected it there");
        const GridTable& table = *found->table;
        if (table.axis_count() > kMaxVehicleAxes || table.output_count() > kMaxVehicleOutputs)
          throw InputError(what + ": surface '" + l.surface + "' has " + std::to_string(table.axis_count()) +
                           " axes and " + std::to_string(table.output_count()) +
                           " outputs; the runtime evaluates a vehicle's surfaces of at most 6 axes and 32 outputs");
        out.u32(3);
        out.u32(static_cast<std::uint32_t>(found - surfaces.begin()));
        out.u32(static_cast<std::uint32_t>(l.output));
        out.u32(static_cast<std::uint32_t>(l.sources.size()));
        out.number(l.sign);
        words(out, std::vector<std::uint32_t>(l.sources.begin(), l.sources.end()));
        break;
      }
    }
  }
  return std::move(out.bytes());
}

}  // namespace

RuntimeSurface runtime_surface(const std::string& name, const CoefficientSurface& surface, RuntimeTexts metadata) {
  if (surface.kind() == CoefficientSurface::Kind::Gp)
    throw InputError("surface '" + name +
                     "' is a GP surface (scattered samples); a runtime file holds gridded "
                     "surfaces; expected a grid: build one from the same runs with --method rbf --resample "
                     "AXIS=FROM:TO:COUNT (one per axis) and export that");
  if (surface.kind() == CoefficientSurface::Kind::Rbf)
    throw InputError("surface '" + name +
                     "' is an RBF surface (scattered samples); a runtime file holds gridded "
                     "surfaces; expected a grid: tabulate it with `hydrocoef surface build NAME ... --method rbf "
                     "--resample AXIS=FROM:TO:COUNT` (one per axis) and export that");
  if (!surface.symmetry().empty())
    throw InputError("surface '" + name +
                     "' has a mirror symmetry imposed (--symmetry); a runtime file holds "
                     "tables evaluated as they are; expected a surface built without --symmetry");
  RuntimeSurface out;
  out.name = name;
  out.table = surface.grid();
  out.axis_units = surface.axis_units();
  out.output_units = surface.output_units();
  if (surface.has_standard_deviation()) {
    out.sigma_table = surface.run_uncertainty_grid();
    out.loo = surface.loo_standard_deviation();
  }
  out.metadata = std::move(metadata);
  return out;
}

RuntimeTexts runtime_model_texts(RuntimeTexts given, bool vehicle) {
  given.emplace_back("format", vehicle ? "hydrocoef runtime file, version 2: surfaces and a vehicle (docs/runtime.md)"
                                       : "hydrocoef runtime file, version 1 (docs/runtime.md)");
  given.emplace_back("hydrocoef_version", kVersion);
  given.emplace_back("frame", "body axes: x forward, y starboard, z down (FRD), origin at the body's reference point");
  given.emplace_back("units",
                     "SI: m/s for u, v, w; rad/s for p, q, r; rad for angles; N for X, Y, Z; N m for K, M, "
                     "N; each axis's and output's unit stated with it");
  given.emplace_back("sign_convention",
                     "on-body: forces and moments of the fluid on the body (SNAME); damping is negative");
  return given;
}

std::string runtime_file_bytes(const RuntimeTexts& model, const std::vector<RuntimeSurface>& surfaces,
                               const RuntimeVehicle* vehicle) {
  if (surfaces.size() > kMaxSurfaces)
    throw InputError("a runtime file holds at most 4096 surfaces; expected fewer than " +
                     std::to_string(surfaces.size()));
  for (std::size_t i = 0; i < surfaces.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (surfaces[i].name == surfaces[j].name)
        throw InputError("surface '" + surfaces[i].name + "' is given twice; expected each surface once");
  std::vector<std::string> sections;
  Writer model_section;
  model_section.texts(model, "runtime export: model metadata");
  sections.push_back(std::move(model_section.bytes()));
  for (const RuntimeSurface& surface : surfaces) sections.push_back(surface_section(surface));
  if (vehicle != nullptr) sections.push_back(vehicle_section(*vehicle, surfaces));

  Writer file;
  std::string& bytes = file.bytes();
  bytes.append(reinterpret_cast<const char*>(kMagic), sizeof kMagic);
  file.u32(vehicle != nullptr ? kVehicleFormatVersion : kFormatVersion);
  file.u32(static_cast<std::uint32_t>(kHeaderSize));
  file.u64(0);  // file size, below
  file.u64(0);  // content hash, below
  file.u32(static_cast<std::uint32_t>(sections.size()));
  file.u32(0);
  file.u64(kHeaderSize);
  bytes.resize(kHeaderSize, '\0');
  std::size_t offset = kHeaderSize + sections.size() * kSectionEntrySize;
  offset = (offset + 7) / 8 * 8;
  for (std::size_t i = 0; i < sections.size(); ++i) {
    file.u32(i == 0                                           ? kSectionModel
             : vehicle != nullptr && i + 1 == sections.size() ? kSectionVehicle
                                                              : kSectionSurface);
    file.u32(0);
    file.u64(offset);
    file.u64(sections[i].size());
    offset += sections[i].size();
  }
  while (bytes.size() % 8 != 0) bytes.push_back('\0');
  for (const std::string& section : sections) bytes += section;
  const auto put_u64 = [&](std::size_t at, std::uint64_t value) {
    for (int i = 0; i < 8; ++i) bytes[at + static_cast<std::size_t>(i)] = static_cast<char>((value >> (8 * i)) & 0xffu);
  };
  put_u64(16, bytes.size());
  put_u64(24, hc_xxh64(bytes.data() + kHeaderSize, bytes.size() - kHeaderSize, 0));
  return std::move(bytes);
}

}  // namespace hydrocoef
