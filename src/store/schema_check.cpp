#include "src/store/schema_check.hpp"

#include <algorithm>
#include <map>
#include <mutex>
#include <tuple>

#include "src/core/error.hpp"
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

}  // namespace hydrocoef::store
