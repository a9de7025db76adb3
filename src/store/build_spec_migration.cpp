#include "src/store/build_spec_migration.hpp"

#include <nlohmann/json.hpp>

#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/surface/surface_build_spec.hpp"

namespace hydrocoef::store {

void convert_surface_build_options(Connection& connection, const std::string& database) {
  auto read = connection.prepare("SELECT id, name, definition FROM surface ORDER BY id");
  std::vector<std::pair<std::int64_t, std::string>> updates;
  while (read.step()) {
    const std::int64_t id = read.get_int(0);
    const std::string context =
        "surface '" + printable_text(read.get_text(1), 60) + "' (id " + std::to_string(id) + ") in " + database;
    auto definition = nlohmann::json::parse(read.get_text(2), nullptr, false);
    if (definition.is_discarded() || !definition.is_object())
      throw InputError(context + ": its definition is not a JSON object; expected what hydrocoef stores");
    if (!definition.contains("build")) continue;  // not made by surface build: nothing to convert
    definition["build_spec"] = build_spec_from_legacy_options(definition["build"], context);
    definition.erase("build");
    updates.emplace_back(id, escape::json_text(definition));
  }
  read.reset();
  auto write = connection.prepare("UPDATE surface SET definition = ? WHERE id = ?");
  for (const auto& [id, text] : updates) {
    write.bind(1, text).bind(2, id).run();
  }
}

}  // namespace hydrocoef::store
