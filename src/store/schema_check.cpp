#include "src/store/schema_check.hpp"

#include <algorithm>
#include <map>
#include <mutex>
#include <set>
#include <tuple>

#include "src/core/error.hpp"
#include "src/store/dialect.hpp"
#include "src/store/migrations.hpp"

namespace hydrocoef::store {
namespace {

std::string describe(const SchemaEntry& entry) {
  std::string text = "a " + entry.type + " '" + printable_text(entry.name, 60) + "'";
  if (entry.type != "table" && !entry.table.empty()) text += " on table '" + printable_text(entry.table, 60) + "'";
  return text;
}

}  // namespace

std::vector<SchemaEntry> schema_of(Connection& connection) {
  auto select = connection.prepare(
      "SELECT type, name, tbl_name, coalesce(sql, '') FROM sqlite_schema "
      "WHERE NOT (type = 'table' AND name LIKE 'sqlite\\_stat%' ESCAPE '\\')");
  std::vector<SchemaEntry> out;
  while (select.step()) out.push_back({select.get_text(0), select.get_text(1), select.get_text(2), select.get_text(3)});
  std::sort(out.begin(), out.end(), [](const SchemaEntry& a, const SchemaEntry& b) {
    return std::tie(a.type, a.name) < std::tie(b.type, b.name);
  });
  return out;
}

const std::vector<SchemaEntry>& expected_schema(int version) {
  static std::mutex mutex;
  static std::map<int, std::vector<SchemaEntry>> cache;
  const std::lock_guard lock(mutex);
  auto found = cache.find(version);
  if (found != cache.end()) return found->second;
  Connection memory(":memory:", Access::ReadWriteCreate);
  for (int i = 0; i < version && i < static_cast<int>(migrations().size()); ++i)
    memory.execute(migrations()[static_cast<std::size_t>(i)].sql);
  return cache.emplace(version, schema_of(memory)).first->second;
}

std::optional<std::string> schema_difference(const std::vector<SchemaEntry>& expected,
                                             const std::vector<SchemaEntry>& found) {
  auto key = [](const SchemaEntry& e) { return e.type + '\n' + e.name; };
  std::map<std::string, const SchemaEntry*> wanted;
  for (const auto& entry : expected) wanted[key(entry)] = &entry;
  for (const auto& entry : found) {
    const auto it = wanted.find(key(entry));
    if (it == wanted.end()) return "has " + describe(entry) + " that hydrocoef does not create";
    if (it->second->sql != entry.sql || it->second->table != entry.table)
      return "has " + describe(entry) +
             " that differs from the one hydrocoef creates (a column or clause was added, "
             "dropped or changed)";
    wanted.erase(it);
  }
  if (!wanted.empty()) return "lacks " + describe(*wanted.begin()->second);
  return std::nullopt;
}

namespace {

std::string lower_case(std::string text) {
  for (char& c : text)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return text;
}

/// "table run: column u double precision not null", "trigger x on run", ...
std::set<std::string> expected_postgresql_objects(int version) {
  static std::mutex mutex;
  static std::map<int, std::set<std::string>> cache;
  const std::lock_guard lock(mutex);
  if (const auto found = cache.find(version); found != cache.end()) return found->second;
  Connection memory(":memory:", Access::ReadWriteCreate);
  for (int i = 0; i < version && i < static_cast<int>(migrations().size()); ++i)
    memory.execute(migrations()[static_cast<std::size_t>(i)].sql);
  std::set<std::string> out{"table hydrocoef_schema: column version bigint not null"};
  auto objects = memory.prepare(
      "SELECT type, name, tbl_name, sql FROM sqlite_schema WHERE type IN ('table', 'trigger', 'view') "
      "AND name NOT LIKE 'sqlite\\_%' ESCAPE '\\'");
  while (objects.step()) {
    const std::string type = objects.get_text(0), name = objects.get_text(1);
    if (type == "trigger") {
      out.insert("trigger " + name + " on " + objects.get_text(2));
      // The PL/pgSQL function the trigger runs, as the dialect layer writes it.
      const std::string translated = postgresql_migration(objects.get_text(3) + ";");
      const std::string marker = "$hydrocoef$";
      const std::size_t from = translated.find(marker), to = translated.rfind(marker);
      if (from != std::string::npos && to > from)
        out.insert("function " + name + ": " + translated.substr(from + marker.size(), to - from - marker.size()));
      continue;
    }
    if (type == "view") {
      out.insert("view " + name);
      continue;
    }
    auto columns = memory.prepare("SELECT name, type, \"notnull\", pk FROM pragma_table_info(?)");
    columns.bind(1, name);
    while (columns.step()) {
      const std::string declared = columns.get_text(1);
      const std::string pg = declared == "INTEGER" ? "bigint"
                             : declared == "REAL"  ? "double precision"
                             : declared == "BLOB"  ? "bytea"
                                                   : "text";
      const bool not_null = columns.get_int(2) != 0 || columns.get_int(3) != 0;
      // PostgreSQL folds unquoted names to lower case (n_dA_x is n_da_x there).
      out.insert("table " + lower_case(name) + ": column " + lower_case(columns.get_text(0)) + " " + pg +
                 (not_null ? " not null" : ""));
    }
  }
  return cache.emplace(version, out).first->second;
}

std::set<std::string> postgresql_objects(Connection& connection) {
  std::set<std::string> out;
  auto columns = connection.prepare(
      "SELECT c.table_name, c.column_name, c.data_type, c.is_nullable FROM information_schema.columns c "
      "JOIN information_schema.tables t ON t.table_schema = c.table_schema AND t.table_name = c.table_name "
      "WHERE c.table_schema = current_schema() AND t.table_type = 'BASE TABLE'");
  while (columns.step())
    out.insert("table " + columns.get_text(0) + ": column " + columns.get_text(1) + " " + columns.get_text(2) +
               (columns.get_text(3) == "NO" ? " not null" : ""));
  auto views =
      connection.prepare("SELECT table_name FROM information_schema.views WHERE table_schema = current_schema()");
  while (views.step()) out.insert("view " + views.get_text(0));
  // A trigger counts as hydrocoef's only when it is enabled and calls a
  // function of this schema (whose body is compared below): a disabled one
  // would let fits stay fresh after their forces change, and one calling a
  // function elsewhere would run someone else's code.
  auto triggers = connection.prepare(
      "SELECT t.tgname, c.relname, (t.tgenabled = 'O')::int, (pn.nspname = current_schema())::int "
      "FROM pg_trigger t JOIN pg_class c ON c.oid = t.tgrelid JOIN pg_namespace n ON n.oid = c.relnamespace "
      "JOIN pg_proc p ON p.oid = t.tgfoid JOIN pg_namespace pn ON pn.oid = p.pronamespace "
      "WHERE n.nspname = current_schema() AND NOT t.tgisinternal");
  while (triggers.step())
    out.insert("trigger " + triggers.get_text(0) + " on " + triggers.get_text(1) +
               (triggers.get_int(2) != 0 ? "" : " (disabled)") +
               (triggers.get_int(3) != 0 ? "" : " (calling a function of another schema)"));
  auto functions = connection.prepare(
      "SELECT p.proname, p.prosrc FROM pg_proc p JOIN pg_namespace n ON n.oid = p.pronamespace "
      "WHERE n.nspname = current_schema()");
  while (functions.step()) out.insert("function " + functions.get_text(0) + ": " + functions.get_text(1));
  auto rules = connection.prepare("SELECT rulename, tablename FROM pg_rules WHERE schemaname = current_schema()");
  while (rules.step()) out.insert("rule " + rules.get_text(0) + " on " + rules.get_text(1));
  return out;
}

}  // namespace

std::optional<std::string> postgresql_schema_difference(Connection& connection, int version) {
  const std::set<std::string> found = postgresql_objects(connection);
  if (version == 0) {
    if (!found.empty())
      return "has tables but no hydrocoef schema (first: " + printable_text(*found.begin(), 80) +
             "); expected an empty database or schema, or one hydrocoef made";
    return std::nullopt;
  }
  const std::set<std::string> expected = expected_postgresql_objects(version);
  for (const auto& object : found)
    if (!expected.count(object)) return "has " + printable_text(object, 120) + " that hydrocoef does not create";
  for (const auto& object : expected)
    if (!found.count(object)) return "lacks " + printable_text(object, 120);
  return std::nullopt;
}

}  // namespace hydrocoef::store
