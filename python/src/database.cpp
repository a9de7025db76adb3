// hydrocoef.Database in Python: opening and closing (once per object),
// the runs as numpy columns, import_files with what it returns
// (ImportedFile, ImportSummary), one run with its provenance (show_run:
// RunDetails), delete_runs, merge, copy_to, migration and report, each
// result with the CLI's text() and json(). Fits and surfaces add their
// methods in fits.cpp and surfaces.cpp.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "python/src/bindings.hpp"

namespace hydrocoef_python {
namespace {

using namespace pybind11::literals;
using hydrocoef::Database;

/// A new 1-D numpy array that owns the vector's storage (no copy).
template <class T>
py::array_t<T> to_numpy(std::vector<T>&& values) {
  auto owned = std::make_unique<std::vector<T>>(std::move(values));
  const auto size = static_cast<py::ssize_t>(owned->size());
  T* data = owned->data();
  py::capsule owner(owned.get(), [](void* p) { delete static_cast<std::vector<T>*>(p); });
  owned.release();
  return py::array_t<T>(size, data, owner);
}

/// Texts as a numpy array of Python str (dtype object), as pandas keeps them.
py::array to_numpy_strings(const std::vector<std::string>& texts) {
  py::list list(texts.size());
  for (std::size_t i = 0; i < texts.size(); ++i) list[i] = py::str(texts[i]);
  return py::module_::import("numpy").attr("array")(list, "dtype"_a = "object");
}

/// Whether `self` holds its C++ Database: false for an object made by
/// __new__ alone (Database.__new__(Database), object.__new__, a base class's
/// __new__), whose storage pybind11 never filled.
bool holds_database(py::handle self) {
  if (!py::isinstance<Database>(self))
    throw py::type_error("expected a hydrocoef.Database, got " +
                         py::str(py::type::handle_of(self).attr("__name__")).cast<std::string>());
  auto* instance = reinterpret_cast<py::detail::instance*>(self.ptr());
  auto holder = instance->get_value_and_holder(py::detail::get_type_info(typeid(Database)), false);
  return holder && holder.holder_constructed();
}

std::string fspath(const py::handle& path) {
  return py::module_::import("os").attr("fspath")(path).cast<std::string>();
}

hydrocoef::OpenMode parse_mode(const std::string& mode) {
  if (mode == "r") return hydrocoef::OpenMode::ReadOnly;
  if (mode == "rw") return hydrocoef::OpenMode::ReadWrite;
  if (mode == "create") return hydrocoef::OpenMode::Create;
  throw py::value_error("mode '" + mode +
                        "': expected 'r' (read only), 'rw' (read and write an existing database) "
                        "or 'create' (read and write, made when missing)");
}

constexpr const char* kForceNames[] = {"X", "Y", "Z", "K", "M", "N"};

py::dict runs_dict(hydrocoef::RunTable&& table) {
  py::dict out;
  out["id"] = to_numpy(std::move(table.id));
  out["body"] = to_numpy_strings(table.body);
  for (std::size_t c = 0; c < 6; ++c) out[kVelocityNames[c]] = to_numpy(std::move(table.velocity[c]));
  for (auto& [name, column] : table.disturbances) {
    // A disturbance named like a fixed column (an identifier such as "id" or "X") is kept apart.
    const std::string key =
        out.contains(name) || name == "source" || name == "history_flags" ||
                std::find(std::begin(kForceNames), std::end(kForceNames), name) != std::end(kForceNames) ||
                name.ends_with("_std_error")
            ? "disturbance." + name
            : name;
    out[py::str(key)] = to_numpy(std::move(column));
  }
  for (std::size_t c = 0; c < 6; ++c) out[kForceNames[c]] = to_numpy(std::move(table.force[c]));
  for (std::size_t c = 0; c < 6; ++c)
    out[py::str(std::string(kForceNames[c]) + "_std_error")] = to_numpy(std::move(table.force_std_error[c]));
  out["source"] = to_numpy_strings(table.source);
  out["history_flags"] = to_numpy_strings(table.history_flags);
  return out;
}

template <class Map>
Map mapping(const py::object& value, const char* what) {
  if (value.is_none()) return {};
  try {
    return value.cast<Map>();
  } catch (const py::cast_error&) {
    throw py::type_error(std::string(what) + ": expected a dict of str to str");
  }
}

/// A settings dict ({"rho": 998.2, "axes": "-x,y,-z", "ref_point": [0, 0, 0.1]})
/// as the C++ API takes it: str values as they are, others as JSON.
std::map<std::string, std::string> settings_texts(const py::object& settings) {
  std::map<std::string, std::string> out;
  if (settings.is_none()) return out;
  if (!py::isinstance<py::dict>(settings)) throw py::type_error("settings: expected a dict of sidecar keys");
  const auto dumps = py::module_::import("json").attr("dumps");
  for (const auto& item : settings.cast<py::dict>()) {
    const auto key = py::cast<std::string>(item.first);
    out[key] = py::isinstance<py::str>(item.second) ? item.second.cast<std::string>()
                                                    : dumps(item.second, "allow_nan"_a = false).cast<std::string>();
  }
  return out;
}

/// integrate_surface and its result (include/hydrocoef/integrate.hpp).
void bind_integration(py::module_& m) {
  py::class_<hydrocoef::SurfaceIntegration>(m, "SurfaceIntegration", py::is_final(),
                                            made_by_the_module_only("hydrocoef.integrate_surface(...)"),
                                            "One surface export's forces and moments (integrate_surface).")
      .def_readonly("file", &hydrocoef::SurfaceIntegration::file)
      .def_readonly("format", &hydrocoef::SurfaceIntegration::format)
      .def_readonly("force", &hydrocoef::SurfaceIntegration::force, "X, Y, Z on the body [N], body axes.")
      .def_readonly("force_pressure", &hydrocoef::SurfaceIntegration::force_pressure)
      .def_readonly("force_viscous", &hydrocoef::SurfaceIntegration::force_viscous)
      .def_readonly("moment", &hydrocoef::SurfaceIntegration::moment, "K, M, N [N m] about reference_point.")
      .def_readonly("moment_pressure", &hydrocoef::SurfaceIntegration::moment_pressure)
      .def_readonly("moment_viscous", &hydrocoef::SurfaceIntegration::moment_viscous)
      .def_readonly("reference_point", &hydrocoef::SurfaceIntegration::reference_point, "[m], body axes.")
      .def_readonly("area", &hydrocoef::SurfaceIntegration::area, "[m^2]")
      .def_readonly("signed_volume", &hydrocoef::SurfaceIntegration::signed_volume, "[m^3]")
      .def_readonly("faces", &hydrocoef::SurfaceIntegration::faces)
      .def_readonly("closed", &hydrocoef::SurfaceIntegration::closed)
      .def_readonly("warnings", &hydrocoef::SurfaceIntegration::warnings)
      .def("text", &hydrocoef::SurfaceIntegration::text)
      .def("json", &hydrocoef::SurfaceIntegration::json);
  m.def(
      "integrate_surface",
      [](const py::object& path, const py::object& body, const std::string& format, const py::object& settings,
         bool sidecars) {
        hydrocoef::ImportOptions options;
        options.format = format;
        options.body = body.is_none() ? "" : body.cast<std::string>();
        options.settings = settings_texts(settings);
        options.use_sidecars = sidecars;
        const std::string file = fspath(path);
        py::gil_scoped_release release;
        return hydrocoef::integrate_surface(file, options);
      },
      "path"_a, py::kw_only(), "body"_a = py::none(), "format"_a = "auto", "settings"_a = py::none(),
      "sidecars"_a = true,
      R"doc(Integrates one surface export's pressure and wall shear into forces and moments, as `hydrocoef
integrate` does, and stores nothing. settings: as Database.import_files takes them ({"rho": 998.2, "axes":
"-x,y,-z", "ref_point": [0, 0, 0.1], "pressure": "p", ...}). Returns a SurfaceIntegration: force and moment on
the body in body axes [N, N m], their pressure and viscous parts, area, closedness; text() and json() give
what the CLI prints. Raises InputError as the CLI would.)doc");
}

/// The result classes of the records' operations: fields as attributes, text() and json().
void bind_records(py::module_& m) {
  py::class_<hydrocoef::RunDetails>(m, "RunDetails", py::is_final(), made_by_the_module_only("Database.show_run(id)"),
                                    "One run with its provenance (Database.show_run).")
      .def_readonly("id", &hydrocoef::RunDetails::id)
      .def_readonly("body", &hydrocoef::RunDetails::body)
      .def_readonly("velocity", &hydrocoef::RunDetails::velocity, "u, v, w [m/s], p, q, r [rad/s].")
      .def_readonly("disturbances", &hydrocoef::RunDetails::disturbances)
      .def_readonly("force", &hydrocoef::RunDetails::force, "X..N as stored (nan where none).")
      .def_readonly("force_std_error", &hydrocoef::RunDetails::force_std_error)
      .def_readonly("sign_convention", &hydrocoef::RunDetails::sign_convention)
      .def_readonly("source", &hydrocoef::RunDetails::source)
      .def_readonly("density", &hydrocoef::RunDetails::density)
      .def_readonly("kinematic_viscosity", &hydrocoef::RunDetails::kinematic_viscosity)
      .def_readonly("reference_point", &hydrocoef::RunDetails::reference_point)
      .def_readonly("flags", &hydrocoef::RunDetails::flags)
      .def_property_readonly(
          "imports",
          [](const hydrocoef::RunDetails& r) {
            py::list out;
            for (const auto& i : r.imports)
              out.append(py::dict("id"_a = i.id, "path"_a = i.path, "sha256"_a = i.sha256, "importer"_a = i.importer,
                                  "imported_at"_a = i.imported_at, "reading"_a = i.reading));
            return out;
          })
      .def("text", &hydrocoef::RunDetails::text)
      .def("json", &hydrocoef::RunDetails::json);

  py::class_<hydrocoef::DeleteSummary>(m, "DeleteSummary", py::is_final(),
                                       made_by_the_module_only("Database.delete_runs(...)"),
                                       "What Database.delete_runs did.")
      .def_readonly("runs", &hydrocoef::DeleteSummary::runs)
      .def_readonly("components", &hydrocoef::DeleteSummary::components)
      .def_readonly("fits_made_stale", &hydrocoef::DeleteSummary::fits_made_stale)
      .def_readonly("surfaces_made_stale", &hydrocoef::DeleteSummary::surfaces_made_stale)
      .def_readonly("imports_removed", &hydrocoef::DeleteSummary::imports_removed)
      .def("text", &hydrocoef::DeleteSummary::text)
      .def("json", &hydrocoef::DeleteSummary::json);

  py::class_<hydrocoef::MergeSummary>(m, "MergeSummary", py::is_final(), made_by_the_module_only("Database.merge(...)"),
                                      "What Database.merge did.")
      .def_readonly("into", &hydrocoef::MergeSummary::into)
      .def_property_readonly(
          "shards",
          [](const hydrocoef::MergeSummary& s) {
            py::list out;
            for (const auto& o : s.shards)
              out.append(py::dict("shard"_a = o.shard, "imports_added"_a = o.imports_added,
                                  "imports_already"_a = o.imports_already, "runs_created"_a = o.runs_created,
                                  "runs_extended"_a = o.runs_extended, "components"_a = o.components,
                                  "fits_added"_a = o.fits_added, "fits_already"_a = o.fits_already,
                                  "surfaces_added"_a = o.surfaces_added, "surfaces_already"_a = o.surfaces_already,
                                  "mesh_studies_added"_a = o.mesh_studies_added,
                                  "mesh_studies_already"_a = o.mesh_studies_already, "pmm_added"_a = o.pmm_added,
                                  "pmm_already"_a = o.pmm_already, "body_references_added"_a = o.body_references_added,
                                  "body_references_already"_a = o.body_references_already,
                                  "derivative_models_added"_a = o.derivative_models_added,
                                  "derivative_models_already"_a = o.derivative_models_already));
            return out;
          })
      .def("text", &hydrocoef::MergeSummary::text)
      .def("json", &hydrocoef::MergeSummary::json);

  py::class_<hydrocoef::CopySummary>(m, "CopySummary", py::is_final(), made_by_the_module_only("Database.copy_to(...)"),
                                     "What Database.copy_to did.")
      .def_readonly("source", &hydrocoef::CopySummary::from)
      .def_readonly("target", &hydrocoef::CopySummary::to)
      .def_property_readonly("rows",
                             [](const hydrocoef::CopySummary& s) {
                               py::dict out;
                               for (const auto& [table, n] : s.rows) out[py::str(table)] = n;
                               return out;
                             })
      .def("text", &hydrocoef::CopySummary::text)
      .def("json", &hydrocoef::CopySummary::json);

  py::class_<hydrocoef::MigrationSummary>(m, "MigrationSummary", py::is_final(),
                                          made_by_the_module_only("Database.migration()"),
                                          "The schema versions of a database (Database.migration).")
      .def_readonly("database", &hydrocoef::MigrationSummary::database)
      .def_readonly("from_version", &hydrocoef::MigrationSummary::from)
      .def_readonly("to_version", &hydrocoef::MigrationSummary::to)
      .def("text", &hydrocoef::MigrationSummary::text)
      .def("json", &hydrocoef::MigrationSummary::json);

  py::class_<hydrocoef::ReportSummary>(m, "ReportSummary", py::is_final(),
                                       made_by_the_module_only("Database.report(...)"), "What Database.report wrote.")
      .def_readonly("index", &hydrocoef::ReportSummary::index)
      .def_readonly("plots", &hydrocoef::ReportSummary::plots)
      .def_readonly("notes", &hydrocoef::ReportSummary::notes)
      .def_readonly("runs", &hydrocoef::ReportSummary::runs)
      .def_readonly("fits", &hydrocoef::ReportSummary::fits)
      .def_readonly("surfaces", &hydrocoef::ReportSummary::surfaces)
      .def_readonly("histories", &hydrocoef::ReportSummary::histories)
      .def_readonly("sigma_maps", &hydrocoef::ReportSummary::sigma_maps)
      .def_readonly("mesh_study_rows", &hydrocoef::ReportSummary::mesh_study_rows)
      .def_readonly("pmm_fits", &hydrocoef::ReportSummary::pmm_fits)
      .def("text", &hydrocoef::ReportSummary::text)
      .def("json", &hydrocoef::ReportSummary::json);
}

}  // namespace

Database& database_of(py::handle self) {
  if (!holds_database(self))
    throw py::type_error(
        "this hydrocoef.Database was made by __new__ without __init__; open one with "
        "hydrocoef.Database(path)");
  auto* instance = reinterpret_cast<py::detail::instance*>(self.ptr());
  return *instance->get_value_and_holder(py::detail::get_type_info(typeid(Database)), false).value_ptr<Database>();
}

py::class_<Database> declare_database(py::module_& m) {
  return py::class_<Database>(
      m, "Database",
      R"doc(A hydrocoef run database (an SQLite file), as the command-line tool reads and writes it.

    db = hydrocoef.Database("asr-v.db")            # mode="create": made when missing
    db.import_files(["surge.csv"], body="asr-v", settings={"sign": "opposing", "rho": 998.2})
    fit = db.fit(body="asr-v", output="X", terms="1,u,u|u|")
    runs = db.runs(where=["u>=0"])                  # dict of numpy columns; runs.to_pandas()
    s = db.surface("asr-v-surge")

mode: "r" (read only: never writes), "rw" (the file must exist) or "create".
Units SI; body axes x forward, y starboard, z down; forces on the body.
Errors in the input raise hydrocoef.InputError with the CLI's message. Every
write is one transaction. Close it with close() or a with block; any call
after that raises InputError "PATH: database is closed".)doc");
}

void bind_database(py::module_& m, py::class_<Database>& database) {
  py::class_<hydrocoef::ImportedFile>(m, "ImportedFile", py::is_final(),
                                      made_by_the_module_only("Database.import_files(...)"),
                                      "What an import did with one input.")
      .def_readonly("path", &hydrocoef::ImportedFile::path)
      .def_readonly("format", &hydrocoef::ImportedFile::format)
      .def_readonly("runs", &hydrocoef::ImportedFile::runs, "Runs the input holds.")
      .def_readonly("runs_created", &hydrocoef::ImportedFile::runs_created)
      .def_readonly("runs_extended", &hydrocoef::ImportedFile::runs_extended)
      .def_readonly("already_imported", &hydrocoef::ImportedFile::already_imported)
      .def_readonly("replaced", &hydrocoef::ImportedFile::replaced)
      .def_readonly("notes", &hydrocoef::ImportedFile::notes)
      .def("__repr__", [](const hydrocoef::ImportedFile& f) {
        return "<hydrocoef.ImportedFile " + f.path + ": " + f.format + ", " + std::to_string(f.runs) + " runs (" +
               std::to_string(f.runs_created) + " new, " + std::to_string(f.runs_extended) + " extended" +
               (f.already_imported ? ", already imported" : "") + ")>";
      });

  py::class_<hydrocoef::ImportSummary>(m, "ImportSummary", py::is_final(),
                                       made_by_the_module_only("Database.import_files(...)"),
                                       "What Database.import_files did.")
      .def_readonly("files", &hydrocoef::ImportSummary::files, "One ImportedFile per input (folders expanded).")
      .def_readonly("notes", &hydrocoef::ImportSummary::notes)
      .def_readonly("excluded", &hydrocoef::ImportSummary::excluded, "Files left out by include/exclude.")
      .def_readonly("runs_created", &hydrocoef::ImportSummary::runs_created)
      .def_readonly("runs_extended", &hydrocoef::ImportSummary::runs_extended)
      .def_readonly("already_imported", &hydrocoef::ImportSummary::already_imported)
      .def_readonly("replaced", &hydrocoef::ImportSummary::replaced)
      .def_readonly("database", &hydrocoef::ImportSummary::database)
      .def("text", &hydrocoef::ImportSummary::text, "quiet"_a = false,
           "What `hydrocoef import` prints (quiet: the summary line only).")
      .def("json", &hydrocoef::ImportSummary::json, "What `hydrocoef import --json` prints.")
      .def("__repr__", [](const hydrocoef::ImportSummary& s) {
        return "<hydrocoef.ImportSummary " + std::to_string(s.files.size()) +
               " inputs: " + std::to_string(s.runs_created) + " new runs, " + std::to_string(s.runs_extended) +
               " extended, " + std::to_string(s.already_imported) + " already imported>";
      });

  bind_records(m);
  bind_integration(m);

  database
      .def(py::init([](const py::object& path, const std::string& mode) {
             return Database::open(fspath(path), parse_mode(mode));
           }),
           "path"_a, "mode"_a = "create")
      .def_property_readonly("path", [](py::handle self) { return database_of(self).path(); })
      .def_property_readonly("closed", [](py::handle self) { return !database_of(self).is_open(); })
      .def_property_readonly("read_only", [](py::handle self) { return database_of(self).read_only(); })
      .def(
          "close", [](py::handle self) { database_of(self).close(); },
          "Closes the file; surfaces already read stay valid.")
      .def("__enter__",
           [](py::object self) {
             database_of(self);
             return self;
           })
      .def("__exit__", [](py::handle self, const py::args&) { database_of(self).close(); })
      .def(
          "runs",
          [](py::handle self, const py::object& where, const py::object& body, const py::object& exclude_runs) {
            const Database& d = database_of(self);
            return runs_dict(d.runs(texts(where, "where"), body.is_none() ? "" : body.cast<std::string>(),
                                    run_ids(exclude_runs, "exclude_runs")));
          },
          "where"_a = py::none(), "body"_a = py::none(), "exclude_runs"_a = py::none(),
          R"doc(The runs as a dict of numpy columns (hydrocoef.Table: to_pandas()), as `hydrocoef runs` lists them.

where: selection clauses combined with AND ("u>=0", "v=0", "u=0.1:0.3", "current_v!=0");
body: one body's runs; exclude_runs: ids left out.
Columns: id, body, u v w [m/s], p q r [rad/s], each disturbance by name [SI,
nan where a run has none], X Y Z [N] and K M N [N m] (forces on the body, nan
where missing), X_std_error ... N_std_error (standard error of a mean over a
force history, nan where none), source (files, ';'-separated), history_flags.)doc")
      .def(
          "import_files",
          [](py::handle self, const py::object& paths, const py::object& body, const std::string& format,
             const py::object& settings, const py::object& columns, const py::object& units,
             const py::object& disturbance_columns, const py::object& ignore, const py::object& monitors,
             std::size_t average_last, const py::object& include, const py::object& exclude,
             const py::object& key_from_name, const py::object& manifest, bool sidecars, bool prefer_surfaces,
             bool replace, const std::string& also, unsigned jobs, const std::optional<std::string>& form,
             const std::optional<std::string>& drift_convention, std::optional<double> length,
             std::optional<double> speed, std::optional<double> density, std::optional<double> draft,
             std::optional<double> mass, std::optional<double> volume, std::optional<double> gravity) {
            Database& d = database_of(self);
            std::vector<std::string> inputs;
            if (py::isinstance<py::str>(paths) || py::hasattr(paths, "__fspath__")) {
              inputs.push_back(fspath(paths));
            } else {
              for (const auto& p : paths) inputs.push_back(fspath(p));
            }
            hydrocoef::ImportOptions options;
            options.format = format;
            options.body = body.is_none() ? "" : body.cast<std::string>();
            options.settings = settings_texts(settings);
            options.columns = mapping<std::map<std::string, std::string>>(columns, "columns");
            options.units = mapping<std::map<std::string, std::string>>(units, "units");
            options.disturbance_columns = texts(disturbance_columns, "disturbance_columns");
            options.ignored_columns = texts(ignore, "ignore");
            options.monitors = mapping<std::map<std::string, std::string>>(monitors, "monitors");
            options.average_last = average_last;
            options.include = texts(include, "include");
            options.exclude = texts(exclude, "exclude");
            options.key_from_name = key_from_name.is_none() ? "" : key_from_name.cast<std::string>();
            options.manifest = manifest.is_none() ? "" : fspath(manifest);
            options.use_sidecars = sidecars;
            options.prefer_surfaces = prefer_surfaces;
            options.replace = replace;
            options.also = also;
            options.jobs = jobs;
            options.form = form;
            options.drift_convention = drift_convention;
            options.length = length;
            options.speed = speed;
            options.density = density;
            options.draft = draft;
            options.mass = mass;
            options.volume = volume;
            options.gravity = gravity;
            py::gil_scoped_release release;
            return d.import_files(inputs, options);
          },
          "paths"_a, py::kw_only(), "body"_a = py::none(), "format"_a = "auto", "settings"_a = py::none(),
          "columns"_a = py::none(), "units"_a = py::none(), "disturbance_columns"_a = py::none(),
          "ignore"_a = py::none(), "monitors"_a = py::none(), "average_last"_a = 1, "include"_a = py::none(),
          "exclude"_a = py::none(), "key_from_name"_a = py::none(), "manifest"_a = py::none(), "sidecars"_a = true,
          "prefer_surfaces"_a = false, "replace"_a = false, "also"_a = "", "jobs"_a = 0, "form"_a = py::none(),
          "drift_convention"_a = py::none(), "length"_a = py::none(), "speed"_a = py::none(), "density"_a = py::none(),
          "draft"_a = py::none(), "mass"_a = py::none(), "volume"_a = py::none(), "gravity"_a = py::none(),
          R"doc(Imports files, folders and case folders in one transaction, as `hydrocoef import` does.

paths: a path or a list of paths. body: the runs' body (default 'vehicle').
format: auto, table, monitor, history, cfdpost, vtk, cfx-out or captive-table.
form, drift_convention, length, speed, density, draft, mass, volume, gravity:
  captive-test tables (format 'captive-table'): the forces' form (prime, bis,
  mmg), the drift convention (mmg: beta = atan2(-v, u); fossen: atan2(v, u))
  and the reference values [SI], over the table's own '# NAME = VALUE' lines;
  length, draft and volume default to the body's stored reference data.
settings: run settings as a sidecar holds them, above every other source:
  {"rho": 998.2, "nu": 1.004e-6, "axes": "-x,y,-z", "sign": "opposing",
   "ref_point": [0, 0, 0.1], "disturbances": {"current_v": 0.05}, "u": 0.2, ...}
columns / units / monitors: {component: header} maps (the CLI's --column, --unit, --monitor);
disturbance_columns, ignore: table headers; include / exclude: globs for folders;
key_from_name: e.g. 'u{u}_v{v}'; manifest: a sweep CSV; sidecars: read FILE.json and
hydrocoef-run.json; replace / also: see `hydrocoef import --help`; jobs: 0 every core.
Returns an ImportSummary. Every input is read before the database is written:
a bad one raises InputError and leaves the database as it was. The GIL is released.)doc")
      .def(
          "show_run", [](py::handle self, std::int64_t id) { return hydrocoef::show_run(database_of(self), id); },
          "id"_a, "One run with its provenance, as `hydrocoef runs show ID`. Returns a RunDetails.")
      .def(
          "delete_runs",
          [](py::handle self, const py::object& ids, const py::object& where, const py::object& body,
             const py::object& exclude_runs, const py::object& source) {
            hydrocoef::DeleteRunsOptions options;
            options.ids = run_ids(ids, "ids");
            options.where = texts(where, "where");
            options.body = body.is_none() ? "" : body.cast<std::string>();
            options.exclude_runs = run_ids(exclude_runs, "exclude_runs");
            options.source = source.is_none() ? "" : fspath(source);
            auto& d = database_of(self);
            py::gil_scoped_release release;
            return hydrocoef::delete_runs(d, options);
          },
          "ids"_a = py::none(), py::kw_only(), "where"_a = py::none(), "body"_a = py::none(),
          "exclude_runs"_a = py::none(), "source"_a = py::none(),
          R"doc(Deletes runs in one transaction, as `hydrocoef runs delete`: those named by id, and those where /
source (a file their forces came from) select, of body when given. Fits and surfaces built from them become
stale. Returns a DeleteSummary.)doc")
      .def(
          "merge",
          [](py::handle self, const py::object& shards) {
            hydrocoef::MergeOptions options;
            if (py::isinstance<py::str>(shards) || py::hasattr(shards, "__fspath__"))
              options.shards.push_back(fspath(shards));
            else
              for (const auto& shard : shards) options.shards.push_back(fspath(shard));
            auto& d = database_of(self);
            py::gil_scoped_release release;
            return hydrocoef::merge_databases(d, options);
          },
          "shards"_a,
          "Merges shard databases (paths or URLs) into this one in one transaction, as `hydrocoef merge`. "
          "Returns a MergeSummary.")
      .def(
          "copy_to",
          [](py::handle self, py::handle target) {
            const auto& from = database_of(self);
            auto& to = database_of(target);
            py::gil_scoped_release release;
            return hydrocoef::copy_database(from, to);
          },
          "target"_a,
          "Copies every row into the empty Database `target`, ids included, as `hydrocoef copy`. Returns a "
          "CopySummary.")
      .def(
          "migration", [](py::handle self) { return hydrocoef::migration(database_of(self)); },
          "The schema versions before and after opening (`hydrocoef migrate`): a MigrationSummary.")
      .def(
          "report",
          [](py::handle self, const py::object& output, const py::object& body, const py::object& where,
             const py::object& exclude_runs, const py::object& trajectories, const py::object& experiment,
             const std::string& component) {
            hydrocoef::ReportOptions options;
            options.output = fspath(output);
            options.body = body.is_none() ? "" : body.cast<std::string>();
            options.where = texts(where, "where");
            options.exclude_runs = run_ids(exclude_runs, "exclude_runs");
            if (!trajectories.is_none())
              for (const auto& t : trajectories) options.trajectories.push_back(fspath(t));
            options.experiment = experiment.is_none() ? "" : fspath(experiment);
            options.component = component;
            const auto& d = database_of(self);
            py::gil_scoped_release release;
            return hydrocoef::write_report(d, options);
          },
          "output"_a, py::kw_only(), "body"_a = py::none(), "where"_a = py::none(), "exclude_runs"_a = py::none(),
          "trajectories"_a = py::none(), "experiment"_a = py::none(), "component"_a = "r",
          "Writes the self-contained HTML report into the folder `output`, as `hydrocoef report`. Returns a "
          "ReportSummary.")
      .def("__repr__", [](py::handle self) {
        const Database& d = database_of(self);
        return "<hydrocoef.Database '" + d.path() + "'" +
               (d.is_open() ? (d.read_only() ? ", read only" : "") : ", closed") + ">";
      });

  // __init__ on a Database that has one already (open or closed): pybind11
  // runs a constructor once and ignores a second call silently; this
  // refuses it. The wrapper is not named __init__, a name pybind11 takes for
  // a constructor (and ignores again).
  {
    py::object database_class = m.attr("Database");
    py::object construct = database_class.attr("__init__");
    database_class.attr("__init__") = py::cpp_function(
        [construct](py::handle self, const py::object& path, const py::object& mode) {
          if (holds_database(self))
            throw std::runtime_error("this hydrocoef.Database has been opened already (on " + database_of(self).path() +
                                     "); __init__ runs once: make a new hydrocoef.Database(path)");
          construct(self, path, mode);
        },
        py::name("open"), py::is_method(database_class), "path"_a, "mode"_a = "create",
        "Opens the database at path (mode: 'r', 'rw' or 'create'); once per object.");
  }
}

}  // namespace hydrocoef_python
