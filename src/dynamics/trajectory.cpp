#include "src/dynamics/trajectory.hpp"

#include <array>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "src/core/atomic_file.hpp"
#include "src/core/error.hpp"
#include "src/core/numbers.hpp"

namespace hydrocoef {
namespace {

template <class Vector>
void append_all(std::string& line, const Vector& v) {
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    line += ',';
    append_shortest_number(line, v[i]);
  }
}

}  // namespace

TrajectorySample make_sample(const VehicleModel& model, double t_s, const StateVector& x, const ModelInputs& inputs) {
  TrajectorySample s;
  s.t_s = t_s;
  s.p_n = position_n(x);
  s.q_nb = unit_attitude(attitude_nb(x));
  s.euler_rad = euler_from_quaternion(s.q_nb);
  s.nu_b = velocity_b(x);
  s.forces = model.forces(x, inputs);
  return s;
}

std::string trajectory_csv_header() {
  std::string h =
      "t [s],x_n [m],y_n [m],z_n [m],phi [rad],theta [rad],psi [rad],q_eta,q_eps1,q_eps2,q_eps3,"
      "u [m s^-1],v [m s^-1],w [m s^-1],p [rad s^-1],q [rad s^-1],r [rad s^-1],"
      "u_r [m s^-1],v_r [m s^-1],w_r [m s^-1],p_r [rad s^-1],q_r [rad s^-1],r_r [rad s^-1]";
  for (const char* term : {"control", "damping", "hydrostatic", "coriolis"}) {
    for (const char* f : {"X", "Y", "Z"}) h += std::string(",") + f + "_" + term + " [N]";
    for (const char* m : {"K", "M", "N"}) h += std::string(",") + m + "_" + term + " [N m]";
  }
  return h;
}

std::size_t TrajectoryBands::quantity_index(std::string_view name) const {
  for (std::size_t q = 0; q < quantities.size(); ++q)
    if (quantities[q] == name) return q;
  std::string list;
  for (const auto& n : quantities) list += (list.empty() ? "" : ", ") + n;
  throw InputError("found the quantity '" + std::string(name) + "', expected one of " + list);
}

std::string band_column(std::string_view quantity, double percentile) {
  return std::string(quantity) + "_p" + shortest_number(percentile);
}

void write_trajectory_csv(std::ostream& out, const std::vector<TrajectorySample>& samples,
                          const TrajectoryBands* bands) {
  if (bands && bands->t_s.size() != samples.size())
    throw std::invalid_argument("write_trajectory_csv: bands at other times than the samples");
  std::string header = trajectory_csv_header();
  if (bands)
    for (std::size_t q = 0; q < bands->quantities.size(); ++q)
      for (const double p : bands->percentiles)
        header += "," + band_column(bands->quantities[q], p) + " [" + bands->units[q] + "]";
  out << header << '\n';
  std::string line;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const auto& s = samples[k];
    line.clear();
    append_shortest_number(line, s.t_s);
    append_all(line, s.p_n);
    append_all(line, s.euler_rad);
    append_all(line, s.q_nb);
    append_all(line, s.nu_b);
    append_all(line, s.forces.nu_r_b);
    append_all(line, s.forces.control_b);
    append_all(line, s.forces.damping_b);
    append_all(line, s.forces.hydrostatic_b);
    append_all(line, s.forces.coriolis_b);
    if (bands)
      for (std::size_t q = 0; q < bands->quantities.size(); ++q)
        for (std::size_t j = 0; j < bands->percentiles.size(); ++j) {
          line += ',';
          append_shortest_number(line, bands->value(q, j, k));
        }
    line += '\n';
    out << line;
  }
}

void write_trajectory_csv(const std::filesystem::path& path, const std::vector<TrajectorySample>& samples,
                          const TrajectoryBands* bands) {
  // Whole or not at all: a failed write (a full disk) leaves no partial file.
  std::ostringstream out;
  write_trajectory_csv(out, samples, bands);
  write_file_atomically(path, out.str());
}

}  // namespace hydrocoef
