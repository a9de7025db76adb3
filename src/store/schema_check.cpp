#include "src/store/schema_check.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <mutex>
#include <set>
#include <tuple>

#include "src/core/error.hpp"
#include "src/core/text.hpp"
#include "src/store/dialect.hpp"
#include "src/store/migrations.hpp"

namespace hydrocoef::store {
namespace {

std::string describe(const SchemaEntry& entry) {
  std::string text =
      std::string(entry.type == "index" ? "an " : "a ") + entry.type + " '" + printable_text(entry.name, 60) + "'";
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
  // A missing table first: its indexes and triggers go with it.
  for (const auto& [name, entry] : wanted)
    if (entry->type == "table") return "lacks " + describe(*entry);
  if (!wanted.empty()) return "lacks " + describe(*wanted.begin()->second);
  return std::nullopt;
}

namespace {

/// Every comma-separated name of a column list, in order: "(a, b)".
std::string column_list(const std::vector<std::string>& columns) {
  std::string out = "(";
  for (const auto& c : columns) out += (out.size() > 1 ? ", " : "") + c;
  return out + ")";
}

/// SQLite's and PostgreSQL's words for a foreign key action.
std::string action_name(std::string text) {
  text = lower(std::move(text));
  return text == "a"   ? "no action"
         : text == "r" ? "restrict"
         : text == "c" ? "cascade"
         : text == "n" ? "set null"
         : text == "d" ? "set default"
                       : text;
}

/// The keys, indexes, foreign keys and CHECK constraints of one table of the
/// in-memory SQLite database, as postgresql_objects describes them.
void add_expected_constraints(Connection& memory, const std::string& table, std::set<std::string>& out) {
  const std::string prefix = "table " + lower(table) + ": ";
  std::vector<std::pair<int, std::string>> key;
  auto columns = memory.prepare("SELECT name, pk FROM pragma_table_info(?) WHERE pk > 0");
  columns.bind(1, table);
  while (columns.step()) key.emplace_back(columns.get_int(1), lower(columns.get_text(0)));
  std::sort(key.begin(), key.end());
  std::vector<std::string> key_columns;
  for (const auto& k : key) key_columns.push_back(k.second);
  if (!key_columns.empty()) out.insert(prefix + "primary key " + column_list(key_columns));

  auto indexes = memory.prepare("SELECT name, \"unique\", origin, partial FROM pragma_index_list(?)");
  indexes.bind(1, table);
  while (indexes.step()) {
    if (indexes.get_text(2) == "pk") continue;  // the primary key, above
    std::vector<std::string> names;
    auto info = memory.prepare("SELECT coalesce(name, '(expression)') FROM pragma_index_info(?) ORDER BY seqno");
    info.bind(1, indexes.get_text(0));
    while (info.step()) names.push_back(lower(info.get_text(0)));
    out.insert(prefix + (indexes.get_int(1) != 0 ? "unique index " : "index ") + column_list(names) +
               (indexes.get_int(3) != 0 ? " (partial)" : ""));
  }

  auto foreign = memory.prepare(
      "SELECT id, \"table\", \"from\", \"to\", on_update, on_delete FROM pragma_foreign_key_list(?) "
      "ORDER BY id, seq");
  foreign.bind(1, table);
  std::map<std::int64_t, std::array<std::string, 5>> keys;  // id: from, table, to, on update, on delete
  while (foreign.step()) {
    auto& k = keys[foreign.get_int(0)];
    const std::string referenced = lower(foreign.get_text(1));
    k[0] += (k[0].empty() ? "" : ", ") + lower(foreign.get_text(2));
    k[1] = referenced;
    // No column named: the referenced table's primary key.
    std::string to = lower(foreign.get_text(3));
    if (to.empty()) {
      auto pk = memory.prepare("SELECT name FROM pragma_table_info(?) WHERE pk > 0 ORDER BY pk");
      pk.bind(1, foreign.get_text(1));
      while (pk.step()) to += (to.empty() ? "" : ", ") + lower(pk.get_text(0));
    }
    k[2] += (k[2].empty() ? "" : ", ") + to;
    k[3] = action_name(foreign.get_text(4));
    k[4] = action_name(foreign.get_text(5));
  }
  for (const auto& [id, k] : keys)
    out.insert(prefix + "foreign key (" + k[0] + ") references " + k[1] + " (" + k[2] + ") on update " + k[3] +
               " on delete " + k[4]);

  // CHECK constraints by count: SQLite keeps them only in the CREATE TABLE
  // text, and PostgreSQL rewrites their expressions its own way.
  auto sql = memory.prepare("SELECT sql FROM sqlite_schema WHERE type = 'table' AND name = ?");
  sql.bind(1, table);
  std::size_t checks = 0;
  if (sql.step()) {
    const std::string text = sql.get_text(0);
    for (std::size_t at = text.find("CHECK"); at != std::string::npos; at = text.find("CHECK", at + 5)) ++checks;
  }
  if (checks > 0) out.insert(prefix + std::to_string(checks) + " check constraints");
}

/// "table run: column u double precision not null default", "trigger x on
/// run", "table run: primary key (id)", ...
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
    auto columns =
        memory.prepare("SELECT name, type, \"notnull\", pk, dflt_value IS NOT NULL FROM pragma_table_info(?)");
    columns.bind(1, name);
    std::size_t key_columns = 0;
    std::vector<std::string> lines;
    while (columns.step()) {
      const std::string declared = columns.get_text(1);
      const std::string pg = declared == "INTEGER" ? "bigint"
                             : declared == "REAL"  ? "double precision"
                             : declared == "BLOB"  ? "bytea"
                                                   : "text collate C";
      const bool not_null = columns.get_int(2) != 0 || columns.get_int(3) != 0;
      if (columns.get_int(3) > 0) ++key_columns;
      // An INTEGER PRIMARY KEY is an identity column there (dialect.cpp).
      const bool identity = declared == "INTEGER" && columns.get_int(3) == 1;
      // PostgreSQL folds unquoted names to lower case (n_dA_x is n_da_x there).
      lines.push_back("table " + lower(name) + ": column " + lower(columns.get_text(0)) + " " + pg +
                      (not_null ? " not null" : "") + (columns.get_int(4) != 0 ? " default" : "") +
                      (identity ? " identity" : ""));
    }
    // Only a key of one INTEGER column is an identity.
    for (auto& line : lines) {
      const std::string mark = " identity";
      if (key_columns != 1 && line.ends_with(mark)) line.erase(line.size() - mark.size());
      out.insert(line);
    }
    add_expected_constraints(memory, name, out);
  }
  return cache.emplace(version, out).first->second;
}

/// SQL for the column names of a relation's attribute numbers, in order ("a, b";
/// an expression index's column is "(expression)").
std::string column_names_sql(const std::string& relation, const std::string& numbers) {
  return "(SELECT string_agg(coalesce(a.attname, '(expression)'), ', ' ORDER BY k.n) FROM unnest(" + numbers +
         "::int2[]) WITH ORDINALITY AS k(attnum, n) LEFT JOIN pg_attribute a ON a.attrelid = " + relation +
         " AND a.attnum = k.attnum AND k.attnum > 0)";
}

std::set<std::string> postgresql_objects(Connection& connection) {
  std::set<std::string> out;
  auto columns = connection.prepare(
      "SELECT c.table_name, c.column_name, c.data_type, c.is_nullable, coalesce(c.collation_name, ''), "
      "(c.column_default IS NOT NULL)::int, (c.is_identity = 'YES')::int FROM information_schema.columns c "
      "JOIN information_schema.tables t ON t.table_schema = c.table_schema AND t.table_name = c.table_name "
      "WHERE c.table_schema = current_schema() AND t.table_type = 'BASE TABLE'");
  while (columns.step()) {
    const std::string collation = columns.get_text(4);
    out.insert("table " + columns.get_text(0) + ": column " + columns.get_text(1) + " " + columns.get_text(2) +
               (collation.empty() ? "" : " collate " + collation) + (columns.get_text(3) == "NO" ? " not null" : "") +
               (columns.get_int(5) != 0 ? " default" : "") + (columns.get_int(6) != 0 ? " identity" : ""));
  }
  // Keys and indexes, by their columns (their names are each database's own).
  auto indexes = connection.prepare("SELECT t.relname, " + column_names_sql("i.indrelid", "i.indkey") +
                                    ", i.indisprimary::int, i.indisunique::int, (i.indpred IS NOT NULL)::int "
                                    "FROM pg_index i JOIN pg_class t ON t.oid = i.indrelid "
                                    "JOIN pg_namespace n ON n.oid = t.relnamespace WHERE n.nspname = current_schema()");
  while (indexes.step()) {
    const std::string columns_of = "(" + indexes.get_text(1) + ")";
    const std::string kind = indexes.get_int(2) != 0   ? "primary key "
                             : indexes.get_int(3) != 0 ? "unique index "
                                                       : "index ";
    out.insert("table " + indexes.get_text(0) + ": " + kind + columns_of +
               (indexes.get_int(4) != 0 ? " (partial)" : ""));
  }
  auto constraints = connection.prepare(
      "SELECT t.relname, c.contype::text, " + column_names_sql("c.conrelid", "c.conkey") + ", " +
      column_names_sql("c.confrelid", "c.confkey") +
      ", coalesce(r.relname, ''), c.confupdtype::text, c.confdeltype::text FROM pg_constraint c "
      "JOIN pg_class t ON t.oid = c.conrelid JOIN pg_namespace n ON n.oid = t.relnamespace "
      "LEFT JOIN pg_class r ON r.oid = c.confrelid WHERE n.nspname = current_schema() AND c.contype IN ('f', 'c')");
  std::map<std::string, std::size_t> checks;
  while (constraints.step()) {
    const std::string table = constraints.get_text(0);
    if (constraints.get_text(1) == "c") {
      ++checks[table];
      continue;
    }
    out.insert("table " + table + ": foreign key (" + constraints.get_text(2) + ") references " +
               constraints.get_text(4) + " (" + constraints.get_text(3) + ") on update " +
               action_name(constraints.get_text(5)) + " on delete " + action_name(constraints.get_text(6)));
  }
  for (const auto& [table, count] : checks)
    out.insert("table " + table + ": " + std::to_string(count) + " check constraints");
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
  // What a line describes: a column, a table's CHECK count, a foreign key's
  // columns; the same subject on both sides is a change, said as one.
  const auto subject = [](const std::string& line) {
    if (const std::size_t at = line.find(": column "); at != std::string::npos)
      return line.substr(0, line.find(' ', at + 9));
    if (line.ends_with(" check constraints")) return line.substr(0, line.find(": ")) + ": checks";
    if (const std::size_t at = line.find(" on update "); at != std::string::npos) return line.substr(0, at);
    return line;
  };
  for (const auto& object : found) {
    if (expected.count(object)) continue;
    for (const auto& wanted : expected)
      if (!found.count(wanted) && subject(wanted) == subject(object))
        return "has " + printable_text(object, 120) + " where hydrocoef creates " + printable_text(wanted, 120);
    return "has " + printable_text(object, 120) + " that hydrocoef does not create";
  }
  for (const auto& object : expected)
    if (!found.count(object)) return "lacks " + printable_text(object, 120);
  return std::nullopt;
}

}  // namespace hydrocoef::store
