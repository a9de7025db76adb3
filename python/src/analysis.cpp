// The analyses of include/hydrocoef/analysis.hpp in Python: mesh studies
// (grid_convergence), forced oscillation (analyse_pmm, store_pmm, pmm_runs,
// delete_pmm_runs, added_mass_matrix) and the next runs of a GP surface
// (suggest_runs), as module functions taking a Database. Options are keyword
// arguments with the C++ defaults; results are objects with the C++ fields as
// attributes, .text() (what the CLI prints) and .json() (what --json prints).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <string>
#include <vector>

#include "python/src/bindings.hpp"

namespace hydrocoef_python {
namespace {

using namespace pybind11::literals;

/// The calls that make the result classes here.
constexpr const char* kAnalysisMadeBy =
    "hydrocoef's analysis functions (grid_convergence, analyse_pmm, pmm_runs, delete_pmm_runs, added_mass_matrix, "
    "suggest_runs)";

/// A 6x6 matrix as a numpy array.
py::array_t<double> matrix_array(const hydrocoef::Matrix6x6& m) {
  py::array_t<double> out({6, 6});
  auto view = out.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < 6; ++i)
    for (py::ssize_t j = 0; j < 6; ++j) view(i, j) = m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
  return out;
}

std::string text_or_empty(const py::object& value) { return value.is_none() ? "" : value.cast<std::string>(); }

void bind_gci(py::module_& m) {
  py::class_<hydrocoef::GciComponent>(m, "GciComponent", py::is_final(), made_by_the_module_only(kAnalysisMadeBy),
                                      "One force component of one key's mesh study.")
      .def_readonly("component", &hydrocoef::GciComponent::component)
      .def_readonly("phi", &hydrocoef::GciComponent::phi, "Values fine to coarse [N or N m].")
      .def_readonly("r21", &hydrocoef::GciComponent::r21)
      .def_readonly("r32", &hydrocoef::GciComponent::r32)
      .def_readonly("convergence", &hydrocoef::GciComponent::convergence)
      .def_readonly("apparent_order", &hydrocoef::GciComponent::apparent_order)
      .def_readonly("extrapolated", &hydrocoef::GciComponent::extrapolated)
      .def_readonly("relative_error", &hydrocoef::GciComponent::relative_error)
      .def_readonly("extrapolated_relative_error", &hydrocoef::GciComponent::extrapolated_relative_error)
      .def_readonly("gci_fine", &hydrocoef::GciComponent::gci_fine)
      .def_readonly("gci_medium", &hydrocoef::GciComponent::gci_medium)
      .def_readonly("asymptotic_ratio", &hydrocoef::GciComponent::asymptotic_ratio)
      .def_readonly("numerical_uncertainty", &hydrocoef::GciComponent::numerical_uncertainty)
      .def_readonly("values_convergence", &hydrocoef::GciComponent::values_convergence)
      .def_readonly("values_error", &hydrocoef::GciComponent::values_error)
      .def_readonly("note", &hydrocoef::GciComponent::note);
  py::class_<hydrocoef::GciKey>(m, "GciKey", py::is_final(), made_by_the_module_only(kAnalysisMadeBy),
                                "One physical key's mesh study.")
      .def_readonly("body", &hydrocoef::GciKey::body)
      .def_readonly("velocity", &hydrocoef::GciKey::velocity, "u, v, w [m/s], p, q, r [rad/s].")
      .def_readonly("disturbances", &hydrocoef::GciKey::disturbances)
      .def_readonly("description", &hydrocoef::GciKey::description)
      .def_readonly("levels", &hydrocoef::GciKey::levels)
      .def_readonly("cell_sizes", &hydrocoef::GciKey::cell_sizes)
      .def_readonly("runs", &hydrocoef::GciKey::runs)
      .def_readonly("cell_size_from", &hydrocoef::GciKey::cell_size_from)
      .def_readonly("components", &hydrocoef::GciKey::components)
      .def_readonly("notes", &hydrocoef::GciKey::notes);
  py::class_<hydrocoef::GciStudy> study(m, "GciStudy", py::is_final(), made_by_the_module_only(kAnalysisMadeBy),
                                        "A body's mesh studies (Celik et al. 2008), as `hydrocoef gci`.");
  study.def_readonly("body", &hydrocoef::GciStudy::body)
      .def_readonly("mesh_parameter", &hydrocoef::GciStudy::mesh_parameter)
      .def_readonly("safety_factor", &hydrocoef::GciStudy::safety_factor)
      .def_readonly("coverage_factor", &hydrocoef::GciStudy::coverage_factor)
      .def_readonly("keys", &hydrocoef::GciStudy::keys)
      .def_readonly("single_level_keys", &hydrocoef::GciStudy::single_level_keys)
      .def_readonly("runs_without_level", &hydrocoef::GciStudy::runs_without_level)
      .def_readonly("stored", &hydrocoef::GciStudy::stored)
      .def_readonly("fits_made_stale", &hydrocoef::GciStudy::fits_made_stale)
      .def_readonly("surfaces_made_stale", &hydrocoef::GciStudy::surfaces_made_stale);
  add_text_and_json(study);

  m.def(
      "grid_convergence",
      [](py::handle db, const std::string& body, const std::string& mesh_parameter, std::optional<double> volume,
         int dimension, bool allow_unconverged, bool store) {
        hydrocoef::GciOptions options;
        options.body = body;
        options.mesh_parameter = mesh_parameter;
        options.volume = volume;
        options.dimension = dimension;
        options.allow_unconverged = allow_unconverged;
        options.store = store;
        auto& database = database_of(db);
        const py::gil_scoped_release release;
        return hydrocoef::grid_convergence(database, options);
      },
      "database"_a, py::kw_only(), "body"_a, "mesh_parameter"_a = "mesh", "volume"_a = py::none(), "dimension"_a = 3,
      "allow_unconverged"_a = false, "store"_a = true,
      R"doc(The body's mesh studies by Celik et al. (2008), stored unless store=False, as `hydrocoef gci`.

Runs state their mesh with disturbances mesh (the level; mesh_parameter) and cells (N, with volume and
dimension: h = (V/N)^(1/D)) or cell_size (h in m). Returns a GciStudy.)doc");
}

void bind_pmm(py::module_& m) {
  py::class_<hydrocoef::PmmComponent>(m, "PmmComponent", py::is_final(), made_by_the_module_only(kAnalysisMadeBy),
                                      "One force component of a forced-oscillation run: entry [component][dof].")
      .def_readonly("component", &hydrocoef::PmmComponent::component)
      .def_readonly("mean", &hydrocoef::PmmComponent::mean)
      .def_readonly("added_mass", &hydrocoef::PmmComponent::added_mass)
      .def_readonly("added_mass_se", &hydrocoef::PmmComponent::added_mass_se)
      .def_readonly("added_mass_unit", &hydrocoef::PmmComponent::added_mass_unit)
      .def_readonly("damping", &hydrocoef::PmmComponent::damping)
      .def_readonly("damping_se", &hydrocoef::PmmComponent::damping_se)
      .def_readonly("damping_unit", &hydrocoef::PmmComponent::damping_unit)
      .def_readonly("explained", &hydrocoef::PmmComponent::explained)
      .def_readonly("harmonics", &hydrocoef::PmmComponent::harmonics)
      .def_readonly("added_mass_coefficient", &hydrocoef::PmmComponent::added_mass_coefficient)
      .def_readonly("in_phase_spread", &hydrocoef::PmmComponent::in_phase_spread)
      .def_readonly("quadrature_spread", &hydrocoef::PmmComponent::quadrature_spread);
  py::class_<hydrocoef::PmmRunResult>(m, "PmmRun", py::is_final(), made_by_the_module_only(kAnalysisMadeBy),
                                      "One forced-oscillation run analysed.")
      .def_readonly("path", &hydrocoef::PmmRunResult::path)
      .def_readonly("format", &hydrocoef::PmmRunResult::format)
      .def_readonly("body", &hydrocoef::PmmRunResult::body)
      .def_readonly("velocity", &hydrocoef::PmmRunResult::velocity)
      .def_readonly("dof", &hydrocoef::PmmRunResult::dof)
      .def_readonly("amplitude", &hydrocoef::PmmRunResult::amplitude)
      .def_readonly("omega", &hydrocoef::PmmRunResult::omega)
      .def_readonly("period", &hydrocoef::PmmRunResult::period)
      .def_readonly("phase", &hydrocoef::PmmRunResult::phase)
      .def_readonly("motion_source", &hydrocoef::PmmRunResult::motion_source)
      .def_readonly("medium", &hydrocoef::PmmRunResult::medium)
      .def_readonly("window_start", &hydrocoef::PmmRunResult::window_start)
      .def_readonly("window_end", &hydrocoef::PmmRunResult::window_end)
      .def_readonly("periods", &hydrocoef::PmmRunResult::periods)
      .def_readonly("transient_periods", &hydrocoef::PmmRunResult::transient_periods)
      .def_readonly("samples", &hydrocoef::PmmRunResult::samples)
      .def_readonly("harmonics", &hydrocoef::PmmRunResult::harmonics)
      .def_readonly("size", &hydrocoef::PmmRunResult::size)
      .def_readonly("keulegan_carpenter", &hydrocoef::PmmRunResult::keulegan_carpenter)
      .def_readonly("stokes_number", &hydrocoef::PmmRunResult::stokes_number)
      .def_readonly("rho", &hydrocoef::PmmRunResult::rho)
      .def_readonly("displaced_volume", &hydrocoef::PmmRunResult::displaced_volume)
      .def_readonly("restoring", &hydrocoef::PmmRunResult::restoring)
      .def_readonly("notes", &hydrocoef::PmmRunResult::notes)
      .def_readonly("components", &hydrocoef::PmmRunResult::components)
      .def_readonly("stored_id", &hydrocoef::PmmRunResult::stored_id)
      .def_readonly("replaced", &hydrocoef::PmmRunResult::replaced);
  py::class_<hydrocoef::PmmAnalysis> analysis(m, "PmmAnalysis", py::is_final(),
                                              made_by_the_module_only(kAnalysisMadeBy),
                                              "Forced-oscillation runs analysed, as `hydrocoef pmm`.");
  analysis.def_readonly("runs", &hydrocoef::PmmAnalysis::runs)
      .def_readonly("stored", &hydrocoef::PmmAnalysis::stored)
      .def_readonly("database", &hydrocoef::PmmAnalysis::database);
  add_text_and_json(analysis);

  m.def(
      "analyse_pmm",
      [](const py::object& inputs, const std::string& body, const std::string& axes,
         std::optional<std::array<double, 3>> origin, std::optional<std::array<double, 3>> ref_point,
         std::optional<double> rho, std::optional<double> nu, std::optional<std::map<std::string, double>> set,
         std::optional<std::map<std::string, std::string>> columns,
         std::optional<std::map<std::string, std::string>> units, std::optional<std::string> sign,
         std::optional<std::string> motion, std::optional<double> amplitude, std::optional<double> period, double phase,
         std::optional<std::string> ccl, int harmonics, std::optional<double> start, bool stream,
         std::optional<double> volume, std::optional<double> restoring, std::optional<double> size, unsigned jobs) {
        std::vector<std::string> paths;
        if (py::isinstance<py::str>(inputs) || py::hasattr(inputs, "__fspath__"))
          paths.push_back(py::str(py::module_::import("os").attr("fspath")(inputs)).cast<std::string>());
        else
          for (const auto& item : inputs)
            paths.push_back(py::str(py::module_::import("os").attr("fspath")(item)).cast<std::string>());
        hydrocoef::PmmOptions options;
        options.body = body;
        options.axes = axes;
        options.origin = origin;
        options.ref_point = ref_point;
        options.rho = rho;
        options.nu = nu;
        if (set) options.set = *set;
        if (columns) options.columns = *columns;
        if (units) options.units = *units;
        options.sign = sign;
        options.motion = motion;
        options.amplitude = amplitude;
        options.period = period;
        options.phase = phase;
        options.ccl = ccl;
        options.harmonics = harmonics;
        options.start = start;
        options.stream = stream;
        options.volume = volume;
        options.restoring = restoring;
        options.size = size;
        options.jobs = jobs;
        const py::gil_scoped_release release;
        return hydrocoef::analyse_pmm(paths, options);
      },
      "inputs"_a, py::kw_only(), "body"_a = "", "axes"_a = "", "origin"_a = py::none(), "ref_point"_a = py::none(),
      "rho"_a = py::none(), "nu"_a = py::none(), "set"_a = py::none(), "columns"_a = py::none(), "units"_a = py::none(),
      "sign"_a = py::none(), "motion"_a = py::none(), "amplitude"_a = py::none(), "period"_a = py::none(),
      "phase"_a = 0.0, "ccl"_a = py::none(), "harmonics"_a = 1, "start"_a = py::none(), "stream"_a = false,
      "volume"_a = py::none(), "restoring"_a = py::none(), "size"_a = py::none(), "jobs"_a = 0,
      R"doc(Analyses forced-oscillation runs (force histories, OpenFOAM case folders), storing nothing, as
`hydrocoef pmm --no-store`. The motion is the case's unless motion ("surge".."yaw"), amplitude [m or rad]
and period [s] are all given. axes: body axes in CFD axes ("-x,y,-z"); rho [kg/m^3], nu [m^2/s];
volume: displaced volume [m^3]; size: body size [m] for the KC and Stokes numbers. Returns a PmmAnalysis;
store_pmm(db, analysis) stores it.)doc");
  m.def(
      "store_pmm",
      [](py::handle db, hydrocoef::PmmAnalysis& result) {
        auto& database = database_of(db);
        const py::gil_scoped_release release;
        hydrocoef::store_pmm(database, result);
      },
      "database"_a, "analysis"_a,
      "Stores an analysis's runs in one transaction (as `hydrocoef pmm` does) and notes their ids in it.");

  py::class_<hydrocoef::PmmRunSummary>(m, "PmmRunSummary", py::is_final(), made_by_the_module_only(kAnalysisMadeBy),
                                       "A stored forced-oscillation run, as `hydrocoef pmm-runs` lists it.")
      .def_readonly("id", &hydrocoef::PmmRunSummary::id)
      .def_readonly("body", &hydrocoef::PmmRunSummary::body)
      .def_readonly("dof", &hydrocoef::PmmRunSummary::dof)
      .def_readonly("amplitude", &hydrocoef::PmmRunSummary::amplitude)
      .def_readonly("amplitude_unit", &hydrocoef::PmmRunSummary::amplitude_unit)
      .def_readonly("period", &hydrocoef::PmmRunSummary::period)
      .def_readonly("omega", &hydrocoef::PmmRunSummary::omega)
      .def_readonly("medium", &hydrocoef::PmmRunSummary::medium)
      .def_readonly("restoring", &hydrocoef::PmmRunSummary::restoring)
      .def_readonly("added_mass", &hydrocoef::PmmRunSummary::added_mass)
      .def_readonly("damping", &hydrocoef::PmmRunSummary::damping)
      .def_readonly("added_mass_unit", &hydrocoef::PmmRunSummary::added_mass_unit)
      .def_readonly("damping_unit", &hydrocoef::PmmRunSummary::damping_unit)
      .def_readonly("source_path", &hydrocoef::PmmRunSummary::source_path)
      .def_readonly("created_at", &hydrocoef::PmmRunSummary::created_at);
  py::class_<hydrocoef::PmmRunList> list(m, "PmmRunList", py::is_final(), made_by_the_module_only(kAnalysisMadeBy),
                                         "The stored forced-oscillation runs.");
  list.def_readonly("runs", &hydrocoef::PmmRunList::runs);
  add_text_and_json(list);
  m.def(
      "pmm_runs",
      [](py::handle db, const py::object& body) {
        const auto& database = database_of(db);
        const std::string name = text_or_empty(body);
        const py::gil_scoped_release release;
        return hydrocoef::pmm_runs(database, name);
      },
      "database"_a, "body"_a = py::none(),
      "The stored forced-oscillation runs (of one body), as `hydrocoef pmm-runs`.");

  py::class_<hydrocoef::PmmDeletedRun>(m, "PmmDeletedRun", py::is_final(), made_by_the_module_only(kAnalysisMadeBy))
      .def_readonly("id", &hydrocoef::PmmDeletedRun::id)
      .def_readonly("body", &hydrocoef::PmmDeletedRun::body)
      .def_readonly("dof", &hydrocoef::PmmDeletedRun::dof)
      .def_readonly("source_path", &hydrocoef::PmmDeletedRun::source_path);
  py::class_<hydrocoef::PmmDeletion> deletion(m, "PmmDeletion", py::is_final(),
                                              made_by_the_module_only(kAnalysisMadeBy),
                                              "What `hydrocoef pmm-runs delete` removed.");
  deletion.def_readonly("database", &hydrocoef::PmmDeletion::database)
      .def_readonly("deleted", &hydrocoef::PmmDeletion::deleted);
  add_text_and_json(deletion);
  m.def(
      "delete_pmm_runs",
      [](py::handle db, const py::object& ids) {
        auto& database = database_of(db);
        const auto id_list = run_ids(ids, "ids");
        const py::gil_scoped_release release;
        return hydrocoef::delete_pmm_runs(database, id_list);
      },
      "database"_a, "ids"_a,
      "Deletes stored forced-oscillation runs by id in one transaction; an id not stored deletes nothing.");
}

void bind_added_mass(py::module_& m) {
  py::class_<hydrocoef::AddedMassEntry>(m, "AddedMassEntry", py::is_final(), made_by_the_module_only(kAnalysisMadeBy),
                                        "One measured entry of the added-mass matrix, before symmetry.")
      .def_readonly("row", &hydrocoef::AddedMassEntry::row)
      .def_readonly("column", &hydrocoef::AddedMassEntry::column)
      .def_readonly("name", &hydrocoef::AddedMassEntry::name)
      .def_readonly("unit", &hydrocoef::AddedMassEntry::unit)
      .def_readonly("runs", &hydrocoef::AddedMassEntry::runs)
      .def_readonly("added_mass", &hydrocoef::AddedMassEntry::added_mass)
      .def_readonly("added_mass_se", &hydrocoef::AddedMassEntry::added_mass_se)
      .def_readonly("added_mass_spread", &hydrocoef::AddedMassEntry::added_mass_spread)
      .def_readonly("damping", &hydrocoef::AddedMassEntry::damping)
      .def_readonly("damping_se", &hydrocoef::AddedMassEntry::damping_se)
      .def_readonly("omega_min", &hydrocoef::AddedMassEntry::omega_min)
      .def_readonly("omega_max", &hydrocoef::AddedMassEntry::omega_max)
      .def_readonly("kc_min", &hydrocoef::AddedMassEntry::kc_min)
      .def_readonly("kc_max", &hydrocoef::AddedMassEntry::kc_max)
      .def_readonly("pmm_runs", &hydrocoef::AddedMassEntry::pmm_runs);
  py::class_<hydrocoef::AddedMassFrequency>(m, "AddedMassFrequency", py::is_final(),
                                            made_by_the_module_only(kAnalysisMadeBy),
                                            "The in-line added mass and damping of one DOF at one frequency.")
      .def_readonly("dof", &hydrocoef::AddedMassFrequency::dof)
      .def_readonly("omega", &hydrocoef::AddedMassFrequency::omega)
      .def_readonly("period", &hydrocoef::AddedMassFrequency::period)
      .def_readonly("runs", &hydrocoef::AddedMassFrequency::runs)
      .def_readonly("amplitude_min", &hydrocoef::AddedMassFrequency::amplitude_min)
      .def_readonly("amplitude_max", &hydrocoef::AddedMassFrequency::amplitude_max)
      .def_readonly("added_mass", &hydrocoef::AddedMassFrequency::added_mass)
      .def_readonly("added_mass_se", &hydrocoef::AddedMassFrequency::added_mass_se)
      .def_readonly("damping", &hydrocoef::AddedMassFrequency::damping)
      .def_readonly("damping_se", &hydrocoef::AddedMassFrequency::damping_se)
      .def_readonly("used", &hydrocoef::AddedMassFrequency::used);
  py::class_<hydrocoef::QuadraticDampingFit>(m, "QuadraticDampingFit", py::is_final(),
                                             made_by_the_module_only(kAnalysisMadeBy),
                                             "D_eq(A) = linear + quadratic (8/(3 pi)) A omega.")
      .def_readonly("dof", &hydrocoef::QuadraticDampingFit::dof)
      .def_readonly("omega", &hydrocoef::QuadraticDampingFit::omega)
      .def_readonly("amplitudes", &hydrocoef::QuadraticDampingFit::amplitudes)
      .def_readonly("linear", &hydrocoef::QuadraticDampingFit::linear)
      .def_readonly("linear_se", &hydrocoef::QuadraticDampingFit::linear_se)
      .def_readonly("quadratic", &hydrocoef::QuadraticDampingFit::quadratic)
      .def_readonly("quadratic_se", &hydrocoef::QuadraticDampingFit::quadratic_se);
  py::class_<hydrocoef::AddedMassMatrix> matrix(
      m, "AddedMassMatrix", py::is_final(), made_by_the_module_only(kAnalysisMadeBy),
      "A body's 6x6 added-mass and damping matrices (rows and columns surge..yaw), as `hydrocoef added-mass`.");
  matrix.def_readonly("body", &hydrocoef::AddedMassMatrix::body)
      .def_readonly("omega", &hydrocoef::AddedMassMatrix::omega)
      .def_readonly("period", &hydrocoef::AddedMassMatrix::period)
      .def_readonly("records", &hydrocoef::AddedMassMatrix::records)
      .def_readonly("other_frequency_records", &hydrocoef::AddedMassMatrix::other_frequency_records)
      .def_property_readonly(
          "added_mass", [](const hydrocoef::AddedMassMatrix& a) { return matrix_array(a.added_mass); },
          "M_A (6x6 numpy array; kg, kg m, kg m^2), symmetric.")
      .def_property_readonly("added_mass_se",
                             [](const hydrocoef::AddedMassMatrix& a) { return matrix_array(a.added_mass_se); })
      .def_property_readonly(
          "damping", [](const hydrocoef::AddedMassMatrix& a) { return matrix_array(a.damping); },
          "D (6x6 numpy array; N s/m, N s, N m s), as measured.")
      .def_property_readonly("damping_se",
                             [](const hydrocoef::AddedMassMatrix& a) { return matrix_array(a.damping_se); })
      .def_readonly("entries", &hydrocoef::AddedMassMatrix::entries)
      .def_readonly("missing", &hydrocoef::AddedMassMatrix::missing)
      .def_readonly("notes", &hydrocoef::AddedMassMatrix::notes)
      .def_readonly("positive_definite", &hydrocoef::AddedMassMatrix::positive_definite)
      .def_readonly("smallest_eigenvalue", &hydrocoef::AddedMassMatrix::smallest_eigenvalue)
      .def_readonly("quadratic_damping", &hydrocoef::AddedMassMatrix::quadratic_damping)
      .def_readonly("by_frequency", &hydrocoef::AddedMassMatrix::by_frequency);
  add_text_and_json(matrix);
  m.def(
      "added_mass_matrix",
      [](py::handle db, const std::string& body, std::optional<std::map<std::string, std::string>> same,
         const py::object& zero, std::optional<double> period, bool allow_indefinite) {
        hydrocoef::AddedMassMatrixOptions options;
        options.body = body;
        if (same) options.same = *same;
        options.zero = texts(zero, "zero");
        options.period = period;
        options.allow_indefinite = allow_indefinite;
        const auto& database = database_of(db);
        const py::gil_scoped_release release;
        return hydrocoef::added_mass_matrix(database, options);
      },
      "database"_a, "body"_a, py::kw_only(), "same"_a = py::none(), "zero"_a = py::none(), "period"_a = py::none(),
      "allow_indefinite"_a = false,
      R"doc(The body's 6x6 added-mass (and damping) matrices from its stored forced-oscillation runs, as
`hydrocoef added-mass`. same: {"sway": "surge"} takes a DOF no run moves from another; zero: DOFs whose
added mass is zero; period [s]: the runs that make the matrices when there are several frequencies.
Returns an AddedMassMatrix.)doc");
}

void bind_suggest(py::module_& m) {
  py::class_<hydrocoef::SuggestedKey>(m, "SuggestedKey", py::is_final(), made_by_the_module_only(kAnalysisMadeBy),
                                      "A proposed run key and the standard deviation there before it was chosen.")
      .def_readonly("key", &hydrocoef::SuggestedKey::key)
      .def_readonly("sd_before", &hydrocoef::SuggestedKey::sd_before);
  py::class_<hydrocoef::Suggestion> suggestion(m, "Suggestion", py::is_final(),
                                               made_by_the_module_only(kAnalysisMadeBy),
                                               "The next runs of a GP surface, as `hydrocoef suggest`.");
  suggestion.def_readonly("surface", &hydrocoef::Suggestion::surface)
      .def_readonly("output", &hydrocoef::Suggestion::output)
      .def_readonly("unit", &hydrocoef::Suggestion::unit)
      .def_readonly("axes", &hydrocoef::Suggestion::axes)
      .def_readonly("lower", &hydrocoef::Suggestion::lower)
      .def_readonly("upper", &hydrocoef::Suggestion::upper)
      .def_readonly("resolution", &hydrocoef::Suggestion::resolution)
      .def_readonly("resolution_given", &hydrocoef::Suggestion::resolution_given)
      .def_readonly("mirror", &hydrocoef::Suggestion::mirror)
      .def_readonly("domain", &hydrocoef::Suggestion::domain)
      .def_readonly("candidates", &hydrocoef::Suggestion::candidates)
      .def_readonly("imported_skipped", &hydrocoef::Suggestion::imported_skipped)
      .def_readonly("running_skipped", &hydrocoef::Suggestion::running_skipped)
      .def_readonly("runs", &hydrocoef::Suggestion::runs)
      .def_readonly("largest_sd_after", &hydrocoef::Suggestion::largest_sd_after)
      .def_readonly("manifest", &hydrocoef::Suggestion::manifest);
  add_text_and_json(suggestion);
  m.def(
      "suggest_runs",
      [](py::handle db, const std::string& surface, std::size_t count, const py::object& bounds,
         const py::object& output, std::size_t candidates, const py::object& round, const py::object& running,
         const py::object& manifest) {
        hydrocoef::SuggestOptions options;
        options.surface = surface;
        options.count = count;
        options.bounds = texts(bounds, "bounds");
        options.output = text_or_empty(output);
        options.candidates = candidates;
        options.round = texts(round, "round");
        for (const auto& file : texts(running, "running")) options.running.push_back(file);
        options.manifest =
            manifest.is_none() ? "" : py::str(py::module_::import("os").attr("fspath")(manifest)).cast<std::string>();
        const auto& database = database_of(db);
        const py::gil_scoped_release release;
        return hydrocoef::suggest_runs(database, options);
      },
      "database"_a, "surface"_a, py::kw_only(), "count"_a = 5, "bounds"_a = py::none(), "output"_a = py::none(),
      "candidates"_a = 4096, "round"_a = py::none(), "running"_a = py::none(), "manifest"_a = py::none(),
      R"doc(The next runs of a GP surface: the keys that most reduce its largest standard deviation inside
the bounds ("u=0.1:0.4"), rounded ("u=0.01"), as `hydrocoef suggest`; written as a sweep manifest when
manifest names a file. Returns a Suggestion.)doc");
}

}  // namespace

void register_analysis(py::module_& m) {
  bind_gci(m);
  bind_pmm(m);
  bind_added_mass(m);
  bind_suggest(m);
  for (const char* name :
       {"GciComponent", "GciKey", "GciStudy", "PmmComponent", "PmmRun", "PmmAnalysis", "PmmRunSummary", "PmmRunList",
        "PmmDeletedRun", "PmmDeletion", "AddedMassEntry", "AddedMassFrequency", "QuadraticDampingFit",
        "AddedMassMatrix", "SuggestedKey", "Suggestion"})
    m.attr(name).attr("__module__") = "hydrocoef";
}

}  // namespace hydrocoef_python
