// RunDatabase::copy_from: every row of one database into an empty one, ids
// included, whatever the two backends.
#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>
#include <tuple>

#include "src/core/error.hpp"
#include "src/store/backend.hpp"
#include "src/store/body_reference.hpp"
#include "src/store/database.hpp"
#include "src/store/migrations.hpp"
#include "src/store/pmm_record.hpp"

namespace hydrocoef {
namespace {

struct TableColumns {
  std::string table;
  std::vector<std::string> columns;
  bool integer_id = false;  ///< an "id INTEGER PRIMARY KEY" (an identity column on PostgreSQL)
};

/// The tables of the latest schema, each after the tables it refers to.
std::vector<TableColumns> tables_in_reference_order() {
  store::Connection memory(":memory:", store::Access::ReadWriteCreate);
  for (const auto& migration : store::migrations()) memory.execute(migration.sql);
  std::map<std::string, std::set<std::string>> refers;
  std::vector<std::string> names;
  {
    auto list = memory.prepare(
        "SELECT name FROM sqlite_schema WHERE type = 'table' AND name NOT LIKE 'sqlite\\_%' ESCAPE '\\' ORDER BY name");
    while (list.step()) names.push_back(list.get_text(0));
  }
  for (const auto& name : names) {
    auto keys = memory.prepare("SELECT \"table\" FROM pragma_foreign_key_list(?)");
    keys.bind(1, name);
    while (keys.step())
      if (keys.get_text(0) != name) refers[name].insert(keys.get_text(0));
  }
  std::vector<TableColumns> out;
  std::set<std::string> done;
  while (done.size() < names.size()) {
    const std::size_t before = done.size();
    for (const auto& name : names) {
      if (done.count(name)) continue;
      bool ready = true;
      for (const auto& other : refers[name]) ready = ready && done.count(other);
      if (!ready) continue;
      TableColumns table{name, {}, false};
      auto columns = memory.prepare("SELECT name, type, pk FROM pragma_table_info(?) ORDER BY cid");
      columns.bind(1, name);
      while (columns.step()) {
        table.columns.push_back(columns.get_text(0));
        if (columns.get_text(0) == "id" && columns.get_text(1) == "INTEGER" && columns.get_int(2) == 1)
          table.integer_id = true;
      }
      out.push_back(std::move(table));
      done.insert(name);
    }
    if (done.size() == before) throw std::logic_error("the schema's references form a cycle");
  }
  return out;
}

}  // namespace

std::vector<std::pair<std::string, std::size_t>> RunDatabase::copy_from(RunDatabase& source) {
  if (read_only_) throw InputError(SourceLocation{path_.string()}, "database opened read-only; cannot copy into it");
  const auto tables = tables_in_reference_order();
  // Every read of the source sees one state of it, even while a job writes it.
  const store::detail::ReadSnapshot source_snapshot(source.connection_.backend_impl());
  store::Transaction transaction(connection_);
  for (const auto& table : tables) {
    auto count = connection_.prepare("SELECT count(*) FROM " + table.table);
    count.step();
    if (count.get_int(0) != 0)
      throw InputError(SourceLocation{path_.string()},
                       "holds data already (" + std::to_string(count.get_int(0)) + " rows in table " + table.table +
                           "); expected an empty database to copy into (hydrocoef merge adds to one that has data)");
  }
  // Every record of the source is read through the checked readers first, as
  // merge and every command read it: a value of the wrong type or range is
  // refused naming its table, row and column before a row is copied.
  (void)source.sources();
  (void)source.runs();
  (void)source.fits();
  (void)source.surfaces();
  (void)source.numerical_uncertainties();
  (void)source.pmm_records();
  (void)source.body_references();
  {
    std::vector<std::int64_t> imports;
    auto list = source.connection_.prepare("SELECT id FROM import");
    while (list.step()) imports.push_back(list.get_int(0));
    for (const std::int64_t id : imports) (void)source.import_record(id);
  }
  std::vector<std::pair<std::string, std::size_t>> copied;
  std::vector<std::tuple<std::string, std::int64_t, std::int64_t>> stale_flags;  // table, id, stale
  for (const auto& table : tables) {
    std::string list, marks;
    for (std::size_t i = 0; i < table.columns.size(); ++i) {
      list += (i ? ", " : "") + table.columns[i];
      marks += i ? ", ?" : "?";
    }
    auto select = source.connection_.prepare("SELECT " + list + " FROM " + table.table);
    auto insert = connection_.prepare("INSERT INTO " + table.table + " (" + list + ") VALUES (" + marks + ")");
    std::size_t rows = 0;
    const auto stale = std::find(table.columns.begin(), table.columns.end(), "stale");
    const auto id = std::find(table.columns.begin(), table.columns.end(), "id");
    while (select.step()) {
      for (std::size_t i = 0; i < table.columns.size(); ++i) {
        const int c = static_cast<int>(i);
        switch (select.column_type(c)) {
          case store::ColumnType::Null: insert.bind_null(c + 1); break;
          case store::ColumnType::Integer: insert.bind(c + 1, select.get_int(c)); break;
          case store::ColumnType::Float: insert.bind(c + 1, select.get_double(c)); break;
          case store::ColumnType::Text: insert.bind(c + 1, select.get_text(c)); break;
          case store::ColumnType::Blob:
            if (select.column_bytes(c) % sizeof(double) != 0)
              throw InputError(SourceLocation{source.path().string()},
                               "table '" + table.table + "', column '" + table.columns[i] + "': a blob of " +
                                   std::to_string(select.column_bytes(c)) +
                                   " bytes; expected float64 values (a multiple of 8 bytes)");
            insert.bind_doubles(c + 1, select.get_doubles(c));
            break;
        }
      }
      insert.run();
      if (stale != table.columns.end() && id != table.columns.end())
        stale_flags.emplace_back(table.table, select.get_int(static_cast<int>(id - table.columns.begin())),
                                 select.get_int(static_cast<int>(stale - table.columns.begin())));
      ++rows;
    }
    copied.emplace_back(table.table, rows);
  }
  // Forces copied after a fit or surface made it stale through the triggers:
  // the flags are the source's.
  for (const auto& [table, id, flag] : stale_flags)
    connection_.prepare("UPDATE " + table + " SET stale = ? WHERE id = ?").bind(1, flag).bind(2, id).run();
  // Ids were copied as they were: the next one made here comes after them.
  if (connection_.backend() == store::Backend::PostgreSQL)
    for (const auto& table : tables)
      if (table.integer_id)
        connection_.execute("SELECT pg_catalog.setval(pg_catalog.pg_get_serial_sequence('" + table.table +
                            "', 'id'), pg_catalog.max(id)) FROM " + table.table +
                            " HAVING pg_catalog.max(id) IS NOT NULL");
  transaction.commit();
  use_wal();
  return copied;
}

}  // namespace hydrocoef
