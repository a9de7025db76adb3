#include "src/store/connection.hpp"

#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "src/core/error.hpp"
#include "src/store/backend.hpp"

namespace hydrocoef::store {

int busy_timeout_seconds() {
  const char* text = std::getenv("HYDROCOEF_DB_TIMEOUT");
  if (!text || !*text) return 60;
  int seconds = -1;
  const std::string_view view(text);
  const auto [end, ec] = std::from_chars(view.data(), view.data() + view.size(), seconds);
  if (ec != std::errc() || end != view.data() + view.size() || seconds < 0 || seconds > 3600)
    throw InputError("HYDROCOEF_DB_TIMEOUT is '" + printable_text(view, 40) +
                     "'; expected a whole number of seconds from 0 to 3600");
  return seconds;
}

Connection::Connection(const std::string& path, Access access) : Connection(detail::open_sqlite(path, access), path) {}

Connection Connection::postgresql(const std::string& url, const std::string& display, Access access) {
  return Connection(detail::open_postgresql(url, display, access), display);
}

Connection Connection::sqlite_private_copy(Connection& source) {
  return Connection(detail::sqlite_private_copy(*source.backend_), source.name_);
}

Connection::Connection(std::unique_ptr<detail::ConnectionBackend> backend, std::string name)
    : backend_(std::move(backend)), name_(std::move(name)) {}

Connection::~Connection() = default;
Connection::Connection(Connection&& other) noexcept = default;
Connection& Connection::operator=(Connection&& other) noexcept = default;

Backend Connection::backend() const { return backend_->kind(); }
void Connection::execute(std::string_view sql) { backend_->execute(sql); }
Statement Connection::prepare(std::string_view sql) { return Statement(backend_->prepare(sql)); }
bool Connection::read_only() const { return backend_->read_only(); }
void Connection::begin_write() { backend_->begin_write(); }
void Connection::commit() { backend_->commit(); }
void Connection::rollback() noexcept { backend_->rollback(); }
void Connection::use_wal() { backend_->use_wal(); }

Statement::Statement(std::unique_ptr<detail::StatementBackend> backend) : backend_(std::move(backend)) {}
Statement::~Statement() = default;
Statement::Statement(Statement&& other) noexcept = default;

Statement& Statement::bind(int index, double value) {
  backend_->bind_double(index, value);
  return *this;
}
Statement& Statement::bind(int index, std::int64_t value) {
  backend_->bind_int(index, value);
  return *this;
}
Statement& Statement::bind(int index, std::string_view value) {
  backend_->bind_text(index, value);
  return *this;
}
Statement& Statement::bind(int index, const std::optional<double>& value) {
  return value ? bind(index, *value) : bind_null(index);
}
Statement& Statement::bind_doubles(int index, const std::vector<double>& values) {
  backend_->bind_blob(index, values.data(), values.size() * sizeof(double));
  return *this;
}
Statement& Statement::bind_null(int index) {
  backend_->bind_null(index);
  return *this;
}

bool Statement::step() { return backend_->step(); }

void Statement::run() {
  while (step()) {}
  reset();
}

void Statement::reset() { backend_->reset(); }

bool Statement::is_null(int column) const { return backend_->column_type(column) == ColumnType::Null; }
double Statement::get_double(int column) const { return backend_->get_double(column); }
std::int64_t Statement::get_int(int column) const { return backend_->get_int(column); }
std::string Statement::get_text(int column) const { return std::string(backend_->get_text(column)); }
std::vector<double> Statement::get_doubles(int column) const {
  const std::string_view bytes = backend_->get_blob(column);
  if (bytes.size() % sizeof(double) != 0) return {};
  std::vector<double> out(bytes.size() / sizeof(double));
  if (!out.empty()) std::memcpy(out.data(), bytes.data(), bytes.size());
  return out;
}
ColumnType Statement::column_type(int column) const { return backend_->column_type(column); }
std::size_t Statement::column_bytes(int column) const {
  return backend_->column_type(column) == ColumnType::Blob ? backend_->get_blob(column).size()
                                                           : backend_->get_text(column).size();
}
const char* Statement::column_name(int column) const { return backend_->column_name(column); }
std::optional<double> Statement::get_optional_double(int column) const {
  if (is_null(column)) return std::nullopt;
  return get_double(column);
}

std::int64_t returned_id(Statement& insert) {
  if (!insert.step()) throw std::logic_error("an INSERT ... RETURNING id returned no row");
  const std::int64_t id = insert.get_int(0);
  insert.reset();
  return id;
}

Transaction::Transaction(Connection& connection) : connection_(connection) { connection_.begin_write(); }

Transaction::~Transaction() {
  if (open_) connection_.rollback();
}

void Transaction::commit() {
  connection_.commit();
  open_ = false;
}

}  // namespace hydrocoef::store
