#include "src/dynamics/surface_source.hpp"

#include <memory>

#include "src/store/database.hpp"
#include "src/surface/stored_surface.hpp"

namespace hydrocoef {

SurfaceResolver database_surface_resolver(const std::filesystem::path& database) {
  // Shared by the resolver's copies: one connection for all the surfaces a vehicle names.
  auto opened = std::make_shared<std::unique_ptr<Database>>();
  return [opened, database](const std::string& name) {
    if (!*opened) *opened = std::make_unique<Database>(database, Database::OpenMode::ReadOnly);
    return load_surface(**opened, name).surface;
  };
}

}  // namespace hydrocoef
