// Database (include/hydrocoef/database.hpp): opening and closing, and what is
// read back: runs as columns, fits, surfaces. The import is src/api/import.cpp,
// the fit src/api/fit.cpp; what the CLI prints of them src/api/*_report.cpp.
#include "src/api/internal.hpp"
#include "src/api/records_report.hpp"
#include "src/core/numbers.hpp"
#include "src/core/sign_convention.hpp"
#include "src/core/text.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace hydrocoef {
inline namespace api {
namespace {

RunDatabase::OpenMode store_mode(OpenMode mode) {
  switch (mode) {
    case OpenMode::ReadOnly: return RunDatabase::OpenMode::ReadOnly;
    case OpenMode::ReadWrite: return RunDatabase::OpenMode::MustExist;
    case OpenMode::Create: return RunDatabase::OpenMode::CreateIfMissing;
  }
  throw std::invalid_argument("hydrocoef::Database::open: unknown OpenMode");
}

std::optional<std::string> optional_body(const std::string& body) {
  return body.empty() ? std::nullopt : std::optional<std::string>(body);
}

}  // namespace

RunDatabase& Database::Impl::open_store() {
  if (!store) throw InputError(SourceLocation{path}, "database is closed");
  return *store;
}

RunDatabase& Database::Impl::writable_store(const char* what) {
  auto& open = open_store();
  if (read_only)
    throw InputError(SourceLocation{path}, std::string("database is open read-only; ") + what +
                                               " needs it opened with OpenMode::ReadWrite or OpenMode::Create");
  return open;
}

Database::Database(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Database::Database(Database&&) noexcept = default;
Database& Database::operator=(Database&&) noexcept = default;
Database::~Database() = default;

Database Database::open(const std::string& path, OpenMode mode) {
  auto impl = std::make_unique<Impl>();
  impl->path = path;
  impl->read_only = mode == OpenMode::ReadOnly;
  impl->store.emplace(path, store_mode(mode));
  return Database(std::move(impl));
}

const std::string& Database::path() const { return impl_->path; }

bool Database::is_open() const {
  const std::lock_guard lock(impl_->mutex);
  return impl_->store.has_value();
}

bool Database::read_only() const { return impl_->read_only; }

void Database::close() {
  const std::lock_guard lock(impl_->mutex);
  impl_->store.reset();
}

RunTable Database::runs(const std::vector<std::string>& where, const std::string& body,
                        const std::vector<std::int64_t>& exclude_runs) const {
  const RunSelection selection = parse_selection(where, exclude_runs);
  const std::lock_guard lock(impl_->mutex);
  RunFilter filter;
  filter.body = optional_body(body);
  auto runs = impl_->open_store().runs(filter);
  std::erase_if(runs, [&](const StoredRun& run) { return !selection.matches(run.key, run.id); });

  RunTable table;
  const std::size_t n = runs.size();
  std::set<std::string> disturbance_names;
  for (const auto& run : runs)
    for (const auto& [name, value] : run.key.disturbances) disturbance_names.insert(name);
  for (const auto& name : disturbance_names) table.disturbances[name].assign(n, kNaN);
  for (std::size_t c = 0; c < 6; ++c) {
    table.velocity[c].resize(n);
    table.force[c].assign(n, kNaN);
    table.force_std_error[c].assign(n, kNaN);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const StoredRun& run = runs[i];
    table.id.push_back(run.id);
    table.body.push_back(run.key.body);
    std::set<std::string> sources;
    for (std::size_t c = 0; c < 6; ++c) {
      table.velocity[c][i] = run.key.nu_b[c];
      const auto& force = run.tau_b[c];
      if (!force) continue;
      // Forces on the body, as `runs --csv` gives them: a damping magnitude as tabulated is negated.
      table.force[c][i] = to_on_body(force->value.total, force->sign);
      if (force->statistics) table.force_std_error[c][i] = force->statistics->values.standard_error;
      sources.insert(force->source_path);
    }
    for (const auto& [name, value] : run.key.disturbances) table.disturbances[name][i] = value;
    table.source.push_back(join(std::vector<std::string>(sources.begin(), sources.end()), ";"));
    table.history_flags.push_back(join(run_flags(run), ","));
  }
  RunTable::Access::set(table, std::make_shared<const RunTable::Rendering>(
                                   RunTable::Rendering{std::move(runs), optional_body(body), impl_->path}));
  return table;
}

std::vector<FitSummary> Database::fits(const std::string& body) const {
  const std::lock_guard lock(impl_->mutex);
  std::vector<FitSummary> out;
  for (const FitRecord& record : impl_->open_store().fits(optional_body(body)))
    out.push_back(records::fit_summary(record));
  return out;
}

namespace {

SurfaceInfo surface_info(const SurfaceRecord& record, const CoefficientSurface& surface) {
  return {record.name,           record.body,           record.kind,
          surface.method_name(), surface.axis_names(),  surface.output_names(),
          record.stale,          record.run_ids.size(), record.created_at};
}

}  // namespace

std::vector<SurfaceInfo> Database::surfaces(const std::string& body) const {
  const std::lock_guard lock(impl_->mutex);
  std::vector<SurfaceInfo> out;
  // Read as `surface list` reads it: the definition checked against the data.
  for (const SurfaceRecord& record : impl_->open_store().surfaces(optional_body(body)))
    out.push_back(surface_info(record, surface_from_record(record)));
  return out;
}

// build_surface and rebuild_surfaces: src/api/surface_build.cpp, with the surface commands.

Surface Database::surface(const std::string& name) const {
  const std::lock_guard lock(impl_->mutex);
  StoredSurface stored = load_surface(impl_->open_store(), name);
  std::string method = stored.surface.method_name();
  return Surface(std::make_shared<const Surface::Impl>(Surface::Impl{
      std::move(stored.surface), stored.record.name, stored.record.body, std::move(method), stored.record.stale}));
}

}  // namespace api
}  // namespace hydrocoef
