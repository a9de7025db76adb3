// The sway and yaw derivatives of include/hydrocoef/pmm_derivatives.hpp in
// Python: pmm_derivatives(db, body, ...), as `hydrocoef derivatives pmm`.
// Options are keyword arguments with the C++ defaults; the result is an
// object with the C++ fields as attributes, .text() (what the CLI prints) and
// .json() (what --json prints).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "python/src/bindings.hpp"

namespace hydrocoef_python {
namespace {

using namespace pybind11::literals;

/// The call that makes the result classes here.
constexpr const char* kPmmDerivativesMadeBy = "pmm_derivatives";

}  // namespace

void register_pmm_derivatives(py::module_& m) {
  using hydrocoef::PmmDerivative;
  using hydrocoef::PmmDerivativeRun;
  using hydrocoef::PmmDerivatives;
  using hydrocoef::PmmFrequencyDerivatives;
  py::class_<PmmDerivative>(m, "PmmDerivative", py::is_final(), made_by_the_module_only(kPmmDerivativesMadeBy),
                            "One sway or yaw derivative (SI), with its prime form when L, rho and U are known.")
      .def_readonly("name", &PmmDerivative::name, "Y_v, Y_vdot, N_v, N_vdot, Y_r, Y_rdot, N_r or N_rdot.")
      .def_readonly("value", &PmmDerivative::value)
      .def_readonly("std_error", &PmmDerivative::std_error)
      .def_readonly("unit", &PmmDerivative::unit)
      .def_readonly("source", &PmmDerivative::source, "The stored entry it is, e.g. -M_A[sway][sway].")
      .def_readonly("prime", &PmmDerivative::prime, "The prime (SNAME 1950) value, or None.")
      .def_readonly("prime_std_error", &PmmDerivative::prime_std_error)
      .def_readonly("normalisation", &PmmDerivative::normalisation);
  py::class_<PmmFrequencyDerivatives>(m, "PmmFrequencyDerivatives", py::is_final(),
                                      made_by_the_module_only(kPmmDerivativesMadeBy),
                                      "The derivatives of the runs of one motion at one speed and frequency.")
      .def_readonly("motion", &PmmFrequencyDerivatives::motion, "pure sway or pure yaw.")
      .def_readonly("dof", &PmmFrequencyDerivatives::dof)
      .def_readonly("speed", &PmmFrequencyDerivatives::speed, "U [m/s].")
      .def_readonly("omega", &PmmFrequencyDerivatives::omega, "[rad/s]")
      .def_readonly("period", &PmmFrequencyDerivatives::period, "[s]")
      .def_readonly("omega_prime", &PmmFrequencyDerivatives::omega_prime, "omega L / U, or None.")
      .def_readonly("runs", &PmmFrequencyDerivatives::runs)
      .def_readonly("amplitude_min", &PmmFrequencyDerivatives::amplitude_min)
      .def_readonly("amplitude_max", &PmmFrequencyDerivatives::amplitude_max)
      .def_readonly("amplitude_unit", &PmmFrequencyDerivatives::amplitude_unit)
      .def_readonly("pmm_runs", &PmmFrequencyDerivatives::pmm_runs)
      .def_readonly("derivatives", &PmmFrequencyDerivatives::derivatives);
  py::class_<PmmDerivativeRun>(m, "PmmDerivativeRun", py::is_final(), made_by_the_module_only(kPmmDerivativesMadeBy),
                               "One stored run's derivatives (SI).")
      .def_readonly("id", &PmmDerivativeRun::id)
      .def_readonly("dof", &PmmDerivativeRun::dof)
      .def_readonly("speed", &PmmDerivativeRun::speed)
      .def_readonly("amplitude", &PmmDerivativeRun::amplitude)
      .def_readonly("omega", &PmmDerivativeRun::omega)
      .def_readonly("source_path", &PmmDerivativeRun::source_path)
      .def_readonly("derivatives", &PmmDerivativeRun::derivatives);
  py::class_<PmmDerivatives>(m, "PmmDerivatives", py::is_final(), made_by_the_module_only(kPmmDerivativesMadeBy),
                             "A body's sway and yaw derivatives, as `hydrocoef derivatives pmm`.")
      .def_readonly("body", &PmmDerivatives::body)
      .def_readonly("length", &PmmDerivatives::length, "L [m] used, or None.")
      .def_readonly("density", &PmmDerivatives::density, "rho [kg/m^3] used, or None.")
      .def_readonly("length_from", &PmmDerivatives::length_from)
      .def_readonly("density_from", &PmmDerivatives::density_from)
      .def_readonly("sets", &PmmDerivatives::sets)
      .def_readonly("runs", &PmmDerivatives::runs)
      .def_readonly("other_runs", &PmmDerivatives::other_runs)
      .def_readonly("notes", &PmmDerivatives::notes)
      .def("text", &PmmDerivatives::text, "What the hydrocoef CLI prints.")
      .def("json", &PmmDerivatives::json, "What the hydrocoef CLI prints with --json (a JSON text).");
  m.def(
      "pmm_derivatives",
      [](py::handle db, const std::string& body, const py::object& runs, std::optional<double> speed,
         std::optional<double> length, std::optional<double> density, bool prime) {
        hydrocoef::PmmDerivativeOptions options;
        options.body = body;
        options.runs = run_ids(runs, "runs");
        options.speed = speed;
        options.length = length;
        options.density = density;
        options.prime = prime;
        const auto& database = database_of(db);
        const py::gil_scoped_release release;
        return hydrocoef::pmm_derivatives(database, options);
      },
      "database"_a, "body"_a, py::kw_only(), "runs"_a = py::none(), "speed"_a = py::none(), "length"_a = py::none(),
      "density"_a = py::none(), "prime"_a = false,
      R"doc(The body's sway and yaw derivatives (Y_v, Y_vdot, N_v, N_vdot; Y_r, Y_rdot, N_r, N_rdot) from its
stored pure sway and pure yaw forced-oscillation runs, as `hydrocoef derivatives pmm`. runs: pmm run ids
(None: all the body's sway and yaw runs); speed: U [m/s] for every run (None: each run's u); length: L [m]
(None: the body's reference length); density [kg/m^3] (None: the runs'); prime: refuse unless omega' and the
prime form can be given. Returns a PmmDerivatives.)doc");
}

}  // namespace hydrocoef_python
